using System.Runtime.InteropServices;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>Limits and tolerances of guide-curve tracing (<c>LmlTraceOptions</c>); start from <see cref="Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct TraceOptions
    {
        /// <summary>The longest curve, in mesh units; <see cref="double.PositiveInfinity"/> for no limit (the default).</summary>
        public double MaxLength;
        /// <summary>The most points per curve (≥ 2; default 100 000).</summary>
        public ulong MaxPoints;
        /// <summary>A root of paper Eq. 4 is accepted within this many degrees of θ (0–90, exclusive; default 2).</summary>
        public double AngleToleranceDegrees;
        /// <summary>The sharpest accepted turn between consecutive segments, in degrees (0–90; default 45).</summary>
        public double MaxTurnDegrees;

        /// <summary>The library's defaults.</summary>
        public static TraceOptions Default()
        {
            TraceOptions options;
            Native.Check(NativeMethods.lml_trace_options_default(out options));
            return options;
        }
    }

    /// <summary>Why a traced curve ended (<c>LML_TRACE_STOP_*</c>).</summary>
    public enum TraceStop : uint
    {
        /// <summary>It reached the boundary (the normal end).</summary>
        Boundary = 0,
        /// <summary>No point on the next edges realises θ within the tolerance and the turn limit (e.g. near a singular spot).</summary>
        NoCandidate = 1,
        /// <summary>It reached <see cref="TraceOptions.MaxLength"/>.</summary>
        LengthLimit = 2,
        /// <summary>It reached <see cref="TraceOptions.MaxPoints"/>.</summary>
        PointLimit = 3,
    }

    /// <summary>
    /// Where two traced curves meet (<c>LmlCrossing</c>): curve and segment indices (segment k joins points k and
    /// k + 1 of its curve) and the meeting point. A self-intersection has <see cref="FirstCurve"/> ==
    /// <see cref="SecondCurve"/>.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Crossing
    {
        /// <summary>The first curve's index.</summary>
        public uint FirstCurve;
        /// <summary>The second curve's index.</summary>
        public uint SecondCurve;
        /// <summary>The segment of the first curve.</summary>
        public uint FirstSegment;
        /// <summary>The segment of the second curve.</summary>
        public uint SecondSegment;
        /// <summary>The meeting point, x, y, z (three values; mesh units).</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] Position;

        /// <summary>True for a curve meeting itself.</summary>
        public bool IsSelfIntersection => FirstCurve == SecondCurve;
    }
}
