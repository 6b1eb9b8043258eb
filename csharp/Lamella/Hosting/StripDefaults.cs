using System;

namespace Lamella.Hosting
{
    /// <summary>
    /// Defaults for strip dimensions relative to the model, so that a pattern in millimetres and one in metres both
    /// start with usable strips: the width the round number (1, 2 or 5 × 10^k) nearest to 2 % of the curves' extent, the
    /// gap of the flat layout half of it.
    /// </summary>
    public static class StripDefaults
    {
        /// <summary>The default width as a fraction of the bounding-box diagonal of the curves.</summary>
        public const double WidthFraction = 0.02;

        /// <summary>
        /// The default strip width for curves through <paramref name="xyz"/> (x, y, z per point, in document units): the
        /// 1, 2 or 5 × 10^k nearest to <see cref="WidthFraction"/> of their bounding-box diagonal. Throws when there are
        /// no finite points or they coincide.
        /// </summary>
        public static double Width(double[] xyz)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            var min = new[] { double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity };
            var max = new[] { double.NegativeInfinity, double.NegativeInfinity, double.NegativeInfinity };
            for (int i = 0; i + 2 < xyz.Length; i += 3)
            {
                for (int c = 0; c < 3; c++)
                {
                    double v = xyz[i + c];
                    if (double.IsNaN(v) || double.IsInfinity(v)) continue;
                    min[c] = Math.Min(min[c], v);
                    max[c] = Math.Max(max[c], v);
                }
            }
            double squared = 0;
            for (int c = 0; c < 3; c++) squared += (max[c] - min[c]) * (max[c] - min[c]);
            double diagonal = Math.Sqrt(squared);
            if (!(diagonal > 0) || double.IsInfinity(diagonal)) throw new ArgumentException("the curves have no extent to derive a strip width from; set the width");
            return Round(WidthFraction * diagonal);
        }

        /// <summary>The default gap between flat strips for strips of <paramref name="width"/>: half of it.</summary>
        public static double Gap(double width) => 0.5 * width;

        /// <summary>The 1, 2 or 5 × 10^k nearest to <paramref name="x"/> (> 0) by ratio.</summary>
        public static double Round(double x)
        {
            if (!(x > 0) || double.IsInfinity(x)) throw new ArgumentOutOfRangeException(nameof(x));
            double decade = Math.Pow(10, Math.Floor(Math.Log10(x)));
            double best = decade, bestRatio = double.PositiveInfinity;
            foreach (double step in new[] { 1.0, 2.0, 5.0, 10.0 })
            {
                double candidate = step * decade, ratio = Math.Max(candidate / x, x / candidate);
                if (ratio < bestRatio)
                {
                    best = candidate;
                    bestRatio = ratio;
                }
            }
            return best;
        }
    }
}
