using System;
using System.Globalization;
using GH_IO.Serialization;
using Grasshopper.Kernel;
using Lamella.Hosting;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// A component that solves live and one-shot (Strip Field, Strip Net, Strip Web, Reshape Surface, and through
    /// <see cref="BaseMeshComponent"/> Optimise Net, Torsion-Free Net and Optimise Web): one solver session
    /// per iteration (list item or tree branch) kept across solutions in <see cref="Sessions"/> and started again when its
    /// own inputs change; a Run input that steps every unconverged session within a time budget shared per solution and
    /// schedules the next solution after a delay as long as the last cycle kept Grasshopper busy; a Solve input that
    /// solves within the solution; Escape stops either until Run is switched off and on. The logic without Grasshopper
    /// is <see cref="LiveStepper"/>; this class adds the messages and the scheduling.
    /// </summary>
    public abstract class LiveComponent : LamellaComponent
    {
        private readonly LiveStepper stepper = new LiveStepper(new LiveSolve(FieldStepping.StopwatchClock()));
        /// <summary>Whether the running iteration holds a session (an error after that keeps it, so a live solve goes on).</summary>
        private bool holding;

        protected LiveComponent(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, iconName)
        {
        }

        /// <summary>The component's sessions, one per iteration, kept across solutions.</summary>
        protected abstract ILiveSessions Sessions { get; }

        /// <summary>What the component keeps in its document (its sessions, whole), or null for nothing.</summary>
        protected virtual IDocumentState DocumentState => null;

        public override bool Write(GH_IWriter writer)
        {
            DocumentState?.Write(writer);
            return base.Write(writer);
        }

        public override bool Read(GH_IReader reader)
        {
            DocumentState?.Read(reader);
            return base.Read(reader);
        }

        /// <summary>
        /// The description of a Run input: each solution steps <paramref name="what"/> for about the live budget;
        /// <paramref name="shows"/> says what the outputs show meanwhile (empty, or starting with "; ").
        /// </summary>
        protected static string RunDescription(string what, string shows) =>
            "True solves live: each solution steps " + what + " for about " + LiveSolve.DefaultBudgetMs.ToString(CultureInfo.InvariantCulture) +
            " ms and schedules the next, until converged" + shows + "; Escape stops (switch Run off and on to continue). Default false.";

        /// <summary>The description of a Solve input: solves <paramref name="what"/> to convergence within the solution.</summary>
        protected static string SolveDescription(string what) =>
            "True solves " + what + " to convergence within this solution (one-shot, for Hops, Rhino.Compute and optimisers; Escape cancels). Default false.";

        protected override void BeginSolution()
        {
            base.BeginSolution();
            // The message speaks of this solution's sessions (an iteration without one leaves none).
            Message = null;
            Sessions.BeginSolution();
            stepper.BeginSolution(Sessions.RunningCount());
        }

        protected override void EndSolution()
        {
            base.EndSolution();
            // Sessions of iterations this solution did not reach belong to inputs that are gone.
            Sessions.EndSolution();
            DocumentState?.EndSolution();
            int? delay = stepper.EndSolution();
            if (delay.HasValue) OnPingDocument()?.ScheduleSolution(delay.Value, new GH_Document.GH_ScheduleDelegate(ExpireForNextStep));
        }

        private void ExpireForNextStep(GH_Document document) => ExpireSolution(false);

        protected override void ReleaseNative()
        {
            base.ReleaseNative();
            Sessions.Clear();
        }

        protected sealed override void Solve(IGH_DataAccess DA)
        {
            holding = false;
            try
            {
                SolveLive(DA);
            }
            finally
            {
                // An iteration without a session (missing or bad inputs, a failed start) releases the one it held.
                if (!holding) Sessions.Skip(DA.Iteration);
            }
        }

        /// <summary>The component's work for one iteration; it calls <see cref="Hold"/> once it holds its session.</summary>
        protected abstract void SolveLive(IGH_DataAccess DA);

        /// <summary>This iteration holds <paramref name="session"/> (null: none), which stays after a later error; returns it.</summary>
        protected T Hold<T>(T session) where T : class, ILiveSession
        {
            holding = session != null;
            return session;
        }

        /// <summary>
        /// The held session of this iteration for inputs with <paramref name="signature"/> in <paramref name="sessions"/>, or
        /// one from <paramref name="start"/> when Run or Solve is on. With neither, only a session these inputs already
        /// have is returned (shown as it stands, with a remark if not converged), else null with a remark that Run or
        /// Solve does <paramref name="work"/>.
        /// </summary>
        protected T LiveSession<T>(IGH_DataAccess DA, LiveSessions<T> sessions, string signature, bool run, bool solveNow, string work, Func<T> start)
            where T : class, ILiveSession
        {
            stepper.RunInput(run, GH_Document.IsEscapeKeyDown);
            T session = run || solveNow ? sessions.Session(DA.Iteration, signature, false, start) : sessions.Held(DA.Iteration, signature);
            if (session == null) AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "set Run (live) or Solve (one-shot) to true to " + work);
            else if (!run && !solveNow && !session.IsConverged) AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "not converged: set Run (live) or Solve (one-shot) to true to continue");
            return Hold(session);
        }

        /// <summary>What the iteration cap warning suggests after "(Max Iterations); ".</summary>
        protected virtual string NotConvergedHint => "raise it";

        /// <summary>
        /// Steps <paramref name="session"/> as Run and Solve ask (see <see cref="LiveStepper.Advance{TReport}"/>) and says
        /// in messages what happened: solved, stopped by Escape, not converged at <paramref name="maxIterations"/>.
        /// </summary>
        protected LiveStep<TReport> Advance<TReport>(ISteppedSession<TReport> session, bool run, bool solveNow, int maxIterations)
        {
            LiveStep<TReport> step = stepper.Advance(session, run, solveNow, maxIterations, GH_Document.IsEscapeKeyDown);
            SteppingOutcome<TReport> outcome = step.Outcome;
            if (step.Mode == LiveMode.Idle) return step;
            if (step.Mode == LiveMode.Halted)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "stopped by Escape: switch Run off and on to continue");
                return step;
            }
            if (step.Mode == LiveMode.Solved && outcome.Stop == SteppingStop.Converged && outcome.Iterations > 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                    "solved in {0} iterations, {1:0} ms", outcome.Iterations, outcome.ElapsedMs));
            }
            if (outcome.Stop == SteppingStop.Cancelled)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "stopped by Escape: switch Run (or Solve) off and on to continue");
            }
            else if (outcome.Stop == SteppingStop.IterationCap)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture,
                    "not converged after {0} iterations (Max Iterations); {1}", outcome.TotalIterations, NotConvergedHint));
            }
            return step;
        }
    }
}
