using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>The state of an <see cref="AlternatingSolver"/> after a step (<c>LmlAlternationReport</c>).</summary>
    public sealed class AlternatingReport
    {
        internal AlternatingReport(AlternationReportRecord r)
        {
            Rounds = checked((long)r.Rounds);
            RoundsThisStep = checked((long)r.RoundsThisStep);
            IsConverged = r.Converged != 0;
            Field = r.Field;
            Surface = new ReshapeReport(r.Surface);
        }

        /// <summary>Rounds (a field step and a surface step each) run since the session was created.</summary>
        public long Rounds { get; }
        /// <summary>Rounds run by the last call of <see cref="AlternatingSolver.Step"/>.</summary>
        public long RoundsThisStep { get; }
        /// <summary>True when both steps of the last round converged (further steps do nothing).</summary>
        public bool IsConverged { get; }
        /// <summary>The last field step (the surface fixed), its iterations counted from that step's start; all zero before the first round.</summary>
        public FieldReport Field { get; }
        /// <summary>The last surface step (the field fixed); its deviations are from the original surface, in the mesh's units.</summary>
        public ReshapeReport Surface { get; }
    }

    /// <summary>
    /// The alternating schedule of paper Sec. 3.3 (<c>LmlAlternation</c>): field steps with the surface fixed and surface
    /// steps with the field fixed, in turn, every vertex held within a tolerance of the original surface throughout.
    /// Unlike <see cref="ReshapeSolver"/>, the field changes too. The field steps use the library's default field
    /// parameters for θ, the surface steps the paper's Table 3 weights. Stepped a few rounds at a time; one thread at a
    /// time (calls are serialised by a lock).
    /// </summary>
    public sealed class AlternatingSolver : IDisposable
    {
        private readonly AlternationHandle handle;
        private readonly object gate = new object();

        /// <summary>
        /// Starts alternating on <paramref name="mesh"/> (the original surface, copied) from <paramref name="field"/> (one
        /// value per vertex, copied), towards P-curves of <paramref name="thetaDegrees"/>. <paramref name="tolerance"/> is a
        /// length in the mesh's units, or with <paramref name="toleranceIsFraction"/> a fraction of the bounding-box
        /// diagonal (0.01 for 1 %). Each field step and each surface step runs at most
        /// <paramref name="iterationsPerStep"/> iterations.
        /// </summary>
        /// <exception cref="ArgumentOutOfRangeException"><paramref name="iterationsPerStep"/> below 1.</exception>
        /// <exception cref="LamellaException">θ or the tolerance out of range (named), a field of the wrong length or constant.</exception>
        public AlternatingSolver(LamellaMesh mesh, double[] field, double thetaDegrees, double tolerance, bool toleranceIsFraction, int iterationsPerStep)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (field == null) throw new ArgumentNullException(nameof(field));
            if (iterationsPerStep < 1) throw new ArgumentOutOfRangeException(nameof(iterationsPerStep), iterationsPerStep, "at least one iteration per step");
            Native.Check(NativeMethods.lml_alternation_new(mesh.Handle, field, Native.Size(field.Length), thetaDegrees, tolerance,
                toleranceIsFraction ? 1u : 0u, (uint)iterationsPerStep, out handle));
        }

        /// <summary>
        /// Runs at most <paramref name="maxRounds"/> rounds (fewer once a round converges); returns the state. A numerical
        /// failure throws (<see cref="Status.DidNotConverge"/>; the session keeps the state of its last whole round).
        /// </summary>
        public AlternatingReport Step(int maxRounds)
        {
            if (maxRounds < 0) throw new ArgumentOutOfRangeException(nameof(maxRounds));
            lock (gate)
            {
                AlternationReportRecord record;
                Native.Check(NativeMethods.lml_alternation_step(handle, (uint)maxRounds, out record));
                return new AlternatingReport(record);
            }
        }

        /// <summary>The state after the last step (or after creation).</summary>
        public AlternatingReport Report
        {
            get
            {
                lock (gate)
                {
                    AlternationReportRecord record;
                    Native.Check(NativeMethods.lml_alternation_report(handle, out record));
                    return new AlternatingReport(record);
                }
            }
        }

        /// <summary>The current vertex positions, xyz per vertex, in the mesh's units.</summary>
        public double[] Positions()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_alternation_positions(handle, b, c, out n));
            }
        }

        /// <summary>The current field, one value per vertex.</summary>
        public double[] Field()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_alternation_field(handle, b, c, out n));
            }
        }

        /// <summary>The distance of every vertex from the original surface, in the mesh's units.</summary>
        public double[] Deviations()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_alternation_deviations(handle, b, c, out n));
            }
        }

        /// <summary>Releases the native session.</summary>
        public void Dispose() => handle.Dispose();
    }
}
