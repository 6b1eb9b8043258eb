using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// Start points for guide curves on the mesh boundary: boundary loops split at corners into segments, evenly
    /// spaced starts along a segment, a start by arc-length parameter, and the boundary point nearest to a point
    /// in space (what a designer picks in a CAD program).
    /// </summary>
    public static class BoundaryStarts
    {
        /// <summary>The default corner threshold: the boundary turns by at least 30° (<c>LML_DEFAULT_CORNER_TURN_DEGREES</c>).</summary>
        public const double DefaultCornerTurnDegrees = 30.0;

        /// <summary>
        /// The number of segments of boundary loop <paramref name="loopIndex"/> when it is split at vertices where it
        /// turns by at least <paramref name="cornerTurnDegrees"/> (in [0°, 180°]); a loop without corners is one segment.
        /// </summary>
        public static int SegmentCount(LamellaMesh mesh, int loopIndex, double cornerTurnDegrees = DefaultCornerTurnDegrees)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            UIntPtr count;
            Native.Check(NativeMethods.lml_boundary_segment_count(mesh.Handle, Index(loopIndex, nameof(loopIndex)), cornerTurnDegrees, out count));
            return Native.Count(count);
        }

        /// <summary>
        /// <paramref name="count"/> start points on segment <paramref name="segmentIndex"/> of loop
        /// <paramref name="loopIndex"/> (split as in <see cref="SegmentCount"/>), evenly spaced by arc length at
        /// (i + ½)·L / count from the segment's first corner, so neighbours are L / count apart.
        /// </summary>
        public static EdgePoint[] EvenlySpaced(LamellaMesh mesh, int loopIndex, double cornerTurnDegrees, int segmentIndex, int count)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            uint loop = Index(loopIndex, nameof(loopIndex)), segment = Index(segmentIndex, nameof(segmentIndex)), n = Index(count, nameof(count));
            return Native.Read((EdgePoint[] b, UIntPtr c, out UIntPtr needed) =>
                NativeMethods.lml_boundary_starts(mesh.Handle, loop, cornerTurnDegrees, segment, n, b, c, out needed));
        }

        /// <summary>The start point at arc-length parameter <paramref name="s"/> ∈ [0, 1] along loop <paramref name="loopIndex"/>, from its first vertex.</summary>
        public static EdgePoint At(LamellaMesh mesh, int loopIndex, double s)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            EdgePoint point;
            Native.Check(NativeMethods.lml_boundary_start_at(mesh.Handle, Index(loopIndex, nameof(loopIndex)), s, out point));
            return point;
        }

        /// <summary>The boundary point closest to the point (x, y, z) in space.</summary>
        public static EdgePoint Nearest(LamellaMesh mesh, double x, double y, double z)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            EdgePoint point;
            Native.Check(NativeMethods.lml_boundary_start_nearest(mesh.Handle, new[] { x, y, z }, out point));
            return point;
        }

        private static uint Index(int value, string name)
        {
            if (value < 0) throw new ArgumentOutOfRangeException(name, name + " must be ≥ 0, not " + value);
            return (uint)value;
        }
    }
}
