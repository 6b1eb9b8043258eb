using System;
using System.Diagnostics;

namespace Lamella.Hosting
{
    /// <summary>Why <see cref="FieldStepping"/> stopped stepping a field.</summary>
    public enum SteppingStop
    {
        /// <summary>The field has converged: further steps do nothing.</summary>
        Converged,
        /// <summary>The time budget is used up (live solving: the next solution continues).</summary>
        TimeBudget,
        /// <summary>The session ran its maximum number of iterations without converging.</summary>
        IterationCap,
        /// <summary>The host asked to stop (Escape).</summary>
        Cancelled,
    }

    /// <summary>What one call of <see cref="FieldStepping"/> did, with the solver's report type.</summary>
    public struct SteppingOutcome<TReport>
    {
        /// <summary>The solver's state afterwards.</summary>
        public TReport Report;
        /// <summary>Iterations run by this call.</summary>
        public long Iterations;
        /// <summary>Iterations the session has run in all afterwards: what the iteration cap counts.</summary>
        public long TotalIterations;
        /// <summary>Why it stopped.</summary>
        public SteppingStop Stop;
        /// <summary>Time spent, in milliseconds (by the clock given).</summary>
        public double ElapsedMs;
    }

    /// <summary>
    /// A solver as <see cref="FieldStepping"/> steps it: its state, a step of at most n iterations, and what a state says
    /// (iterations run in all, converged). <see cref="Steppable"/> makes one of each Lamella solver.
    /// </summary>
    public sealed class Steppable<TReport>
    {
        private readonly Func<TReport> report;
        private readonly Func<int, TReport> step;
        private readonly Func<TReport, long> iterations;
        private readonly Func<TReport, bool> converged;

        /// <summary>A solver read by <paramref name="report"/>, stepped by <paramref name="step"/>; <paramref name="iterations"/> and <paramref name="converged"/> read a state.</summary>
        public Steppable(Func<TReport> report, Func<int, TReport> step, Func<TReport, long> iterations, Func<TReport, bool> converged)
        {
            if (report == null) throw new ArgumentNullException(nameof(report));
            if (step == null) throw new ArgumentNullException(nameof(step));
            if (iterations == null) throw new ArgumentNullException(nameof(iterations));
            if (converged == null) throw new ArgumentNullException(nameof(converged));
            this.report = report;
            this.step = step;
            this.iterations = iterations;
            this.converged = converged;
        }

        /// <summary>The state now.</summary>
        public TReport Report => report();

        /// <summary>Runs at most <paramref name="maxIterations"/> iterations; returns the state.</summary>
        public TReport Step(int maxIterations) => step(maxIterations);

        /// <summary>The iterations <paramref name="state"/> says the session has run in all.</summary>
        public long IterationsOf(TReport state) => iterations(state);

        /// <summary>Whether <paramref name="state"/> is converged (further steps do nothing).</summary>
        public bool IsConverged(TReport state) => converged(state);
    }

    /// <summary>The <see cref="Steppable{TReport}"/> of each Lamella solver: a field, a net or 3-web, a reshape, a base mesh.</summary>
    public static class Steppable
    {
        /// <summary>A field session.</summary>
        public static Steppable<FieldReport> Of(FieldSolver solver)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            return new Steppable<FieldReport>(() => solver.Report, solver.Step, r => (long)r.Iterations, r => r.IsConverged);
        }

        /// <summary>A net of two families or a 3-web.</summary>
        public static Steppable<NetReport> Of(NetSolver solver)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            return new Steppable<NetReport>(() => solver.Report, solver.Step, r => r.Iterations, r => r.IsConverged);
        }

        /// <summary>A surface reshape.</summary>
        public static Steppable<ReshapeReport> Of(ReshapeSolver solver)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            return new Steppable<ReshapeReport>(() => solver.Report, solver.Step, r => r.Iterations, r => r.IsConverged);
        }

        /// <summary>A base-mesh optimisation: a net of rows and columns (torsion-free or not) or a 3-web.</summary>
        public static Steppable<BaseMeshReport> Of(BaseMeshSolver solver)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            return new Steppable<BaseMeshReport>(() => solver.Report, solver.Step, r => r.Iterations, r => r.IsConverged);
        }
    }

    /// <summary>
    /// Steps a solver session (a field, a net or 3-web, a reshape, a base mesh: <see cref="Steppable"/>) the way an interactive host needs: one iteration at a time within a time budget (a live
    /// solve that keeps the canvas responsive, whatever the mesh size), or to convergence within one call (a one-shot
    /// solve for Hops, Rhino.Compute or an optimiser such as Galapagos), both with an iteration cap and a cancel check
    /// before every iteration.
    /// </summary>
    public static class FieldStepping
    {
        /// <summary>A clock in milliseconds from a <see cref="Stopwatch"/>.</summary>
        public static Func<double> StopwatchClock()
        {
            Stopwatch watch = Stopwatch.StartNew();
            return () => watch.Elapsed.TotalMilliseconds;
        }

        /// <summary>
        /// Steps <paramref name="solver"/> one iteration at a time until it converges, its session has run
        /// <paramref name="iterationCap"/> iterations in all, <paramref name="cancelRequested"/> returns true (asked before
        /// every iteration), or another iteration as long as the last one would end past <paramref name="budgetMs"/>
        /// (measured with <paramref name="clockMs"/>). The first iteration always runs (when not converged, capped or
        /// cancelled), so a mesh whose single iteration outlasts the budget still advances. A numerical failure throws
        /// the binding's <see cref="LamellaException"/>; the session keeps its last good state.
        /// </summary>
        public static SteppingOutcome<TReport> StepWithin<TReport>(Steppable<TReport> solver, double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            CheckArguments(budgetMs, iterationCap, cancelRequested, clockMs);
            double start = clockMs(), last = start;
            TReport report = solver.Report;
            long before = solver.IterationsOf(report);
            var outcome = new SteppingOutcome<TReport> { Report = report, TotalIterations = before };
            while (true)
            {
                if (solver.IsConverged(outcome.Report))
                {
                    outcome.Stop = SteppingStop.Converged;
                    break;
                }
                if (outcome.TotalIterations >= iterationCap)
                {
                    outcome.Stop = SteppingStop.IterationCap;
                    break;
                }
                if (outcome.Iterations > 0)
                {
                    double now = clockMs(), lastStep = now - last;
                    if (now - start + lastStep > budgetMs)
                    {
                        outcome.Stop = SteppingStop.TimeBudget;
                        break;
                    }
                    last = now;
                }
                if (cancelRequested())
                {
                    outcome.Stop = SteppingStop.Cancelled;
                    break;
                }
                outcome.Report = solver.Step(1);
                outcome.TotalIterations = solver.IterationsOf(outcome.Report);
                outcome.Iterations = outcome.TotalIterations - before;
            }
            outcome.ElapsedMs = clockMs() - start;
            return outcome;
        }

        /// <summary>A field session's <see cref="StepWithin{TReport}"/>.</summary>
        public static SteppingOutcome<FieldReport> StepWithin(FieldSolver solver, double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs) =>
            StepWithin(Steppable.Of(solver), budgetMs, iterationCap, cancelRequested, clockMs);

        /// <summary>The argument checks of <see cref="StepWithin"/>, shared with the hosts that step a start search first.</summary>
        internal static void CheckArguments(double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs)
        {
            if (cancelRequested == null) throw new ArgumentNullException(nameof(cancelRequested));
            if (clockMs == null) throw new ArgumentNullException(nameof(clockMs));
            if (!(budgetMs > 0)) throw new ArgumentOutOfRangeException(nameof(budgetMs), "the time budget must be > 0 ms");
            if (iterationCap < 0) throw new ArgumentOutOfRangeException(nameof(iterationCap));
        }

        /// <summary>
        /// Steps <paramref name="solver"/> until it converges, within this call: the one-shot solve. Stops early at the
        /// iteration cap (<see cref="SteppingStop.IterationCap"/>: not converged) or when <paramref name="cancelRequested"/>
        /// returns true.
        /// </summary>
        public static SteppingOutcome<TReport> ToConvergence<TReport>(Steppable<TReport> solver, long iterationCap, Func<bool> cancelRequested) =>
            StepWithin(solver, double.PositiveInfinity, iterationCap, cancelRequested, StopwatchClock());

        /// <summary>A field session's <see cref="ToConvergence{TReport}"/>.</summary>
        public static SteppingOutcome<FieldReport> ToConvergence(FieldSolver solver, long iterationCap, Func<bool> cancelRequested) =>
            ToConvergence(Steppable.Of(solver), iterationCap, cancelRequested);
    }
}
