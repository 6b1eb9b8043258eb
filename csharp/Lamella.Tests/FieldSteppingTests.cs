using System;
using Lamella.Hosting;
using NUnit.Framework;

namespace Lamella.Tests
{
    /// <summary>Stepping a real field the way an interactive host does: within a time budget, to convergence, capped, cancellable.</summary>
    [TestFixture]
    public class FieldSteppingTests
    {
        private Cylinder cylinder;

        [TestFixtureSetUp]
        public void Surface() => cylinder = new Cylinder(20, 12, 7);

        private FieldSolver NewField()
        {
            using (var mesh = LamellaMesh.FromArrays(cylinder.Xyz, cylinder.Triangles))
            {
                return new FieldSolver(mesh, cylinder.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60));
            }
        }

        /// <summary>A clock that advances by <paramref name="step"/> ms each time it is read (a fixed cost per iteration).</summary>
        internal static Func<double> TickingClock(double step)
        {
            double now = 0;
            return () => now += step;
        }

        [Test]
        public void BudgetStopsBeforeAnIterationWouldOverrun()
        {
            using (FieldSolver field = NewField())
            {
                // Each iteration "takes" 40 ms: after two (80 ms) a third would end at 120 > 100.
                SteppingOutcome<FieldReport> outcome = FieldStepping.StepWithin(field, 100, 1000, () => false, TickingClock(40));
                Assert.AreEqual(SteppingStop.TimeBudget, outcome.Stop);
                Assert.AreEqual(2, outcome.Iterations);
                Assert.AreEqual(2UL, field.Report.Iterations);
                // A budget shorter than one iteration still makes progress.
                outcome = FieldStepping.StepWithin(field, 1, 1000, () => false, TickingClock(40));
                Assert.AreEqual(1, outcome.Iterations);
                Assert.AreEqual(3UL, outcome.Report.Iterations);
            }
        }

        [Test]
        public void RealClockBudgetIsKept()
        {
            // A finer cylinder (2,257 vertices) whose solve takes far longer than the budget.
            var fine = new Cylinder(60, 36, 11);
            using (var mesh = LamellaMesh.FromArrays(fine.Xyz, fine.Triangles))
            using (var field = new FieldSolver(mesh, fine.InitialField, FieldParams.Default(Family.PseudoGeodesic, 60)))
            {
                field.Step(1);
                var watch = System.Diagnostics.Stopwatch.StartNew();
                FieldReport single = field.Step(1);
                double oneIteration = watch.Elapsed.TotalMilliseconds;
                Assert.AreEqual(2UL, single.Iterations);
                double budget = Math.Max(30, 4 * oneIteration);
                SteppingOutcome<FieldReport> outcome = FieldStepping.StepWithin(field, budget, 1000, () => false, FieldStepping.StopwatchClock());
                Console.WriteLine("  one iteration {0:0.0} ms; budget {1:0} ms: {2} iterations in {3:0.0} ms", oneIteration, budget, outcome.Iterations, outcome.ElapsedMs);
                Assert.AreEqual(SteppingStop.TimeBudget, outcome.Stop);
                Assert.GreaterOrEqual(outcome.Iterations, 2);
                // Predictive: it stops when the next iteration would overrun, so it ends within the budget plus one
                // iteration's variation, far below the next budget (a fixed count would not care).
                Assert.Less(outcome.ElapsedMs, budget + 2 * oneIteration + 20);
            }
        }

        [Test]
        public void CancelIsAskedBeforeEveryIteration()
        {
            using (FieldSolver field = NewField())
            {
                int asked = 0;
                SteppingOutcome<FieldReport> outcome = FieldStepping.StepWithin(field, double.PositiveInfinity, 1000, () => ++asked > 3, FieldStepping.StopwatchClock());
                Assert.AreEqual(SteppingStop.Cancelled, outcome.Stop);
                Assert.AreEqual(3, outcome.Iterations);
                Assert.AreEqual(4, asked);
            }
        }

        [Test]
        public void CapStopsAnUnconvergedField()
        {
            using (FieldSolver field = NewField())
            {
                SteppingOutcome<FieldReport> outcome = FieldStepping.ToConvergence(field, 5, () => false);
                Assert.AreEqual(SteppingStop.IterationCap, outcome.Stop);
                Assert.AreEqual(5UL, outcome.Report.Iterations);
                Assert.IsFalse(outcome.Report.IsConverged);
                Assert.AreEqual(0, FieldStepping.ToConvergence(field, 5, () => false).Iterations, "the cap counts the session's iterations");
            }
        }

        [Test]
        public void OneShotSolveConvergesInOneCall()
        {
            using (FieldSolver field = NewField())
            {
                Assert.Greater(field.Report.AngleErrorMaxDegrees, 5.0, "the start is not the answer");
                SteppingOutcome<FieldReport> outcome = FieldStepping.ToConvergence(field, 300, () => false);
                Console.WriteLine("  one-shot: {0} iterations, {1:0} ms, {2}", outcome.Iterations, outcome.ElapsedMs, outcome.Report);
                Assert.AreEqual(SteppingStop.Converged, outcome.Stop);
                Assert.IsTrue(outcome.Report.IsConverged);
                Assert.AreEqual((long)outcome.Report.Iterations, outcome.Iterations);
                Assert.LessOrEqual(outcome.Report.AngleErrorMaxDegrees, 0.5);
                Assert.AreEqual(0, FieldStepping.ToConvergence(field, 300, () => false).Iterations, "a converged field is not stepped");
            }
        }

        [Test]
        public void BadArgumentsAreRejected()
        {
            using (FieldSolver field = NewField())
            {
                Assert.Throws<ArgumentOutOfRangeException>(() => FieldStepping.StepWithin(field, 0, 10, () => false, () => 0));
                Assert.Throws<ArgumentOutOfRangeException>(() => FieldStepping.StepWithin(field, 10, -1, () => false, () => 0));
                Assert.Throws<ArgumentNullException>(() => FieldStepping.StepWithin(null, 10, 10, () => false, () => 0));
            }
        }
    }
}
