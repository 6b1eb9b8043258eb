using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>The state of a <see cref="ShadingSolver"/> after a step (<c>LmlShadingReport</c>). Energies unweighted on the problem scaled to mean edge 1.</summary>
    public sealed class ShadingReport
    {
        internal ShadingReport(ShadingReportRecord r)
        {
            Iterations = checked((long)r.Iterations);
            IsConverged = r.Converged != 0;
            BlockVertices = checked((long)r.BlockVertices);
            PassVertices = checked((long)r.PassVertices);
            SingularVertices = checked((long)r.SingularVertices);
            StartSlopeDegrees = r.ConstantSlopeStart != 0 ? (double?)r.StartSlopeDegrees : null;
            EnergyFair = r.EnergyFair;
            EnergyGrad = r.EnergyGrad;
            EnergyBlock = r.EnergyBlock;
            EnergyLight = r.EnergyLight;
            EnergyConstraints = r.EnergyConstraints;
            EnergyTotal = r.EnergyTotal;
        }

        /// <summary>Iterations run since the session was created.</summary>
        public long Iterations { get; }
        /// <summary>True when converged (further steps do nothing).</summary>
        public bool IsConverged { get; }
        /// <summary>Vertices with a blocking light term.</summary>
        public long BlockVertices { get; }
        /// <summary>Vertices with a letting-through light term.</summary>
        public long PassVertices { get; }
        /// <summary>Light vertices where the level curve is not regular.</summary>
        public long SingularVertices { get; }
        /// <summary>The slope (degrees, against the earth axis) of the constant-slope family the field started from (paper Fig. 34–35), or null for a height-field start or a given start field.</summary>
        public double? StartSlopeDegrees { get; }
        /// <summary>E_fair.</summary>
        public double EnergyFair { get; }
        /// <summary>E_grad.</summary>
        public double EnergyGrad { get; }
        /// <summary>E_block (Eq. 26).</summary>
        public double EnergyBlock { get; }
        /// <summary>E_light (Eq. 27).</summary>
        public double EnergyLight { get; }
        /// <summary>The constraints defining the binormals, principal normals and the lights in R_l.</summary>
        public double EnergyConstraints { get; }
        /// <summary>The weighted total minimised (Eq. 25).</summary>
        public double EnergyTotal { get; }
    }

    /// <summary>The region fractions of a sun-path check (<c>LmlSunPathSummary</c>): blocked share of the direct-sun hours; null where no sample of the region sees the sun.</summary>
    public sealed class SunPathSummary
    {
        internal SunPathSummary(SunPathSummaryRecord r)
        {
            BlockFraction = r.BlockFraction < 0 ? (double?)null : r.BlockFraction;
            PassFraction = r.PassFraction < 0 ? (double?)null : r.PassFraction;
            FreeFraction = r.FreeFraction < 0 ? (double?)null : r.FreeFraction;
            BlockSuns = checked((long)r.BlockSuns);
            PassSuns = checked((long)r.PassSuns);
            Rays = checked((long)r.Rays);
        }

        /// <summary>Block vertices against the block hours' suns.</summary>
        public double? BlockFraction { get; }
        /// <summary>Pass vertices against the pass hours' suns.</summary>
        public double? PassFraction { get; }
        /// <summary>Free vertices against the block hours' suns.</summary>
        public double? FreeFraction { get; }
        /// <summary>Sun positions above the horizon (every hour of every day) of the block hours.</summary>
        public long BlockSuns { get; }
        /// <summary>Sun positions of the pass hours.</summary>
        public long PassSuns { get; }
        /// <summary>Rays cast.</summary>
        public long Rays { get; }
    }

    /// <summary>
    /// A shading design (paper Sec. 6, <c>LmlShading</c>): a field optimised so that the rectifying planes of its level
    /// curves block the sun of a site's dates and hours at <see cref="ShadingLabel.Block"/> vertices and let it through
    /// at <see cref="ShadingLabel.Pass"/> ones (E_block, E_light, Eq. 25–27, Table 2 weights), strips with one θ per curve,
    /// and the sun-path check through them. Stepped like <see cref="FieldSolver"/>; one thread at a time (calls are
    /// serialised by a lock).
    /// </summary>
    public sealed class ShadingSolver : IDisposable
    {
        private readonly ShadingHandle handle;
        private readonly object gate = new object();

        /// <summary>Starts the design on <paramref name="mesh"/> with one label per vertex and <paramref name="ring"/> free edge rings at each block/pass border.</summary>
        /// <exception cref="LamellaException">A site value out of range, a label out of range or the wrong count (named).</exception>
        public ShadingSolver(LamellaMesh mesh, ShadingSite site, ShadingLabel[] labels, int ring = 1)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (labels == null) throw new ArgumentNullException(nameof(labels));
            if (ring < 0) throw new ArgumentOutOfRangeException(nameof(ring));
            Native.Check(NativeMethods.lml_shading_new(mesh.Handle, ref site, labels, Native.Size(labels.Length), (uint)ring, out handle));
        }

        /// <summary>
        /// Starts the design like <see cref="ShadingSolver(LamellaMesh, ShadingSite, ShadingLabel[], int)"/>, but from
        /// <paramref name="startField"/> (one value per vertex, as many as <paramref name="labels"/>; not constant, finite,
        /// magnitude at most 1e100) instead of the paper's start (<c>lml_shading_new_from_field</c>, the CLI's
        /// <c>--start-field</c>): <see cref="Field"/> returns it (up to about 1 ulp of rescaling) until the first step, and
        /// <see cref="ShadingReport.StartSlopeDegrees"/> is null.
        /// </summary>
        /// <exception cref="ArgumentException"><paramref name="startField"/> and <paramref name="labels"/> differ in length.</exception>
        /// <exception cref="LamellaException">As the other constructor, and a non-finite or too large start value (the native
        /// message names the vertex) or a constant start field (<see cref="Status.SingularField"/>).</exception>
        public ShadingSolver(LamellaMesh mesh, ShadingSite site, ShadingLabel[] labels, int ring, double[] startField)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (labels == null) throw new ArgumentNullException(nameof(labels));
            if (startField == null) throw new ArgumentNullException(nameof(startField));
            if (ring < 0) throw new ArgumentOutOfRangeException(nameof(ring));
            // The C function reads n labels and n start values: a shorter array must not reach it.
            if (startField.Length != labels.Length)
                throw new ArgumentException(startField.Length + " start values for " + labels.Length + " labels", nameof(startField));
            Native.Check(NativeMethods.lml_shading_new_from_field(mesh.Handle, ref site, labels, Native.Size(labels.Length), (uint)ring, startField, out handle));
        }

        /// <summary>Runs at most <paramref name="maxIterations"/> iterations; returns the state (converged or not).</summary>
        public ShadingReport Step(int maxIterations)
        {
            if (maxIterations < 0) throw new ArgumentOutOfRangeException(nameof(maxIterations));
            lock (gate)
            {
                ShadingReportRecord record;
                Native.Check(NativeMethods.lml_shading_step(handle, (uint)maxIterations, out record));
                return new ShadingReport(record);
            }
        }

        /// <summary>The state after the last step (or after creation).</summary>
        public ShadingReport Report
        {
            get
            {
                lock (gate)
                {
                    ShadingReportRecord record;
                    Native.Check(NativeMethods.lml_shading_report(handle, out record));
                    return new ShadingReport(record);
                }
            }
        }

        /// <summary>The field, one value per vertex.</summary>
        public double[] Field()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_shading_field(handle, b, c, out n));
            }
        }

        /// <summary>
        /// Strips of <paramref name="width"/> along <paramref name="count"/> level curves, each for its own θ, judged with
        /// <paramref name="toleranceDegrees"/> against it: <see cref="Strips.Verdict"/> says whether a strip misses
        /// (<see cref="Strips.EnsureAcceptable"/> throws). Their θ: <see cref="Thetas"/>.
        /// </summary>
        public Strips BuildStrips(int count, double width, double toleranceDegrees = 2.0)
        {
            if (count < 0) throw new ArgumentOutOfRangeException(nameof(count));
            lock (gate)
            {
                StripsHandle strips;
                Status status = Native.Check(NativeMethods.lml_shading_strips(handle, (uint)count, width, toleranceDegrees, out strips));
                return Strips.FromNative(strips, status);
            }
        }

        /// <summary>θ in degrees of every strip of the last <see cref="BuildStrips"/>, in the strips' order.</summary>
        public double[] Thetas()
        {
            lock (gate)
            {
                return Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_shading_thetas(handle, b, c, out n));
            }
        }

        /// <summary>
        /// The sun-path check of <paramref name="strips"/> from samples <paramref name="offset"/> behind every vertex, a
        /// ray towards the sun every hour of every day; per-vertex fractions: <see cref="VertexFractions"/>.
        /// </summary>
        public SunPathSummary Evaluate(Strips strips, double offset)
        {
            if (strips == null) throw new ArgumentNullException(nameof(strips));
            lock (gate)
            {
                SunPathSummaryRecord record;
                Native.Check(NativeMethods.lml_shading_evaluate(handle, strips.Handle, offset, out record));
                return new SunPathSummary(record);
            }
        }

        /// <summary>Per vertex, the blocked share of its direct-sun hours of the last <see cref="Evaluate"/> (null where the sun never reaches it).</summary>
        public double?[] VertexFractions()
        {
            double[] raw;
            lock (gate)
            {
                raw = Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_shading_vertex_fractions(handle, b, c, out n));
            }
            var fractions = new double?[raw.Length];
            for (int i = 0; i < raw.Length; i++) fractions[i] = raw[i] < 0 ? (double?)null : raw[i];
            return fractions;
        }

        /// <summary>Releases the native session.</summary>
        public void Dispose() => handle.Dispose();
    }
}
