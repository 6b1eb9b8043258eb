using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>A validated triangle mesh, a topological disk possibly with holes (<c>LmlMesh</c>). Immutable.</summary>
    public sealed class LamellaMesh : IDisposable
    {
        internal readonly MeshHandle Handle;

        private LamellaMesh(MeshHandle handle)
        {
            Handle = handle;
        }

        /// <summary>
        /// Creates a mesh from flat arrays: <paramref name="xyz"/> holds x, y, z per vertex, <paramref name="triangles"/>
        /// three zero-based vertex indices per triangle, consistently oriented.
        /// </summary>
        public static LamellaMesh FromArrays(double[] xyz, int[] triangles)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            if (triangles == null) throw new ArgumentNullException(nameof(triangles));
            if (xyz.Length % 3 != 0) throw new ArgumentException("xyz holds " + xyz.Length + " values, not a multiple of 3", nameof(xyz));
            if (triangles.Length % 3 != 0) throw new ArgumentException("triangles holds " + triangles.Length + " indices, not a multiple of 3", nameof(triangles));
            var indices = new uint[triangles.Length];
            for (int i = 0; i < triangles.Length; i++)
            {
                if (triangles[i] < 0) throw new ArgumentOutOfRangeException(nameof(triangles), "triangle " + i / 3 + " corner " + i % 3 + " is negative (" + triangles[i] + ")");
                indices[i] = (uint)triangles[i];
            }
            MeshHandle handle;
            Native.Check(NativeMethods.lml_mesh_new(xyz, Native.Size(xyz.Length / 3), indices, Native.Size(triangles.Length / 3), out handle));
            return new LamellaMesh(handle);
        }

        /// <summary>Reads and validates a Wavefront OBJ file (polygons are fanned into triangles).</summary>
        public static LamellaMesh ReadObj(string path)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            MeshHandle handle;
            Native.Check(NativeMethods.lml_mesh_read_obj(Utf8.ToNative(path), out handle));
            return new LamellaMesh(handle);
        }

        /// <summary>
        /// The Brauner surface of the paper's Fig. 32 (Sec. 5.2.4, Eq. 23): x = cos²u − 2v, y = sin u cos u − u,
        /// z = 2μ e^{−v} cos u over u ∈ [0.6, π − 0.6], v ∈ [−0.5, 0.5], about <paramref name="targetVertices"/> vertices
        /// (100 to 1,000,000). Its u-lines (<see cref="BraunerULines"/>) are asymptotic curves of constant slope atan(μ e^{−v}).
        /// </summary>
        public static LamellaMesh Brauner(int targetVertices, double mu)
        {
            if (targetVertices < 0) throw new ArgumentOutOfRangeException(nameof(targetVertices));
            MeshHandle handle;
            Native.Check(NativeMethods.lml_mesh_new_brauner(Native.Size(targetVertices), mu, out handle));
            return new LamellaMesh(handle);
        }

        /// <summary>
        /// The u-lines v = v_k of <see cref="Brauner"/>'s surface, computed exactly: <paramref name="lines"/> (≥ 2) curves, v_k
        /// spread evenly over [−0.5, 0.5], each of <paramref name="points"/> (≥ 2) points (x, y, z each). Line k rises at
        /// the slope atan(μ e^{−v_k}) against the horizontal.
        /// </summary>
        public static double[][] BraunerULines(double mu, int lines, int points)
        {
            if (lines < 0) throw new ArgumentOutOfRangeException(nameof(lines));
            if (points < 0) throw new ArgumentOutOfRangeException(nameof(points));
            double[] xyz = Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_brauner_u_lines(mu, Native.Size(lines), Native.Size(points), b, c, out n));
            var result = new double[lines][];
            for (int k = 0; k < lines; k++)
            {
                result[k] = new double[3 * points];
                Array.Copy(xyz, 3 * points * k, result[k], 0, 3 * points);
            }
            return result;
        }

        /// <summary>The number of vertices.</summary>
        public int VertexCount
        {
            get
            {
                UIntPtr count;
                Native.Check(NativeMethods.lml_mesh_vertex_count(Handle, out count));
                return Native.Count(count);
            }
        }

        /// <summary>The number of triangles.</summary>
        public int TriangleCount
        {
            get
            {
                UIntPtr count;
                Native.Check(NativeMethods.lml_mesh_triangle_count(Handle, out count));
                return Native.Count(count);
            }
        }

        /// <summary>The vertex positions, x, y, z per vertex.</summary>
        public double[] Positions() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_mesh_positions(Handle, b, c, out n));

        /// <summary>The triangles, three vertex indices each.</summary>
        public int[] Triangles() =>
            Array.ConvertAll(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_mesh_triangles(Handle, b, c, out n)), i => checked((int)i));

        /// <summary>Releases the native mesh (harmless to call twice).</summary>
        public void Dispose() => Handle.Dispose();
    }
}
