using System;

namespace Lamella.Hosting
{
    /// <summary>
    /// One field being designed in a host: the native session, the signature of the inputs it belongs to, the θ in use
    /// and the parameters it was started with. It is either started from a start field or restored from a
    /// <see cref="SavedField"/>; a restored session shows the saved report and values until it is stepped again, and a
    /// field saved converged is not stepped again (as before saving).
    /// </summary>
    public sealed class FieldSession : IDisposable
    {
        private FieldReport? savedReport;
        private double[] savedValues;

        private FieldSession(FieldSolver solver, string signature, double thetaDegrees, FieldParams parameters)
        {
            Solver = solver;
            Signature = signature;
            ThetaDegrees = thetaDegrees;
            Parameters = parameters;
        }

        /// <summary>The native session (shared with downstream readers; owned by this object).</summary>
        public FieldSolver Solver { get; }
        /// <summary>The fingerprint of the inputs this session was started from.</summary>
        public string Signature { get; }
        /// <summary>The θ being solved for, in degrees (the θ input, or the estimate from strokes).</summary>
        public double ThetaDegrees { get; }
        /// <summary>The parameters the session was started with.</summary>
        public FieldParams Parameters { get; }
        /// <summary>True for a session re-created from saved values that has not been stepped since.</summary>
        public bool IsRestored => savedValues != null;

        /// <summary>The state: the saved report of a restored session until it is stepped, else the session's own.</summary>
        public FieldReport Report => savedReport ?? Solver.Report;

        /// <summary>The field, one value per vertex (exactly the saved values of a restored session until it is stepped).</summary>
        public double[] Values() => savedValues != null ? (double[])savedValues.Clone() : Solver.Values();

        /// <summary>Starts a session on <paramref name="mesh"/> from <paramref name="startField"/>.</summary>
        public static FieldSession Start(LamellaMesh mesh, double[] startField, FieldParams parameters, string signature)
        {
            if (signature == null) throw new ArgumentNullException(nameof(signature));
            return new FieldSession(new FieldSolver(mesh, startField, parameters), signature, parameters.ThetaDegrees, parameters);
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
            var session = new FieldSession(new FieldSolver(mesh, saved.Values, saved.Parameters), saved.Signature, saved.ThetaDegrees, saved.Parameters);
            session.savedReport = saved.Report;
            session.savedValues = (double[])saved.Values.Clone();
            return session;
        }

        /// <summary>
        /// Steps within a time budget (see <see cref="FieldStepping.StepWithin"/>); a restored session saved converged
        /// reports <see cref="SteppingStop.Converged"/> without stepping.
        /// </summary>
        public SteppingOutcome StepWithin(double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs)
        {
            if (savedReport.HasValue && savedReport.Value.IsConverged)
            {
                return new SteppingOutcome { Report = savedReport.Value, Stop = SteppingStop.Converged };
            }
            savedReport = null;
            savedValues = null;
            return FieldStepping.StepWithin(Solver, budgetMs, iterationCap, cancelRequested, clockMs);
        }

        /// <summary>Steps to convergence within this call (see <see cref="FieldStepping.ToConvergence"/>), same rule for restored sessions.</summary>
        public SteppingOutcome ToConvergence(long iterationCap, Func<bool> cancelRequested) =>
            StepWithin(double.PositiveInfinity, iterationCap, cancelRequested, FieldStepping.StopwatchClock());

        /// <summary>What a document keeps of this session (see <see cref="SavedField"/>).</summary>
        public SavedField Save(int iteration) => new SavedField(iteration, Signature, ThetaDegrees, Parameters, Report, Values());

        /// <summary>Releases the native session (harmless twice).</summary>
        public void Dispose() => Solver.Dispose();
    }
}
