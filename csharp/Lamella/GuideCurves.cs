using System;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// Traced guide curves (<c>LmlGuides</c>): discrete P-curves of angle θ (paper Sec. 3.2.1, Eq. 4), one per start
    /// point on the mesh boundary, point by point on the mesh edges. In start order they are the level sets
    /// F = 0, 1, 2, … of the initial field (<see cref="InitialField.FromGuides"/>). Immutable; they keep their own
    /// copy of the mesh, which may be disposed.
    /// </summary>
    public sealed class GuideCurves : IDisposable
    {
        internal readonly GuidesHandle Handle;

        private GuideCurves(GuidesHandle handle)
        {
            Handle = handle;
        }

        /// <summary>
        /// Traces one curve per start point, in order. θ (<paramref name="thetaDegrees"/>, in [0°, 180°]) is the angle
        /// between the binormal and the surface normal (90°: geodesics; θ and 180° − θ are the mirror families);
        /// <paramref name="startAngleDegrees"/> (in (0°, 180°)) is the start tangent's angle against the boundary
        /// direction that has the interior on its left, turned into the surface (90°: perpendicular).
        /// <paramref name="options"/> null takes <see cref="TraceOptions.Default"/>.
        /// </summary>
        public static GuideCurves Trace(LamellaMesh mesh, EdgePoint[] starts, double thetaDegrees, double startAngleDegrees, TraceOptions? options = null)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (starts == null) throw new ArgumentNullException(nameof(starts));
            TraceOptions chosen = options ?? TraceOptions.Default();
            GuidesHandle handle;
            Native.Check(NativeMethods.lml_guides_trace(mesh.Handle, starts, Native.Size(starts.Length), thetaDegrees, startAngleDegrees, ref chosen, out handle));
            return new GuideCurves(handle);
        }

        /// <summary>The number of curves (one per start point).</summary>
        public int Count
        {
            get
            {
                UIntPtr count;
                Native.Check(NativeMethods.lml_guides_count(Handle, out count));
                return Native.Count(count);
            }
        }

        /// <summary>The offset table (Count + 1 values from 0): curve i has points Offsets[i] .. Offsets[i + 1].</summary>
        public int[] Offsets() =>
            Native.Offsets(Native.Read((UIntPtr[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_guides_offsets(Handle, b, c, out n)));

        /// <summary>The points of all curves, x, y, z each, starting at the start points.</summary>
        public double[] Points() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_guides_points(Handle, b, c, out n));

        /// <summary>The points of all curves as points on mesh edges (the same points as <see cref="Points"/>).</summary>
        public EdgePoint[] EdgePoints() =>
            Native.Read((EdgePoint[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_guides_edge_points(Handle, b, c, out n));

        /// <summary>Why each curve ended.</summary>
        public TraceStop[] Stops() =>
            Native.Read((TraceStop[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_guides_stops(Handle, b, c, out n));

        /// <summary>The length of each curve, in mesh units.</summary>
        public double[] Lengths() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_guides_lengths(Handle, b, c, out n));

        /// <summary>Where different curves cross and where a curve meets itself.</summary>
        public Crossing[] Crossings() =>
            Native.Read((Crossing[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_guides_crossings(Handle, b, c, out n));

        /// <summary>
        /// Throws <see cref="LamellaException"/> with <see cref="Status.InvalidGuides"/> (the message names the curves)
        /// unless the curves are free of crossings and self-intersections and ordered like level sets (paper
        /// Sec. 3.2.2): each curve separates its two neighbours.
        /// </summary>
        public void CheckOrder() => Native.Check(NativeMethods.lml_guides_check_order(Handle));

        /// <summary>Releases the native curves (harmless to call twice).</summary>
        public void Dispose() => Handle.Dispose();
    }
}
