using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// Rectifying developable strips along level curves (<c>LmlStrips</c>): planar quads, centre lines, rulings,
    /// flat unrollings, the Table 4 metrics and the verdict on θ. Strip i with n centre points has 2n vertices (left boundary, then
    /// right) and n − 1 quads; three offset tables cut the flat arrays per strip. Immutable.
    /// </summary>
    public sealed class Strips : IDisposable
    {
        internal readonly StripsHandle Handle;
        /// <summary>The library's message when the strips were built without an acceptable family, else empty.</summary>
        private readonly string verdictMessage;

        private Strips(StripsHandle handle, string verdictMessage)
        {
            Handle = handle;
            this.verdictMessage = verdictMessage;
        }

        /// <summary>
        /// Builds a rectifying strip on every polyline of <paramref name="curves"/>; polylines that cannot carry one are
        /// listed by <see cref="Skipped"/>. Strips that miss θ by more than <see cref="StripParams.ToleranceDegrees"/> (or
        /// have flipped quads) are built all the same: <see cref="Verdict"/> says so, <see cref="EnsureAcceptable"/> throws.
        /// </summary>
        public static Strips Build(LevelCurves curves, StripParams parameters)
        {
            if (curves == null) throw new ArgumentNullException(nameof(curves));
            StripsHandle handle;
            Status status = Native.Check(NativeMethods.lml_strips_new(curves.Handle, ref parameters, out handle));
            return FromNative(handle, status);
        }

        /// <summary>Strips the library built on another call (e.g. <see cref="ShadingSolver.BuildStrips"/>) that returned <paramref name="status"/>.</summary>
        internal static Strips FromNative(StripsHandle handle, Status status)
        {
            // Read at once: the message belongs to the last call on this thread.
            string message = status == Status.NoAcceptableFamily ? Utf8.FromNative(NativeMethods.lml_last_error_message()) : string.Empty;
            return new Strips(handle, message);
        }

        /// <summary>The verdict: whether every strip meets θ within the tolerance, without flipped quads, and where it misses most.</summary>
        public Verdict Verdict
        {
            get
            {
                VerdictRecord record;
                Native.Check(NativeMethods.lml_strips_verdict(Handle, out record));
                return new Verdict(record, record.Acceptable != 0 ? string.Empty : verdictMessage);
            }
        }

        /// <summary>Throws <see cref="NoAcceptableFamilyException"/> (with the <see cref="Verdict"/>) unless the strips meet θ within the tolerance, without flipped quads.</summary>
        public void EnsureAcceptable()
        {
            Verdict verdict = Verdict;
            if (!verdict.IsAcceptable) throw new NoAcceptableFamilyException(verdict);
        }

        /// <summary>The number of strips.</summary>
        public int Count
        {
            get
            {
                UIntPtr count;
                Native.Check(NativeMethods.lml_strips_count(Handle, out count));
                return Native.Count(count);
            }
        }

        /// <summary>Offsets (in points) of the centres, rulings and unrolled centres per strip.</summary>
        public int[] PointOffsets() =>
            Native.Offsets(Native.Read((UIntPtr[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_point_offsets(Handle, b, c, out n)));

        /// <summary>Offsets of the vertices (2n per strip) of <see cref="Vertices"/> and <see cref="UnrolledVertices"/>.</summary>
        public int[] VertexOffsets() =>
            Native.Offsets(Native.Read((UIntPtr[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_vertex_offsets(Handle, b, c, out n)));

        /// <summary>Offsets of the quads (n − 1 per strip) of <see cref="Quads"/>.</summary>
        public int[] QuadOffsets() =>
            Native.Offsets(Native.Read((UIntPtr[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_quad_offsets(Handle, b, c, out n)));

        /// <summary>The strip vertices in space, x, y, z each.</summary>
        public double[] Vertices() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_vertices(Handle, b, c, out n));

        /// <summary>The quads, four indices each into the whole vertex array (spatial and unrolled alike).</summary>
        public int[] Quads() =>
            Array.ConvertAll(Native.Read((uint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_quads(Handle, b, c, out n)), i => checked((int)i));

        /// <summary>The centre lines, x, y, z per point.</summary>
        public double[] Centres() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_centres(Handle, b, c, out n));

        /// <summary>The unit rulings at the centre points, x, y, z each.</summary>
        public double[] Rulings() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_rulings(Handle, b, c, out n));

        /// <summary>The strips laid flat: x, y of each vertex of <see cref="Vertices"/>; each strip starts at the origin along +x.</summary>
        public double[] UnrolledVertices() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_unrolled_vertices(Handle, b, c, out n));

        /// <summary>The unrolled centre lines: x, y of each point of <see cref="Centres"/>.</summary>
        public double[] UnrolledCentres() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_unrolled_centres(Handle, b, c, out n));

        /// <summary>
        /// The Sec. 5.1 diagnostics of every centre point, laid out as <see cref="Centres"/> (one per point, strips one
        /// after another): how far the binormals are from the rectifying developables' rulings, where their singular points lie.
        /// </summary>
        public VertexDiagnostics[] Diagnostics() =>
            Native.Read((VertexDiagnostics[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_diagnostics(Handle, b, c, out n));

        /// <summary>The Table 4 measures of each strip.</summary>
        public StripMetrics[] Metrics() =>
            Native.Read((StripMetrics[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_metrics(Handle, b, c, out n));

        /// <summary>The Table 4 measures of the whole pattern.</summary>
        public PatternMetrics PatternMetrics
        {
            get
            {
                PatternMetrics metrics;
                Native.Check(NativeMethods.lml_strips_pattern_metrics(Handle, out metrics));
                return metrics;
            }
        }

        /// <summary>The curves no strip could be built on, and why.</summary>
        public SkippedCurve[] Skipped() =>
            Native.Read((SkippedCurve[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_strips_skipped(Handle, b, c, out n));

        /// <summary>
        /// The interactive 3D viewer page of the strips (what <c>lamella design</c> writes as view.html): one
        /// self-contained HTML file, no network needed, showing the surface and level curves of
        /// <paramref name="curves"/> (the curves the strips were built on), the strips coloured per strip, by the angle
        /// error of their rectifying planes or by <paramref name="utilisation"/> (one value per strip, e.g.
        /// <see cref="StripCheck.MaxUtilisation"/>; null for none), their rulings and flat unrollings, and each strip's
        /// length and Table 4 figures on hover or click. <paramref name="title"/> names the design (null: "Lamella strips").
        /// </summary>
        public string ViewHtml(LevelCurves curves, double[] utilisation = null, string title = null)
        {
            if (curves == null) throw new ArgumentNullException(nameof(curves));
            byte[] name = title == null ? null : Utf8.ToNative(title);
            UIntPtr count = Native.Size(utilisation == null ? 0 : utilisation.Length);
            byte[] bytes = Native.Read((byte[] b, UIntPtr c, out UIntPtr n) =>
                NativeMethods.lml_strips_view_html(Handle, curves.Handle, utilisation, count, name, b, c, out n));
            return Utf8.FromTerminated(bytes);
        }

        /// <summary>Releases the native strips (harmless to call twice).</summary>
        public void Dispose() => Handle.Dispose();
    }
}
