using System;

namespace Lamella.Conversion
{
    /// <summary>Colours for previewing a field on its mesh: a blue → pale → red ramp over the field's range.</summary>
    public static class FieldColours
    {
        /// <summary>The colour of a vertex without a value (NaN), opaque ARGB.</summary>
        public const int Missing = unchecked((int)0xFFA0A0A0);

        // Ramp stops (R, G, B), evenly spaced from the minimum to the maximum of the field.
        private static readonly int[,] Stops =
        {
            { 49, 54, 149 }, { 69, 117, 180 }, { 224, 243, 248 }, { 244, 109, 67 }, { 165, 0, 38 },
        };

        /// <summary>
        /// One opaque ARGB colour per value: the minimum gets the first stop, the maximum the last, values between are
        /// interpolated linearly; NaN gets <see cref="Missing"/>, and a constant field the middle stop.
        /// </summary>
        public static int[] Argb(double[] values)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            double min = double.PositiveInfinity, max = double.NegativeInfinity;
            foreach (double v in values)
            {
                if (double.IsNaN(v) || double.IsInfinity(v)) continue;
                min = Math.Min(min, v);
                max = Math.Max(max, v);
            }
            return Argb(values, min, max);
        }

        /// <summary>
        /// One opaque ARGB colour per value over the fixed range [<paramref name="min"/>, <paramref name="max"/>] (values
        /// outside are clamped); NaN gets <see cref="Missing"/>, and an empty range the middle stop.
        /// </summary>
        public static int[] Argb(double[] values, double min, double max)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            var colours = new int[values.Length];
            int last = Stops.GetLength(0) - 1;
            for (int i = 0; i < values.Length; i++)
            {
                double v = values[i];
                if (double.IsNaN(v) || double.IsInfinity(v))
                {
                    colours[i] = Missing;
                    continue;
                }
                double t = max > min ? Math.Max(0.0, Math.Min(1.0, (v - min) / (max - min))) * last : 0.5 * last;
                int k = Math.Min((int)Math.Floor(t), last - 1);
                double f = t - k;
                int r = (int)Math.Round(Stops[k, 0] + f * (Stops[k + 1, 0] - Stops[k, 0]));
                int g = (int)Math.Round(Stops[k, 1] + f * (Stops[k + 1, 1] - Stops[k, 1]));
                int b = (int)Math.Round(Stops[k, 2] + f * (Stops[k + 1, 2] - Stops[k, 2]));
                colours[i] = unchecked((int)0xFF000000) | r << 16 | g << 8 | b;
            }
            return colours;
        }
    }
}
