using System;
using System.Collections.Generic;
using System.Linq;
using Lamella.Hosting;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>
    /// The live and one-shot solving that Strip Field, Strip Net, Strip Web, Reshape Surface, Optimise Net, Torsion-Free
    /// Net and Optimise Web share (<see cref="LiveStepper"/>, <see cref="LiveSessions{T}"/>,
    /// <see cref="SolverSession{TSolver, TReport}"/>), driven as Grasshopper drives it, solution after solution, on a real
    /// net of two families and a real reshape of the hyperbolic paraboloid z = xy/5 and a real torsion-free base mesh (the
    /// perturbed helices on the cylinder of <see cref="BaseMeshTests"/>), with a fake clock that each solver iteration
    /// advances by a fixed time.
    /// </summary>
    [TestFixture]
    public class LiveStepperTests
    {
        /// <summary>The fake time one solver iteration takes, in ms.</summary>
        private const double IterationMs = 10;
        /// <summary>The live budget per solution, in ms, shared by the sessions running when it starts.</summary>
        private const double BudgetMs = 80;

        private Grid hypar;
        private int[] triangles;
        private double[] field;

        /// <summary>A fake clock in milliseconds: it moves only when a solver iteration runs.</summary>
        private sealed class FakeClock
        {
            public double Now;
            public double Read() => Now;

            /// <summary><paramref name="steps"/> with every iteration taking <see cref="IterationMs"/> on this clock.</summary>
            public Steppable<TReport> Timed<TReport>(Steppable<TReport> steps) =>
                new Steppable<TReport>(() => steps.Report, n =>
                {
                    TReport before = steps.Report, after = steps.Step(n);
                    Now += IterationMs * (steps.IterationsOf(after) - steps.IterationsOf(before));
                    return after;
                }, steps.IterationsOf, steps.IsConverged);
        }

        [TestFixtureSetUp]
        public void Surface()
        {
            // 14 × 14 cells over [−3, 3]²: 225 vertices lifted onto z = xy/5, whose asymptotic curves are its rulings.
            hypar = new Grid(14, 14, 6.0 / 14, -3, -3);
            for (int v = 0; v < hypar.VertexCount; v++) hypar.Xyz[3 * v + 2] = hypar.Xyz[3 * v] * hypar.Xyz[3 * v + 1] / 5.0;
            triangles = hypar.Triangles();
            field = hypar.Values((x, y) => x + 0.3 * y);
        }

        private string SignatureOf(params double[] inputs) => Conversion.Signature.Of(hypar.Xyz, triangles, inputs);

        /// <summary>
        /// What a component keeps across its solutions, as these tests drive it: a fake clock, the stepper on it, one
        /// iteration's net, reshape and base-mesh sessions, and a log of the sessions started.
        /// </summary>
        private sealed class Host : IDisposable
        {
            public readonly FakeClock Clock = new FakeClock();
            public readonly LiveStepper Stepper;
            public readonly List<string> Started = new List<string>();
            public readonly LiveSessions<SolverSession<NetSolver, NetReport>> Nets = new LiveSessions<SolverSession<NetSolver, NetReport>>();
            public readonly LiveSessions<SolverSession<ReshapeSolver, ReshapeReport>> Reshapes = new LiveSessions<SolverSession<ReshapeSolver, ReshapeReport>>();
            public readonly LiveSessions<SolverSession<BaseMeshRun, BaseMeshReport>> BaseMeshes = new LiveSessions<SolverSession<BaseMeshRun, BaseMeshReport>>();

            public Host()
            {
                Stepper = new LiveStepper(new LiveSolve(Clock.Read, BudgetMs, 10, 1000));
            }

            /// <summary>A solution starts; returns the sessions still running, which share the budget.</summary>
            public int BeginSolution()
            {
                Nets.BeginSolution();
                Reshapes.BeginSolution();
                BaseMeshes.BeginSolution();
                int running = Nets.RunningCount() + Reshapes.RunningCount() + BaseMeshes.RunningCount();
                Stepper.BeginSolution(running);
                return running;
            }

            /// <summary>The solution ends; returns the delay of the next one, or null: none scheduled.</summary>
            public int? EndSolution()
            {
                Nets.EndSolution();
                Reshapes.EndSolution();
                BaseMeshes.EndSolution();
                return Stepper.EndSolution();
            }

            public void Dispose()
            {
                Nets.Dispose();
                Reshapes.Dispose();
                BaseMeshes.Dispose();
            }
        }

        /// <summary>The held net session of the asymptotic net (θ 0° and 0°), or a new one from the default start, timed by the host's clock.</summary>
        private SolverSession<NetSolver, NetReport> Net(Host host) => host.Nets.Session(0, SignatureOf(0, 0, 30), false, () =>
        {
            host.Started.Add("net");
            using (var mesh = LamellaMesh.FromArrays(hypar.Xyz, triangles))
            {
                double[][] start = NetSolver.DefaultStart(mesh, 0, 0);
                var net = new NetSolver(mesh, 0, 0, start[0], start[1], 30);
                return new SolverSession<NetSolver, NetReport>(net, host.Clock.Timed(Steppable.Of(net)), SignatureOf(0, 0, 30));
            }
        });

        /// <summary>
        /// The held reshape session, or a new one, timed by the host's clock: the surface moved so that the levels of
        /// x + 0.3 y become P-curves of 80° (within 2 % of the diagonal).
        /// </summary>
        private SolverSession<ReshapeSolver, ReshapeReport> Reshape(Host host) => host.Reshapes.Session(0, SignatureOf(80, 2), false, () =>
        {
            host.Started.Add("reshape");
            using (var mesh = LamellaMesh.FromArrays(hypar.Xyz, triangles))
            {
                var reshape = new ReshapeSolver(mesh, field, 80, 0.02, true);
                return new SolverSession<ReshapeSolver, ReshapeReport>(reshape, host.Clock.Timed(Steppable.Of(reshape)), SignatureOf(80, 2));
            }
        });

        /// <summary>
        /// One live solution's stepping of a session that ran <paramref name="before"/> iterations, converged or not:
        /// within its share of the budget it runs exactly as many iterations as fit (each takes
        /// <see cref="IterationMs"/>) unless it converges first, and its count grows by what it ran.
        /// </summary>
        private static void CheckLiveStep<TReport>(LiveStep<TReport> step, long before, bool convergedBefore, double budgetMs, string what)
        {
            SteppingOutcome<TReport> outcome = step.Outcome;
            Assert.AreEqual(LiveMode.Stepped, step.Mode, what);
            Assert.AreEqual(before + outcome.Iterations, outcome.TotalIterations, what + ": the count grows by the iterations run");
            Assert.LessOrEqual(outcome.ElapsedMs, budgetMs, what + ": within its budget");
            Assert.AreEqual(IterationMs * outcome.Iterations, outcome.ElapsedMs, 1e-9, what);
            if (convergedBefore)
            {
                Assert.AreEqual(0, outcome.Iterations, what + ": a converged session is not stepped");
                Assert.AreEqual(SteppingStop.Converged, outcome.Stop, what);
            }
            else if (outcome.Stop == SteppingStop.TimeBudget)
            {
                Assert.AreEqual(Math.Floor(budgetMs / IterationMs), outcome.Iterations, what + ": as many iterations as fit");
                Assert.IsTrue(step.Continues, what);
            }
            else
            {
                Assert.AreEqual(SteppingStop.Converged, outcome.Stop, what + ": only convergence stops it early");
                Assert.Greater(outcome.Iterations, 0, what);
                Assert.LessOrEqual(outcome.Iterations, Math.Floor(budgetMs / IterationMs), what);
                Assert.IsFalse(step.Continues, what);
            }
        }

        /// <summary>
        /// Strip Net and Reshape Surface with Run on, one session each, solution after solution: every solution steps each
        /// unconverged session within its share of the 80 ms budget (the whole budget in the first solution, when no
        /// session ran yet; half while both run; the whole again for the one left), the iteration counts grow across
        /// solutions on the same sessions (each started once), the next solution is scheduled while one runs on, and not
        /// once both have converged.
        /// </summary>
        [Test]
        public void RunStepsANetAndAReshapeWithinTheBudgetUntilBothConverge()
        {
            using (var host = new Host())
            {
                SolverSession<NetSolver, NetReport> firstNet = null;
                SolverSession<ReshapeSolver, ReshapeReport> firstReshape = null;
                int solutions = 0, scheduled = 0;
                bool bothConverged = false;
                while (!bothConverged)
                {
                    Assert.Less(++solutions, 200, "converges in a bounded number of solutions");
                    double share = BudgetMs / Math.Max(1, host.BeginSolution());
                    var net = Net(host);
                    var reshape = Reshape(host);
                    if (firstNet == null)
                    {
                        firstNet = net;
                        firstReshape = reshape;
                    }
                    Assert.AreSame(firstNet, net, "the net session is kept across solutions");
                    Assert.AreSame(firstReshape, reshape, "the reshape session is kept across solutions");

                    NetReport netBefore = net.Report;
                    ReshapeReport reshapeBefore = reshape.Report;
                    LiveStep<NetReport> netStep = host.Stepper.Advance(net, true, false, 1000, () => false);
                    LiveStep<ReshapeReport> reshapeStep = host.Stepper.Advance(reshape, true, false, 1000, () => false);
                    CheckLiveStep(netStep, netBefore.Iterations, netBefore.IsConverged, share, "net, solution " + solutions);
                    CheckLiveStep(reshapeStep, reshapeBefore.Iterations, reshapeBefore.IsConverged, share, "reshape, solution " + solutions);
                    if (!netBefore.IsConverged) Assert.Greater(net.Report.Iterations, netBefore.Iterations, "the net's count grows");
                    if (!reshapeBefore.IsConverged) Assert.Greater(reshape.Report.Iterations, reshapeBefore.Iterations, "the reshape's count grows");

                    int? delay = host.EndSolution();
                    bothConverged = net.IsConverged && reshape.IsConverged;
                    Assert.AreEqual(!bothConverged, delay.HasValue, "the next solution is scheduled while a session runs on");
                    if (delay.HasValue)
                    {
                        scheduled++;
                        Assert.That(delay.Value, Is.InRange(10, 1000));
                    }
                }
                CollectionAssert.AreEqual(new[] { "net", "reshape" }, host.Started, "each session started once");
                Assert.Greater(solutions, 3, "the solve took several live solutions");
                Assert.AreEqual(solutions - 1, scheduled);
                Console.WriteLine("  live: net {0} and reshape {1} iterations in {2} solutions", firstNet.Report.Iterations, firstReshape.Report.Iterations, solutions);
                Assert.Less(firstReshape.Report.AngleErrorRmsDegrees, 1.0, "the reshape reached its θ");
                Assert.Less(firstNet.Report.AngleErrorRmsDegrees[0], 1.0, "the net reached its families");

                // Converged: a further solution (another input downstream changed) steps nothing and schedules nothing.
                Assert.AreEqual(0, host.BeginSolution());
                LiveStep<NetReport> idle = host.Stepper.Advance(Net(host), true, false, 1000, () => false);
                Assert.AreEqual(SteppingStop.Converged, idle.Outcome.Stop);
                Assert.AreEqual(0, idle.Outcome.Iterations);
                Assert.IsNull(host.EndSolution());
                Assert.AreEqual(2, host.Started.Count, "not started again");
            }
        }

        /// <summary>
        /// Escape during a live solve stops it at once (asked before every iteration) and stops scheduling; while Run stays
        /// on, later solutions do not step; Run switched off and on again steps on from where it stopped, an Escape pressed
        /// before that forgotten.
        /// </summary>
        [Test]
        public void EscapeStopsSteppingUntilRunIsSwitchedOffAndOn()
        {
            using (var host = new Host())
            {
                int asked = 0;
                bool pressed = false;
                Func<bool> escape = () => { asked++; bool was = pressed; pressed = false; return was; };
                Func<bool, LiveStep<ReshapeReport>> solution = run =>
                {
                    host.BeginSolution();
                    return host.Stepper.Advance(Reshape(host), run, false, 1000, escape);
                };

                LiveStep<ReshapeReport> step = solution(true);
                Assert.AreEqual(8, step.Outcome.Iterations, "Run steps: 8 iterations of 10 ms in 80 ms");
                Assert.AreEqual(1 + 8, asked, "escape: asked once when Run went on (to forget an earlier press), then before every iteration");
                Assert.IsNotNull(host.EndSolution());

                // Escape pressed during the next solution's third iteration check.
                int askedBefore = asked;
                escape = () => ++asked - askedBefore == 3;
                step = solution(true);
                Assert.AreEqual(SteppingStop.Cancelled, step.Outcome.Stop);
                Assert.AreEqual(2, step.Outcome.Iterations, "two iterations ran before the press was seen");
                Assert.AreEqual(10, step.Outcome.TotalIterations);
                Assert.IsTrue(host.Stepper.Cancelled);
                Assert.IsNull(host.EndSolution(), "no next solution after Escape");

                // Run still on (an upstream change re-solves): not stepped, not scheduled.
                escape = () => { asked++; return false; };
                askedBefore = asked;
                step = solution(true);
                Assert.AreEqual(LiveMode.Halted, step.Mode);
                Assert.AreEqual(10, step.Outcome.Report.Iterations);
                Assert.AreEqual(askedBefore, asked, "a halted session is not stepped");
                Assert.IsNull(host.EndSolution());

                // Run off: shown as it stands; then on again, with an Escape pressed while it was off.
                step = solution(false);
                Assert.AreEqual(LiveMode.Idle, step.Mode);
                Assert.IsFalse(host.Stepper.Cancelled, "switching Run off forgets the Escape");
                Assert.AreEqual(10, step.Outcome.Report.Iterations);
                Assert.IsNull(host.EndSolution());
                pressed = true;
                escape = () => { asked++; bool was = pressed; pressed = false; return was; };
                step = solution(true);
                Assert.AreEqual(LiveMode.Stepped, step.Mode);
                Assert.AreEqual(SteppingStop.TimeBudget, step.Outcome.Stop, "the earlier press was forgotten, not taken for a new one");
                Assert.AreEqual(18, step.Outcome.TotalIterations, "steps on from where it stopped");
                Assert.IsNotNull(host.EndSolution());
                CollectionAssert.AreEqual(new[] { "reshape" }, host.Started, "one session throughout");
            }
        }

        /// <summary>
        /// Solve converges within one solution and schedules nothing; Max Iterations stops a live net (not scheduled
        /// further); new inputs start a new session and release the old one.
        /// </summary>
        [Test]
        public void SolveConvergesAtOnceAndTheCapStopsALiveSolve()
        {
            using (var host = new Host())
            {
                host.BeginSolution();
                LiveStep<ReshapeReport> solved = host.Stepper.Advance(Reshape(host), false, true, 1000, () => false);
                Assert.AreEqual(LiveMode.Solved, solved.Mode);
                Assert.AreEqual(SteppingStop.Converged, solved.Outcome.Stop);
                Assert.IsTrue(solved.Outcome.Report.IsConverged);
                Assert.Greater(solved.Outcome.Iterations, 8, "more than one live budget's worth in one solution");

                var net = Net(host);
                LiveStep<NetReport> capped = host.Stepper.Advance(net, true, false, 5, () => false);
                Assert.AreEqual(SteppingStop.IterationCap, capped.Outcome.Stop);
                Assert.AreEqual(5, capped.Outcome.TotalIterations);
                Assert.IsFalse(capped.Outcome.Report.IsConverged);
                Assert.IsFalse(capped.Continues);
                Assert.IsNull(host.EndSolution(), "neither the solved nor the capped session asks for another solution");
                Assert.AreEqual(1, host.Nets.RunningCount(), "the capped net is not converged");

                // Another θ: a new session; the old one is released.
                host.BeginSolution();
                SolverSession<NetSolver, NetReport> other;
                using (var mesh = LamellaMesh.FromArrays(hypar.Xyz, triangles))
                {
                    other = host.Nets.Session(0, SignatureOf(90, 90, 30), false, () => SolverSession.Of(
                        new NetSolver(mesh, 90, 90, field, hypar.Values((x, y) => y - 0.3 * x), 30), SignatureOf(90, 90, 30)));
                }
                Assert.AreNotSame(net, other);
                Assert.Throws<ObjectDisposedException>(() => net.Solver.Step(1), "the replaced session's solver is released");
                Assert.AreEqual(0, other.Report.Iterations);
                Assert.IsNull(host.Nets.Held(0, SignatureOf(0, 0, 30)));
                Assert.AreSame(other, host.Nets.Held(0, SignatureOf(90, 90, 30)));
            }
        }

        /// <summary>
        /// Torsion-Free Net with Run on: the perturbed ±45° helices on the cylinder (<see cref="HelixNet"/>) optimised
        /// back to a geodesic net with torsion-free nodes (θ 90° both, Eq. 21), one session across solutions, each solution
        /// stepping it within the whole 80 ms budget; iterations grow solution by solution, the next solution is scheduled
        /// until it converges and not after. The nodes the session kept at its start are those of the net as given (the
        /// library's initial report says their largest ruling angle); after the solve every node's rulings are within
        /// 0.5° where they were up to 90° apart. Solve (one-shot, through <see cref="SolverSession.Of(BaseMeshRun, string)"/>)
        /// reaches the same net within one solution; a solver that has stepped cannot give its initial nodes any more.
        /// </summary>
        [Test]
        public void RunStepsATorsionFreeNetUntilItConvergesAndItsNodesUntwist()
        {
            var cylinder = new Cylinder(72, 40, 7);
            var helices = new HelixNet(0.02);
            string signature = Conversion.Signature.Of(helices.Points, new int[0], 90, 90, 1);
            using (var host = new Host())
            using (var reference = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                Func<BaseMeshSolver> start = () => new BaseMeshSolver(reference, helices.Points, helices.Rows, helices.Columns, 90, 90, true);
                Func<SolverSession<BaseMeshRun, BaseMeshReport>> session = () => host.BaseMeshes.Session(0, signature, false, () =>
                {
                    host.Started.Add("torsion-free net");
                    var run = new BaseMeshRun(start(), true);
                    return new SolverSession<BaseMeshRun, BaseMeshReport>(run, host.Clock.Timed(Steppable.Of(run.Solver)), signature);
                });

                SolverSession<BaseMeshRun, BaseMeshReport> live = null;
                var nodeAngleMax = new List<double>();
                int solutions = 0;
                bool converged = false;
                while (!converged)
                {
                    Assert.Less(++solutions, 100, "converges in a bounded number of solutions");
                    double share = BudgetMs / Math.Max(1, host.BeginSolution());
                    var current = session();
                    if (live == null) live = current;
                    Assert.AreSame(live, current, "the session is kept across solutions");
                    BaseMeshReport before = current.Report;
                    LiveStep<BaseMeshReport> step = host.Stepper.Advance(current, true, false, 300, () => false);
                    CheckLiveStep(step, before.Iterations, before.IsConverged, share, "torsion-free net, solution " + solutions);
                    Assert.AreEqual(BudgetMs, share, "one session: the whole budget");
                    if (!before.IsConverged) Assert.Greater(current.Report.Iterations, before.Iterations, "the count grows");
                    nodeAngleMax.Add(step.Outcome.Report.NodeRulingAngleMaxDegrees);
                    int? delay = host.EndSolution();
                    converged = current.IsConverged;
                    Assert.AreEqual(!converged, delay.HasValue, "the next solution is scheduled while it runs on");
                }
                CollectionAssert.AreEqual(new[] { "torsion-free net" }, host.Started, "started once");
                Assert.Greater(solutions, 3, "the solve took several live solutions");
                BaseMeshSolver solver = live.Solver.Solver;
                BaseMeshReport report = live.Report;
                Assert.IsTrue(report.FamiliesMet && report.IsTorsionFree, report.Describe());
                Console.WriteLine("  live torsion-free net: {0} iterations in {1} solutions; node ruling angle max per solution {2}", report.Iterations, solutions,
                    string.Join(", ", nodeAngleMax.Select(a => a.ToString("0.##", System.Globalization.CultureInfo.InvariantCulture))));

                // The node ruling angles before (kept at the start) and after, node by node.
                BaseMeshNode[] initial = live.Solver.InitialNodes, final = solver.Nodes();
                CollectionAssert.AreEqual(initial.Select(n => n.Vertex).ToArray(), final.Select(n => n.Vertex).ToArray(), "the same nodes");
                double[] anglesBefore = initial.Where(n => n.RulingAngleDegrees.HasValue).Select(n => n.RulingAngleDegrees.Value).ToArray();
                double[] anglesAfter = final.Where(n => n.RulingAngleDegrees.HasValue).Select(n => n.RulingAngleDegrees.Value).ToArray();
                Assert.AreEqual(solver.InitialReport.NodeCount, anglesBefore.Length);
                Assert.AreEqual(solver.InitialReport.NodeRulingAngleMaxDegrees, anglesBefore.Max(), 1e-9, "the kept nodes are the net's as given");
                Assert.AreEqual(report.NodeRulingAngleMaxDegrees, anglesAfter.Max(), 1e-9);
                Assert.Greater(anglesBefore.Max(), 10.0, "the perturbed net's strips meet at its nodes far apart");
                Assert.LessOrEqual(anglesAfter.Max(), 0.5, "torsion-free after");
                Assert.Less(Rms(anglesAfter), Rms(anglesBefore) / 100, "the node angles fall by two orders of magnitude");
                for (int i = 0; i < initial.Length; i++)
                {
                    if (!initial[i].RulingAngleDegrees.HasValue || !final[i].RulingAngleDegrees.HasValue) continue;
                    Assert.LessOrEqual(final[i].RulingAngleDegrees.Value, Math.Max(initial[i].RulingAngleDegrees.Value, 0.5), "node at vertex " + initial[i].Vertex);
                }
                Assert.Less(nodeAngleMax.Last(), nodeAngleMax.First(), "the live iterates show the nodes untwisting");

                // Solve: the same optimisation to convergence within one solution, nothing scheduled.
                host.BeginSolution();
                var oneShot = host.BaseMeshes.Session(1, signature, false, () => SolverSession.Of(new BaseMeshRun(start(), false), signature));
                LiveStep<BaseMeshReport> solved = host.Stepper.Advance(oneShot, false, true, 300, () => false);
                Assert.AreEqual(LiveMode.Solved, solved.Mode);
                Assert.AreEqual(SteppingStop.Converged, solved.Outcome.Stop);
                Assert.AreEqual(report.Iterations, solved.Outcome.Iterations, "as many iterations as the live solve");
                Assert.IsNull(oneShot.Solver.InitialNodes, "not asked for");
                CollectionAssert.AreEqual(solver.Positions(), oneShot.Solver.Solver.Positions(), "the same net");
                Assert.IsNull(host.EndSolution());

                // A stepped solver's nodes are no longer the net's as given; the run refuses it and releases it.
                BaseMeshSolver stepped = start();
                stepped.Step(1);
                Assert.Throws<InvalidOperationException>(() => new BaseMeshRun(stepped, true));
                Assert.Throws<ObjectDisposedException>(() => stepped.Step(1), "released");
            }
        }

        private static double Rms(double[] values) => Math.Sqrt(values.Sum(v => v * v) / values.Length);
    }
}
