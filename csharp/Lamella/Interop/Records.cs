using System.Runtime.InteropServices;

namespace Lamella.Interop
{
    /// <summary>
    /// <c>LmlCandidate</c> as the library writes it: one candidate start of a search and how its short solve ended
    /// (angles in degrees). The binding hands it out as <see cref="Candidate"/>, with its text.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct CandidateRecord
    {
        /// <summary><c>LML_START_HEIGHT</c> or <c>LML_START_GUIDES</c> (<see cref="StartKind"/>).</summary>
        public uint Kind;
        /// <summary>Height candidates: 1 when the field is minus the height.</summary>
        public uint Negated;
        /// <summary>Height candidates: the unit direction.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] Direction;
        /// <summary>Guide candidates: the boundary side.</summary>
        public ulong Side;
        /// <summary>Guide candidates: the start angle of the guides against the boundary.</summary>
        public double StartAngleDegrees;
        /// <summary>1 when scored.</summary>
        public uint Scored;
        /// <summary>1 when rejected.</summary>
        public uint Rejected;
        /// <summary>Lower is better (valid when scored).</summary>
        public double Score;
        /// <summary>RMS angle error along the level curves.</summary>
        public double RmsErrorDegrees;
        /// <summary>Largest angle error along the level curves.</summary>
        public double MaxErrorDegrees;
        /// <summary>Fraction of nearly straight measured points.</summary>
        public double StraightFraction;
        /// <summary>Singular vertices after the short solve.</summary>
        public ulong SingularVertices;
    }

    /// <summary><c>LmlVerdict</c> as the library writes it; the binding hands it out as <see cref="Verdict"/>, with the message.</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct VerdictRecord
    {
        /// <summary>1 when acceptable.</summary>
        public ulong Acceptable;
        /// <summary>The tolerance the strips were judged with.</summary>
        public double ToleranceDegrees;
        /// <summary>Strips with a quad more than the tolerance off θ.</summary>
        public ulong StripsMissingTheta;
        /// <summary>Strips with flipped quads.</summary>
        public ulong StripsWithFlippedQuads;
        /// <summary>The strip of the quad that misses θ most.</summary>
        public ulong WorstStrip;
        /// <summary>That quad's index along its strip.</summary>
        public ulong WorstQuad;
        /// <summary>That quad's centre.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] WorstPoint;
        /// <summary>That quad's angle error.</summary>
        public double WorstErrorDegrees;
        /// <summary>Strips whose centre line leaves the surface by more than 1 % of its bounding-box diagonal.</summary>
        public ulong StripsOffSurface;
    }

    /// <summary>
    /// <c>LmlNetReport</c>: the state of a net optimisation after a step (angles in degrees; index 0 is the first
    /// field, 1 the second). The binding hands it out as <see cref="NetReport"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NetReportRecord
    {
        public ulong Iterations;
        public ulong Converged;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] AngleErrorRmsDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] AngleErrorMaxDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public ulong[] SingularVertexCount;
        public double MinIntersectionDegrees;
        public double MeanIntersectionDegrees;
        public ulong FacesBelowMin;
        public double EnergyTotal;
    }

    /// <summary>
    /// <c>LmlNode</c>: one node of a gridshell, where a strip of the first family crosses one of the second. The binding
    /// hands it out as <see cref="Node"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NodeRecord
    {
        public ulong Vertex;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public ulong[] Strips;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] ArcLengths;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] Position;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] Axis;
        public double RulingAngleDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public uint[] DiagnosticsDefined;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public uint[] SingularPointNear;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] ConicalCurvature;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] DarbouxAngleDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] BinormalOffset;
    }

    /// <summary>
    /// <c>LmlWebReport</c>: the state of a 3-web after a step beyond what <see cref="NetReportRecord"/> says of its first
    /// two families (angles in degrees; index 0 of the pairs: the third family against the first, 1: against the
    /// second). The binding hands it out as <see cref="WebReport"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct WebReportRecord
    {
        public double AngleErrorRmsDegrees;
        public double AngleErrorMaxDegrees;
        public ulong SingularVertexCount;
        public double ResidualMax;
        public double ResidualRms;
        public double ThirdFamilyFactor;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] MinIntersectionDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] MeanIntersectionDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public ulong[] FacesBelowMin;
    }

    /// <summary>
    /// <c>LmlWebNode</c>: one node of a 3-web gridshell, where a strip of family <c>Families[0]</c> crosses one of
    /// <c>Families[1]</c> (the smaller first); <c>Node</c>'s per-strip entries follow that order. The binding hands it
    /// out as <see cref="WebNode"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct WebNodeRecord
    {
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public uint[] Families;
        public uint Reserved;
        public NodeRecord Node;
    }

    /// <summary>
    /// <c>LmlReshapeReport</c>: the state of a surface optimisation after a step (lengths in the mesh's units, angles
    /// in degrees). The binding hands it out as <see cref="ReshapeReport"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct ReshapeReportRecord
    {
        public ulong Iterations;
        public ulong Converged;
        public double AngleErrorRmsDegrees;
        public double AngleErrorMaxDegrees;
        public double MaxDeviation;
        public double RmsDeviation;
        public double Tolerance;
        public double MaxEdgeChange;
        public double EnergyAngle;
        public double EnergyFair;
        public double EnergyClose;
        public double EnergyEdge;
    }

    /// <summary>
    /// <c>LmlAlternationReport</c>: the state of an alternating field and surface optimisation after a step (the last
    /// field step's report and the last surface step's). The binding hands it out as <see cref="AlternatingReport"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct AlternationReportRecord
    {
        public ulong Rounds;
        public ulong RoundsThisStep;
        public ulong Converged;
        public FieldReport Field;
        public ReshapeReportRecord Surface;
    }

    /// <summary>
    /// <c>LmlBaseMeshReport</c>: the state of a base-mesh optimisation (lengths in the net's units, angles in degrees;
    /// index 0 is the rows, 1 the columns). The binding hands it out as <see cref="BaseMeshReport"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct BaseMeshReportRecord
    {
        public ulong Iterations;
        public ulong Converged;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] TargetDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] AngleErrorRmsDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public double[] AngleErrorMaxDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public ulong[] MeasuredVertices;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 2)]
        public ulong[] StraightVertices;
        public double MaxDeviation;
        public double RmsDeviation;
        public double MaxDeviationPercent;
        public ulong NodeCount;
        public double NodeRulingAngleMaxDegrees;
        public double NodeRulingAngleRmsDegrees;
        public ulong FamiliesMet;
        public ulong TorsionFree;
        public double Energy;
    }

    /// <summary>
    /// <c>LmlBaseMeshNode</c>: a node of an optimised net with the angle between its two strips' rulings. The binding
    /// hands it out as <see cref="BaseMeshNode"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct BaseMeshNodeRecord
    {
        public uint Vertex;
        public uint Defined;
        public double RulingAngleDegrees;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] Axis;
    }

    /// <summary>
    /// <c>LmlBaseMeshFamilyReport</c>: one family's part of a base-mesh report (angles in degrees). The binding hands it
    /// out as <see cref="BaseMeshFamilyReport"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct BaseMeshFamilyReportRecord
    {
        public double TargetDegrees;
        public double AngleErrorRmsDegrees;
        public double AngleErrorMaxDegrees;
        public ulong MeasuredVertices;
        public ulong StraightVertices;
    }

    /// <summary><c>LmlShadingReport</c>: the state of a shading optimisation after a step. The binding hands it out as <see cref="ShadingReport"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct ShadingReportRecord
    {
        public ulong Iterations;
        public ulong Converged;
        public ulong BlockVertices;
        public ulong PassVertices;
        public ulong SingularVertices;
        public ulong ConstantSlopeStart;
        public double StartSlopeDegrees;
        public double EnergyFair;
        public double EnergyGrad;
        public double EnergyBlock;
        public double EnergyLight;
        public double EnergyConstraints;
        public double EnergyTotal;
    }

    /// <summary><c>LmlSunPathSummary</c>: the region fractions of a sun-path check (−1: no sample the sun reaches). Handed out as <see cref="SunPathSummary"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct SunPathSummaryRecord
    {
        public double BlockFraction;
        public double PassFraction;
        public double FreeFraction;
        public ulong BlockSuns;
        public ulong PassSuns;
        public ulong Rays;
    }
}
