using System.Runtime.InteropServices;

namespace Lamella.Interop
{
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
}
