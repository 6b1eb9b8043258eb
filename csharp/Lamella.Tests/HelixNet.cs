using System;
using System.Collections.Generic;
using System.Linq;

namespace Lamella.Tests
{
    /// <summary>The ±45° helices on the cylinder: vertex (i, j) at s = 1.5 + (i + j) h/2 around the axis, z = 7.5 + (j − i) h/2.</summary>
    internal sealed class HelixNet
    {
        private const int Lines = 40;
        private const double Step = 1.2;

        public readonly double[] Points;
        /// <summary>Rows (constant i, increasing j) and columns (constant j, increasing i).</summary>
        public readonly int[][] Rows, Columns;
        /// <summary>(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j) wherever all four exist.</summary>
        public readonly int[] Quads;

        /// <summary>The net with each coordinate moved by up to <paramref name="noise"/>.</summary>
        public HelixNet(double noise)
        {
            var index = new int[Lines, Lines];
            var points = new List<double>();
            var random = new Random(5);
            for (int i = 0; i < Lines; i++)
            {
                for (int j = 0; j < Lines; j++)
                {
                    double s = 1.5 + (i + j) * Step / 2, z = 7.5 + (j - i) * Step / 2;
                    index[i, j] = -1;
                    if (s > 24.5 || z < 0.8 || z > Cylinder.Height - 0.8) continue;
                    index[i, j] = points.Count / 3;
                    points.Add(Cylinder.Radius * Math.Cos(s / Cylinder.Radius) + noise * (2 * random.NextDouble() - 1));
                    points.Add(Cylinder.Radius * Math.Sin(s / Cylinder.Radius) + noise * (2 * random.NextDouble() - 1));
                    points.Add(z + noise * (2 * random.NextDouble() - 1));
                }
            }
            Points = points.ToArray();
            Rows = Runs((a, b) => index[a, b]);
            Columns = Runs((a, b) => index[b, a]);
            var quads = new List<int>();
            for (int i = 0; i + 1 < Lines; i++)
            {
                for (int j = 0; j + 1 < Lines; j++)
                {
                    int[] quad = { index[i, j], index[i, j + 1], index[i + 1, j + 1], index[i + 1, j] };
                    if (quad.All(v => v >= 0)) quads.AddRange(quad);
                }
            }
            Quads = quads.ToArray();
        }

        /// <summary>The vertices of each grid line in order (consecutive: the patch is convex), lines of two or more.</summary>
        private static int[][] Runs(Func<int, int, int> vertex)
        {
            var lines = new List<int[]>();
            for (int a = 0; a < Lines; a++)
            {
                int[] line = Enumerable.Range(0, Lines).Select(b => vertex(a, b)).Where(v => v >= 0).ToArray();
                if (line.Length >= 2) lines.Add(line);
            }
            return lines.ToArray();
        }
    }
}
