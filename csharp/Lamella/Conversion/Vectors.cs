using System;

namespace Lamella.Conversion
{
    /// <summary>Checks of the 3-vectors the binding passes to the library as double[3].</summary>
    internal static class Vectors
    {
        /// <summary>A copy of <paramref name="axis"/> after checking it holds x, y, z (the library checks the values).</summary>
        internal static double[] Axis(double[] axis, string name)
        {
            if (axis == null) throw new ArgumentNullException(name);
            if (axis.Length != 3) throw new ArgumentException("an axis holds 3 values (x, y, z), not " + axis.Length, name);
            return (double[])axis.Clone();
        }
    }
}
