using System;
using System.Collections.Generic;
using System.Globalization;

namespace Lamella.Conversion
{
    /// <summary>
    /// A CAD mesh made fit for the library, and the way back to it. CAD meshes arrive unwelded (a mesh per
    /// polysurface face, texture seams: coincident vertices that give false boundaries where traces stop and level
    /// curves break), with faces collapsed to a line or a point, repeated faces and vertices no face uses, all of which
    /// the library rejects or misreads. The clean copy welds vertices closer than a tolerance (each to the first such
    /// input vertex, whose position it keeps), drops triangles that repeat a corner or have zero area by the library's
    /// own test, drops repeated triangles, and removes unused vertices; <see cref="VertexMap"/> takes per-vertex results
    /// back to the input mesh's vertices. A mesh with nothing to clean comes back unchanged, vertex for vertex.
    /// </summary>
    public sealed class CleanMesh
    {
        /// <summary>The library's zero-area test: twice a triangle's area at most this times its longest edge squared.</summary>
        private const double ZeroAreaRatio = 1e-12;

        /// <summary>The clean vertices, x, y, z each.</summary>
        public double[] Xyz { get; }
        /// <summary>The clean triangles, three indices into <see cref="Xyz"/> each, oriented as the input faces.</summary>
        public int[] Triangles { get; }
        /// <summary>For each input vertex, its vertex in the clean mesh, or −1 when no remaining face uses it.</summary>
        public int[] VertexMap { get; }
        /// <summary>The weld tolerance used (a length in the mesh's units; 0 welds only identical positions).</summary>
        public double Tolerance { get; }
        /// <summary>Input vertices merged into an earlier one within <see cref="Tolerance"/>.</summary>
        public int WeldedVertices { get; }
        /// <summary>Triangles dropped because they repeat a corner (after welding) or have zero area.</summary>
        public int DegenerateTriangles { get; }
        /// <summary>Triangles dropped because an earlier triangle has the same three corners.</summary>
        public int RepeatedTriangles { get; }
        /// <summary>Input vertices (not welded into another) that no remaining face uses.</summary>
        public int UnusedVertices { get; }

        private CleanMesh(double[] xyz, int[] triangles, int[] vertexMap, double tolerance, int welded, int degenerate, int repeated, int unused)
        {
            Xyz = xyz;
            Triangles = triangles;
            VertexMap = vertexMap;
            Tolerance = tolerance;
            WeldedVertices = welded;
            DegenerateTriangles = degenerate;
            RepeatedTriangles = repeated;
            UnusedVertices = unused;
        }

        /// <summary>The number of vertices of the input mesh.</summary>
        public int InputVertexCount => VertexMap.Length;

        /// <summary>The number of clean vertices.</summary>
        public int VertexCount => Xyz.Length / 3;

        /// <summary>True when anything was welded, dropped or removed.</summary>
        public bool Changed => WeldedVertices + DegenerateTriangles + RepeatedTriangles + UnusedVertices > 0;

        /// <summary>
        /// Cleans a mesh given as vertices (x, y, z each) and faces of four corners each (a triangle repeats its third
        /// corner as the fourth, as Rhino's MeshFace does; quads are split along the shorter diagonal, see
        /// <see cref="MeshArrays.Triangulate"/>). Vertices closer than <paramref name="tolerance"/> (≥ 0) are welded.
        /// Throws <see cref="ArgumentException"/> naming the vertex or face for non-finite coordinates or corners out
        /// of range.
        /// </summary>
        public static CleanMesh FromFaces(double[] xyz, int[] faceCorners, double tolerance)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            if (faceCorners == null) throw new ArgumentNullException(nameof(faceCorners));
            if (xyz.Length % 3 != 0) throw new ArgumentException("xyz holds " + xyz.Length + " values, not a multiple of 3", nameof(xyz));
            if (!(tolerance >= 0) || double.IsInfinity(tolerance)) throw new ArgumentOutOfRangeException(nameof(tolerance), "the weld tolerance must be finite and ≥ 0");
            int inputCount = xyz.Length / 3;
            for (int i = 0; i < xyz.Length; i++)
            {
                if (double.IsNaN(xyz[i]) || double.IsInfinity(xyz[i])) throw new ArgumentException("vertex " + i / 3 + " has a non-finite coordinate", nameof(xyz));
            }

            int[] representative = Weld(xyz, tolerance, out int welded);
            var welds = new int[faceCorners.Length];
            for (int k = 0; k < faceCorners.Length; k++)
            {
                welds[k] = faceCorners[k] >= 0 && faceCorners[k] < inputCount ? representative[faceCorners[k]] : faceCorners[k];
            }
            // Triangulate checks the corner indices (naming the face) and splits quads; faces that collapsed to a
            // triangle after welding repeat a corner and are told apart below.
            int[] split = MeshArrays.Triangulate(xyz, NormaliseCorners(welds));

            var kept = new List<int>(split.Length);
            var seen = new HashSet<TriangleKey>();
            int degenerate = 0, repeated = 0;
            for (int t = 0; t < split.Length / 3; t++)
            {
                int a = split[3 * t], b = split[3 * t + 1], c = split[3 * t + 2];
                if (a == b || b == c || a == c || IsZeroArea(xyz, a, b, c))
                {
                    degenerate++;
                }
                else if (!seen.Add(new TriangleKey(a, b, c)))
                {
                    repeated++;
                }
                else
                {
                    kept.Add(a);
                    kept.Add(b);
                    kept.Add(c);
                }
            }

            // Compact: clean vertices in the order of their input representatives, so a clean input maps to itself.
            var used = new bool[inputCount];
            foreach (int v in kept) used[v] = true;
            var compact = new int[inputCount];
            int count = 0, unused = 0;
            for (int v = 0; v < inputCount; v++)
            {
                if (representative[v] != v) continue;
                if (used[v]) compact[v] = count++;
                else
                {
                    compact[v] = -1;
                    unused++;
                }
            }
            var cleanXyz = new double[3 * count];
            for (int v = 0; v < inputCount; v++)
            {
                if (representative[v] == v && compact[v] >= 0) Array.Copy(xyz, 3 * v, cleanXyz, 3 * compact[v], 3);
            }
            var map = new int[inputCount];
            for (int v = 0; v < inputCount; v++) map[v] = compact[representative[v]];
            var triangles = kept.ToArray();
            for (int k = 0; k < triangles.Length; k++) triangles[k] = compact[triangles[k]];
            return new CleanMesh(cleanXyz, triangles, map, tolerance, welded, degenerate, repeated, unused);
        }

        /// <summary>
        /// What cleaning changed, for a remark (culture-invariant), or null when the mesh was used as it is.
        /// </summary>
        public string Describe()
        {
            if (!Changed) return null;
            var parts = new List<string>();
            if (WeldedVertices > 0) parts.Add(Count(WeldedVertices, "coincident vertex", "coincident vertices") + " welded (within " + Tolerance.ToString("G4", CultureInfo.InvariantCulture) + ")");
            if (DegenerateTriangles > 0) parts.Add(Count(DegenerateTriangles, "degenerate triangle", "degenerate triangles") + " (repeated corner or zero area) removed");
            if (RepeatedTriangles > 0) parts.Add(Count(RepeatedTriangles, "repeated triangle", "repeated triangles") + " removed");
            if (UnusedVertices > 0) parts.Add(Count(UnusedVertices, "unused vertex", "unused vertices") + " dropped");
            return "mesh cleaned: " + string.Join(", ", parts) + "; per-vertex outputs follow the input mesh's " + InputVertexCount + " vertices";
        }

        /// <summary>
        /// Per-vertex values of the clean mesh (<paramref name="dimension"/> values per vertex) as values per input vertex:
        /// welded vertices repeat their clean vertex's values, vertices no face uses get <paramref name="missing"/>.
        /// </summary>
        public double[] ToInputVertices(double[] values, int dimension, double missing)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            if (dimension < 1) throw new ArgumentOutOfRangeException(nameof(dimension));
            if (values.Length != dimension * VertexCount) throw new ArgumentException(values.Length + " values for " + VertexCount + " clean vertices of dimension " + dimension, nameof(values));
            var result = new double[dimension * InputVertexCount];
            for (int v = 0; v < InputVertexCount; v++)
            {
                int c = VertexMap[v];
                for (int k = 0; k < dimension; k++) result[dimension * v + k] = c < 0 ? missing : values[dimension * c + k];
            }
            return result;
        }

        private static string Count(int n, string one, string many) => n.ToString(CultureInfo.InvariantCulture) + " " + (n == 1 ? one : many);

        /// <summary>
        /// The representative of each vertex: itself, or the first earlier representative within the tolerance. A grid
        /// of cells the size of the tolerance finds the candidates in the 27 cells around a vertex.
        /// </summary>
        internal static int[] Weld(double[] xyz, double tolerance, out int welded)
        {
            int n = xyz.Length / 3;
            var representative = new int[n];
            var cells = new Dictionary<Cell, List<int>>();
            double squared = tolerance * tolerance;
            welded = 0;
            for (int v = 0; v < n; v++)
            {
                Cell home = Cell.Of(xyz, v, tolerance);
                int found = -1;
                for (int dx = -1; dx <= 1 && found < 0; dx++)
                {
                    for (int dy = -1; dy <= 1 && found < 0; dy++)
                    {
                        for (int dz = -1; dz <= 1 && found < 0; dz++)
                        {
                            if (tolerance == 0 && (dx != 0 || dy != 0 || dz != 0)) continue;
                            List<int> members;
                            if (!cells.TryGetValue(home.Offset(dx, dy, dz), out members)) continue;
                            foreach (int r in members)
                            {
                                if (SquaredDistance(xyz, v, r) <= squared)
                                {
                                    found = r;
                                    break;
                                }
                            }
                        }
                    }
                }
                if (found >= 0)
                {
                    representative[v] = found;
                    welded++;
                    continue;
                }
                representative[v] = v;
                List<int> list;
                if (!cells.TryGetValue(home, out list)) cells[home] = list = new List<int>();
                list.Add(v);
            }
            return representative;
        }

        /// <summary>
        /// Four corners per face with repeated corners of a quad squeezed out, so that a quad with two welded corners
        /// becomes the triangle a b c c; faces with fewer than three distinct corners keep theirs (dropped later).
        /// </summary>
        private static int[] NormaliseCorners(int[] corners)
        {
            if (corners.Length % 4 != 0) return corners; // Triangulate names the problem
            var result = (int[])corners.Clone();
            var distinct = new List<int>(4);
            for (int f = 0; f < corners.Length / 4; f++)
            {
                distinct.Clear();
                for (int k = 0; k < 4; k++)
                {
                    int v = corners[4 * f + k];
                    if (distinct.Count == 0 || distinct[distinct.Count - 1] != v) distinct.Add(v);
                }
                if (distinct.Count > 1 && distinct[0] == distinct[distinct.Count - 1]) distinct.RemoveAt(distinct.Count - 1);
                if (distinct.Count == 3)
                {
                    result[4 * f] = distinct[0];
                    result[4 * f + 1] = distinct[1];
                    result[4 * f + 2] = distinct[2];
                    result[4 * f + 3] = distinct[2];
                }
            }
            return result;
        }

        private static bool IsZeroArea(double[] xyz, int a, int b, int c)
        {
            double ux = xyz[3 * b] - xyz[3 * a], uy = xyz[3 * b + 1] - xyz[3 * a + 1], uz = xyz[3 * b + 2] - xyz[3 * a + 2];
            double vx = xyz[3 * c] - xyz[3 * a], vy = xyz[3 * c + 1] - xyz[3 * a + 1], vz = xyz[3 * c + 2] - xyz[3 * a + 2];
            double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
            double twiceArea = Math.Sqrt(cx * cx + cy * cy + cz * cz);
            double longest = Math.Max(SquaredDistance(xyz, a, b), Math.Max(SquaredDistance(xyz, b, c), SquaredDistance(xyz, c, a)));
            return twiceArea <= ZeroAreaRatio * longest;
        }

        private static double SquaredDistance(double[] xyz, int i, int j)
        {
            double dx = xyz[3 * i] - xyz[3 * j], dy = xyz[3 * i + 1] - xyz[3 * j + 1], dz = xyz[3 * i + 2] - xyz[3 * j + 2];
            return dx * dx + dy * dy + dz * dz;
        }

        /// <summary>A grid cell (cell coordinates as doubles, exact for any mesh a CAD program holds).</summary>
        private struct Cell : IEquatable<Cell>
        {
            private readonly double x, y, z;

            private Cell(double x, double y, double z)
            {
                // + 0.0 turns −0 into +0: they are equal but may hash differently.
                this.x = x + 0.0;
                this.y = y + 0.0;
                this.z = z + 0.0;
            }

            public static Cell Of(double[] xyz, int v, double size) =>
                size == 0 ? new Cell(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2])
                    : new Cell(Math.Floor(xyz[3 * v] / size), Math.Floor(xyz[3 * v + 1] / size), Math.Floor(xyz[3 * v + 2] / size));

            public Cell Offset(int dx, int dy, int dz) => new Cell(x + dx, y + dy, z + dz);

            public bool Equals(Cell other) => x.Equals(other.x) && y.Equals(other.y) && z.Equals(other.z);

            public override bool Equals(object obj) => obj is Cell && Equals((Cell)obj);

            public override int GetHashCode() => unchecked((x.GetHashCode() * 397 ^ y.GetHashCode()) * 397 ^ z.GetHashCode());
        }

        /// <summary>A triangle's corners as a set (a repeated triangle may start at another corner or run the other way).</summary>
        private struct TriangleKey : IEquatable<TriangleKey>
        {
            private readonly int a, b, c;

            public TriangleKey(int p, int q, int r)
            {
                a = Math.Min(p, Math.Min(q, r));
                c = Math.Max(p, Math.Max(q, r));
                b = p + q + r - a - c;
            }

            public bool Equals(TriangleKey other) => a == other.a && b == other.b && c == other.c;

            public override bool Equals(object obj) => obj is TriangleKey && Equals((TriangleKey)obj);

            public override int GetHashCode() => unchecked((a * 397 ^ b) * 397 ^ c);
        }
    }
}
