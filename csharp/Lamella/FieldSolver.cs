using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// A field optimisation session (<c>LmlField</c>): a scalar field on a copy of the mesh whose level curves
    /// should form the family of its <see cref="FieldParams"/>, stepped until converged, saved and restored.
    /// Every native call on the session holds the session's lock, so calls from several threads run one after another
    /// (in an unspecified order) instead of racing on the native state.
    /// </summary>
    public sealed class FieldSolver : IDisposable
    {
        private readonly FieldHandle Handle;

        /// <summary>Held around every native call that reads or changes this session.</summary>
        private readonly object gate = new object();

        internal FieldSolver(FieldHandle handle)
        {
            Handle = handle;
        }

        /// <summary>
        /// Starts an optimisation from <paramref name="initialField"/> (one value per vertex, not constant, e.g. a
        /// height function roughly across the wanted curves). The session copies the mesh, which may be disposed afterwards.
        /// </summary>
        public FieldSolver(LamellaMesh mesh, double[] initialField, FieldParams parameters)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (initialField == null) throw new ArgumentNullException(nameof(initialField));
            Native.Check(NativeMethods.lml_field_new(mesh.Handle, initialField, Native.Size(initialField.Length), ref parameters, out Handle));
        }

        /// <summary>Runs <paramref name="call"/> on the native handle while holding the session's lock (for the other wrappers that read the session).</summary>
        internal T Locked<T>(Func<FieldHandle, T> call)
        {
            lock (gate) return call(Handle);
        }

        /// <summary>Restores a session from bytes written by <see cref="Save"/>; it continues bit for bit as the original would.</summary>
        public static FieldSolver Load(byte[] bytes)
        {
            if (bytes == null) throw new ArgumentNullException(nameof(bytes));
            FieldHandle handle;
            Native.Check(NativeMethods.lml_field_load(bytes, Native.Size(bytes.Length), out handle));
            return new FieldSolver(handle);
        }

        /// <summary>
        /// Runs at most <paramref name="maxIterations"/> iterations and returns the state; <see cref="FieldReport.IsConverged"/>
        /// says whether to step again. A numerical failure throws (<see cref="Status.DidNotConverge"/>; the field keeps its last good state).
        /// </summary>
        public FieldReport Step(int maxIterations)
        {
            if (maxIterations < 0) throw new ArgumentOutOfRangeException(nameof(maxIterations));
            var report = default(FieldReport);
            Native.Check(Locked(h => NativeMethods.lml_field_step(h, (uint)maxIterations, out report)));
            return report;
        }

        /// <summary>Runs until convergence, at most <paramref name="maxIterations"/> iterations; throws <see cref="Status.DidNotConverge"/> when the budget runs out.</summary>
        public FieldReport Solve(int maxIterations)
        {
            if (maxIterations < 0) throw new ArgumentOutOfRangeException(nameof(maxIterations));
            var report = default(FieldReport);
            Native.Check(Locked(h => NativeMethods.lml_field_solve(h, (uint)maxIterations, out report)));
            return report;
        }

        /// <summary>The state after the last step (or after creation / loading).</summary>
        public FieldReport Report
        {
            get
            {
                var report = default(FieldReport);
                Native.Check(Locked(h => NativeMethods.lml_field_report(h, out report)));
                return report;
            }
        }

        /// <summary>
        /// The slope β in degrees a constant-slope session aims at: the given one, or for <see cref="Family.FreeSlope"/> the one
        /// fitted to the field before its last iteration. Other families throw <see cref="Status.InvalidArgument"/>.
        /// </summary>
        public double SlopeDegrees
        {
            get
            {
                double slope = 0.0;
                Native.Check(Locked(h => NativeMethods.lml_field_slope(h, out slope)));
                return slope;
            }
        }

        /// <summary>Replaces the remaining weight schedule by constant weights (paper Eq. 12); a converged session runs again.</summary>
        public void SetWeights(Weights weights) => Native.Check(Locked(h => NativeMethods.lml_field_set_weights(h, weights)));

        /// <summary>The current field, one value per vertex.</summary>
        public double[] Values() =>
            Locked(h => Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_field_values(h, b, c, out n)));

        /// <summary>The unit binormal of the level curve at each vertex (x, y, z; zero at boundary and singular vertices).</summary>
        public double[] Binormals() =>
            Locked(h => Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_field_binormals(h, b, c, out n)));

        /// <summary>The unit side vector of the Darboux frame (paper Eq. 10) at each vertex (x, y, z).</summary>
        public double[] SideVectors() =>
            Locked(h => Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_field_side_vectors(h, b, c, out n)));

        /// <summary>The singular vertices of the last report.</summary>
        public int[] SingularVertices() =>
            Array.ConvertAll(Locked(h => Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_field_singular_vertices(h, b, c, out n))), i => checked((int)i));

        /// <summary>The whole session as portable bytes (for <see cref="Load"/>).</summary>
        public byte[] Save() =>
            Locked(h => Native.Read((byte[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_field_save(h, b, c, out n)));

        /// <summary>Releases the native session (harmless to call twice; waits for a call running on another thread).</summary>
        public void Dispose()
        {
            lock (gate) Handle.Dispose();
        }
    }
}
