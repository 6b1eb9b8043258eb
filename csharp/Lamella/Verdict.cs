using System;
using System.Globalization;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// The verdict on a strip pattern (<c>LmlVerdict</c>): whether every strip's plane meets θ within the tolerance the
    /// strips were built with (<see cref="StripParams.ToleranceDegrees"/>), without flipped quads and without leaving the
    /// surface by more than 1 % of its bounding-box diagonal, and where the pattern misses θ most. Judged on the strips a fabricator would get, against the smooth surface. Angles in degrees.
    /// </summary>
    public sealed class Verdict
    {
        private readonly double[] worstPoint;

        internal Verdict(VerdictRecord record, string message)
        {
            IsAcceptable = record.Acceptable != 0;
            ToleranceDegrees = record.ToleranceDegrees;
            StripsMissingTheta = checked((int)record.StripsMissingTheta);
            StripsWithFlippedQuads = checked((int)record.StripsWithFlippedQuads);
            StripsOffSurface = checked((int)record.StripsOffSurface);
            WorstStrip = checked((int)record.WorstStrip);
            WorstQuad = checked((int)record.WorstQuad);
            worstPoint = (double[])(record.WorstPoint ?? new double[3]).Clone();
            WorstErrorDegrees = record.WorstErrorDegrees;
            Message = message ?? string.Empty;
        }

        /// <summary>
        /// True when every strip is within the tolerance of θ, no quad is flipped, no centre line leaves the surface by more
        /// than 1 % of its bounding-box diagonal and at least one strip was built.
        /// </summary>
        public bool IsAcceptable { get; }
        /// <summary>The largest angle error of a quad of an acceptable pattern.</summary>
        public double ToleranceDegrees { get; }
        /// <summary>Strips with a quad more than the tolerance off θ.</summary>
        public int StripsMissingTheta { get; }
        /// <summary>Strips with flipped quads.</summary>
        public int StripsWithFlippedQuads { get; }
        /// <summary>Strips whose centre line leaves the surface by more than 1 % of its bounding-box diagonal.</summary>
        public int StripsOffSurface { get; }
        /// <summary>The strip of the quad that misses θ most (0 when no strip was built).</summary>
        public int WorstStrip { get; }
        /// <summary>That quad's index along its strip.</summary>
        public int WorstQuad { get; }
        /// <summary>That quad's centre, x, y, z (a copy).</summary>
        public double[] WorstPoint => (double[])worstPoint.Clone();
        /// <summary>That quad's angle error: how far its plane is from the angle θ asks for.</summary>
        public double WorstErrorDegrees { get; }
        /// <summary>
        /// The library's one-line message for a pattern that is not acceptable (<c>lml_last_error_message</c> after
        /// <c>lml_strips_new</c>): the strips that miss, the worst point and what to try. Empty when acceptable.
        /// </summary>
        public string Message { get; }

        /// <summary>One line: the library's message, or for an acceptable pattern the tolerance and the worst quad.</summary>
        public override string ToString() =>
            IsAcceptable
                ? string.Format(CultureInfo.InvariantCulture, "acceptable: every strip within {0:0.###}° of θ and 1 % of the surface, no flipped quad (worst: strip {1} quad {2}, {3:0.###}° off)",
                    ToleranceDegrees, WorstStrip, WorstQuad, WorstErrorDegrees)
                : Message;
    }

    /// <summary>
    /// Strips that miss θ by more than the tolerance, or have flipped quads (<see cref="Status.NoAcceptableFamily"/>):
    /// thrown by <see cref="Strips.EnsureAcceptable"/>, carrying the <see cref="Verdict"/>. The strips themselves stay
    /// valid. (Not marked serialisable: it would need LamellaException's serialisation constructor.)
    /// </summary>
    [Serializable]
    public sealed class NoAcceptableFamilyException : LamellaException
    {
        /// <summary>Restores a serialised exception: its status and native message (the verdict's one-line
        /// account); <see cref="Verdict"/> is not carried across serialisation and is null then.</summary>
        private NoAcceptableFamilyException(System.Runtime.Serialization.SerializationInfo info, System.Runtime.Serialization.StreamingContext context)
            : base(info, context)
        {
        }

        /// <summary>Creates the exception for a verdict that is not acceptable.</summary>
        public NoAcceptableFamilyException(Verdict verdict)
            : base(Status.NoAcceptableFamily, (verdict ?? throw new ArgumentNullException(nameof(verdict))).Message)
        {
            Verdict = verdict;
        }

        /// <summary>The verdict: which strips miss, where, by how much.</summary>
        public Verdict Verdict { get; }
    }
}
