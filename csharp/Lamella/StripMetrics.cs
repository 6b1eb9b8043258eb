using System;
using System.Runtime.InteropServices;

namespace Lamella
{
    /// <summary>Warning bits of a strip (<c>LML_STRIP_WARNING_*</c>).</summary>
    [Flags]
    public enum StripWarnings : ulong
    {
        /// <summary>No warning.</summary>
        None = 0,
        /// <summary>Fewer than 3 points (skipped).</summary>
        TooFewPoints = 1 << 0,
        /// <summary>A non-finite point (skipped).</summary>
        NonFiniteInput = 1 << 1,
        /// <summary>A (nearly) zero-length segment (skipped).</summary>
        ZeroLengthSegment = 1 << 2,
        /// <summary>The optimisation failed numerically (skipped).</summary>
        SolverFailed = 1 << 3,
        /// <summary>The curve passes singular field vertices.</summary>
        SingularVertices = 1 << 4,
        /// <summary>A closed curve was cut open at its first point.</summary>
        ClosedCurveOpened = 1 << 5,
        /// <summary>Neighbouring rulings cross inside the strip.</summary>
        WidthTooLarge = 1 << 6,
        /// <summary>Some quads flip their orientation.</summary>
        FlippedQuads = 1 << 7,
    }

    /// <summary>One strip's Table 4 measures (<c>LmlStripMetrics</c>); lengths in the mesh's unit, angles in degrees.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct StripMetrics
    {
        /// <summary>Index of the strip's level curve.</summary>
        public ulong Curve;
        /// <summary>Level value of that curve.</summary>
        public double Level;
        /// <summary>Length of the centre line.</summary>
        public double Length;
        /// <summary>diff_θ: max |θ_measured − θ| over the inner centre points.</summary>
        public double MaxDiffThetaDegrees;
        /// <summary>e_straight: straightness of the unrolled centre line, relative to its length.</summary>
        public double EStraight;
        /// <summary>E_planar: Σ det(d̂_j, d̂_j+1, ê_j)².</summary>
        public double EPlanar;
        /// <summary>The largest planarity residual of one quad.</summary>
        public double MaxPlanar;
        /// <summary>Appro: max distance from the surface, % of the bounding-box diagonal.</summary>
        public double ApproPercent;
        /// <summary>Quads whose orientation flips.</summary>
        public ulong FlippedQuads;
        /// <summary>Warning bits.</summary>
        public StripWarnings Warnings;
        /// <summary>
        /// Max over the quads of the error of the strip plane's angle against the smooth surface normal (the quad normal
        /// should make 90° − θ with it), degrees: what the <see cref="Verdict"/> judges.
        /// </summary>
        public double MaxQuadAngleErrorDegrees;
        /// <summary>The longest ruling segment from the centre line to a boundary, over the strip width (≥ 0.5).</summary>
        public double MaxRulingOverWidth;
    }

    /// <summary>Table 4 over a whole pattern (<c>LmlPatternMetrics</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct PatternMetrics
    {
        /// <summary>The number of strips built.</summary>
        public ulong StripCount;
        /// <summary>Curves no strip could be built on.</summary>
        public ulong SkippedCount;
        /// <summary>Max diff_θ over the strips, degrees.</summary>
        public double MaxDiffThetaDegrees;
        /// <summary>Max e_straight over the strips.</summary>
        public double MaxEStraight;
        /// <summary>Σ E_planar over the strips.</summary>
        public double EPlanar;
        /// <summary>The largest planarity residual of one quad.</summary>
        public double MaxPlanar;
        /// <summary>Max Appro over the strips, %.</summary>
        public double ApproPercent;
        /// <summary>Flipped quads over the strips.</summary>
        public ulong FlippedQuads;
        /// <summary>Max <see cref="StripMetrics.MaxQuadAngleErrorDegrees"/> over the strips, degrees.</summary>
        public double MaxQuadAngleErrorDegrees;
        /// <summary>Max <see cref="StripMetrics.MaxRulingOverWidth"/> over the strips.</summary>
        public double MaxRulingOverWidth;
    }

    /// <summary>A level curve no strip could be built on, and why (<c>LmlSkippedCurve</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SkippedCurve
    {
        /// <summary>Index of the curve.</summary>
        public ulong Curve;
        /// <summary>Why it was skipped.</summary>
        public StripWarnings Warnings;
    }
}
