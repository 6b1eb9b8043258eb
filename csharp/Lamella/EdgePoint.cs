using System.Runtime.InteropServices;

namespace Lamella
{
    /// <summary>
    /// A point on a mesh edge (<c>LmlEdgePoint</c>): (1 − T)·p_A + T·p_B on the edge between vertices A and B.
    /// Traced curves and boundary start points are made of them.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct EdgePoint
    {
        /// <summary>The first vertex of the edge.</summary>
        public uint A;
        /// <summary>The second vertex of the edge.</summary>
        public uint B;
        /// <summary>The parameter along the edge, in [0, 1]: 0 at <see cref="A"/>, 1 at <see cref="B"/>.</summary>
        public double T;

        /// <summary>Creates the point (1 − t)·p_a + t·p_b.</summary>
        public EdgePoint(uint a, uint b, double t)
        {
            A = a;
            B = b;
            T = t;
        }

        /// <summary>The point's position (x, y, z) on a mesh with vertex positions <paramref name="xyz"/> (x, y, z per vertex).</summary>
        public double[] Position(double[] xyz)
        {
            if (xyz == null) throw new System.ArgumentNullException(nameof(xyz));
            if (3L * System.Math.Max(A, B) + 2 >= xyz.Length)
            {
                throw new System.ArgumentOutOfRangeException(nameof(xyz), "edge " + A + "–" + B + " refers to a vertex beyond the " + xyz.Length / 3 + " given");
            }
            var p = new double[3];
            for (int k = 0; k < 3; k++)
            {
                p[k] = (1 - T) * xyz[3 * A + k] + T * xyz[3 * B + k];
            }
            return p;
        }

        /// <inheritdoc />
        public override string ToString() =>
            string.Format(System.Globalization.CultureInfo.InvariantCulture, "edge {0}–{1} at t = {2:0.####}", A, B, T);
    }
}
