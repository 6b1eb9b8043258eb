using System;

namespace Lamella.Tests
{
    /// <summary>Small vector helpers over flat x, y, z arrays.</summary>
    internal static class Vec
    {
        public static double[] At(double[] xyz, int i) => new[] { xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2] };
        public static double[] Sub(double[] a, double[] b) => new[] { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
        public static double Dot(double[] a, double[] b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        public static double[] Cross(double[] a, double[] b) =>
            new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
        public static double Norm(double[] a) => Math.Sqrt(Dot(a, a));
        public static double Distance(double[] a, double[] b) => Norm(Sub(a, b));
        public static double Distance2(double[] xy, int i, int j) =>
            Math.Sqrt((xy[2 * i] - xy[2 * j]) * (xy[2 * i] - xy[2 * j]) + (xy[2 * i + 1] - xy[2 * j + 1]) * (xy[2 * i + 1] - xy[2 * j + 1]));
        public static double Degrees(double cosine) => Math.Acos(Math.Max(-1.0, Math.Min(1.0, cosine))) * 180.0 / Math.PI;
    }
}
