using System;
using System.Collections.Generic;

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
        public static double[] LayOutFlat(double[] unrolled, int[] vertexOffsets, double gap) =>
            Shift(unrolled, vertexOffsets, FlatLayoutShifts(unrolled, vertexOffsets, gap));

        /// <summary>
        /// The translation (dx, dy per strip) of <see cref="LayOutFlat"/>, to move other flat data of the strips (their
        /// unrolled centre lines) along with them; (0, 0) for a strip without vertices.
        /// </summary>
        public static double[] FlatLayoutShifts(double[] unrolled, int[] vertexOffsets, double gap)
        {
            if (unrolled == null) throw new ArgumentNullException(nameof(unrolled));
            if (!(gap >= 0) || double.IsInfinity(gap)) throw new ArgumentOutOfRangeException(nameof(gap), "the gap must be finite and ≥ 0");
            Packing.CheckOffsets(vertexOffsets, unrolled.Length / 2);
            var shifts = new double[2 * (vertexOffsets.Length - 1)];
            double top = 0;
            bool placed = false;
            for (int s = 0; s + 1 < vertexOffsets.Length; s++)
            {
                if (vertexOffsets[s + 1] == vertexOffsets[s])
                {
                    continue;
                }
                double minX = double.PositiveInfinity, minY = double.PositiveInfinity, maxY = double.NegativeInfinity;
                for (int v = vertexOffsets[s]; v < vertexOffsets[s + 1]; v++)
                {
                    minX = Math.Min(minX, unrolled[2 * v]);
                    minY = Math.Min(minY, unrolled[2 * v + 1]);
                    maxY = Math.Max(maxY, unrolled[2 * v + 1]);
                }
                shifts[2 * s] = -minX;
                shifts[2 * s + 1] = (placed ? top + gap : 0) - minY;
                top = maxY + shifts[2 * s + 1];
                placed = true;
            }
            return shifts;
        }

        /// <summary>Moves each item of plane points (x, y each) by its shift (dx, dy per item); returns x, y, z per point (z = 0).</summary>
        public static double[] Shift(double[] planePoints, int[] offsets, double[] shifts)
        {
            if (planePoints == null) throw new ArgumentNullException(nameof(planePoints));
            if (shifts == null) throw new ArgumentNullException(nameof(shifts));
            Packing.CheckOffsets(offsets, planePoints.Length / 2);
            if (shifts.Length != 2 * (offsets.Length - 1)) throw new ArgumentException(shifts.Length / 2 + " shifts for " + (offsets.Length - 1) + " items", nameof(shifts));
            var xyz = new double[planePoints.Length / 2 * 3];
            for (int s = 0; s + 1 < offsets.Length; s++)
            {
                for (int v = offsets[s]; v < offsets[s + 1]; v++)
                {
                    xyz[3 * v] = planePoints[2 * v] + shifts[2 * s];
                    xyz[3 * v + 1] = planePoints[2 * v + 1] + shifts[2 * s + 1];
                }
            }
            return xyz;
        }

        /// <summary>
        /// Points given in XY coordinates (x, y, z each) placed on a plane: origin + x·X + y·Y + z·(X × Y), for the
        /// plane's unit, orthogonal axes X and Y (as a Rhino Plane has).
        /// </summary>
        public static double[] OnPlane(double[] xyz, double[] origin, double[] xAxis, double[] yAxis)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            foreach (double[] v in new[] { origin, xAxis, yAxis })
            {
                if (v == null || v.Length != 3) throw new ArgumentException("the plane's origin and axes take three values each");
                foreach (double c in v)
                {
                    if (double.IsNaN(c) || double.IsInfinity(c)) throw new ArgumentException("the plane is not finite");
                }
            }
            double[] zAxis =
            {
                xAxis[1] * yAxis[2] - xAxis[2] * yAxis[1], xAxis[2] * yAxis[0] - xAxis[0] * yAxis[2], xAxis[0] * yAxis[1] - xAxis[1] * yAxis[0],
            };
            var result = new double[xyz.Length];
            for (int p = 0; p < xyz.Length / 3; p++)
            {
                for (int c = 0; c < 3; c++)
                {
                    result[3 * p + c] = origin[c] + xyz[3 * p] * xAxis[c] + xyz[3 * p + 1] * yAxis[c] + xyz[3 * p + 2] * zAxis[c];
                }
            }
            return result;
        }

        /// <summary>
        /// Each strip's boundary as a closed polyline, <paramref name="dimension"/> values per point: left_0 … left_n−1,
        /// right_n−1 … right_0 and left_0 again. Flat, the cutting line of the strip; in space, the outline that nodes and
        /// connections are detailed on. A strip of 2n vertices gives 2n + 1 points.
        /// </summary>
        public static Packed Outlines(double[] vertices, int dimension, int[] vertexOffsets)
        {
            if (vertices == null) throw new ArgumentNullException(nameof(vertices));
            if (dimension < 1) throw new ArgumentOutOfRangeException(nameof(dimension));
            Packing.CheckOffsets(vertexOffsets, vertices.Length / dimension);
            var outlines = new List<double[]>(vertexOffsets.Length - 1);
            for (int s = 0; s + 1 < vertexOffsets.Length; s++)
            {
                int first = vertexOffsets[s], count = vertexOffsets[s + 1] - first, n = count / 2;
                if (count % 2 != 0) throw new ArgumentException("strip " + s + " has " + count + " vertices, not two per centre point", nameof(vertexOffsets));
                var outline = new double[count == 0 ? 0 : (count + 1) * dimension];
                for (int k = 0; k < count; k++)
                {
                    int v = k < n ? first + k : first + n + (count - 1 - k); // left forward, then right backward
                    Array.Copy(vertices, v * dimension, outline, k * dimension, dimension);
                }
                if (count > 0) Array.Copy(vertices, first * dimension, outline, count * dimension, dimension);
                outlines.Add(outline);
            }
            return Packing.Pack(outlines, dimension);
        }

        /// <summary>The middle point (index ⌊n / 2⌋ of n) of each item, x, y, z each: where a strip's label goes; an empty item gives NaN.</summary>
        public static double[] MiddlePoints(double[] points, int[] offsets)
        {
            if (points == null) throw new ArgumentNullException(nameof(points));
            Packing.CheckOffsets(offsets, points.Length / 3);
            var middles = new double[3 * (offsets.Length - 1)];
            for (int s = 0; s + 1 < offsets.Length; s++)
            {
                int n = offsets[s + 1] - offsets[s];
                for (int c = 0; c < 3; c++) middles[3 * s + c] = n == 0 ? double.NaN : points[3 * (offsets[s] + n / 2) + c];
            }
            return middles;
        }
    }
}
