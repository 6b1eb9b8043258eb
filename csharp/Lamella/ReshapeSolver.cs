using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>The state of a <see cref="ReshapeSolver"/> after a step (<c>LmlReshapeReport</c>). Lengths in the mesh's units.</summary>
    public sealed class ReshapeReport
    {
        internal ReshapeReport(ReshapeReportRecord r)
        {
            Iterations = checked((long)r.Iterations);
            IsConverged = r.Converged != 0;
            AngleErrorRmsDegrees = r.AngleErrorRmsDegrees;
            AngleErrorMaxDegrees = r.AngleErrorMaxDegrees;
            MaxDeviation = r.MaxDeviation;
            RmsDeviation = r.RmsDeviation;
            Tolerance = r.Tolerance;
            MaxEdgeChange = r.MaxEdgeChange;
            EnergyAngle = r.EnergyAngle;
            EnergyFair = r.EnergyFair;
            EnergyClose = r.EnergyClose;
            EnergyEdge = r.EnergyEdge;
        }

        /// <summary>Iterations run since the session was created.</summary>
        public long Iterations { get; }
        /// <summary>True when converged (further steps do nothing).</summary>
        public bool IsConverged { get; }
        /// <summary>RMS of |θ_measured − θ| over the curve vertices (the optimiser's own measure), degrees.</summary>
        public double AngleErrorRmsDegrees { get; }
        /// <summary>Largest angle error over the curve vertices, degrees.</summary>
        public double AngleErrorMaxDegrees { get; }
        /// <summary>Largest distance of a vertex from the original surface.</summary>
        public double MaxDeviation { get; }
        /// <summary>RMS distance of the vertices from the original surface.</summary>
        public double RmsDeviation { get; }
        /// <summary>The bound on <see cref="MaxDeviation"/>.</summary>
        public double Tolerance { get; }
        /// <summary>Largest relative change of an edge length.</summary>
        public double MaxEdgeChange { get; }
        /// <summary>E^S_angle (unweighted, on the problem scaled to mean edge length 1).</summary>
        public double EnergyAngle { get; }
        /// <summary>E^S_fair.</summary>
        public double EnergyFair { get; }
        /// <summary>E^S_close (Eq. 14).</summary>
        public double EnergyClose { get; }
        /// <summary>E^S_edge (Eq. 15).</summary>
        public double EnergyEdge { get; }
    }

    /// <summary>
    /// Moves a surface a little so that the level sets of a fixed field become P-curves of the angle θ (paper Sec. 3.3,
    /// Fig. 17, <c>LmlReshape</c>), with the paper's Table 3 weights and a bound on the deviation from the original
    /// surface. Stepped like <see cref="FieldSolver"/>; one thread at a time (calls are serialised by a lock).
    /// </summary>
    public sealed class ReshapeSolver : IDisposable
    {
        private readonly ReshapeHandle handle;
        private readonly object gate = new object();

        /// <summary>
        /// Starts moving <paramref name="mesh"/> for the level sets of <paramref name="field"/> (one value per vertex,
        /// held fixed). <paramref name="tolerance"/> is a length in the mesh's units, or with
        /// <paramref name="toleranceIsFraction"/> a fraction of the bounding-box diagonal (0.005 for 0.5 %).
        /// </summary>
        /// <exception cref="LamellaException">θ or the tolerance out of range (named), a field of the wrong length or constant.</exception>
        public ReshapeSolver(LamellaMesh mesh, double[] field, double thetaDegrees, double tolerance, bool toleranceIsFraction)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (field == null) throw new ArgumentNullException(nameof(field));
            Native.Check(NativeMethods.lml_reshape_new(mesh.Handle, field, Native.Size(field.Length), thetaDegrees, tolerance,
                toleranceIsFraction ? 1u : 0u, out handle));
        }

        private ReshapeSolver(ReshapeHandle handle)
        {
            this.handle = handle;
        }

        /// <summary>
        /// Restores a session saved with <see cref="Save"/> (<c>lml_reshape_load</c>); it continues bit for bit as the
        /// saved one would have.
        /// </summary>
        /// <exception cref="LamellaException"><see cref="Status.CorruptData"/> for damaged, truncated or foreign bytes (a field session's, another format version).</exception>
        public static ReshapeSolver Load(byte[] bytes)
        {
            if (bytes == null) throw new ArgumentNullException(nameof(bytes));
            ReshapeHandle loaded;
            Native.Check(NativeMethods.lml_reshape_load(bytes, Native.Size(bytes.Length), out loaded));
            return new ReshapeSolver(loaded);
        }

        /// <summary>The whole session as bytes (<c>lml_reshape_save</c>): original surface, field, moved positions, solver state.</summary>
        public byte[] Save()
        {
            lock (gate)
            {
                return Native.Read((byte[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_reshape_save(handle, b, c, out n));
            }
        }

        /// <summary>Runs at most <paramref name="maxIterations"/> iterations; returns the state (converged or not).</summary>
        public ReshapeReport Step(int maxIterations)
        {
            if (maxIterations < 0) throw new ArgumentOutOfRangeException(nameof(maxIterations));
            lock (gate)
            {
                ReshapeReportRecord record;
                Native.Check(NativeMethods.lml_reshape_step(handle, (uint)maxIterations, out record));
                return new ReshapeReport(record);
            }
        }

        /// <summary>The state after the last step (or after creation).</summary>
        public ReshapeReport Report
        {
            get
            {
                lock (gate)
                {
                    ReshapeReportRecord record;
                    Native.Check(NativeMethods.lml_reshape_report(handle, out record));
                    return new ReshapeReport(record);
                }
            }
        }

        /// <summary>The current vertex positions, xyz per vertex, in the mesh's units.</summary>
        public double[] Positions()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_reshape_positions(handle, b, c, out n));
            }
        }

        /// <summary>The distance of every vertex from the original surface, in the mesh's units.</summary>
        public double[] Deviations()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_reshape_deviations(handle, b, c, out n));
            }
        }

        /// <summary>Releases the native session.</summary>
        public void Dispose() => handle.Dispose();
    }
}
