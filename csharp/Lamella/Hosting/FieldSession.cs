using System;

namespace Lamella.Hosting
{
    /// <summary>
    /// One field being designed in a host: the native session, the signature of the inputs it belongs to, the θ in use
    /// and the parameters it was started with. It is started from a start field, started by the library's
    /// <see cref="StartSearch"/> (then it first searches, one candidate per live budget slice, and has no field until the
    /// search ends), or restored from a <see cref="SavedField"/>; a restored session shows the saved report and values
    /// until it is stepped again, and a field saved converged is not stepped again (as before saving).
    /// </summary>
    public sealed class FieldSession : ISteppedSession<FieldReport>
    {
        private FieldReport? savedReport;
        private double[] savedValues;
        /// <summary>The start search while it runs; null once its field is taken (or for other starts).</summary>
        private StartSearch search;
        private FieldSolver solver;
        private Candidate[] candidates = new Candidate[0];

        private FieldSession(FieldSolver solver, StartSearch search, string signature, double thetaDegrees, FieldParams parameters)
        {
            this.solver = solver;
            this.search = search;
            Signature = signature;
            ThetaDegrees = thetaDegrees;
            Parameters = parameters;
        }

        /// <summary>The native session (shared with downstream readers; owned by this object); null while the start search runs.</summary>
        public FieldSolver Solver => solver;
        /// <summary>True while the start search runs: no field yet.</summary>
        public bool IsSearching => search != null;
        /// <summary>The fingerprint of the inputs this session was started from.</summary>
        public string Signature { get; }
        /// <summary>The θ being solved for, in degrees (the θ input, or the estimate from strokes).</summary>
        public double ThetaDegrees { get; }
        /// <summary>The parameters the session was started with.</summary>
        public FieldParams Parameters { get; }
        /// <summary>True for a session re-created from saved values that has not been stepped since.</summary>
        public bool IsRestored => savedValues != null;
        /// <summary>The start search's candidates probed so far (all of them once the field is taken); empty for other starts.</summary>
        public Candidate[] Candidates => (Candidate[])candidates.Clone();
        /// <summary>The candidate the field continues from, once the start search has ended; null before and for other starts.</summary>
        public Candidate? ChosenStart { get; private set; }

        /// <summary>The state: the saved report of a restored session until it is stepped, else the session's own (all zero while searching).</summary>
        public FieldReport Report => savedReport ?? (solver != null ? solver.Report : default(FieldReport));

        /// <summary>Whether the field has converged (a live host no longer steps it).</summary>
        public bool IsConverged => Report.IsConverged;

        /// <summary>The field, one value per vertex (exactly the saved values of a restored session until it is stepped).</summary>
        public double[] Values()
        {
            if (savedValues != null) return (double[])savedValues.Clone();
            if (solver == null) throw new InvalidOperationException("the start search is still running: there is no field yet");
            return solver.Values();
        }

        /// <summary>Starts a session on <paramref name="mesh"/> from <paramref name="startField"/>.</summary>
        public static FieldSession Start(LamellaMesh mesh, double[] startField, FieldParams parameters, string signature)
        {
            if (signature == null) throw new ArgumentNullException(nameof(signature));
            return new FieldSession(new FieldSolver(mesh, startField, parameters), null, signature, parameters.ThetaDegrees, parameters);
        }

        /// <summary>
        /// Starts a session on <paramref name="mesh"/> with the library's start search for <paramref name="parameters"/>
        /// (the family follows θ; the gradient target is the chosen candidate's). Stepping it first probes the candidates,
        /// then continues with the best one's field.
        /// </summary>
        public static FieldSession Search(LamellaMesh mesh, FieldParams parameters, string signature)
        {
            if (signature == null) throw new ArgumentNullException(nameof(signature));
            return new FieldSession(null, new StartSearch(mesh, parameters), signature, parameters.ThetaDegrees, parameters);
        }

        /// <summary>
        /// Re-creates a saved field on <paramref name="mesh"/> (the mesh it was solved on, which the caller checks with the
        /// signature): a session started from the saved values with the saved parameters. Its level curves are those of
        /// the saved field; stepping it (only when it was saved unconverged) runs the parameters' schedule again from the
        /// saved field, with the iteration count starting at 0.
        /// </summary>
        public static FieldSession Restore(LamellaMesh mesh, SavedField saved)
        {
            if (saved == null) throw new ArgumentNullException(nameof(saved));
            var session = new FieldSession(new FieldSolver(mesh, saved.Values, saved.Parameters), null, saved.Signature, saved.ThetaDegrees, saved.Parameters);
            session.savedReport = saved.Report;
            session.savedValues = (double[])saved.Values.Clone();
            return session;
        }

        /// <summary>
        /// Steps within a time budget. While the start search runs, one budget slice probes one candidate (about 20 field
        /// iterations, or almost none when its short solve ran beside the one before) and stops with <see cref="SteppingStop.TimeBudget"/>; the slice that probes the last candidate also
        /// takes the best one's field, which later slices step (see <see cref="FieldStepping.StepWithin"/>). An infinite
        /// budget runs the whole search and then the field. The search's iterations do not count against
        /// <paramref name="iterationCap"/>. A restored session saved converged reports <see cref="SteppingStop.Converged"/>
        /// without stepping. Throws the binding's <see cref="LamellaException"/> when every candidate was rejected
        /// (<see cref="Status.SingularField"/>; the session keeps its candidates).
        /// </summary>
        public SteppingOutcome<FieldReport> StepWithin(double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs)
        {
            if (savedReport.HasValue && savedReport.Value.IsConverged)
            {
                return new SteppingOutcome<FieldReport> { Report = savedReport.Value, TotalIterations = (long)savedReport.Value.Iterations, Stop = SteppingStop.Converged };
            }
            FieldStepping.CheckArguments(budgetMs, iterationCap, cancelRequested, clockMs);
            savedReport = null;
            savedValues = null;
            double searchMs = 0;
            if (search != null)
            {
                double start = clockMs();
                bool oneShot = double.IsPositiveInfinity(budgetMs);
                do
                {
                    if (cancelRequested())
                    {
                        return new SteppingOutcome<FieldReport> { Report = Report, Stop = SteppingStop.Cancelled, ElapsedMs = clockMs() - start };
                    }
                    // Complete (also when a former call found every candidate rejected): take the winner's field.
                    if (search.IsComplete || !search.Step()) TakeSearchField();
                    else candidates = search.Candidates;
                }
                while (oneShot && search != null);
                searchMs = clockMs() - start;
                if (!oneShot) return new SteppingOutcome<FieldReport> { Report = Report, Stop = SteppingStop.TimeBudget, ElapsedMs = searchMs };
            }
            SteppingOutcome<FieldReport> outcome = FieldStepping.StepWithin(solver, budgetMs, iterationCap, cancelRequested, clockMs);
            outcome.ElapsedMs += searchMs;
            return outcome;
        }

        /// <summary>The search is complete: its candidates are kept, the winner's field becomes the session's, the search is released.</summary>
        private void TakeSearchField()
        {
            candidates = search.Candidates;
            FieldSolver field = search.TakeField();
            int? winner = search.Winner;
            ChosenStart = winner.HasValue ? candidates[winner.Value] : (Candidate?)null;
            search.Dispose();
            search = null;
            solver = field;
        }

        /// <summary>Steps to convergence within this call (see <see cref="StepWithin"/> with an infinite budget), same rule for restored sessions.</summary>
        public SteppingOutcome<FieldReport> ToConvergence(long iterationCap, Func<bool> cancelRequested) =>
            StepWithin(double.PositiveInfinity, iterationCap, cancelRequested, FieldStepping.StopwatchClock());

        /// <summary>What a document keeps of this session (see <see cref="SavedField"/>); a session still searching has nothing to keep.</summary>
        public SavedField Save(int iteration)
        {
            if (IsSearching) throw new InvalidOperationException("the start search is still running: there is no field to save");
            return new SavedField(iteration, Signature, ThetaDegrees, Parameters, Report, Values());
        }

        /// <summary>Releases the native session and search (harmless twice).</summary>
        public void Dispose()
        {
            search?.Dispose();
            solver?.Dispose();
        }
    }
}
