using System;
using System.Linq;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// The alternating schedule through the binding (paper Sec. 3.3, <see cref="AlternatingSolver"/>): field steps and
    /// surface steps in turn on the cylinder towards a 45° family, the deviations within the tolerance, the level curves
    /// of the new field on the moved surface measured from outside; invalid arguments refused by name; the same input
    /// giving the same bits.
    /// </summary>
    [TestFixture]
    public class AlternationTests
    {
        private const double Theta = 45.0;
        private const double ToleranceFraction = 0.01;
        private const int IterationsPerStep = 30;

        /// <summary>
        /// The signed angle (degrees) between the discrete binormal (paper Eq. 1) of the polyline corner prev → p → next
        /// and the unit surface normal <paramref name="n"/> at p, with <see cref="Cylinder.BinormalAngle"/>'s sign
        /// convention (the sign of b · (n × t)), but against a given normal instead of the cylinder's.
        /// </summary>
        private static double BinormalAngle(double[] prev, double[] p, double[] next, double[] n)
        {
            double[] e0 = Vec.Sub(p, prev), e1 = Vec.Sub(next, p), b = Vec.Cross(e0, e1);
            double[] t = { e0[0] / Vec.Norm(e0) + e1[0] / Vec.Norm(e1), e0[1] / Vec.Norm(e0) + e1[1] / Vec.Norm(e1), e0[2] / Vec.Norm(e0) + e1[2] / Vec.Norm(e1) };
            double bn = Vec.Dot(b, n) / Vec.Norm(b);
            return Vec.Degrees(Vec.Dot(b, Vec.Cross(n, t)) < 0 ? -bn : bn);
        }

        /// <summary>
        /// The mean |angle − θ| over the inner points of the level curves (10 uniform levels, resampled every
        /// <paramref name="spacing"/>) of <paramref name="field"/> on the mesh <paramref name="xyz"/>, against the mesh's own
        /// surface normals at the curve points; nearly straight corners, which have no binormal, are left out.
        /// </summary>
        private static double MeanLevelCurveAngleError(double[] xyz, int[] triangles, double[] field, double spacing, out int measured)
        {
            using (var mesh = LamellaMesh.FromArrays(xyz, triangles))
            using (var solver = new FieldSolver(mesh, field, FieldParams.Default(Family.PseudoGeodesic, Theta)))
            using (var curves = LevelCurves.Uniform(solver, 10, spacing))
            {
                int[] offsets = curves.Offsets();
                double[] points = curves.Points(), normals = curves.Normals();
                double sum = 0;
                measured = 0;
                for (int c = 0; c < curves.Count; c++)
                {
                    for (int p = offsets[c] + 1; p + 1 < offsets[c + 1]; p++)
                    {
                        double[] a = Vec.At(points, p - 1), x = Vec.At(points, p), b = Vec.At(points, p + 1);
                        double[] e0 = Vec.Sub(x, a), e1 = Vec.Sub(b, x);
                        if (Vec.Norm(Vec.Cross(e0, e1)) < 1e-5 * Vec.Norm(e0) * Vec.Norm(e1)) continue;
                        sum += Math.Abs(BinormalAngle(a, x, b, Vec.At(normals, p)) - Theta);
                        measured++;
                    }
                }
                return sum / measured;
            }
        }

        /// <summary>The mean edge length of a triangle mesh (each edge counted once per triangle side).</summary>
        private static double MeanEdgeLength(double[] xyz, int[] triangles)
        {
            double sum = 0;
            for (int t = 0; t < triangles.Length; t += 3)
            {
                for (int k = 0; k < 3; k++) sum += Vec.Distance(Vec.At(xyz, triangles[t + k]), Vec.At(xyz, triangles[t + (k + 1) % 3]));
            }
            return sum / triangles.Length;
        }

        [Test]
        public void TheCylinderAlternatesTowardsA45DegreeFamilyWithinTheTolerance()
        {
            var cylinder = new Cylinder(16, 10, 11);
            int n = cylinder.VertexCount;
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var alternation = new AlternatingSolver(mesh, cylinder.InitialField, Theta, ToleranceFraction, true, IterationsPerStep))
            {
                AlternatingReport start = alternation.Report;
                Assert.AreEqual(0, start.Rounds);
                Assert.AreEqual(0, start.RoundsThisStep);
                Assert.IsFalse(start.IsConverged);
                Assert.AreEqual(0UL, start.Field.Iterations, "no field step before the first round");
                Assert.Greater(start.Surface.Tolerance, 0.0);
                CollectionAssert.AreEqual(cylinder.Xyz, alternation.Positions(), "nothing moves before the first round");
                CollectionAssert.AreEqual(cylinder.InitialField, alternation.Field());

                AlternatingReport first = alternation.Step(1);
                Assert.AreEqual(1, first.Rounds);
                Assert.AreEqual(1, first.RoundsThisStep);
                Assert.Greater(first.Field.Iterations, 0UL);
                Assert.LessOrEqual(first.Field.Iterations, (ulong)IterationsPerStep);
                Assert.Greater(first.Surface.Iterations, 0);
                Assert.LessOrEqual(first.Surface.Iterations, IterationsPerStep);

                AlternatingReport report = alternation.Step(2);
                Assert.LessOrEqual(report.Rounds, 3);
                Assert.AreEqual(report.Rounds - 1, report.RoundsThisStep);
                if (!first.IsConverged) Assert.Greater(report.Rounds, 1, "a round that has not converged is followed by another");
                if (report.Rounds < 3) Assert.IsTrue(report.IsConverged, "fewer rounds than asked only once converged");
                AlternatingReport again = alternation.Report;
                Assert.AreEqual(report.Rounds, again.Rounds);
                Assert.AreEqual(report.Surface.MaxDeviation, again.Surface.MaxDeviation);

                // The tolerance: 1 % of the bounding-box diagonal of the original surface.
                double[] lo = { double.MaxValue, double.MaxValue, double.MaxValue }, hi = { double.MinValue, double.MinValue, double.MinValue };
                for (int v = 0; v < n; v++)
                {
                    for (int k = 0; k < 3; k++)
                    {
                        lo[k] = Math.Min(lo[k], cylinder.Xyz[3 * v + k]);
                        hi[k] = Math.Max(hi[k], cylinder.Xyz[3 * v + k]);
                    }
                }
                Assert.AreEqual(ToleranceFraction * Vec.Distance(lo, hi), report.Surface.Tolerance, 1e-9 * report.Surface.Tolerance);

                double[] deviations = alternation.Deviations();
                double[] xyz = alternation.Positions();
                double[] field = alternation.Field();
                Assert.AreEqual(n, deviations.Length);
                Assert.AreEqual(3 * n, xyz.Length);
                Assert.AreEqual(n, field.Length);
                foreach (double d in deviations)
                {
                    Assert.GreaterOrEqual(d, 0.0);
                    Assert.LessOrEqual(d, report.Surface.Tolerance * (1 + 1e-12));
                }
                Assert.AreEqual(deviations.Max(), report.Surface.MaxDeviation);
                Assert.Greater(report.Surface.MaxDeviation, 0.0);
                double moved = 0;
                for (int i = 0; i < xyz.Length; i++) moved = Math.Max(moved, Math.Abs(xyz[i] - cylinder.Xyz[i]));
                Assert.Greater(moved, 0.0, "the surface moved");
                Assert.IsTrue(field.All(f => !double.IsNaN(f) && !double.IsInfinity(f)));
                Assert.IsTrue(field.Where((f, v) => f != cylinder.InitialField[v]).Any(), "the field changed too");

                // The optimiser's own measures, each step's with its own discretisation of the curves (measured here:
                // field 0.22°, surface 2.12° RMS after 3 rounds; the surface measure already reads 2.4° on the field step's
                // result before any surface iteration, so on this coarse mesh the two differ by how they measure, not
                // because the surface step undoes the field step). The surface bound is therefore 2.5°, not 2°.
                Console.WriteLine("  after {0} rounds{1}: field step {2} iterations, angle error {3:0.###}° RMS, {4:0.###}° max; " +
                    "surface step {5} iterations, angle error {6:0.###}° RMS; deviation max {7:0.####} (tolerance {8:0.####}), vertices moved up to {9:0.####}",
                    report.Rounds, report.IsConverged ? ", converged" : "", report.Field.Iterations, report.Field.AngleErrorRmsDegrees,
                    report.Field.AngleErrorMaxDegrees, report.Surface.Iterations, report.Surface.AngleErrorRmsDegrees,
                    report.Surface.MaxDeviation, report.Surface.Tolerance, moved);
                Assert.Less(report.Field.AngleErrorRmsDegrees, 1.0);
                Assert.Less(report.Surface.AngleErrorRmsDegrees, 2.5);

                // From outside: the level curves of the new field on the moved surface (not a cylinder any more, so
                // against that surface's own normals at the curve points), resampled every 3 mean edge lengths as the
                // library's outside measure does (quality::DEFAULT_SPACING_EDGES): finer, the polylines' kinks where they
                // cross the coarse triangles dominate the discrete binormal (4° mean at one edge length). The start
                // field's curves (nearly horizontal circles: geodesics, 90°) are about 45° off.
                double spacing = 3 * MeanEdgeLength(xyz, cylinder.Triangles);
                int before, after;
                double start0 = MeanLevelCurveAngleError(cylinder.Xyz, cylinder.Triangles, cylinder.InitialField, spacing, out before);
                double end = MeanLevelCurveAngleError(xyz, cylinder.Triangles, field, spacing, out after);
                Console.WriteLine("  level curves every {0:0.##}: mean |angle - 45| {1:0.###}° at {2} points (the start field's on the original surface: {3:0.###}° at {4})",
                    spacing, end, after, start0, before);
                Assert.Greater(start0, 30.0);
                Assert.GreaterOrEqual(after, 20);
                Assert.Less(end, 2.0);
            }
        }

        [Test]
        public void InvalidArgumentsAreRefusedByName()
        {
            var cylinder = new Cylinder(8, 6, 3);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                double[] field = cylinder.InitialField;
                Assert.AreEqual("mesh", Assert.Throws<ArgumentNullException>(() => new AlternatingSolver(null, field, Theta, 0.01, true, 10)).ParamName);
                Assert.AreEqual("field", Assert.Throws<ArgumentNullException>(() => new AlternatingSolver(mesh, null, Theta, 0.01, true, 10)).ParamName);
                var error = Assert.Throws<LamellaException>(() => new AlternatingSolver(mesh, new double[3], Theta, 0.01, true, 10));
                Assert.AreEqual(Status.InvalidArgument, error.Status);
                StringAssert.Contains("field", error.NativeMessage);
                StringAssert.Contains(cylinder.VertexCount.ToString(System.Globalization.CultureInfo.InvariantCulture), error.NativeMessage);
                Assert.AreEqual("iterationsPerStep", Assert.Throws<ArgumentOutOfRangeException>(() => new AlternatingSolver(mesh, field, Theta, 0.01, true, 0)).ParamName);
                Assert.AreEqual("iterationsPerStep", Assert.Throws<ArgumentOutOfRangeException>(() => new AlternatingSolver(mesh, field, Theta, 0.01, true, -1)).ParamName);
                foreach (double tolerance in new[] { 0.0, -0.01 })
                {
                    foreach (bool fraction in new[] { true, false })
                    {
                        error = Assert.Throws<LamellaException>(() => new AlternatingSolver(mesh, field, Theta, tolerance, fraction, 10));
                        Assert.AreEqual(Status.InvalidArgument, error.Status);
                        StringAssert.Contains("tolerance", error.NativeMessage);
                    }
                }
                error = Assert.Throws<LamellaException>(() => new AlternatingSolver(mesh, field, 200.0, 0.01, true, 10));
                StringAssert.Contains("theta", error.NativeMessage);
                error = Assert.Throws<LamellaException>(() => new AlternatingSolver(mesh, new double[cylinder.VertexCount], Theta, 0.01, true, 10));
                Assert.AreEqual(Status.SingularField, error.Status, "a constant field");
                using (var alternation = new AlternatingSolver(mesh, field, Theta, 0.01, true, 10))
                {
                    Assert.AreEqual("maxRounds", Assert.Throws<ArgumentOutOfRangeException>(() => alternation.Step(-1)).ParamName);
                    Assert.AreEqual(0, alternation.Step(0).Rounds, "zero rounds: nothing runs");
                }
            }
        }

        [Test]
        public void TheSameInputGivesTheSameBits()
        {
            var cylinder = new Cylinder(16, 10, 11);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (AlternatingSolver a = new AlternatingSolver(mesh, cylinder.InitialField, Theta, ToleranceFraction, true, 10),
                b = new AlternatingSolver(mesh, cylinder.InitialField, Theta, ToleranceFraction, true, 10))
            {
                AlternatingReport ra = a.Step(1), rb = b.Step(1);
                Assert.AreEqual(1, ra.Rounds);
                Assert.AreEqual(ra.Surface.MaxDeviation, rb.Surface.MaxDeviation);
                Assert.AreEqual(ra.Field.EnergyTotal, rb.Field.EnergyTotal);
                CollectionAssert.AreEqual(a.Positions(), b.Positions());
                CollectionAssert.AreEqual(a.Field(), b.Field());
                CollectionAssert.AreEqual(a.Deviations(), b.Deviations());
                CollectionAssert.AreNotEqual(cylinder.Xyz, a.Positions(), "a round moved the surface");
            }
        }
    }
}
