using System;

namespace Lamella.Hosting
{
    /// <summary>
    /// The pace of a live solve in a host that recomputes everything downstream after each step (Grasshopper): a time
    /// budget per solution for the solver, shared by the sessions still running, and a delay before the next solution
    /// as long as the last cycle kept the host busy, so that the canvas stays responsive at least half of the time
    /// however slow the downstream components are. Also remembers a cancel (Escape) until the designer switches Run
    /// off. All times in milliseconds of the clock given.
    /// </summary>
    public sealed class LiveSolve
    {
        /// <summary>Solver time per solution while running (≈ 50–100 ms keeps a canvas fluid).</summary>
        public const double DefaultBudgetMs = 80;
        /// <summary>The shortest delay before the next solution.</summary>
        public const double DefaultMinDelayMs = 10;
        /// <summary>The longest delay before the next solution.</summary>
        public const double DefaultMaxDelayMs = 1000;

        private readonly Func<double> clockMs;
        private readonly double minDelayMs, maxDelayMs;
        private double lastStart = double.NaN, lastDelay;
        private double busyMs = double.NaN;
        private bool running;

        /// <summary>A pace with the given solver budget and delay bounds, timed by <paramref name="clockMs"/>.</summary>
        public LiveSolve(Func<double> clockMs, double budgetMs = DefaultBudgetMs, double minDelayMs = DefaultMinDelayMs, double maxDelayMs = DefaultMaxDelayMs)
        {
            if (clockMs == null) throw new ArgumentNullException(nameof(clockMs));
            if (!(budgetMs > 0) || !(minDelayMs >= 1) || !(maxDelayMs >= minDelayMs)) throw new ArgumentOutOfRangeException(nameof(budgetMs), "need budget > 0 and 1 ≤ min delay ≤ max delay");
            this.clockMs = clockMs;
            BudgetMs = budgetMs;
            this.minDelayMs = minDelayMs;
            this.maxDelayMs = maxDelayMs;
        }

        /// <summary>Solver time per solution, shared by the running sessions.</summary>
        public double BudgetMs { get; }

        /// <summary>The clock the pace is timed by, in milliseconds (also the one to time the stepping by).</summary>
        public Func<double> ClockMs => clockMs;

        /// <summary>True after <see cref="Cancel"/> until <see cref="RunSwitchedOff"/>: no stepping, no scheduling.</summary>
        public bool Cancelled { get; private set; }

        /// <summary>How long the last complete cycle kept the host busy (NaN before two solutions).</summary>
        public double LastBusyMs => busyMs;

        /// <summary>
        /// A solution starts (BeforeSolveInstance). The time since the previous start, less the delay the previous
        /// solution was scheduled with, is how long that cycle kept the host busy (solver, downstream, redraw).
        /// </summary>
        public void SolutionStarted()
        {
            double now = clockMs();
            if (!double.IsNaN(lastStart)) busyMs = Math.Max(0, now - lastStart - lastDelay);
            lastStart = now;
            lastDelay = 0;
        }

        /// <summary>The solver budget of one of <paramref name="runningSessions"/> sessions stepped in this solution.</summary>
        public double BudgetPerSession(int runningSessions) => BudgetMs / Math.Max(1, runningSessions);

        /// <summary>The delay to schedule the next solution with: the last busy time, within the bounds; recorded for the next cycle.</summary>
        public int NextDelayMs()
        {
            double delay = double.IsNaN(busyMs) ? minDelayMs : Math.Min(maxDelayMs, Math.Max(minDelayMs, busyMs));
            lastDelay = Math.Round(delay);
            return (int)lastDelay;
        }

        /// <summary>The designer pressed Escape: stop stepping and scheduling until Run goes off and on again.</summary>
        public void Cancel() => Cancelled = true;

        /// <summary>Run is off: a later Run starts stepping again.</summary>
        public void RunSwitchedOff()
        {
            Cancelled = false;
            running = false;
        }

        /// <summary>
        /// Run is on: true the first time after it was off (or ever), when a host should forget an Escape pressed before
        /// (Grasshopper's escape check reports any press since it was last asked).
        /// </summary>
        public bool RunSwitchedOn()
        {
            bool starting = !running;
            running = true;
            return starting;
        }
    }
}
