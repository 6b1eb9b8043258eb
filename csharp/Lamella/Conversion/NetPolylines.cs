using System;
using System.Collections.Generic;

namespace Lamella.Conversion
{
    /// <summary>
    /// A net or a web given as polylines of points, welded (<see cref="NetPolylines.FromPoints"/>): its vertices and each
    /// family's polylines as vertex indices, as <see cref="BaseMeshSolver"/> takes them.
    /// </summary>
    public sealed class WeldedNet
    {
        internal WeldedNet(double[] xyz, int[][][] polylines, int weldedPoints)
        {
            Xyz = xyz;
            Polylines = polylines;
            WeldedPoints = weldedPoints;
        }

        /// <summary>The vertices, x, y, z each, in the order of their first point (family by family, polyline by polyline).</summary>
        public double[] Xyz { get; }
        /// <summary>Per family (0 the rows, 1 the columns, 2 a web's diagonals), its polylines as vertex indices into <see cref="Xyz"/>.</summary>
        public int[][][] Polylines { get; }
        /// <summary>Points merged into an earlier one: the crossings of the polylines, counted once per further point there.</summary>
        public int WeldedPoints { get; }

        /// <summary>The number of vertices.</summary>
        public int VertexCount => Xyz.Length / 3;
    }

    /// <summary>
    /// The rows and columns of a quad mesh with the combinatorics of a net (paper Sec. 3.5), as
    /// <see cref="BaseMeshSolver"/> takes them: opposite sides of a quad belong to one family, neighbouring quads agree on
    /// the side they share, and every vertex has at most two neighbours along each family. The first quad of each
    /// connected piece decides: its first side (corner 0 to corner 1) runs along a row. For the quads of a
    /// <see cref="StripNet"/> ((i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)) the rows are its rows (equal i), each
    /// running along increasing j.
    /// </summary>
    public static class NetPolylines
    {
        /// <summary>
        /// The polylines of each family (index 0 the rows, 1 the columns) of <paramref name="quads"/> (four vertex indices
        /// each, around the quad) over <paramref name="vertexCount"/> vertices, each polyline a list of vertex indices in
        /// order, starting at its end of lower index; polylines and families in the order of their first vertex. Vertices
        /// on no quad are on no polyline.
        /// </summary>
        /// <exception cref="ArgumentException">A quad repeats a corner (a triangle) or refers to a vertex out of range, an edge has more than two quads, the quads' sides cannot be split into two families, a vertex has more than two neighbours along one family, or a polyline closes (each named).</exception>
        public static int[][][] FromQuads(int[] quads, int vertexCount)
        {
            if (quads == null) throw new ArgumentNullException(nameof(quads));
            if (quads.Length % 4 != 0) throw new ArgumentException("quads holds " + quads.Length + " indices, not 4 per quad", nameof(quads));
            int count = quads.Length / 4;
            for (int q = 0; q < count; q++)
            {
                for (int c = 0; c < 4; c++)
                {
                    int v = quads[4 * q + c];
                    if (v < 0 || v >= vertexCount) throw new ArgumentException("quad " + q + " refers to vertex " + v + ", but there are " + vertexCount + " vertices", nameof(quads));
                    for (int d = 0; d < c; d++)
                    {
                        if (quads[4 * q + d] == v) throw new ArgumentException("quad " + q + " repeats vertex " + v + ": a net has quads only", nameof(quads));
                    }
                }
            }
            // The quad sides at each edge (side s of quad q: corner s to corner s + 1).
            var sides = new Dictionary<long, List<int>>();
            for (int q = 0; q < count; q++)
            {
                for (int s = 0; s < 4; s++)
                {
                    long key = EdgeKey(quads, q, s, vertexCount);
                    List<int> at;
                    if (!sides.TryGetValue(key, out at)) sides[key] = at = new List<int>(2);
                    if (at.Count == 2) throw new ArgumentException("the edge " + quads[4 * q + s] + "–" + quads[4 * q + (s + 1) % 4] + " has more than two quads", nameof(quads));
                    at.Add(4 * q + s);
                }
            }
            // The family of each quad's side 0, spread from quad to quad across shared edges: side s of quad q belongs
            // to family (family[q] + s) % 2.
            var family = new int[count];
            for (int q = 0; q < count; q++) family[q] = -1;
            var queue = new Queue<int>();
            for (int first = 0; first < count; first++)
            {
                if (family[first] >= 0) continue;
                family[first] = 0;
                queue.Enqueue(first);
                while (queue.Count > 0)
                {
                    int q = queue.Dequeue();
                    for (int s = 0; s < 4; s++)
                    {
                        foreach (int side in sides[EdgeKey(quads, q, s, vertexCount)])
                        {
                            int other = side / 4, expected = (family[q] + s + side % 4) % 2;
                            if (family[other] < 0)
                            {
                                family[other] = expected;
                                queue.Enqueue(other);
                            }
                            else if (family[other] != expected)
                            {
                                throw new ArgumentException("quad " + other + " meets quad " + q + " across a row on one side and a column on the other: the quads do not form a net of rows and columns", nameof(quads));
                            }
                        }
                    }
                }
            }
            // The neighbours of every vertex along each family.
            var neighbours = new[] { new List<int>[vertexCount], new List<int>[vertexCount] };
            foreach (List<int> at in sides.Values)
            {
                int q = at[0] / 4, s = at[0] % 4, k = (family[q] + s) % 2;
                int a = quads[4 * q + s], b = quads[4 * q + (s + 1) % 4];
                Link(neighbours[k], a, b, k);
                Link(neighbours[k], b, a, k);
            }
            return new[] { Chains(neighbours[0], "row"), Chains(neighbours[1], "column") };
        }

        /// <summary>
        /// The net (two families) or web (three) of polylines given by their points: <paramref name="families"/>[k][l] holds
        /// the x, y, z of polyline l of family k (0 the rows, 1 the columns, 2 the diagonals), in order along it, such as
        /// Strip Web's polylines. Points closer than <paramref name="tolerance"/> (≥ 0; 0 welds identical positions only)
        /// become one vertex at the first one's position: where polylines of different families cross, they share it.
        /// </summary>
        /// <exception cref="ArgumentException">A polyline whose coordinates are not x, y, z triples, non-finite, of fewer than two points, or with two consecutive points within the tolerance (named rows[l], columns[l] or diagonals[l]).</exception>
        public static WeldedNet FromPoints(double[][][] families, double tolerance)
        {
            if (families == null) throw new ArgumentNullException(nameof(families));
            if (!(tolerance >= 0) || double.IsInfinity(tolerance)) throw new ArgumentOutOfRangeException(nameof(tolerance), "the weld tolerance must be finite and ≥ 0");
            var points = new List<double>();
            for (int k = 0; k < families.Length; k++)
            {
                if (families[k] == null) throw new ArgumentNullException(nameof(families), "family " + k + " is null");
                for (int l = 0; l < families[k].Length; l++)
                {
                    double[] line = families[k][l];
                    string name = BaseMeshSolver.FamilyName(k) + "[" + l + "]";
                    if (line == null || line.Length % 3 != 0) throw new ArgumentException(name + " does not hold x, y, z triples", nameof(families));
                    if (line.Length < 6) throw new ArgumentException(name + " has " + line.Length / 3 + " points; a polyline needs at least 2", nameof(families));
                    foreach (double c in line)
                    {
                        if (double.IsNaN(c) || double.IsInfinity(c)) throw new ArgumentException(name + " has a non-finite coordinate", nameof(families));
                    }
                    points.AddRange(line);
                }
            }
            double[] all = points.ToArray();
            int welded;
            int[] representative = CleanMesh.Weld(all, tolerance, out welded);
            // The vertices in the order of their representatives.
            var vertex = new int[representative.Length];
            var xyz = new List<double>();
            for (int p = 0; p < representative.Length; p++)
            {
                if (representative[p] != p) continue;
                vertex[p] = xyz.Count / 3;
                xyz.AddRange(new[] { all[3 * p], all[3 * p + 1], all[3 * p + 2] });
            }
            var polylines = new int[families.Length][][];
            int at = 0;
            for (int k = 0; k < families.Length; k++)
            {
                polylines[k] = new int[families[k].Length][];
                for (int l = 0; l < families[k].Length; l++)
                {
                    int[] line = polylines[k][l] = new int[families[k][l].Length / 3];
                    for (int i = 0; i < line.Length; i++, at++)
                    {
                        line[i] = vertex[representative[at]];
                        if (i > 0 && line[i] == line[i - 1])
                        {
                            throw new ArgumentException(BaseMeshSolver.FamilyName(k) + "[" + l + "]: points " + (i - 1) + " and " + i + " are within the weld tolerance " + tolerance.ToString(System.Globalization.CultureInfo.InvariantCulture), nameof(families));
                        }
                    }
                }
            }
            return new WeldedNet(xyz.ToArray(), polylines, welded);
        }

        private static long EdgeKey(int[] quads, int q, int s, int vertexCount)
        {
            int a = quads[4 * q + s], b = quads[4 * q + (s + 1) % 4];
            return (long)Math.Min(a, b) * vertexCount + Math.Max(a, b);
        }

        private static void Link(List<int>[] neighbours, int a, int b, int k)
        {
            if (neighbours[a] == null) neighbours[a] = new List<int>(2);
            if (neighbours[a].Count == 2) throw new ArgumentException("vertex " + a + " has more than two neighbours along the " + (k == 0 ? "rows" : "columns") + ": an irregular vertex", "quads");
            neighbours[a].Add(b);
        }

        /// <summary>The polylines of one family, each walked from its end of lower index.</summary>
        private static int[][] Chains(List<int>[] neighbours, string name)
        {
            var lines = new List<int[]>();
            var done = new bool[neighbours.Length];
            for (int v = 0; v < neighbours.Length; v++)
            {
                if (done[v] || neighbours[v] == null || neighbours[v].Count != 1) continue;
                var line = new List<int> { v };
                done[v] = true;
                for (int previous = -1, at = v; ;)
                {
                    int next = neighbours[at][0] != previous ? neighbours[at][0] : neighbours[at].Count > 1 ? neighbours[at][1] : -1;
                    if (next < 0) break;
                    line.Add(next);
                    done[next] = true;
                    previous = at;
                    at = next;
                }
                lines.Add(line.ToArray());
            }
            for (int v = 0; v < neighbours.Length; v++)
            {
                if (!done[v] && neighbours[v] != null) throw new ArgumentException("the " + name + " through vertex " + v + " closes: a net has open polylines", "quads");
            }
            return lines.ToArray();
        }
    }
}
