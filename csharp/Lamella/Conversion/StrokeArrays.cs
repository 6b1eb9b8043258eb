using System;
using System.Collections.Generic;

namespace Lamella.Conversion
{
    /// <summary>
    /// Strokes sketched on a surface, as polylines of x, y, z points, made ready for
    /// <see cref="InitialField.FromStrokes(LamellaMesh, IList{double[]}, out double)"/>: the library keeps at most one
    /// point per triangle, so a stroke should have points at least every half edge length or it skips triangles.
    /// </summary>
    public static class StrokeArrays
    {
        /// <summary>The mean length of the mesh's edges (each edge counted once), from vertices (x, y, z each) and triangles.</summary>
        public static double MeanEdgeLength(double[] xyz, int[] triangles)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            if (triangles == null) throw new ArgumentNullException(nameof(triangles));
            if (triangles.Length % 3 != 0) throw new ArgumentException("triangles holds " + triangles.Length + " indices, not a multiple of 3", nameof(triangles));
            int vertexCount = xyz.Length / 3;
            var seen = new HashSet<long>();
            double sum = 0;
            for (int t = 0; t < triangles.Length / 3; t++)
            {
                for (int k = 0; k < 3; k++)
                {
                    int a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
                    if (a < 0 || a >= vertexCount || b < 0 || b >= vertexCount)
                    {
                        throw new ArgumentOutOfRangeException(nameof(triangles), "triangle " + t + " refers to a vertex outside 0.." + (vertexCount - 1));
                    }
                    if (seen.Add((long)Math.Min(a, b) * vertexCount + Math.Max(a, b)))
                    {
                        sum += Distance(xyz, a, xyz, b);
                    }
                }
            }
            return seen.Count == 0 ? 0 : sum / seen.Count;
        }

        /// <summary>
        /// The polyline <paramref name="xyz"/> (x, y, z per point) with points inserted so that no segment is longer than
        /// <paramref name="maxSegment"/> (> 0): a segment of length l is split into ⌈l / maxSegment⌉ equal parts. The given
        /// points are kept, in order; nothing else changes.
        /// </summary>
        public static double[] Densify(double[] xyz, double maxSegment)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            if (xyz.Length % 3 != 0) throw new ArgumentException("xyz holds " + xyz.Length + " values, not a multiple of 3", nameof(xyz));
            if (!(maxSegment > 0) || double.IsInfinity(maxSegment)) throw new ArgumentOutOfRangeException(nameof(maxSegment), "the segment length must be finite and > 0");
            int n = xyz.Length / 3;
            var result = new List<double>(xyz.Length);
            for (int i = 0; i < n; i++)
            {
                if (i > 0)
                {
                    double length = Distance(xyz, i - 1, xyz, i);
                    if (double.IsNaN(length) || double.IsInfinity(length)) throw new ArgumentException("point " + i + " or " + (i - 1) + " is not finite", nameof(xyz));
                    if (length / maxSegment > 1e6) throw new ArgumentException("segment " + (i - 1) + " is over a million times longer than " + maxSegment, nameof(maxSegment));
                    int parts = Math.Max(1, (int)Math.Ceiling(length / maxSegment));
                    for (int k = 1; k < parts; k++)
                    {
                        double s = (double)k / parts;
                        for (int c = 0; c < 3; c++) result.Add((1 - s) * xyz[3 * (i - 1) + c] + s * xyz[3 * i + c]);
                    }
                }
                for (int c = 0; c < 3; c++) result.Add(xyz[3 * i + c]);
            }
            return result.ToArray();
        }

        private static double Distance(double[] p, int i, double[] q, int j)
        {
            double dx = p[3 * i] - q[3 * j], dy = p[3 * i + 1] - q[3 * j + 1], dz = p[3 * i + 2] - q[3 * j + 2];
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }
    }
}
