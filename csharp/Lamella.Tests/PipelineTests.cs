using System;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// The whole pipeline through the binding against the real native library: a C#-generated cylinder → field
    /// (θ = 60°, stepped until converged) → level curves → strips → unrolled strips, each checked against the
    /// cylinder's analytic geometry, not just counted.
    /// </summary>
    [TestFixture]
    public class PipelineTests
    {
        private const double Theta = 60.0;
        private const double Width = 1.0;
        private const int CurveCount = 5;
        private const double Spacing = 1.0;

        private Cylinder cylinder;
        private FieldSolver field;
        private FieldReport start, final;
        private long totalIterations;
        private LevelCurves curves;
        private Strips strips;

        [TestFixtureSetUp]
        public void Solve()
        {
            // 40 x 24 cells of about 0.65 x 0.63: 1025 vertices.
            cylinder = new Cylinder(40, 24, 7);
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                field = new FieldSolver(mesh, cylinder.InitialField, FieldParams.Default(Family.PseudoGeodesic, Theta));
            }
            start = field.Report;
            FieldReport report;
            do
            {
                report = field.Step(5);
                totalIterations += (long)report.IterationsThisStep;
            } while (!report.IsConverged && totalIterations < 300);
            final = report;
            Console.WriteLine("  field: " + final);
            curves = LevelCurves.Uniform(field, CurveCount, Spacing);
            strips = Strips.Build(curves, StripParams.Default(Theta, Width));
        }

        [TestFixtureTearDown]
        public void Release()
        {
            strips?.Dispose();
            curves?.Dispose();
            field?.Dispose();
        }

        [Test]
        public void FieldConvergesWithinTheCoresBound()
        {
            Assert.Greater(start.AngleErrorMaxDegrees, 5.0, "the start must not already be the answer");
            Assert.IsTrue(final.IsConverged, "not converged after " + final.Iterations + " iterations");
            Assert.AreEqual(totalIterations, (long)final.Iterations);
            // tests/integration/field_cylinder.rs: E_angle ≤ 1e-5, no singular vertices; the report's max angle error, measured along
            // the level polylines, reads 0.75° here since the curve-level jets of the core (3f04e84; under 0.5° before,
            // as tests/integration/field_cylinder.rs still asks): 1° (the frames against the analytic normal: 2°, below).
            Assert.LessOrEqual(final.EnergyAngle, 1e-5);
            Assert.LessOrEqual(final.AngleErrorMaxDegrees, 1.0);
            Assert.LessOrEqual(final.AngleErrorRmsDegrees, final.AngleErrorMaxDegrees);
            Assert.AreEqual(0UL, final.SingularVertexCount);
            Assert.AreEqual(0, field.SingularVertices().Length);
            // Interior vertices of the 41 x 25 grid: 39 x 23 = 897; nearly all measured.
            Assert.Greater(final.MeasuredVertices, 800UL);
            // Converged: a further step does nothing.
            var again = field.Step(5);
            Assert.IsTrue(again.IsConverged);
            Assert.AreEqual(0UL, again.IterationsThisStep);
        }

        [Test]
        public void BinormalsMeetTheAnalyticNormalAtTheta()
        {
            Assert.AreEqual(3 * cylinder.VertexCount, field.Binormals().Length);
            Assert.AreEqual(3 * cylinder.VertexCount, field.SideVectors().Length);
            Cylinder.Frames frames = Cylinder.FrameErrors(field, cylinder.Xyz, Theta);
            Console.WriteLine("  frames at {0} vertices: max |angle(b, n) - 60| = {1:0.000}°", frames.Framed, frames.WorstAngle);
            Assert.AreEqual(39 * 23, frames.Framed);
            Assert.Less(frames.WorstUnit, 1e-9);
            // Against the analytic normal, not the mesh's vertex normal the solver uses (they differ by a
            // fraction of the angle between neighbouring faces, h / R ≈ 3.7° here): 2° as in the C harness.
            Assert.Less(frames.WorstAngle, 2.0);
            Assert.Less(frames.WorstTangent, Math.Sin(2.0 * Math.PI / 180));
        }

        [Test]
        public void LevelCurvesLieOnTheCylinderAtUniformLevels()
        {
            double[] values = field.Values();
            double min = double.PositiveInfinity, max = double.NegativeInfinity;
            foreach (double f in values) { min = Math.Min(min, f); max = Math.Max(max, f); }
            // A level may cross the patch in more than one piece (cut by the boundary), so there are at least
            // as many polylines as levels, each at one of the uniform values, in level order.
            int count = curves.Count;
            Assert.GreaterOrEqual(count, CurveCount);
            double[] levels = curves.Levels();
            Assert.AreEqual(count, levels.Length);
            var uniform = new double[CurveCount];
            for (int k = 0; k < CurveCount; k++) uniform[k] = min + (k + 1) * (max - min) / (CurveCount + 1);
            int matched = 0;
            for (int c = 0; c < count; c++)
            {
                while (matched < CurveCount && Math.Abs(levels[c] - uniform[matched]) > 1e-12 * (max - min)) matched++;
                Assert.Less(matched, CurveCount, "polyline " + c + " has level " + levels[c] + ", not one of the uniform levels in order");
            }
            int[] offsets = curves.Offsets();
            double[] points = curves.Points(), normals = curves.Normals();
            Assert.AreEqual(count + 1, offsets.Length);
            Assert.AreEqual(3 * offsets[count], points.Length);
            Assert.AreEqual(points.Length, normals.Length);
            CollectionAssert.AreEqual(new bool[count], curves.Closed(), "no level set of the patch is closed");
            double offSurface = 0, normalError = 0, angleSum = 0;
            int angles = 0;
            for (int c = 0; c < count; c++)
            {
                Assert.GreaterOrEqual(offsets[c + 1] - offsets[c], 3);
                for (int p = offsets[c]; p < offsets[c + 1]; p++)
                {
                    double[] x = Vec.At(points, p), n = Cylinder.Normal(points, p);
                    offSurface = Math.Max(offSurface, Math.Abs(Math.Sqrt(x[0] * x[0] + x[1] * x[1]) - Cylinder.Radius));
                    normalError = Math.Max(normalError, 1 - Vec.Dot(Vec.At(normals, p), n));
                    if (p > offsets[c] && p + 1 < offsets[c + 1])
                    {
                        angleSum += Math.Abs(Cylinder.BinormalAngle(Vec.At(points, p - 1), x, Vec.At(points, p + 1)) - Theta);
                        angles++;
                    }
                    // Resampled at the requested spacing (the last segment of a curve may be shorter).
                    if (p + 2 < offsets[c + 1])
                    {
                        Assert.AreEqual(Spacing, Vec.Distance(x, Vec.At(points, p + 1)), 0.25 * Spacing);
                    }
                }
            }
            Console.WriteLine("  curves: max |r - R| {0:0.00e0}, mean binormal angle error {1:0.00}°", offSurface, angleSum / angles);
            // On the mesh: chords deviate from the cylinder by at most the sagitta h² / (8R) ≈ 0.01.
            Assert.Less(offSurface, 0.02);
            Assert.Less(normalError, 1 - Math.Cos(4 * Math.PI / 180));
            // Level polylines of the 60° field, before any strip optimisation: pseudo-geodesics up to the
            // field's discretisation (3° on average, as the C harness allows).
            Assert.Less(angleSum / angles, 3.0);
        }

        [Test]
        public void StripsArePlanarDevelopableAndUnrollStraight()
        {
            int s = strips.Count;
            Assert.AreEqual(curves.Count, s, "a strip on every polyline");
            Assert.AreEqual(0, strips.Skipped().Length);
            int[] points = strips.PointOffsets(), vertices = strips.VertexOffsets(), quadOffsets = strips.QuadOffsets();
            double[] xyz = strips.Vertices(), flat = strips.UnrolledVertices(), centres = strips.Centres(), rulings = strips.Rulings(), flatCentres = strips.UnrolledCentres();
            int[] quads = strips.Quads();
            Assert.AreEqual(3 * vertices[s], xyz.Length);
            Assert.AreEqual(2 * vertices[s], flat.Length);
            Assert.AreEqual(3 * points[s], centres.Length);
            Assert.AreEqual(3 * points[s], rulings.Length);
            Assert.AreEqual(2 * points[s], flatCentres.Length);
            Assert.AreEqual(4 * quadOffsets[s], quads.Length);
            double planar = 0, isometry = 0, straight = 0, width = 0, offSurface = 0, midpoint = 0, unit = 0, angle = 0;
            for (int i = 0; i < s; i++)
            {
                int n = points[i + 1] - points[i], o = vertices[i];
                Assert.AreEqual(2 * n, vertices[i + 1] - o);
                Assert.AreEqual(n - 1, quadOffsets[i + 1] - quadOffsets[i]);
                for (int q = quadOffsets[i]; q < quadOffsets[i + 1]; q++)
                {
                    int j = q - quadOffsets[i];
                    int[] v = { quads[4 * q], quads[4 * q + 1], quads[4 * q + 2], quads[4 * q + 3] };
                    CollectionAssert.AreEqual(new[] { o + j, o + j + 1, o + n + j + 1, o + n + j }, v);
                    planar = Math.Max(planar, NonPlanarity(Vec.At(xyz, v[0]), Vec.At(xyz, v[1]), Vec.At(xyz, v[2]), Vec.At(xyz, v[3])));
                    // Congruent to the unrolled quad: four sides and both diagonals keep their lengths.
                    int[,] pairs = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 2 }, { 1, 3 } };
                    for (int k = 0; k < 6; k++)
                    {
                        int a = v[pairs[k, 0]], b = v[pairs[k, 1]];
                        isometry = Math.Max(isometry, Math.Abs(Vec.Distance(Vec.At(xyz, a), Vec.At(xyz, b)) - Vec.Distance2(flat, a, b)));
                    }
                }
                // The unrolled centre line: distance of each point from the chord of its end points.
                int first = points[i], last = points[i + 1] - 1;
                double ax = flatCentres[2 * first], ay = flatCentres[2 * first + 1], bx = flatCentres[2 * last], by = flatCentres[2 * last + 1];
                double chord = Math.Sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay)), length = 0;
                for (int j = first; j < last; j++) length += Vec.Distance2(flatCentres, j, j + 1);
                for (int j = 0; j < n; j++)
                {
                    int p = first + j;
                    double off = Math.Abs((bx - ax) * (flatCentres[2 * p + 1] - ay) - (by - ay) * (flatCentres[2 * p] - ax)) / chord;
                    straight = Math.Max(straight, off / length);
                    foreach (int fv in new[] { o + j, o + n + j })
                    {
                        double side = Math.Abs((bx - ax) * (flat[2 * fv + 1] - ay) - (by - ay) * (flat[2 * fv] - ax)) / chord;
                        width = Math.Max(width, Math.Abs(side - 0.5 * Width));
                    }
                    double[] c = Vec.At(centres, p), l = Vec.At(xyz, o + j), r = Vec.At(xyz, o + n + j);
                    for (int k = 0; k < 3; k++) midpoint = Math.Max(midpoint, Math.Abs(0.5 * (l[k] + r[k]) - c[k]));
                    offSurface = Math.Max(offSurface, Math.Abs(Math.Sqrt(c[0] * c[0] + c[1] * c[1]) - Cylinder.Radius));
                    unit = Math.Max(unit, Math.Abs(Vec.Norm(Vec.At(rulings, p)) - 1));
                    if (j > 0 && j + 1 < n)
                    {
                        angle = Math.Max(angle, Math.Abs(Cylinder.BinormalAngle(Vec.At(centres, p - 1), c, Vec.At(centres, p + 1)) - Theta));
                    }
                }
            }
            Console.WriteLine("  strips: non-planarity {0:0.0e0}, isometry {1:0.0e0}, straightness {2:0.0e0}, width {3:0.0e0}, |angle - 60| {4:0.000}°",
                planar, isometry, straight, width, angle);
            // The C harness's thresholds (measured values there have a margin of ~50).
            Assert.Less(planar, 1e-5);
            Assert.Less(isometry, 1e-9 * Width);
            Assert.Less(straight, 2e-5);
            Assert.Less(width, 5e-4 * Width);
            Assert.Less(midpoint, 1e-9);
            Assert.Less(unit, 1e-9);
            // The centre lines are θ-pseudo-geodesics of the cylinder itself: discrete binormals against the analytic normal.
            Assert.LessOrEqual(angle, 1.5);
            Assert.Less(offSurface, 0.02);
        }

        [Test]
        public void DiagnosticsFollowPropositionTwoAtEveryCentrePoint()
        {
            VertexDiagnostics[] diagnostics = strips.Diagnostics();
            Assert.AreEqual(strips.Centres().Length / 3, diagnostics.Length);
            int bending = 0;
            foreach (VertexDiagnostics d in diagnostics)
            {
                if (!d.Has(DiagnosticParts.ConicalCurvature))
                {
                    Assert.AreEqual(0.0, d.ConicalCurvature);
                    Assert.AreEqual(0.0, d.BinormalOffset);
                    continue;
                }
                bending++;
                Assert.IsTrue(d.Has(DiagnosticParts.Curvature | DiagnosticParts.Torsion | DiagnosticParts.DarbouxAngle | DiagnosticParts.BinormalOffset));
                Assert.AreEqual(d.Torsion / d.Curvature, d.ConicalCurvature, 1e-12 * (1 + Math.Abs(d.ConicalCurvature)));
                Assert.AreEqual(Math.Atan(Math.Abs(d.ConicalCurvature)) * 180.0 / Math.PI, d.DarbouxAngleDegrees, 1e-9);
                double k = d.ConicalCurvature, v = 0.5 * Width;
                Assert.AreEqual(d.Curvature * k * k * v * v / 2.0, d.BinormalOffset, 1e-9 * (1 + d.BinormalOffset), "Prop. 2 at half the width");
                // A θ-pseudo-geodesic's principal normal makes the angle 90° − θ with the surface normal, so
                // κ = κ_n / sin θ, and on the cylinder |κ_n| ≤ 1/R; 10 % for the three-point circles of a centre
                // line that leaves the surface a little (measured: 7 % at worst).
                Assert.LessOrEqual(d.Curvature, 1.1 / (Cylinder.Radius * Math.Sin(Theta * Math.PI / 180.0)));
            }
            Assert.Greater(bending, diagnostics.Length / 2);
        }

        [Test]
        public void MetricsAgreeWithThePatternSummary()
        {
            StripMetrics[] metrics = strips.Metrics();
            PatternMetrics pattern = strips.PatternMetrics;
            Assert.AreEqual(strips.Count, metrics.Length);
            Assert.AreEqual((ulong)metrics.Length, pattern.StripCount);
            Assert.AreEqual(0UL, pattern.SkippedCount);
            double worstTheta = 0, sumPlanar = 0;
            for (int i = 0; i < metrics.Length; i++)
            {
                Assert.AreEqual((ulong)i, metrics[i].Curve);
                Assert.AreEqual(CentreLength(i), metrics[i].Length, 1e-9 * metrics[i].Length);
                Assert.AreEqual(0UL, metrics[i].FlippedQuads);
                Assert.AreEqual(StripWarnings.None, metrics[i].Warnings & (StripWarnings.FlippedQuads | StripWarnings.WidthTooLarge | StripWarnings.SingularVertices));
                worstTheta = Math.Max(worstTheta, metrics[i].MaxDiffThetaDegrees);
                sumPlanar += metrics[i].EPlanar;
            }
            Assert.AreEqual(worstTheta, pattern.MaxDiffThetaDegrees);
            Assert.AreEqual(sumPlanar, pattern.EPlanar, 1e-12 * (1 + sumPlanar));
            Assert.LessOrEqual(pattern.MaxDiffThetaDegrees, 1.5);
            Assert.LessOrEqual(pattern.MaxEStraight, 1e-3);
            Assert.Less(pattern.MaxPlanar, 1e-4);
            // Appro is in % of the bounding-box diagonal: the centre points are projected onto the mesh, so they
            // stay within 5e-3 length units of it (under 1 % of an edge).
            Assert.Less(pattern.ApproPercent / 100 * BoxDiagonal(cylinder.Xyz), 5e-3);
        }

        [Test]
        public void ConvergedFieldGivesAnAcceptablePattern()
        {
            Verdict verdict = strips.Verdict;
            StripMetrics[] metrics = strips.Metrics();
            PatternMetrics pattern = strips.PatternMetrics;
            Console.WriteLine("  verdict: " + verdict);
            Assert.IsTrue(verdict.IsAcceptable);
            Assert.AreEqual(2.0, verdict.ToleranceDegrees, "the library's default tolerance");
            Assert.AreEqual(2.0, StripParams.Default(Theta, Width).ToleranceDegrees);
            Assert.AreEqual(0, verdict.StripsMissingTheta);
            Assert.AreEqual(0, verdict.StripsWithFlippedQuads);
            Assert.AreEqual(0, verdict.StripsOffSurface);
            Assert.IsEmpty(verdict.Message);
            StringAssert.StartsWith("acceptable: every strip within 2° of θ", verdict.ToString());
            Assert.DoesNotThrow(strips.EnsureAcceptable);
            // The worst quad is the pattern's worst, of the worst strip, a quad of that strip, on the cylinder.
            double worst = 0, ruling = 0;
            foreach (StripMetrics m in metrics)
            {
                worst = Math.Max(worst, m.MaxQuadAngleErrorDegrees);
                ruling = Math.Max(ruling, m.MaxRulingOverWidth);
            }
            Assert.AreEqual(worst, verdict.WorstErrorDegrees);
            Assert.AreEqual(worst, pattern.MaxQuadAngleErrorDegrees);
            Assert.AreEqual(ruling, pattern.MaxRulingOverWidth);
            Assert.LessOrEqual(worst, verdict.ToleranceDegrees);
            Assert.AreEqual(worst, metrics[verdict.WorstStrip].MaxQuadAngleErrorDegrees);
            int[] quadOffsets = strips.QuadOffsets();
            Assert.Less(verdict.WorstQuad, quadOffsets[verdict.WorstStrip + 1] - quadOffsets[verdict.WorstStrip]);
            double[] p = verdict.WorstPoint;
            Assert.AreEqual(Cylinder.Radius, Math.Sqrt(p[0] * p[0] + p[1] * p[1]), 0.05);
            // The longest ruling segment from the centre line, over the width, measured on the strip vertices: each
            // boundary vertex is the centre point plus or minus its ruling segment.
            double[] vertices = strips.Vertices(), centres = strips.Centres();
            int[] pointOffsets = strips.PointOffsets(), vertexOffsets = strips.VertexOffsets();
            double measured = 0;
            for (int i = 0; i < strips.Count; i++)
            {
                int n = pointOffsets[i + 1] - pointOffsets[i];
                for (int j = 0; j < n; j++)
                {
                    double[] c = Vec.At(centres, pointOffsets[i] + j);
                    measured = Math.Max(measured, Vec.Distance(Vec.At(vertices, vertexOffsets[i] + j), c) / Width);
                    measured = Math.Max(measured, Vec.Distance(Vec.At(vertices, vertexOffsets[i] + n + j), c) / Width);
                }
            }
            Assert.AreEqual(measured, pattern.MaxRulingOverWidth, 1e-9);
            Assert.GreaterOrEqual(measured, 0.5 - 1e-9, "the strip is Width across; a ruling crosses it obliquely");
        }

        /// <summary>
        /// The same curves judged with a tolerance below the pattern's worst plane error (never 0 on a triangle mesh,
        /// checked): the same strips, but no acceptable family. Built all the same, with the native message; only
        /// EnsureAcceptable throws, with the typed exception.
        /// </summary>
        [Test]
        public void StrictToleranceMissesThetaButKeepsTheStrips()
        {
            Verdict good = strips.Verdict;
            Assert.Greater(good.WorstErrorDegrees, 1e-3);
            StripParams strict = StripParams.Default(Theta, Width);
            strict.ToleranceDegrees = 0.5 * good.WorstErrorDegrees;
            using (var missed = Strips.Build(curves, strict))
            {
                Verdict verdict = missed.Verdict;
                Console.WriteLine("  verdict: " + verdict);
                Assert.IsFalse(verdict.IsAcceptable);
                Assert.AreEqual(strict.ToleranceDegrees, verdict.ToleranceDegrees);
                Assert.GreaterOrEqual(verdict.StripsMissingTheta, 1);
                Assert.AreEqual(good.WorstStrip, verdict.WorstStrip);
                Assert.AreEqual(good.WorstQuad, verdict.WorstQuad);
                Assert.AreEqual(good.WorstErrorDegrees, verdict.WorstErrorDegrees);
                StringAssert.StartsWith("no acceptable family: strip", verdict.Message);
                StringAssert.Contains("worst: strip " + good.WorstStrip + " quad " + good.WorstQuad, verdict.Message);
                Assert.AreEqual(verdict.Message, verdict.ToString());
                // The strips are the same: the tolerance judges them, it does not change them.
                Assert.AreEqual(strips.Count, missed.Count);
                AssertBitwiseEqual(strips.Vertices(), missed.Vertices());
                var e = Assert.Throws<NoAcceptableFamilyException>(missed.EnsureAcceptable);
                Assert.AreEqual(Status.NoAcceptableFamily, e.Status);
                Assert.AreEqual(verdict.Message, e.NativeMessage);
                Assert.AreEqual(verdict.WorstErrorDegrees, e.Verdict.WorstErrorDegrees);
                Assert.IsInstanceOf<LamellaException>(e);
            }
        }

        [Test]
        public void SavedSessionRestoresBitForBit()
        {
            byte[] bytes = field.Save();
            Assert.AreEqual((byte)'L', bytes[0]);
            Assert.AreEqual((byte)'F', bytes[3]);
            using (var restored = FieldSolver.Load(bytes))
            {
                CollectionAssert.AreEqual(bytes, restored.Save());
                AssertBitwiseEqual(field.Values(), restored.Values());
                Assert.AreEqual(field.Report.Iterations, restored.Report.Iterations);
            }
        }

        [Test]
        public void RestoredSessionContinuesAsTheOriginal()
        {
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var original = new FieldSolver(mesh, cylinder.InitialField, FieldParams.Default(Family.PseudoGeodesic, Theta)))
            {
                original.Step(3);
                using (var copy = FieldSolver.Load(original.Save()))
                {
                    FieldReport a = original.Step(4), b = copy.Step(4);
                    Assert.AreEqual(7UL, a.Iterations);
                    Assert.AreEqual(BitConverter.DoubleToInt64Bits(a.EnergyTotal), BitConverter.DoubleToInt64Bits(b.EnergyTotal));
                    AssertBitwiseEqual(original.Values(), copy.Values());
                    CollectionAssert.AreEqual(original.Save(), copy.Save());
                }
            }
        }

        [Test]
        public void MeshRoundTripsThroughTheLibrary()
        {
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                Assert.AreEqual(cylinder.VertexCount, mesh.VertexCount);
                Assert.AreEqual(cylinder.Triangles.Length / 3, mesh.TriangleCount);
                AssertBitwiseEqual(cylinder.Xyz, mesh.Positions());
                CollectionAssert.AreEqual(cylinder.Triangles, mesh.Triangles());
            }
        }

        /// <summary>The length of strip <paramref name="i"/>'s centre line, summed from its points.</summary>
        private double CentreLength(int i)
        {
            int[] points = strips.PointOffsets();
            double[] centres = strips.Centres();
            double length = 0;
            for (int p = points[i]; p + 1 < points[i + 1]; p++) length += Vec.Distance(Vec.At(centres, p), Vec.At(centres, p + 1));
            return length;
        }

        private static double BoxDiagonal(double[] xyz)
        {
            double sum = 0;
            for (int k = 0; k < 3; k++)
            {
                double lo = double.PositiveInfinity, hi = double.NegativeInfinity;
                for (int i = k; i < xyz.Length; i += 3) { lo = Math.Min(lo, xyz[i]); hi = Math.Max(hi, xyz[i]); }
                sum += (hi - lo) * (hi - lo);
            }
            return Math.Sqrt(sum);
        }

        private static void AssertBitwiseEqual(double[] expected, double[] actual)
        {
            Assert.AreEqual(expected.Length, actual.Length);
            for (int i = 0; i < expected.Length; i++)
            {
                if (BitConverter.DoubleToInt64Bits(expected[i]) != BitConverter.DoubleToInt64Bits(actual[i]))
                {
                    Assert.Fail("value " + i + " differs: " + expected[i].ToString("R") + " vs " + actual[i].ToString("R"));
                }
            }
        }

        /// <summary>|det(b − a, c − a, d − a)| / (|b − a| |c − a| |d − a|): 0 exactly when the four corners are coplanar.</summary>
        private static double NonPlanarity(double[] a, double[] b, double[] c, double[] d)
        {
            double[] u = Vec.Sub(b, a), v = Vec.Sub(c, a), w = Vec.Sub(d, a);
            return Math.Abs(Vec.Dot(u, Vec.Cross(v, w))) / (Vec.Norm(u) * Vec.Norm(v) * Vec.Norm(w));
        }
    }
}
