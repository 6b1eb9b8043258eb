using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// The state of a <see cref="NetSolver"/> after a step (<c>LmlNetReport</c>); of a 3-web, of its first two families
    /// (<see cref="NetSolver.WebReport"/> tells the rest). Angles in degrees.
    /// </summary>
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
    /// minimum angle and, optionally, near a target angle. Or a 3-web (Sec. 4.2, <see cref="Web"/>): three fields F, H
    /// and the diagonal G held to F + G + H = 0 at every vertex. Stepped like <see cref="FieldSolver"/>; one thread at a
    /// time (calls are serialised by a lock).
    /// </summary>
    public sealed class NetSolver : IDisposable
    {
        private readonly NetHandle handle;
        private readonly object gate = new object();

        /// <summary>Starts the optimisation from <paramref name="first"/> and <paramref name="second"/> (one value per vertex each).</summary>
        /// <exception cref="LamellaException">An argument out of range (named), a field of the wrong length or constant.</exception>
        public NetSolver(LamellaMesh mesh, double firstThetaDegrees, double secondThetaDegrees, double[] first, double[] second,
            double minIntersectionDegrees = 30.0, double? intersectionDegrees = null)
            : this(Start(mesh, first, second, (MeshHandle m, double[] fields, UIntPtr n, out NetHandle created) =>
                NativeMethods.lml_net_new(m, firstThetaDegrees, secondThetaDegrees, fields, n, minIntersectionDegrees, intersectionDegrees ?? double.NaN, out created)))
        {
        }

        private NetSolver(NetHandle handle)
        {
            this.handle = handle;
            uint count;
            try
            {
                Native.Check(NativeMethods.lml_net_family_count(handle, out count));
            }
            catch
            {
                handle.Dispose();
                throw;
            }
            FamilyCount = checked((int)count);
        }

        /// <summary>A native constructor taking the two start fields one after the other (<c>lml_net_new</c>, <c>lml_web_new</c>).</summary>
        private delegate Status StartCall(MeshHandle mesh, double[] fields, UIntPtr n, out NetHandle net);

        /// <summary>Checks the start fields, passes them to <paramref name="start"/> as one array and returns the new session.</summary>
        private static NetHandle Start(LamellaMesh mesh, double[] first, double[] second, StartCall start)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (first == null) throw new ArgumentNullException(nameof(first));
            if (second == null) throw new ArgumentNullException(nameof(second));
            if (first.Length != second.Length) throw new ArgumentException("the two fields differ in length", nameof(second));
            var fields = new double[2 * first.Length];
            Array.Copy(first, fields, first.Length);
            Array.Copy(second, 0, fields, first.Length, second.Length);
            NetHandle created;
            Native.Check(start(mesh.Handle, fields, Native.Size(first.Length), out created));
            return created;
        }

        /// <summary>
        /// Starts a 3-web (paper Sec. 4.2, <c>lml_web_new</c>): fields F and H of the first two families from
        /// <paramref name="f"/> and <paramref name="h"/> (one value per vertex each, e.g. <see cref="DefaultStart"/> at
        /// <paramref name="thetaF"/> and <paramref name="thetaH"/>), and G of the third, the diagonal one, started as
        /// −F − H; the three held to F + G + H = 0 (Eq. 18) at every vertex, every pair crossing at no less than
        /// <paramref name="minIntersectionDegrees"/>. <paramref name="intersectionDegrees"/>: a weak target angle of F and
        /// H, or null. E.g. θ 0, 0, 90: an AAG web. Step, save and read it like a net; <see cref="WebReport"/> says how
        /// Eq. 18 and the third family fare.
        /// </summary>
        /// <exception cref="LamellaException">An argument out of range (named: <c>thetas[i]</c> for a θ), a field of the wrong length or constant.</exception>
        public static NetSolver Web(LamellaMesh mesh, double thetaF, double thetaH, double thetaG, double[] f, double[] h,
            double minIntersectionDegrees = 30.0, double? intersectionDegrees = null)
        {
            var thetas = new[] { thetaF, thetaH, thetaG };
            return new NetSolver(Start(mesh, f, h, (MeshHandle m, double[] fields, UIntPtr n, out NetHandle created) =>
                NativeMethods.lml_web_new(m, thetas, fields, n, minIntersectionDegrees, intersectionDegrees ?? double.NaN, out created)));
        }

        /// <summary>The number of families (<c>lml_net_family_count</c>): 2 for a net, 3 for a 3-web.</summary>
        public int FamilyCount { get; }

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

        /// <summary>The whole session as bytes (<c>lml_net_save</c>): mesh, every field, parameters, solver state.</summary>
        public byte[] Save()
        {
            lock (gate)
            {
                return Native.Read((byte[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_net_save(handle, b, c, out n));
            }
        }

        /// <summary>
        /// The default start of a net (<c>lml_net_start</c>): the first family from the default start search, the second
        /// among the candidates crossing it at 45° or more on average, and if that pair is not acceptable pairs of heights
        /// ±30° about each principal axis, each judged by a short net solve (where every pair has a nearly straight family,
        /// the best of those). Returns the two fields (one value per vertex each).
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

        /// <summary>
        /// The state of a 3-web after the last step (or after creation) beyond what <see cref="Report"/> says of its first
        /// two families (<c>lml_net_web_report</c>): Eq. 18's residual, the third family's angle error and crossings.
        /// </summary>
        /// <exception cref="LamellaException"><see cref="Status.InvalidArgument"/> on a net of two families (the library's message says so).</exception>
        public WebReport WebReport()
        {
            lock (gate)
            {
                WebReportRecord record;
                Native.Check(NativeMethods.lml_net_web_report(handle, out record));
                return new WebReport(record);
            }
        }

        /// <summary>
        /// Field <paramref name="k"/> (below <see cref="FamilyCount"/>: F, H and G of a 3-web), one value per vertex, in the
        /// scale of its start (a 3-web's three in one common scale).
        /// </summary>
        public double[] Field(int k)
        {
            CheckFamily(k, nameof(k));
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_net_field(handle, (uint)k, b, c, out n));
            }
        }

        /// <summary>
        /// The even-pace levels of family <paramref name="k"/> (0: F, 1: H, 2: G) of a 3-web's current fields, increasing
        /// (<c>lml_web_levels</c>): F's and H's at one pace, the smaller of range / (count + 1) for
        /// <paramref name="countF"/> levels of F and <paramref name="countH"/> of H, each centred in its field's range (the
        /// family with the wider range gets more levels than asked), G's on the diagonals of their net, shifted by half a
        /// pace when <paramref name="kagome"/> (a Kagome pattern, whose three families never meet at one point). The same
        /// arguments give the same levels in <see cref="LevelCurves.OfWeb"/> and <see cref="StripWeb"/> until the next step.
        /// </summary>
        /// <exception cref="LamellaException">A net of two families, a count above <c>LML_MAX_LEVELS</c> or 0, or a constant field (named).</exception>
        public double[] WebLevels(int countF, int countH, bool kagome, int k)
        {
            CheckWebFamily(k, nameof(k));
            return WebCall(countF, countH, kagome, (h, f, g, kg) =>
                Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_web_levels(h, f, g, kg, (uint)k, b, c, out n)));
        }

        /// <summary>Throws <see cref="ArgumentOutOfRangeException"/> unless <paramref name="k"/> is one of this session's families.</summary>
        internal void CheckFamily(int k, string name)
        {
            if (k < 0 || k >= FamilyCount)
                throw new ArgumentOutOfRangeException(name, k, FamilyCount == 2 ? "a net has fields 0 and 1" : "a 3-web has fields 0, 1 and 2");
        }

        /// <summary>Throws <see cref="ArgumentOutOfRangeException"/> unless <paramref name="k"/> names a family of a 3-web (0, 1 or 2).</summary>
        internal static void CheckWebFamily(int k, string name)
        {
            if (k < 0 || k > 2) throw new ArgumentOutOfRangeException(name, k, "a 3-web has families 0, 1 and 2");
        }

        /// <summary>
        /// Runs <paramref name="call"/> on the native handle under the session's lock with a 3-web's level arguments as the
        /// C ABI takes them (<c>count_f</c>, <c>count_h</c>, <c>kagome</c>); the library judges the counts' range.
        /// </summary>
        internal T WebCall<T>(int countF, int countH, bool kagome, Func<NetHandle, UIntPtr, UIntPtr, uint, T> call)
        {
            if (countF < 0) throw new ArgumentOutOfRangeException(nameof(countF));
            if (countH < 0) throw new ArgumentOutOfRangeException(nameof(countH));
            return Locked(h => call(h, Native.Size(countF), Native.Size(countH), kagome ? 1u : 0u));
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
