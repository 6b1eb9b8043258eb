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

    /// <summary>What one call of <see cref="FieldStepping"/> did.</summary>
    public struct SteppingOutcome
    {
        /// <summary>The field's state afterwards.</summary>
        public FieldReport Report;
        /// <summary>Iterations run by this call.</summary>
        public long Iterations;
        /// <summary>Why it stopped.</summary>
        public SteppingStop Stop;
        /// <summary>Time spent, in milliseconds (by the clock given).</summary>
        public double ElapsedMs;
    }

    /// <summary>
    /// Steps a field session the way an interactive host needs: one iteration at a time within a time budget (a live
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
        public static SteppingOutcome StepWithin(FieldSolver solver, double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            CheckArguments(budgetMs, iterationCap, cancelRequested, clockMs);
            double start = clockMs(), last = start;
            var outcome = new SteppingOutcome { Report = solver.Report };
            while (true)
            {
                if (outcome.Report.IsConverged)
                {
                    outcome.Stop = SteppingStop.Converged;
                    break;
                }
                if ((long)outcome.Report.Iterations >= iterationCap)
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
                outcome.Iterations += (long)outcome.Report.IterationsThisStep;
            }
            outcome.ElapsedMs = clockMs() - start;
            return outcome;
        }

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
        public static SteppingOutcome ToConvergence(FieldSolver solver, long iterationCap, Func<bool> cancelRequested) =>
            StepWithin(solver, double.PositiveInfinity, iterationCap, cancelRequested, StopwatchClock());
    }
}
