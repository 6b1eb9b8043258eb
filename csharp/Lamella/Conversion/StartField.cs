using System;

namespace Lamella.Conversion
{
    /// <summary>Start fields for a field solve: values whose level curves roughly follow the wanted strips.</summary>
    public static class StartField
    {
        /// <summary>The height of each vertex (x, y, z each) along the direction (dx, dy, dz), which is normalised.</summary>
        public static double[] Height(double[] xyz, double dx, double dy, double dz)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            double length = Math.Sqrt(dx * dx + dy * dy + dz * dz);
            if (!(length > 0) || double.IsInfinity(length)) throw new ArgumentException("the direction must be a finite, non-zero vector");
            var values = new double[xyz.Length / 3];
            for (int i = 0; i < values.Length; i++)
            {
                values[i] = (xyz[3 * i] * dx + xyz[3 * i + 1] * dy + xyz[3 * i + 2] * dz) / length;
            }
            return values;
        }
    }
}
