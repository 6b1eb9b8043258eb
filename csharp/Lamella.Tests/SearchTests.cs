using System;
using System.Linq;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// The default start search through the binding, on a generated cylinder: stepped until complete, its candidates
    /// and winner, the field taken once and converged to the family θ names (60°: the paper's pseudo-geodesics against
    /// the analytic normal; 90°: geodesics, the helices, straight in the development).
    /// </summary>
    [TestFixture]
    public class SearchTests
    {
        private Cylinder cylinder;

        [TestFixtureSetUp]
        public void Surface()
        {
            // 20 x 12 cells of about 1.3 x 1.25: 273 vertices, a few hundred milliseconds per search.
            cylinder = new Cylinder(20, 12, 7);
        }

        /// <summary>Steps a search on the cylinder until it is complete; checks the stepping contract and the candidates.</summary>
        private StartSearch Complete(double thetaDegrees)
        {
            StartSearch search;
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                search = new StartSearch(mesh, FieldParams.Default(Family.PseudoGeodesic, thetaDegrees));
            }
            Assert.AreEqual(0, search.CandidateCount);
            Assert.IsNull(search.Winner, "nothing scored yet");
            int steps = 0;
            bool more;
            do
            {
                more = search.Step();
                steps++;
                Assert.AreEqual(steps, search.CandidateCount, "each step probes one candidate");
                Assert.AreEqual(!more, search.IsComplete);
            } while (more && steps < 100);
            Assert.IsTrue(search.IsComplete);
            Assert.IsFalse(search.Step(), "a complete search probes nothing more");
            Assert.AreEqual(steps, search.CandidateCount);
            Candidate[] candidates = search.Candidates;
            Console.WriteLine("  θ {0}: {1} candidates\n    {2}", thetaDegrees, candidates.Length, string.Join("\n    ", candidates.Select(c => c.ToString())));
            for (int i = 0; i < candidates.Length; i++)
            {
                Candidate c = candidates[i];
                Assert.AreEqual(i, c.Index);
                Assert.AreNotEqual(c.IsScored, c.IsRejected, c.Text);
                StringAssert.Contains(c.IsScored ? ": score " : ": rejected: ", c.Text);
                if (c.Kind == StartKind.Height)
                {
                    Assert.AreEqual(1.0, Vec.Norm(c.Direction), 1e-12);
                    StringAssert.StartsWith((c.IsNegated ? "minus " : "") + "height along (", c.Text);
                }
                else
                {
                    StringAssert.StartsWith("guides from boundary side " + c.Side, c.Text);
                }
                if (c.IsScored)
                {
                    Assert.LessOrEqual(c.RmsErrorDegrees, c.MaxErrorDegrees + 1e-12);
                    Assert.GreaterOrEqual(c.Score, c.RmsErrorDegrees + 0.25 * c.MaxErrorDegrees - 1e-9);
                }
            }
            Candidate best = candidates.Where(c => c.IsScored).OrderBy(c => c.Score).First();
            Assert.AreEqual(best.Index, search.Winner);
            return search;
        }

        /// <summary>Takes the search's field (once) and converges it.</summary>
        private static FieldSolver TakeAndConverge(StartSearch search)
        {
            int? winner = search.Winner;
            int count = search.CandidateCount;
            FieldSolver field = search.TakeField();
            Assert.IsTrue(search.IsFieldTaken);
            Assert.Throws<InvalidOperationException>(() => search.TakeField());
            Assert.Throws<InvalidOperationException>(() => search.Step());
            Assert.AreEqual(winner, search.Winner, "the winner stays known after the field was taken");
            Assert.AreEqual(count, search.Candidates.Length, "the candidates stay readable");
            FieldReport report = field.Solve(400);
            Console.WriteLine("  the winner's field: " + report);
            Assert.IsTrue(report.IsConverged);
            Assert.AreEqual(0UL, report.SingularVertexCount);
            return field;
        }

        [Test]
        public void SearchLeadsToThePseudoGeodesicsOfTheta()
        {
            long before = Library.DebugLiveHandles;
            using (StartSearch search = Complete(60))
            {
                Assert.AreEqual(before + 1, Library.DebugLiveHandles, "the search is one handle (the mesh is disposed)");
                // Heights come in both signs: F and −F lead to the two mirror families of pseudo-geodesics.
                Candidate[] heights = search.Candidates.Where(c => c.Kind == StartKind.Height).ToArray();
                Assert.AreEqual(heights.Length, 2 * heights.Count(c => c.IsNegated));
                using (FieldSolver field = TakeAndConverge(search))
                {
                    Cylinder.Frames frames = Cylinder.FrameErrors(field, cylinder.Xyz, 60);
                    Console.WriteLine("  frames at {0} vertices: max |angle(b, n) - 60| = {1:0.000}°", frames.Framed, frames.WorstAngle);
                    Assert.AreEqual(19 * 11, frames.Framed, "every interior vertex");
                    // Against the analytic normal; the mesh's normals differ by a fraction of h / R ≈ 7.5° here.
                    Assert.Less(frames.WorstAngle, 3.0);
                    Assert.Less(frames.WorstTangent, Math.Sin(3.0 * Math.PI / 180));
                    Assert.Greater(field.Report.EnergyFrame, 0.0, "E_angle with the auxiliary frames of Eq. 9–10");
                }
            }
            Assert.AreEqual(before, Library.DebugLiveHandles);
        }

        [Test]
        public void ThetaNinetyGivesTheGeodesicsStraightInTheDevelopment()
        {
            using (StartSearch search = Complete(90))
            {
                // The library names the family by θ: geodesics, where F and −F are the same family (one sign).
                Assert.IsFalse(search.Candidates.Any(c => c.IsNegated));
                using (FieldSolver field = TakeAndConverge(search))
                using (LevelCurves curves = LevelCurves.Uniform(field, 5, 0))
                {
                    double[] points = curves.Points();
                    int[] offsets = curves.Offsets();
                    Assert.GreaterOrEqual(curves.Count, 5);
                    double bend = 0;
                    for (int c = 0; c < curves.Count; c++)
                    {
                        double[] a = Cylinder.Development(Vec.At(points, offsets[c])), b = Cylinder.Development(Vec.At(points, offsets[c + 1] - 1));
                        double chord = Math.Sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]));
                        for (int p = offsets[c]; p < offsets[c + 1]; p++)
                        {
                            double[] x = Cylinder.Development(Vec.At(points, p));
                            bend = Math.Max(bend, Math.Abs((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) / chord / chord);
                        }
                    }
                    Console.WriteLine("  θ 90: level curves off their chords in the development by {0:0.###e+0} of the chord", bend);
                    Assert.Less(bend, 1e-2);
                    // E_geo (Eq. 13): no auxiliary frames, unlike E_angle.
                    Assert.AreEqual(0.0, field.Report.EnergyFrame);
                    // Where a level curve bends (not on rulings), its binormal is at 90°.
                    Assert.Less(Cylinder.FrameErrors(field, cylinder.Xyz, 90).WorstAngle, 3.0);
                }
            }
        }

        [Test]
        public void WhereEveryFamilyIsNearlyStraightTheBestOfThemWins()
        {
            // A helicoid (r cos a, r sin a, 1.2 a), r in [1, 6], a in [0, 2.5]: away from its axis it bends with radii
            // beyond the model's size, so every 60° family is nearly straight over most of it and every candidate is
            // rejected as degenerate. The winner is then the best of those, still marked rejected.
            const double Pitch = 1.2;
            var grid = new Grid(36, 36, 1.0 / 36, 0, 0);
            double[] xyz = grid.Xyz;
            for (int v = 0; v < grid.VertexCount; v++)
            {
                double r = 1 + 5 * xyz[3 * v], a = 2.5 * xyz[3 * v + 1];
                xyz[3 * v] = r * Math.Cos(a);
                xyz[3 * v + 1] = r * Math.Sin(a);
                xyz[3 * v + 2] = Pitch * a;
            }
            using (var mesh = LamellaMesh.FromArrays(xyz, grid.Triangles()))
            using (var search = new StartSearch(mesh, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                while (search.Step()) { }
                Candidate[] candidates = search.Candidates;
                Assert.IsTrue(candidates.All(c => c.IsRejected), "some candidate was accepted: the fallback is not tested");
                int? winner = search.Winner;
                Assert.IsNotNull(winner, "a fallback winner");
                StringAssert.Contains("nearly straight", candidates[winner.Value].Text);
                using (FieldSolver field = search.TakeField())
                {
                    Assert.AreEqual(winner, search.Winner);
                    Assert.IsTrue(field.Solve(400).IsConverged);
                    using (LevelCurves curves = LevelCurves.Uniform(field, 8, 0.3))
                    {
                        // The curves resampled every 0.3 (about the mean edge), chords over three points: where they bend
                        // (radius below 12, the model's size), their binormals against the exact normal
                        // (Pitch sin a, -Pitch cos a, r) keep 60° (or its mirror, 120°). Measured: 29 points, mean 0.74°.
                        double[] points = curves.Points();
                        int[] offsets = curves.Offsets();
                        double sum = 0;
                        int measured = 0;
                        for (int c = 0; c < curves.Count; c++)
                        {
                            for (int p = offsets[c] + 3; p + 3 < offsets[c + 1]; p++)
                            {
                                double[] x0 = Vec.At(points, p - 3), x1 = Vec.At(points, p), x2 = Vec.At(points, p + 3);
                                double[] b = Vec.Cross(Vec.Sub(x1, x0), Vec.Sub(x2, x1));
                                double radius = Vec.Distance(x1, x0) * Vec.Distance(x2, x1) * Vec.Distance(x2, x0) / (2 * Vec.Norm(b));
                                if (!(radius < 12)) continue;
                                double a = x1[2] / Pitch, rr = Math.Sqrt(x1[0] * x1[0] + x1[1] * x1[1]);
                                double[] n = { Pitch * Math.Sin(a), -Pitch * Math.Cos(a), rr };
                                double angle = Vec.Degrees(Math.Abs(Vec.Dot(b, n)) / (Vec.Norm(b) * Vec.Norm(n)));
                                sum += Math.Abs(angle - 60);
                                measured++;
                            }
                        }
                        Console.WriteLine("  helicoid θ 60: winner {0}; {1} bending points, mean |angle(b, n) - 60| = {2:0.00}°", candidates[winner.Value].Text, measured, sum / measured);
                        Assert.Greater(measured, 20);
                        Assert.Less(sum / measured, 2.0);
                    }
                }
            }
        }

        [Test]
        public void LargeMeshesAreSearchedOnACoarsening()
        {
            using (var small = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            using (var search = new StartSearch(small, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                Assert.IsNull(search.ProxyVertexCount, "a small mesh is searched itself");
            }
            // 90 x 60 cells: 5,551 vertices, more than 1.5 x 1,500.
            var fine = new Cylinder(90, 60, 5);
            using (var mesh = LamellaMesh.FromArrays(fine.Xyz, fine.Triangles))
            using (var search = new StartSearch(mesh, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                int? proxy = search.ProxyVertexCount;
                Console.WriteLine("  {0} vertices searched on a {1}-vertex coarsening", fine.VertexCount, proxy);
                Assert.IsNotNull(proxy);
                Assert.GreaterOrEqual(proxy.Value, 1250);
                Assert.LessOrEqual(proxy.Value, 1500);
                // Probe until one candidate is scored (the heights across the axis are the rulings, rejected unsolved).
                bool more;
                do { more = search.Step(); } while (more && !search.Candidate(search.CandidateCount - 1).IsScored);
                Candidate scored = search.Candidate(search.CandidateCount - 1);
                Assert.IsTrue(scored.IsScored, scored.Text);
                Assert.Less(scored.RmsErrorDegrees, 45.0);
                using (FieldSolver field = search.TakeField())
                {
                    Assert.AreEqual(fine.VertexCount, field.Values().Length, "the field is carried to every vertex of the mesh");
                    Assert.IsTrue(field.Values().All(v => !double.IsNaN(v) && !double.IsInfinity(v)));
                }
                Assert.AreEqual(proxy, search.ProxyVertexCount, "still readable after the field was taken");
            }
        }
    }
}
