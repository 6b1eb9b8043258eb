using System;

namespace Lamella.Tests
{
    /// <summary>
    /// A test surface: a patch of the cylinder of radius 10 over a 150° span and height 15, triangulated from a
    /// jittered grid with alternating diagonals (irregular, no directional bias), normals pointing away from the axis.
    /// The initial field is a perturbed height function, so the solver has real work to do.
    /// </summary>
    internal sealed class Cylinder
    {
        public const double Radius = 10.0;
        public const double SpanDegrees = 150.0;
        public const double Height = 15.0;

        public readonly double[] Xyz;
        public readonly int[] Triangles;
        public readonly double[] InitialField;
        public int VertexCount => Xyz.Length / 3;

        /// <summary>
        /// Start fields of the geodesic net of circles and rulings, tilted a little off both: the height plus 0.18 of
        /// the arc length, and the arc length less 0.18 of the height.
        /// </summary>
        public double[][] TiltedCirclesAndRulings()
        {
            var first = new double[VertexCount];
            var second = new double[VertexCount];
            for (int v = 0; v < VertexCount; v++)
            {
                double arc = Radius * Math.Atan2(Xyz[3 * v + 1], Xyz[3 * v]);
                first[v] = Xyz[3 * v + 2] + 0.18 * arc;
                second[v] = arc - 0.18 * Xyz[3 * v + 2];
            }
            return new[] { first, second };
        }

        public Cylinder(int columns, int rows, int seed)
        {
            double arc = Radius * SpanDegrees * Math.PI / 180.0, ds = arc / columns, dz = Height / rows;
            var random = new Random(seed);
            Xyz = new double[3 * (columns + 1) * (rows + 1)];
            InitialField = new double[(columns + 1) * (rows + 1)];
            for (int j = 0; j <= rows; j++)
            {
                for (int i = 0; i <= columns; i++)
                {
                    int v = j * (columns + 1) + i;
                    // Interior grid points move by up to a quarter cell; the boundary stays straight.
                    double s = ds * (i + (i > 0 && i < columns ? 0.5 * (random.NextDouble() - 0.5) : 0));
                    double z = dz * (j + (j > 0 && j < rows ? 0.5 * (random.NextDouble() - 0.5) : 0));
                    Xyz[3 * v] = Radius * Math.Cos(s / Radius);
                    Xyz[3 * v + 1] = Radius * Math.Sin(s / Radius);
                    Xyz[3 * v + 2] = z;
                    InitialField[v] = z + 0.8 * Math.Sin(s / 9.0) + 0.3 * Math.Cos(z / 5.0);
                }
            }
            Triangles = new int[6 * columns * rows];
            int t = 0;
            for (int j = 0; j < rows; j++)
            {
                for (int i = 0; i < columns; i++)
                {
                    int a = j * (columns + 1) + i, b = a + 1, d = a + columns + 1, e = d + 1;
                    int[] cell = (i + j) % 2 == 0 ? new[] { a, b, e, a, e, d } : new[] { a, b, d, b, e, d };
                    Array.Copy(cell, 0, Triangles, t, 6);
                    t += 6;
                }
            }
        }

        /// <summary>The analytic unit normal at a point on the cylinder (radial).</summary>
        public static double[] Normal(double[] p, int index)
        {
            double r = Math.Sqrt(p[3 * index] * p[3 * index] + p[3 * index + 1] * p[3 * index + 1]);
            return new[] { p[3 * index] / r, p[3 * index + 1] / r, 0.0 };
        }

        /// <summary>
        /// The signed angle (degrees) between the discrete binormal (paper Eq. 1) of the polyline corner
        /// prev → p → next and the analytic normal at p: acos(sign(b·u)·(b·n)) with u = n × t (paper Sec. 3.1).
        /// </summary>
        public static double BinormalAngle(double[] prev, double[] p, double[] next)
        {
            double[] e0 = Vec.Sub(p, prev), e1 = Vec.Sub(next, p), b = Vec.Cross(e0, e1);
            double[] t = { e0[0] / Vec.Norm(e0) + e1[0] / Vec.Norm(e1), e0[1] / Vec.Norm(e0) + e1[1] / Vec.Norm(e1), e0[2] / Vec.Norm(e0) + e1[2] / Vec.Norm(e1) };
            double r = Math.Sqrt(p[0] * p[0] + p[1] * p[1]);
            double[] n = { p[0] / r, p[1] / r, 0 };
            double bn = Vec.Dot(b, n) / Vec.Norm(b);
            return Vec.Degrees(Vec.Dot(b, Vec.Cross(n, t)) < 0 ? -bn : bn);
        }

        /// <summary>How far a field's frames are from the analytic ones (see <see cref="FrameErrors"/>).</summary>
        public struct Frames
        {
            /// <summary>Vertices with a frame (non-zero binormal).</summary>
            public int Framed;
            /// <summary>Max |signed angle(b, n) − θ| in degrees, the sign of b from the side vector (paper Fig. 8).</summary>
            public double WorstAngle;
            /// <summary>Max | |b| − 1 |.</summary>
            public double WorstUnit;
            /// <summary>Max |u · n|: the side vector should be tangent.</summary>
            public double WorstTangent;
        }

        /// <summary>The frames of <paramref name="field"/> (on a mesh with vertices <paramref name="xyz"/> on this cylinder) against the analytic normal at θ.</summary>
        public static Frames FrameErrors(FieldSolver field, double[] xyz, double thetaDegrees)
        {
            double[] b = field.Binormals(), u = field.SideVectors();
            var frames = new Frames();
            for (int v = 0; v < xyz.Length / 3; v++)
            {
                double[] bv = Vec.At(b, v), uv = Vec.At(u, v), n = Normal(xyz, v);
                if (Vec.Norm(bv) == 0) continue; // boundary vertex
                frames.Framed++;
                frames.WorstUnit = Math.Max(frames.WorstUnit, Math.Abs(Vec.Norm(bv) - 1));
                // b is fixed up to sign: the side vector picks the family (paper Fig. 8).
                double bn = Vec.Dot(bv, n) * (Vec.Dot(bv, uv) < 0 ? -1 : 1);
                frames.WorstAngle = Math.Max(frames.WorstAngle, Math.Abs(Vec.Degrees(bn) - thetaDegrees));
                frames.WorstTangent = Math.Max(frames.WorstTangent, Math.Abs(Vec.Dot(uv, n)));
            }
            return frames;
        }

        /// <summary>The isometric development of a point: (arc length around the axis from the left side, height).</summary>
        public static double[] Development(double[] p) => new[] { Radius * Math.Atan2(p[1], p[0]), p[2] };

        /// <summary>
        /// The developed P-curve of angle θ with its apex (lowest or highest point) at (x0, z0), opening upwards (up)
        /// or downwards: z = z0 ± (cosh(k(x − x0)) − 1)/k with k = tan(90° − θ)/R (Wunderlich's catenaries; the
        /// derivation is in tests/integration/tracing_cylinder.rs).
        /// </summary>
        public static double Catenary(double thetaDegrees, double x0, double z0, bool up, double x)
        {
            double k = Math.Tan((90.0 - thetaDegrees) * Math.PI / 180.0) / Radius;
            return z0 + (up ? 1 : -1) * (Math.Cosh(k * (x - x0)) - 1) / k;
        }
    }
}
