using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>The state of a <see cref="NetSolver"/> after a step (<c>LmlNetReport</c>). Angles in degrees.</summary>
    public sealed class NetReport
    {
        internal NetReport(NetReportRecord r)
        {
            Iterations = checked((long)r.Iterations);
            IsConverged = r.Converged != 0;
            AngleErrorRmsDegrees = (double[])(r.AngleErrorRmsDegrees ?? new double[2]).Clone();
            AngleErrorMaxDegrees = (double[])(r.AngleErrorMaxDegrees ?? new double[2]).Clone();
            MinIntersectionDegrees = r.MinIntersectionDegrees;
            MeanIntersectionDegrees = r.MeanIntersectionDegrees;
            FacesBelowMin = checked((long)r.FacesBelowMin);
            EnergyTotal = r.EnergyTotal;
        }

        /// <summary>Iterations run since the session was created.</summary>
        public long Iterations { get; }
        /// <summary>True when the final stage has converged (further steps do nothing).</summary>
        public bool IsConverged { get; }
        /// <summary>RMS of each family's angle error over its measured vertices (index 0: first field).</summary>
        public double[] AngleErrorRmsDegrees { get; }
        /// <summary>Largest angle error of each family.</summary>
        public double[] AngleErrorMaxDegrees { get; }
        /// <summary>Smallest unsigned intersection angle of the two families over the faces.</summary>
        public double MinIntersectionDegrees { get; }
        /// <summary>Area-weighted mean unsigned intersection angle.</summary>
        public double MeanIntersectionDegrees { get; }
        /// <summary>Faces where the families cross below the minimum angle.</summary>
        public long FacesBelowMin { get; }
        /// <summary>The weighted energy being minimised.</summary>
        public double EnergyTotal { get; }
    }

    /// <summary>
    /// A net of two curve families (paper Sec. 4.1, <c>LmlNet</c>): two fields optimised together on one mesh, each toward
    /// its family (θ: 0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics), crossing at no less than a
    /// minimum angle and, optionally, near a target angle. Stepped like <see cref="FieldSolver"/>; one thread at a time
    /// (calls are serialised by a lock).
    /// </summary>
    public sealed class NetSolver : IDisposable
    {
        private readonly NetHandle handle;
        private readonly object gate = new object();

        /// <summary>Starts the optimisation from <paramref name="first"/> and <paramref name="second"/> (one value per vertex each).</summary>
        /// <exception cref="LamellaException">An argument out of range (named), a field of the wrong length or constant.</exception>
        public NetSolver(LamellaMesh mesh, double firstThetaDegrees, double secondThetaDegrees, double[] first, double[] second,
            double minIntersectionDegrees = 30.0, double? intersectionDegrees = null)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (first == null) throw new ArgumentNullException(nameof(first));
            if (second == null) throw new ArgumentNullException(nameof(second));
            if (first.Length != second.Length) throw new ArgumentException("the two fields differ in length", nameof(second));
            var fields = new double[2 * first.Length];
            Array.Copy(first, fields, first.Length);
            Array.Copy(second, 0, fields, first.Length, second.Length);
            Native.Check(NativeMethods.lml_net_new(mesh.Handle, firstThetaDegrees, secondThetaDegrees, fields, Native.Size(first.Length),
                minIntersectionDegrees, intersectionDegrees ?? double.NaN, out handle));
        }

        private NetSolver(NetHandle handle)
        {
            this.handle = handle;
        }

        /// <summary>
        /// Restores a session saved with <see cref="Save"/> (<c>lml_net_load</c>); it continues bit for bit as the saved one
        /// would have.
        /// </summary>
        /// <exception cref="LamellaException"><see cref="Status.CorruptData"/> for damaged, truncated or foreign bytes (another kind of session, another format version).</exception>
        public static NetSolver Load(byte[] bytes)
        {
            if (bytes == null) throw new ArgumentNullException(nameof(bytes));
            NetHandle loaded;
            Native.Check(NativeMethods.lml_net_load(bytes, Native.Size(bytes.Length), out loaded));
            return new NetSolver(loaded);
        }

        /// <summary>The whole session as bytes (<c>lml_net_save</c>): mesh, both fields, parameters, solver state.</summary>
        public byte[] Save()
        {
            lock (gate)
            {
                return Native.Read((byte[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_net_save(handle, b, c, out n));
            }
        }

        /// <summary>
        /// The default start of a net (<c>lml_net_start</c>): the first family from the default start search, the second
        /// among the candidates crossing it at 45° or more on average. Returns the two fields (one value per vertex each).
        /// </summary>
        /// <exception cref="LamellaException">θ or the minimum angle out of range (named), or no candidate leads to a family.</exception>
        public static double[][] DefaultStart(LamellaMesh mesh, double firstThetaDegrees, double secondThetaDegrees, double minIntersectionDegrees = 30.0)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            double[] both = Native.Read((double[] b, UIntPtr c, out UIntPtr n) =>
                NativeMethods.lml_net_start(mesh.Handle, firstThetaDegrees, secondThetaDegrees, minIntersectionDegrees, b, c, out n));
            int half = both.Length / 2;
            var first = new double[half];
            var second = new double[half];
            Array.Copy(both, first, half);
            Array.Copy(both, half, second, 0, half);
            return new[] { first, second };
        }

        /// <summary>Runs at most <paramref name="maxIterations"/> iterations; returns the state (converged or not).</summary>
        public NetReport Step(int maxIterations)
        {
            if (maxIterations < 0) throw new ArgumentOutOfRangeException(nameof(maxIterations));
            lock (gate)
            {
                NetReportRecord record;
                Native.Check(NativeMethods.lml_net_step(handle, (uint)maxIterations, out record));
                return new NetReport(record);
            }
        }

        /// <summary>The state after the last step (or after creation).</summary>
        public NetReport Report
        {
            get
            {
                lock (gate)
                {
                    NetReportRecord record;
                    Native.Check(NativeMethods.lml_net_report(handle, out record));
                    return new NetReport(record);
                }
            }
        }

        /// <summary>Field <paramref name="k"/> (0 or 1), one value per vertex, in the scale of its start.</summary>
        public double[] Field(int k)
        {
            if (k < 0 || k > 1) throw new ArgumentOutOfRangeException(nameof(k), "a net has fields 0 and 1");
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_net_field(handle, (uint)k, b, c, out n));
            }
        }

        /// <summary>Runs <paramref name="call"/> on the native handle under the session's lock.</summary>
        internal T Locked<T>(Func<NetHandle, T> call)
        {
            lock (gate)
            {
                return call(handle);
            }
        }

        /// <summary>Releases the native session.</summary>
        public void Dispose() => handle.Dispose();
    }
}
