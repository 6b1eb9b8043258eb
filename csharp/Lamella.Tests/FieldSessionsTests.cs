using System;
using System.Collections.Generic;
using System.Linq;
using Lamella.Conversion;
using Lamella.Hosting;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// One field session per iteration of a host component (a list of meshes or θ), kept across solutions, released
    /// when not needed, saved compactly and restored without solving; on real fields.
    /// </summary>
    [TestFixture]
    public class FieldSessionsTests
    {
        private Cylinder first, second;

        [TestFixtureSetUp]
        public void Surfaces()
        {
            first = new Cylinder(20, 12, 7);
            second = new Cylinder(16, 10, 3);
        }

        private static string SignatureOf(Cylinder c, double theta) => Signature.Of(c.Xyz, c.Triangles, theta);

        /// <summary>A start function that counts its calls.</summary>
        private static Func<LamellaMesh, FieldSession> Starter(Cylinder c, double theta, List<string> log)
        {
            return mesh =>
            {
                log.Add("start " + c.VertexCount + " θ " + theta);
                return FieldSession.Start(mesh, c.InitialField, FieldParams.Default(Family.PseudoGeodesic, theta), SignatureOf(c, theta));
            };
        }

        /// <summary>
        /// The case that never converged before: two meshes in one component, stepped live (one or two iterations per
        /// solution). Each keeps its own session across solutions, so both converge, each started exactly once.
        /// </summary>
        [Test]
        public void EachItemOfAListKeepsItsSessionUntilConverged()
        {
            var log = new List<string>();
            var inputs = new[] { first, second };
            using (var sessions = new FieldSessions())
            {
                var initial = new FieldSession[2];
                int solutions = 0;
                while (solutions < 400)
                {
                    solutions++;
                    sessions.BeginSolution();
                    for (int i = 0; i < 2; i++)
                    {
                        FieldSession session = sessions.Session(i, inputs[i].Xyz, inputs[i].Triangles, SignatureOf(inputs[i], 60), false, Starter(inputs[i], 60, log));
                        if (initial[i] == null) initial[i] = session;
                        Assert.AreSame(initial[i], session, "item " + i + " keeps its session");
                        session.StepWithin(100, 1000, () => false, FieldSteppingTests.TickingClock(40));
                    }
                    sessions.EndSolution();
                    if (sessions.RunningCount() == 0) break;
                }
                Console.WriteLine("  two fields converged in {0} live solutions", solutions);
                Assert.AreEqual(0, sessions.RunningCount());
                CollectionAssert.AreEqual(new[] { "start 273 θ 60", "start 187 θ 60" }, log);
                Assert.LessOrEqual(sessions[0].Report.AngleErrorMaxDegrees, 0.5);
                Assert.LessOrEqual(sessions[1].Report.AngleErrorMaxDegrees, 0.5);
            }
        }

        [Test]
        public void ChangedInputsRestartOnlyTheirOwnFieldAndGoneItemsAreReleased()
        {
            var log = new List<string>();
            long before = Library.DebugLiveHandles;
            using (var sessions = new FieldSessions())
            {
                sessions.BeginSolution();
                FieldSession a = sessions.Session(0, first.Xyz, first.Triangles, SignatureOf(first, 60), false, Starter(first, 60, log));
                FieldSession b = sessions.Session(1, second.Xyz, second.Triangles, SignatureOf(second, 60), false, Starter(second, 60, log));
                sessions.EndSolution();
                Assert.AreEqual(before + 2, Library.DebugLiveHandles);

                // θ of item 1 changes: item 0 keeps its session, item 1 restarts.
                sessions.BeginSolution();
                Assert.AreSame(a, sessions.Session(0, first.Xyz, first.Triangles, SignatureOf(first, 60), false, Starter(first, 60, log)));
                FieldSession b2 = sessions.Session(1, second.Xyz, second.Triangles, SignatureOf(second, 70), false, Starter(second, 70, log));
                sessions.EndSolution();
                Assert.AreNotSame(b, b2);
                Assert.AreEqual(70, b2.ThetaDegrees);
                Assert.Throws<ObjectDisposedException>(() => b.Solver.Step(1), "the replaced session is released");
                Assert.AreEqual(before + 2, Library.DebugLiveHandles);

                // Reset restarts even with the same inputs.
                sessions.BeginSolution();
                Assert.AreNotSame(a, sessions.Session(0, first.Xyz, first.Triangles, SignatureOf(first, 60), true, Starter(first, 60, log)));
                // The list shrinks to one item: item 1's session goes at the end of the solution.
                sessions.EndSolution();
                Assert.AreEqual(1, sessions.Count);
                Assert.AreEqual(before + 1, Library.DebugLiveHandles);

                // An item without a field (a missing mesh) releases its session.
                sessions.BeginSolution();
                sessions.Skip(0);
                sessions.EndSolution();
                Assert.AreEqual(0, sessions.Count);
                Assert.AreEqual(before, Library.DebugLiveHandles);
                Assert.AreEqual(4, log.Count, "started: 0, 1, 1 again (θ), 0 again (reset)");
            }
            Assert.Throws<InvalidOperationException>(() =>
            {
                using (var sessions = new FieldSessions())
                {
                    sessions.Session(0, first.Xyz, first.Triangles, "another signature", false, Starter(first, 60, new List<string>()));
                }
            }, "a session must carry the signature it is stored under");
            Assert.AreEqual(before, Library.DebugLiveHandles);
        }

        /// <summary>
        /// A document stores each field's values (not the native session: ~100 bytes per vertex), and a reopened
        /// document shows the same converged field — report, values, level curves — without solving.
        /// </summary>
        [Test]
        public void SavedFieldsComeBackWithoutSolving()
        {
            var log = new List<string>();
            byte[] stored, session;
            double[] values;
            FieldReport report;
            double[] curvePoints;
            using (var sessions = new FieldSessions())
            {
                sessions.BeginSolution();
                FieldSession field = sessions.Session(0, first.Xyz, first.Triangles, SignatureOf(first, 60), false, Starter(first, 60, log));
                Assert.AreEqual(SteppingStop.Converged, field.ToConvergence(300, () => false).Stop);
                sessions.EndSolution();
                stored = sessions.Save();
                session = field.Solver.Save();
                values = field.Values();
                report = field.Report;
                using (var curves = LevelCurves.Uniform(field.Solver, 6, 0)) curvePoints = curves.Points();
            }
            Console.WriteLine("  {0} vertices: document stores {1} bytes ({2:0.0} per vertex), the whole session is {3} bytes ({4:0.0} per vertex)",
                first.VertexCount, stored.Length, (double)stored.Length / first.VertexCount, session.Length, (double)session.Length / first.VertexCount);
            Assert.Less(stored.Length, session.Length / 8, "store less than the whole session");

            using (var reopened = new FieldSessions())
            {
                reopened.Load(stored);
                Assert.AreEqual(stored, reopened.Save(), "saving before the first solution keeps the loaded fields");
                reopened.BeginSolution();
                FieldSession field = reopened.Session(0, first.Xyz, first.Triangles, SignatureOf(first, 60), false, Starter(first, 60, log));
                reopened.EndSolution();
                CollectionAssert.AreEqual(new[] { "start 273 θ 60" }, log, "restored, not started");
                Assert.IsTrue(field.IsRestored);
                Assert.AreEqual(report.Iterations, field.Report.Iterations);
                Assert.IsTrue(field.Report.IsConverged);
                Assert.AreEqual(report.EnergyAngle, field.Report.EnergyAngle);
                CollectionAssert.AreEqual(values, field.Values(), "exactly the saved values");
                using (var curves = LevelCurves.Uniform(field.Solver, 6, 0))
                {
                    double[] points = curves.Points();
                    Assert.AreEqual(curvePoints.Length, points.Length);
                    Assert.Less(points.Zip(curvePoints, (p, q) => Math.Abs(p - q)).Max(), 1e-9, "the same level curves");
                }
                SteppingOutcome<FieldReport> outcome = field.StepWithin(100, 1000, () => false, FieldSteppingTests.TickingClock(1));
                Assert.AreEqual(SteppingStop.Converged, outcome.Stop, "converged before saving: not solved again");
                Assert.AreEqual(0, outcome.Iterations);
            }

            // Other inputs than the saved ones: the saved field is not used.
            using (var reopened = new FieldSessions())
            {
                reopened.Load(stored);
                reopened.BeginSolution();
                Assert.IsFalse(reopened.Session(0, first.Xyz, first.Triangles, SignatureOf(first, 61), false, Starter(first, 61, log)).IsRestored);
                reopened.EndSolution();
                Assert.AreEqual("start 273 θ 61", log.Last());
            }
        }

        /// <summary>
        /// Without a start field the host runs the library's start search: live, one candidate per budget slice (the
        /// slice stops there), no field and nothing to save meanwhile; the slice of the last candidate takes the best
        /// one's field, which later slices step to convergence without counting the search's iterations.
        /// </summary>
        [Test]
        public void SearchingSessionProbesOneCandidatePerSliceThenSteps()
        {
            long before = Library.DebugLiveHandles;
            FieldParams parameters = FieldParams.Default(Family.PseudoGeodesic, 60);
            using (var sessions = new FieldSessions())
            {
                Func<LamellaMesh, FieldSession> search = mesh => FieldSession.Search(mesh, parameters, SignatureOf(second, 60));
                int slices = 0;
                FieldSession session = null;
                while (slices < 100)
                {
                    sessions.BeginSolution();
                    session = sessions.Session(0, second.Xyz, second.Triangles, SignatureOf(second, 60), false, search);
                    bool searching = session.IsSearching;
                    int probed = session.Candidates.Length;
                    SteppingOutcome<FieldReport> outcome = session.StepWithin(80, 1000, () => false, FieldSteppingTests.TickingClock(1));
                    sessions.EndSolution();
                    slices++;
                    if (!searching) break;
                    Assert.AreEqual(SteppingStop.TimeBudget, outcome.Stop, "a slice of the search ends the solution's budget");
                    Assert.AreEqual(0, outcome.Iterations, "no field iteration while searching");
                    Assert.AreEqual(probed + 1, session.Candidates.Length, "one candidate per slice");
                    if (session.IsSearching)
                    {
                        Assert.IsNull(session.Solver);
                        Assert.IsNull(session.ChosenStart);
                        Assert.AreEqual(1, sessions.RunningCount(), "a searching session is running");
                        Assert.Throws<InvalidOperationException>(() => session.Values());
                        Assert.AreEqual(0, FieldArchive.Read(sessions.Save()).Count, "nothing to store while searching");
                        StringAssert.StartsWith("searching a start · " + session.Candidates.Length + " candidate", StartDescriptions.Progress(session.Candidates));
                    }
                }
                Candidate[] candidates = session.Candidates;
                Console.WriteLine("  start search in {0} live slices: {1}", slices - 1, StartDescriptions.Chosen(session.ChosenStart.Value, candidates.Length));
                Assert.AreEqual(candidates.Length + 1, slices, "one slice per candidate, then the field");
                Assert.IsNotNull(session.Solver);
                Candidate chosen = session.ChosenStart.Value;
                Assert.AreEqual(candidates.Where(c => c.IsScored).Min(c => c.Score), chosen.Score, "the best candidate");
                StringAssert.StartsWith("start: " + (chosen.IsNegated ? "minus " : "") + "height", StartDescriptions.Short(chosen));
                string report = StartDescriptions.Report(candidates, chosen.Index, session.Report);
                StringAssert.StartsWith(session.Report.Describe() + "\n\nstart search:\n", report);
                string[] lines = report.Substring(report.IndexOf("start search:", StringComparison.Ordinal)).Split('\n');
                Assert.AreEqual(candidates.Length + 1, lines.Length, "one line per candidate");
                CollectionAssert.AreEqual(new[] { "* " + chosen }, lines.Where(line => line.StartsWith("* ")).ToArray(), "the chosen one marked");
                Assert.AreEqual(before + 1, Library.DebugLiveHandles, "the search was released, its field kept");

                // Then the field converges live; its iterations start with the field.
                SteppingOutcome<FieldReport> last = default(SteppingOutcome<FieldReport>);
                for (int i = 0; i < 400 && last.Stop != SteppingStop.Converged; i++)
                {
                    last = session.StepWithin(80, 1000, () => false, FieldSteppingTests.TickingClock(10));
                }
                Assert.AreEqual(SteppingStop.Converged, last.Stop);
                Assert.Less(last.Report.Iterations, 1000UL);
                Assert.AreEqual(1, FieldArchive.Read(sessions.Save()).Count, "a field to store now");
            }
            Assert.AreEqual(before, Library.DebugLiveHandles);
        }

        /// <summary>The one-shot solve runs the whole search and then the field; Escape during the search stops it with nothing taken.</summary>
        [Test]
        public void OneShotSolveRunsTheWholeSearchThenTheField()
        {
            FieldParams parameters = FieldParams.Default(Family.PseudoGeodesic, 60);
            using (var mesh = LamellaMesh.FromArrays(second.Xyz, second.Triangles))
            {
                using (FieldSession session = FieldSession.Search(mesh, parameters, "s"))
                {
                    SteppingOutcome<FieldReport> outcome = session.ToConvergence(1000, () => false);
                    Assert.AreEqual(SteppingStop.Converged, outcome.Stop);
                    Assert.IsFalse(session.IsSearching);
                    Assert.IsTrue(session.ChosenStart.HasValue);
                    Assert.Greater(session.Candidates.Length, 1);
                    // The family: frames against the cylinder's analytic normal (16 x 10 cells, h / R ≈ 9.4°: 3°).
                    Cylinder.Frames frames = Cylinder.FrameErrors(session.Solver, second.Xyz, 60);
                    Assert.AreEqual(15 * 9, frames.Framed);
                    Assert.Less(frames.WorstAngle, 3.0);
                }
                using (FieldSession session = FieldSession.Search(mesh, parameters, "s"))
                {
                    int asked = 0;
                    SteppingOutcome<FieldReport> outcome = session.ToConvergence(1000, () => ++asked > 2);
                    Assert.AreEqual(SteppingStop.Cancelled, outcome.Stop);
                    Assert.IsTrue(session.IsSearching);
                    Assert.AreEqual(2, session.Candidates.Length, "two candidates, then Escape");
                }
            }
        }

        [Test]
        public void ArchiveRoundTripsAndRejectsDamage()
        {
            FieldParams parameters = FieldParams.Default(Family.PseudoGeodesic, 47.5);
            parameters.GradientTarget = 0.25;
            var report = new FieldReport { Iterations = 12, Stage = 2, EnergyAngle = 3.5e-7, AngleErrorMaxDegrees = 0.125, SingularVertexCount = 1, Converged = 1 };
            var field = new SavedField(3, "abc", 47.5, parameters, report, new[] { 1.0, -2.5, double.Epsilon, 1e300 });
            byte[] bytes = FieldArchive.Write(new[] { field });
            SavedField back = FieldArchive.Read(bytes).Single();
            Assert.AreEqual(3, back.Iteration);
            Assert.AreEqual("abc", back.Signature);
            Assert.AreEqual(47.5, back.ThetaDegrees);
            Assert.AreEqual(parameters, back.Parameters);
            Assert.AreEqual(report, back.Report);
            CollectionAssert.AreEqual(field.Values, back.Values);

            StringAssert.Contains("bad magic", Assert.Throws<FormatException>(() => FieldArchive.Read(new byte[] { 1, 2, 3, 4, 5, 6, 7, 8 })).Message);
            byte[] future = (byte[])bytes.Clone();
            future[4] = 9;
            StringAssert.Contains("version 9", Assert.Throws<FormatException>(() => FieldArchive.Read(future)).Message);
            Assert.Throws<FormatException>(() => FieldArchive.Read(bytes.Take(bytes.Length - 10).ToArray()));
            byte[] damaged = (byte[])bytes.Clone();
            for (int i = 8; i < damaged.Length; i++) damaged[i] ^= 0x5a;
            Assert.Throws<FormatException>(() => FieldArchive.Read(damaged));
        }

        [Test]
        public void ArchiveOfALargeSmoothFieldStaysSmall()
        {
            // 50,000 values of a smooth field: about 100 bytes per vertex as a whole session, under 8 here.
            var values = new double[50000];
            for (int i = 0; i < values.Length; i++) values[i] = 3.0 * Math.Sin(i * 1e-3) + 1e-3 * i;
            byte[] bytes = FieldArchive.Write(new[] { new SavedField(0, new string('f', 64), 60, FieldParams.Default(Family.PseudoGeodesic, 60), new FieldReport(), values) });
            Console.WriteLine("  50,000 values: {0} bytes ({1:0.00} per vertex)", bytes.Length, bytes.Length / 50000.0);
            Assert.Less(bytes.Length, 8 * values.Length);
        }

        /// <summary>
        /// A cylinder meshed as two unwelded patches: cleaned, solved in one shot, and the field comes back per input
        /// vertex, equal on both copies of every seam vertex.
        /// </summary>
        [Test]
        public void FieldOnACleanedMeshLinesUpWithTheInputVertices()
        {
            // Split the cylinder's vertices into two patches along column 10 by duplicating that column.
            const int columns = 20, rows = 12, seam = 10;
            int perRow = columns + 1;
            var xyz = new List<double>(first.Xyz);
            var duplicate = new Dictionary<int, int>();
            for (int j = 0; j <= rows; j++)
            {
                int v = j * perRow + seam;
                duplicate[v] = xyz.Count / 3;
                xyz.AddRange(Vec.At(first.Xyz, v));
            }
            var corners = new List<int>();
            for (int t = 0; t < first.Triangles.Length / 3; t++)
            {
                int[] tri = { first.Triangles[3 * t], first.Triangles[3 * t + 1], first.Triangles[3 * t + 2] };
                // Triangles right of the seam use the copies.
                bool right = tri.All(v => v % perRow >= seam);
                foreach (int v in tri) corners.Add(right && duplicate.ContainsKey(v) ? duplicate[v] : v);
                corners.Add(corners[corners.Count - 1]);
            }
            CleanMesh clean = CleanMesh.FromFaces(xyz.ToArray(), corners.ToArray(), 1e-9);
            Assert.AreEqual(rows + 1, clean.WeldedVertices);
            CollectionAssert.AreEqual(first.Xyz, clean.Xyz, "the welded mesh is the cylinder again");
            using (var mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
            using (var field = new FieldSolver(mesh, first.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                Assert.IsTrue(FieldStepping.ToConvergence(field, 300, () => false).Report.IsConverged);
                double[] perInput = clean.ToInputVertices(field.Values(), 1, double.NaN);
                Assert.AreEqual(xyz.Count / 3, perInput.Length);
                foreach (KeyValuePair<int, int> pair in duplicate) Assert.AreEqual(perInput[pair.Key], perInput[pair.Value]);
                double[] binormals = clean.ToInputVertices(field.Binormals(), 3, 0);
                foreach (KeyValuePair<int, int> pair in duplicate) CollectionAssert.AreEqual(Vec.At(binormals, pair.Key), Vec.At(binormals, pair.Value));
            }
        }
    }
}
