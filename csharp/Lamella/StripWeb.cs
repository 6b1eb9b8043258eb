using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// One node of a 3-web gridshell (<c>LmlWebNode</c>): where a strip of family <see cref="Families"/>[0] crosses one of
    /// <see cref="Families"/>[1]; at a vertex where three families meet there is a node for each pair. The per-strip
    /// entries of <see cref="Node"/> (<see cref="Node.Strips"/>, <see cref="Node.ArcLengths"/>, the diagnostics) at index
    /// i are of family <see cref="Families"/>[i], <see cref="Node.Vertex"/> indexes <see cref="StripWeb.Vertices"/>.
    /// </summary>
    public sealed class WebNode : Node
    {
        internal WebNode(WebNodeRecord r)
            : base(r.Node)
        {
            Families = new[] { checked((int)r.Families[0]), checked((int)r.Families[1]) };
        }

        /// <summary>The two families that cross here (0: F, 1: H, 2: G), the smaller first.</summary>
        public int[] Families { get; }
    }

    /// <summary>
    /// A 3-web gridshell as built from three strip families (<c>LmlStripWeb</c>, paper Sec. 4.2 and 5.1): the web where the
    /// level curves at the web's even-pace levels cross — triangles, or with Kagome triangles and hexagons — its
    /// polylines per family, and the nodes where the strips cross. Immutable.
    /// </summary>
    public sealed class StripWeb : IDisposable
    {
        private readonly StripWebHandle handle;

        /// <summary>
        /// The web of the 3-web <paramref name="net"/>'s current fields at the levels of
        /// <see cref="NetSolver.WebLevels"/>(<paramref name="countF"/>, <paramref name="countH"/>, <paramref name="kagome"/>),
        /// and the nodes of the strips <paramref name="f"/>, <paramref name="h"/> and <paramref name="g"/> (built on
        /// <see cref="LevelCurves.OfWeb"/> of families 0, 1 and 2 with the same arguments).
        /// </summary>
        /// <exception cref="LamellaException">A net of two families, a count out of range, strips on other levels (named), a constant field.</exception>
        public StripWeb(NetSolver net, int countF, int countH, bool kagome, Strips f, Strips h, Strips g)
        {
            if (net == null) throw new ArgumentNullException(nameof(net));
            if (f == null) throw new ArgumentNullException(nameof(f));
            if (h == null) throw new ArgumentNullException(nameof(h));
            if (g == null) throw new ArgumentNullException(nameof(g));
            StripWebHandle created = null;
            Native.Check(net.WebCall(countF, countH, kagome, (n, cf, ch, kg) =>
                NativeMethods.lml_strip_web_new(n, cf, ch, kg, f.Handle, h.Handle, g.Handle, out created)));
            handle = created;
        }

        internal StripWebHandle Handle => handle;

        /// <summary>The web's vertices as x, y, z triples: crossings of the families' levels, ordered by their levels of F, then of H.</summary>
        public double[] Vertices() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_vertices(handle, b, c, out n));

        /// <summary>
        /// Per vertex, the index of the level of each family through it (into that family's
        /// <see cref="NetSolver.WebLevels"/>; three entries, null where none of the family's curves passes): two or three
        /// are set at every vertex, exactly two in a Kagome pattern.
        /// </summary>
        public int?[][] VertexLevels()
        {
            long[] flat = Native.Read((long[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_vertex_levels(handle, b, c, out n));
            var levels = new int?[flat.Length / 3][];
            for (int v = 0; v < levels.Length; v++)
            {
                levels[v] = new int?[3];
                for (int k = 0; k < 3; k++)
                {
                    if (flat[3 * v + k] >= 0) levels[v][k] = checked((int)flat[3 * v + k]);
                }
            }
            return levels;
        }

        /// <summary>
        /// The faces as vertex indices: triangles, and in a Kagome pattern hexagons, oriented as the net of F and H
        /// ((i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)).
        /// </summary>
        public int[][] Faces() =>
            Native.Runs(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_face_sizes(handle, b, c, out n)),
                Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_face_vertices(handle, b, c, out n)));

        /// <summary>
        /// The polylines of family <paramref name="family"/> (0: F, 1: H, 2: G) as vertex indices: each a maximal run of two
        /// or more consecutive web vertices along one level of the family.
        /// </summary>
        public int[][] Polylines(int family)
        {
            NetSolver.CheckWebFamily(family, nameof(family));
            uint k = (uint)family;
            return Native.Runs(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_polyline_sizes(handle, k, b, c, out n)),
                Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_polyline_vertices(handle, k, b, c, out n)));
        }

        /// <summary>The level index (into the family's <see cref="NetSolver.WebLevels"/>) of each of <see cref="Polylines"/>(<paramref name="family"/>).</summary>
        public int[] PolylineLevels(int family)
        {
            NetSolver.CheckWebFamily(family, nameof(family));
            return Array.ConvertAll(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_polyline_levels(handle, (uint)family, b, c, out n)),
                i => checked((int)i));
        }

        /// <summary>The nodes, ordered by vertex, at a vertex by pair of families: every crossing of two families' levels where both carry a strip.</summary>
        public WebNode[] Nodes() =>
            Array.ConvertAll(Native.Read((WebNodeRecord[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strip_web_nodes(handle, b, c, out n)), r => new WebNode(r));

        /// <summary>Releases the native web (harmless to call twice).</summary>
        public void Dispose() => handle.Dispose();
    }
}
