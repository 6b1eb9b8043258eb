using System;
using System.Runtime.InteropServices;

namespace Lamella
{
    /// <summary>Which quantities of a <see cref="VertexDiagnostics"/> are defined (<c>LML_DIAGNOSTIC_*</c> bits).</summary>
    [Flags]
    public enum DiagnosticParts : uint
    {
        /// <summary>The curvature κ.</summary>
        Curvature = 1,
        /// <summary>The torsion τ.</summary>
        Torsion = 1 << 1,
        /// <summary>The conical curvature k = τ/κ (the vertex bends).</summary>
        ConicalCurvature = 1 << 2,
        /// <summary>The angle atan |k| between binormal and Darboux vector.</summary>
        DarbouxAngle = 1 << 3,
        /// <summary>The angle between the strip's binormal and its ruling.</summary>
        BinormalRuling = 1 << 4,
        /// <summary>Prop. 2's offset at half the strip width.</summary>
        BinormalOffset = 1 << 5,
        /// <summary>The distance to the ruling's singular point (else it is at infinity).</summary>
        SingularPointDistance = 1 << 6,
    }

    /// <summary>
    /// The node and strip diagnostics of paper Sec. 5.1 (Prop. 1–2) at one centre-line point of a strip
    /// (<c>LmlVertexDiagnostics</c>, <see cref="Strips.Diagnostics"/>). A quantity not in <see cref="Defined"/> is 0.
    /// Lengths in the mesh's unit, angles in degrees.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct VertexDiagnostics
    {
        /// <summary>The quantities that are defined (end points and straight stretches have no conical curvature).</summary>
        public DiagnosticParts Defined;
        /// <summary>1 when the singular point of the rectifying developable's ruling lies inside the strip or within one strip width of it.</summary>
        public uint SingularPointNear;
        /// <summary>Curvature κ ≥ 0.</summary>
        public double Curvature;
        /// <summary>Torsion τ (signed).</summary>
        public double Torsion;
        /// <summary>Conical curvature k = τ/κ.</summary>
        public double ConicalCurvature;
        /// <summary>Angle atan |k| between the binormal and the ruling of the rectifying developable.</summary>
        public double DarbouxAngleDegrees;
        /// <summary>Angle between the strip's binormal and its ruling at the point.</summary>
        public double BinormalRulingDegrees;
        /// <summary>κ k² v² / 2 at v = half the strip width: the binormal point's distance from the developable.</summary>
        public double BinormalOffset;
        /// <summary>Distance along the ruling from the curve to the ruling's singular point.</summary>
        public double SingularPointDistance;

        /// <summary>Whether all of <paramref name="parts"/> are defined.</summary>
        public bool Has(DiagnosticParts parts) => (Defined & parts) == parts;
    }
}
