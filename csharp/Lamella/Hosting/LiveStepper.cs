using System;

namespace Lamella.Hosting
{
    /// <summary>What a live host did with a session in one solution (see <see cref="LiveStepper.Advance{TReport}"/>).</summary>
    public enum LiveMode
    {
        /// <summary>Neither Run nor Solve: not stepped; the host shows the session as it stands.</summary>
        Idle,
        /// <summary>Run is on but Escape stopped it: not stepped until Run is switched off and on.</summary>
        Halted,
        /// <summary>Run: stepped within this solution's share of the live budget.</summary>
        Stepped,
        /// <summary>Solve: stepped to convergence (or the iteration cap, or Escape) within this solution.</summary>
        Solved,
    }

    /// <summary>How <see cref="LiveStepper.Advance{TReport}"/> advanced one session.</summary>
    public struct LiveStep<TReport>
    {
        /// <summary>What was done.</summary>
        public LiveMode Mode;
        /// <summary>
        /// What the stepping did (<see cref="LiveMode.Stepped"/>, <see cref="LiveMode.Solved"/>); for
        /// <see cref="LiveMode.Idle"/> and <see cref="LiveMode.Halted"/>, where no iteration ran, the session's state with
        /// <see cref="SteppingStop.Converged"/> when it is, else <see cref="SteppingStop.Cancelled"/> (not stepped), and no
        /// iteration count.
        /// </summary>
        public SteppingOutcome<TReport> Outcome;

        /// <summary>
        /// True when the session was stepped within its budget and runs on: the host schedules another solution (see
        /// <see cref="LiveStepper.EndSolution"/>) and may show the current iterate only, leaving what is slow to build
        /// until it converges or stops.
        /// </summary>
        public bool Continues => Mode == LiveMode.Stepped && Outcome.Stop == SteppingStop.TimeBudget;
    }

    /// <summary>
    /// The live and one-shot solving of a host component (Grasshopper) without the host: per solution, each session is
    /// stepped as the component's Run and Solve inputs ask. Run steps it within the solution's share of the live budget
    /// (<see cref="LiveSolve"/>: the budget is shared by the sessions running when the solution started) and, while any
    /// session runs on, <see cref="EndSolution"/> gives the delay to schedule the next solution after; Solve steps it to
    /// convergence within the solution (for Hops, Rhino.Compute and optimisers). An Escape (the host's cancel check, asked
    /// before every iteration) stops stepping and scheduling until Run is switched off and on. One per component; any
    /// session type (a field, a net or 3-web, a reshape, a base mesh: <see cref="ISteppedSession{TReport}"/>).
    /// </summary>
    public sealed class LiveStepper
    {
        private readonly LiveSolve pace;
        private int runningAtStart;
        private bool continues;

        /// <summary>Steps at <paramref name="pace"/>, timed by its clock.</summary>
        public LiveStepper(LiveSolve pace)
        {
            if (pace == null) throw new ArgumentNullException(nameof(pace));
            this.pace = pace;
        }

        /// <summary>The pace: budget, delays, cancel.</summary>
        public LiveSolve Pace => pace;

        /// <summary>True after an Escape until Run is switched off: no stepping with Run, no scheduling.</summary>
        public bool Cancelled => pace.Cancelled;

        /// <summary>A solution starts with <paramref name="runningSessions"/> sessions not converged (they share the budget).</summary>
        public void BeginSolution(int runningSessions)
        {
            if (runningSessions < 0) throw new ArgumentOutOfRangeException(nameof(runningSessions));
            pace.SolutionStarted();
            runningAtStart = runningSessions;
            continues = false;
        }

        /// <summary>
        /// The Run input of an iteration, also one without a session: off forgets an Escape (a later Run steps again);
        /// switched on, <paramref name="escape"/> is asked once to forget a press made before (Grasshopper's check reports
        /// any press since it was last asked).
        /// </summary>
        public void RunInput(bool run, Func<bool> escape)
        {
            if (escape == null) throw new ArgumentNullException(nameof(escape));
            if (!run) pace.RunSwitchedOff();
            else if (pace.RunSwitchedOn()) escape();
        }

        /// <summary>
        /// Steps <paramref name="session"/> as the inputs ask (after <see cref="RunInput"/>): with
        /// <paramref name="solveNow"/> to convergence, with <paramref name="run"/> (unless an Escape stopped it) within this
        /// solution's share of the budget, else not at all. Both stop at <paramref name="iterationCap"/> iterations in all
        /// and when <paramref name="escape"/> returns true (asked before every iteration), which also stops live stepping and
        /// scheduling until Run is switched off and on.
        /// </summary>
        public LiveStep<TReport> Advance<TReport>(ISteppedSession<TReport> session, bool run, bool solveNow, long iterationCap, Func<bool> escape)
        {
            if (session == null) throw new ArgumentNullException(nameof(session));
            RunInput(run, escape);
            var step = new LiveStep<TReport>();
            if (solveNow)
            {
                step.Mode = LiveMode.Solved;
                step.Outcome = session.StepWithin(double.PositiveInfinity, iterationCap, escape, pace.ClockMs);
            }
            else if (run && !pace.Cancelled)
            {
                step.Mode = LiveMode.Stepped;
                step.Outcome = session.StepWithin(pace.BudgetPerSession(runningAtStart), iterationCap, escape, pace.ClockMs);
                if (step.Continues) continues = true;
            }
            else
            {
                step.Mode = run ? LiveMode.Halted : LiveMode.Idle;
                step.Outcome = new SteppingOutcome<TReport> { Report = session.Report, Stop = session.IsConverged ? SteppingStop.Converged : SteppingStop.Cancelled };
                return step;
            }
            if (step.Outcome.Stop == SteppingStop.Cancelled) pace.Cancel();
            return step;
        }

        /// <summary>
        /// The solution ended: the delay in milliseconds to schedule the next solution after when a session stepped in it
        /// runs on and no Escape stopped it (the pace records it), else null: nothing to schedule.
        /// </summary>
        public int? EndSolution() => continues && !pace.Cancelled ? pace.NextDelayMs() : (int?)null;
    }
}
