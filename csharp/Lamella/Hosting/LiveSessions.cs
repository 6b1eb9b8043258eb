using System;
using System.Collections.Generic;
using System.Linq;

namespace Lamella.Hosting
{
    /// <summary>A solver session a host keeps across its solutions: the signature of the inputs it was started from, and whether it has converged.</summary>
    public interface ILiveSession : IDisposable
    {
        /// <summary>The fingerprint of the inputs this session was started from.</summary>
        string Signature { get; }
        /// <summary>True once converged: a live host no longer steps it.</summary>
        bool IsConverged { get; }
    }

    /// <summary>A session a host steps (see <see cref="LiveStepper"/>), with its solver's report type.</summary>
    public interface ISteppedSession<TReport> : ILiveSession
    {
        /// <summary>The state now.</summary>
        TReport Report { get; }

        /// <summary>Steps within a time budget (an infinite one: to convergence), as <see cref="FieldStepping.StepWithin{TReport}"/>.</summary>
        SteppingOutcome<TReport> StepWithin(double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs);
    }

    /// <summary>The sessions of a host component, one per iteration, as its solutions see them (see <see cref="LiveSessions{T}"/>).</summary>
    public interface ILiveSessions
    {
        /// <summary>A solution starts.</summary>
        void BeginSolution();
        /// <summary>The solution ended: sessions of iterations it did not reach are released.</summary>
        void EndSolution();
        /// <summary>Sessions not converged (the ones a live solve still steps).</summary>
        int RunningCount();
        /// <summary>Iteration <paramref name="iteration"/> ran without a session (missing or bad inputs): its session, if any, is released.</summary>
        void Skip(int iteration);
        /// <summary>Releases every session (the component leaves its document, or the document closes).</summary>
        void Clear();
    }

    /// <summary>
    /// A native solver (a net or 3-web, a reshape, a base mesh) as a session a host keeps and steps: the solver, owned, the
    /// signature of the inputs it was started from and its <see cref="Steppable{TReport}"/>.
    /// </summary>
    public sealed class SolverSession<TSolver, TReport> : ISteppedSession<TReport> where TSolver : class, IDisposable
    {
        private readonly Steppable<TReport> steps;

        /// <summary>Owns <paramref name="solver"/>, stepped through <paramref name="steps"/>, for inputs with <paramref name="signature"/>.</summary>
        public SolverSession(TSolver solver, Steppable<TReport> steps, string signature)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            if (steps == null) throw new ArgumentNullException(nameof(steps));
            if (signature == null) throw new ArgumentNullException(nameof(signature));
            Solver = solver;
            this.steps = steps;
            Signature = signature;
        }

        /// <summary>The native solver (owned by this session).</summary>
        public TSolver Solver { get; }
        /// <inheritdoc />
        public string Signature { get; }
        /// <inheritdoc />
        public TReport Report => steps.Report;
        /// <inheritdoc />
        public bool IsConverged => steps.IsConverged(Report);

        /// <inheritdoc />
        public SteppingOutcome<TReport> StepWithin(double budgetMs, long iterationCap, Func<bool> cancelRequested, Func<double> clockMs) =>
            FieldStepping.StepWithin(steps, budgetMs, iterationCap, cancelRequested, clockMs);

        /// <summary>Releases the solver (harmless twice).</summary>
        public void Dispose() => Solver.Dispose();
    }

    /// <summary>The <see cref="SolverSession{TSolver, TReport}"/> of a net (or 3-web), of a reshape and of a base mesh.</summary>
    public static class SolverSession
    {
        /// <summary>A session owning <paramref name="net"/>, a net of two families or a 3-web.</summary>
        public static SolverSession<NetSolver, NetReport> Of(NetSolver net, string signature) =>
            new SolverSession<NetSolver, NetReport>(net, Steppable.Of(net), signature);

        /// <summary>A session owning <paramref name="reshape"/>.</summary>
        public static SolverSession<ReshapeSolver, ReshapeReport> Of(ReshapeSolver reshape, string signature) =>
            new SolverSession<ReshapeSolver, ReshapeReport>(reshape, Steppable.Of(reshape), signature);

        /// <summary>A session owning <paramref name="baseMesh"/>, a base-mesh optimisation (a net of rows and columns or a 3-web).</summary>
        public static SolverSession<BaseMeshRun, BaseMeshReport> Of(BaseMeshRun baseMesh, string signature)
        {
            if (baseMesh == null) throw new ArgumentNullException(nameof(baseMesh));
            return new SolverSession<BaseMeshRun, BaseMeshReport>(baseMesh, Steppable.Of(baseMesh.Solver), signature);
        }
    }

    /// <summary>
    /// The sessions of one host component across its solutions, one per iteration (list item or tree branch of its
    /// inputs). A session lives on while its iteration's inputs keep their signature, so a live solve keeps converging
    /// across solutions; it is started again when its own inputs change (or on reset). Sessions of iterations a solution
    /// no longer reaches are released at its end.
    /// </summary>
    public sealed class LiveSessions<T> : ILiveSessions, IDisposable where T : class, ILiveSession
    {
        private readonly IterationSlots<T> slots = new IterationSlots<T>();
        private int iterations;

        /// <summary>The number of sessions held.</summary>
        public int Count => slots.Stored().Count();

        /// <summary>The session of iteration <paramref name="iteration"/>, or null.</summary>
        public T this[int iteration] => slots[iteration];

        /// <summary>The iterations the current solution has reached so far (the highest + 1).</summary>
        public int Iterations => iterations;

        /// <summary>Every held session with its iteration, in order.</summary>
        public IEnumerable<KeyValuePair<int, T>> Stored() => slots.Stored();

        /// <inheritdoc />
        public int RunningCount() => slots.Stored().Count(slot => !slot.Value.IsConverged);

        /// <inheritdoc />
        public void BeginSolution() => iterations = 0;

        /// <summary>
        /// The session of <paramref name="iteration"/> for inputs with <paramref name="signature"/>: the held one while its
        /// signature matches (unless <paramref name="reset"/>), else a new one from <paramref name="start"/>, which must
        /// carry that signature. A replaced session is released.
        /// </summary>
        public T Session(int iteration, string signature, bool reset, Func<T> start)
        {
            if (signature == null) throw new ArgumentNullException(nameof(signature));
            if (start == null) throw new ArgumentNullException(nameof(start));
            T session = Held(iteration, signature);
            if (!reset && session != null) return session;
            session = start();
            if (session == null || session.Signature != signature)
            {
                session?.Dispose();
                throw new InvalidOperationException("the started session does not carry the signature asked for");
            }
            slots.Set(iteration, session);
            return session;
        }

        /// <summary>The session of <paramref name="iteration"/> if it was started from inputs with <paramref name="signature"/>, else null (nothing is started or released).</summary>
        public T Held(int iteration, string signature)
        {
            Reached(iteration);
            T session = slots[iteration];
            return session != null && session.Signature == signature ? session : null;
        }

        /// <inheritdoc />
        public void Skip(int iteration)
        {
            Reached(iteration);
            slots.Set(iteration, null);
        }

        /// <inheritdoc />
        public void EndSolution() => slots.Trim(iterations);

        /// <inheritdoc />
        public void Clear() => slots.Clear();

        /// <summary>Same as <see cref="Clear"/>.</summary>
        public void Dispose() => Clear();

        private void Reached(int iteration)
        {
            if (iteration < 0) throw new ArgumentOutOfRangeException(nameof(iteration));
            iterations = Math.Max(iterations, iteration + 1);
        }
    }
}
