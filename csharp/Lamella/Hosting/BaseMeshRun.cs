using System;

namespace Lamella.Hosting
{
    /// <summary>
    /// A base-mesh solver (<see cref="BaseMeshSolver"/>) as a host keeps it across solutions, owned, with the nodes of
    /// the net as given when asked for: the library reports the nodes of the current net only, so a host that shows each
    /// node's ruling angle before and after the optimisation (Grasshopper's Torsion-Free Net) reads them once, before
    /// the first step. A <see cref="SolverSession{TSolver, TReport}"/> holds it (<see cref="SolverSession.Of(BaseMeshRun, string)"/>).
    /// </summary>
    public sealed class BaseMeshRun : IDisposable
    {
        /// <summary>
        /// Owns <paramref name="solver"/>; with <paramref name="keepInitialNodes"/>, reads its nodes now (it must not have
        /// stepped yet). The solver is released when this throws.
        /// </summary>
        /// <exception cref="InvalidOperationException"><paramref name="keepInitialNodes"/> for a solver that has stepped: its nodes are no longer the given net's.</exception>
        public BaseMeshRun(BaseMeshSolver solver, bool keepInitialNodes)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            try
            {
                if (keepInitialNodes)
                {
                    if (solver.Report.Iterations != 0)
                        throw new InvalidOperationException("the solver has stepped: its nodes are no longer those of the net as given");
                    InitialNodes = solver.Nodes();
                }
            }
            catch
            {
                solver.Dispose();
                throw;
            }
            Solver = solver;
        }

        /// <summary>The solver (owned).</summary>
        public BaseMeshSolver Solver { get; }

        /// <summary>The nodes of the net as given, before any iteration, with their ruling angles; null unless asked for.</summary>
        public BaseMeshNode[] InitialNodes { get; }

        /// <summary>Releases the solver (harmless twice).</summary>
        public void Dispose() => Solver.Dispose();
    }
}
