using System;

namespace Lamella.Conversion
{
    /// <summary>One strip as its own mesh: vertices (2 or 3 values each) and quads indexing them from 0.</summary>
    public sealed class StripMesh
    {
        /// <summary>The strip's vertices: left boundary, then right boundary.</summary>
        public double[] Vertices { get; }
        /// <summary>Four local vertex indices per quad.</summary>
        public int[] Quads { get; }

        /// <summary>Wraps the arrays.</summary>
        public StripMesh(double[] vertices, int[] quads)
        {
            Vertices = vertices;
            Quads = quads;
        }
    }

    /// <summary>The strip arrays of the C ABI cut into per-strip meshes, rulings and a flat layout.</summary>
    public static class StripArrays
    {
        /// <summary>
        /// Splits the whole vertex array (<paramref name="dimension"/> values per vertex) and the global quads into one
        /// mesh per strip, with quad indices relative to the strip's first vertex.
        /// </summary>
        public static StripMesh[] Split(double[] vertices, int dimension, int[] quads, int[] vertexOffsets, int[] quadOffsets)
        {
            if (vertices == null || quads == null || vertexOffsets == null || quadOffsets == null) throw new ArgumentNullException(nameof(vertices));
            Packing.CheckOffsets(vertexOffsets, vertices.Length / dimension);
            Packing.CheckOffsets(quadOffsets, quads.Length / 4);
            if (vertexOffsets.Length != quadOffsets.Length) throw new ArgumentException("the vertex and quad offset tables count different strips");
            var strips = new StripMesh[vertexOffsets.Length - 1];
            var unpacked = Packing.Unpack(new Packed(vertices, vertexOffsets, dimension));
            for (int s = 0; s < strips.Length; s++)
            {
                int first = vertexOffsets[s], count = vertexOffsets[s + 1] - first;
                var local = new int[4 * (quadOffsets[s + 1] - quadOffsets[s])];
                for (int k = 0; k < local.Length; k++)
                {
                    int index = quads[4 * quadOffsets[s] + k] - first;
                    if (index < 0 || index >= count) throw new ArgumentException("quad " + (quadOffsets[s] + k / 4) + " of strip " + s + " leaves the strip's vertices");
                    local[k] = index;
                }
                strips[s] = new StripMesh(unpacked[s], local);
            }
            return strips;
        }

        /// <summary>
        /// The rulings as segments across the strips, from the left to the right boundary vertex: six values
        /// (x0 y0 z0 x1 y1 z1) per centre point. Strip i with n points has vertices left_0..left_n−1, right_0..right_n−1.
        /// </summary>
        public static double[] RulingSegments(double[] vertices, int[] vertexOffsets)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            Packing.CheckOffsets(vertexOffsets, vertices.Length / 3);
            var segments = new double[vertices.Length];
            int written = 0;
            for (int s = 0; s + 1 < vertexOffsets.Length; s++)
            {
                int first = vertexOffsets[s], n = (vertexOffsets[s + 1] - first) / 2;
                for (int j = 0; j < n; j++)
                {
                    Array.Copy(vertices, 3 * (first + j), segments, written, 3);
                    Array.Copy(vertices, 3 * (first + n + j), segments, written + 3, 3);
                    written += 6;
                }
            }
            return segments;
        }

        /// <summary>
        /// Lays the unrolled strips (x, y per vertex, each from the origin along +x) out on the XY plane without
        /// overlap: each strip is moved so its bounding box starts at x = 0 and at <paramref name="gap"/> above the
        /// previous strip's box. Returns x, y, z per vertex (z = 0).
        /// </summary>
        public static double[] LayOutFlat(double[] unrolled, int[] vertexOffsets, double gap)
        {
            if (unrolled == null) throw new ArgumentNullException(nameof(unrolled));
            if (!(gap >= 0) || double.IsInfinity(gap)) throw new ArgumentOutOfRangeException(nameof(gap), "the gap must be finite and ≥ 0");
            Packing.CheckOffsets(vertexOffsets, unrolled.Length / 2);
            var xyz = new double[unrolled.Length / 2 * 3];
            double top = 0;
            bool placed = false;
            for (int s = 0; s + 1 < vertexOffsets.Length; s++)
            {
                double minX = double.PositiveInfinity, minY = double.PositiveInfinity, maxY = double.NegativeInfinity;
                for (int v = vertexOffsets[s]; v < vertexOffsets[s + 1]; v++)
                {
                    minX = Math.Min(minX, unrolled[2 * v]);
                    minY = Math.Min(minY, unrolled[2 * v + 1]);
                    maxY = Math.Max(maxY, unrolled[2 * v + 1]);
                }
                if (vertexOffsets[s + 1] == vertexOffsets[s])
                {
                    continue;
                }
                double shiftY = (placed ? top + gap : 0) - minY;
                for (int v = vertexOffsets[s]; v < vertexOffsets[s + 1]; v++)
                {
                    xyz[3 * v] = unrolled[2 * v] - minX;
                    xyz[3 * v + 1] = unrolled[2 * v + 1] + shiftY;
                }
                top = maxY + shiftY;
                placed = true;
            }
            return xyz;
        }
    }
}
