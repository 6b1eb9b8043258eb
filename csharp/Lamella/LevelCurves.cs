using System;
using Lamella.Conversion;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// Level polylines of a field (<c>LmlCurves</c>) with their levels, normals and closed flags. Immutable; they
    /// keep their own copy of the surface, so the field may be stepped on or disposed.
    /// </summary>
    public sealed class LevelCurves : IDisposable
    {
        internal readonly CurvesHandle Handle;

        private LevelCurves(CurvesHandle handle)
        {
            Handle = handle;
        }

        /// <summary>
        /// The level curves at <paramref name="levels"/> (inside the field's range). <paramref name="spacing"/> 0 keeps one
        /// point per crossed mesh edge; > 0 resamples at about that arc length (the strips' quad length).
        /// </summary>
        public static LevelCurves AtLevels(FieldSolver field, double[] levels, double spacing)
        {
            if (field == null) throw new ArgumentNullException(nameof(field));
            if (levels == null) throw new ArgumentNullException(nameof(levels));
            CurvesHandle handle = null;
            Native.Check(field.Locked(h => NativeMethods.lml_curves_new(h, levels, Native.Size(levels.Length), spacing, out handle)));
            return new LevelCurves(handle);
        }

        /// <summary>
        /// The level curves of field <paramref name="k"/> (below <see cref="NetSolver.FamilyCount"/>) of a net at
        /// <paramref name="count"/> values spread uniformly over its range, extremes left out: the base curves of that
        /// family's strips (<c>lml_curves_new_from_net</c>). A 3-web's strips take <see cref="OfWeb"/> instead.
        /// </summary>
        public static LevelCurves OfNet(NetSolver net, int k, int count, double spacing)
        {
            if (net == null) throw new ArgumentNullException(nameof(net));
            net.CheckFamily(k, nameof(k));
            if (count < 0) throw new ArgumentOutOfRangeException(nameof(count));
            CurvesHandle handle = null;
            Native.Check(net.Locked(h => NativeMethods.lml_curves_new_from_net(h, (uint)k, Native.Size(count), spacing, out handle)));
            return new LevelCurves(handle);
        }

        /// <summary>
        /// The level curves of field <paramref name="k"/> (0: F, 1: H, 2: G) of a 3-web at its even-pace levels
        /// (<see cref="NetSolver.WebLevels"/> with the same <paramref name="countF"/>, <paramref name="countH"/> and
        /// <paramref name="kagome"/>): the base curves of that family's strips, for <see cref="StripWeb"/>
        /// (<c>lml_curves_new_from_web</c>). <paramref name="spacing"/> as in <see cref="AtLevels"/>.
        /// </summary>
        /// <exception cref="LamellaException">A net of two families, a count or the spacing out of range (named), a constant field.</exception>
        public static LevelCurves OfWeb(NetSolver net, int k, int countF, int countH, bool kagome, double spacing)
        {
            if (net == null) throw new ArgumentNullException(nameof(net));
            NetSolver.CheckWebFamily(k, nameof(k));
            CurvesHandle handle = null;
            Native.Check(net.WebCall(countF, countH, kagome, (h, f, g, kg) => NativeMethods.lml_curves_new_from_web(h, (uint)k, f, g, kg, spacing, out handle)));
            return new LevelCurves(handle);
        }

        /// <summary>
        /// The boundary of the region where the slope <paramref name="slopeDegrees"/> about <paramref name="axis"/> is
        /// reachable (paper Sec. 5.2.3: the isophote where the tangent planes themselves have that slope, moved a little
        /// inwards); the reachable region lies on the steeper side. No polyline: all of the surface is reachable, or none.
        /// </summary>
        public static LevelCurves ReachableBoundary(LamellaMesh mesh, double[] axis, double slopeDegrees)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            double[] checkedAxis = Vectors.Axis(axis, nameof(axis));
            CurvesHandle handle = null;
            Native.Check(NativeMethods.lml_curves_new_reachable_boundary(mesh.Handle, checkedAxis, slopeDegrees, out handle));
            return new LevelCurves(handle);
        }

        /// <summary>The level curves at <paramref name="count"/> values spread uniformly over the field's range, extremes left out.</summary>
        public static LevelCurves Uniform(FieldSolver field, int count, double spacing)
        {
            if (field == null) throw new ArgumentNullException(nameof(field));
            if (count < 0) throw new ArgumentOutOfRangeException(nameof(count));
            CurvesHandle handle = null;
            Native.Check(field.Locked(h => NativeMethods.lml_curves_new_uniform(h, Native.Size(count), spacing, out handle)));
            return new LevelCurves(handle);
        }

        /// <summary>The number of polylines.</summary>
        public int Count
        {
            get
            {
                UIntPtr count;
                Native.Check(NativeMethods.lml_curves_count(Handle, out count));
                return Native.Count(count);
            }
        }

        /// <summary>The offset table (Count + 1 values from 0): polyline i has points Offsets[i] .. Offsets[i + 1].</summary>
        public int[] Offsets() =>
            Native.Offsets(Native.Read((UIntPtr[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_curves_offsets(Handle, b, c, out n)));

        /// <summary>The points of all polylines, x, y, z each; a closed polyline does not repeat its first point.</summary>
        public double[] Points() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_curves_points(Handle, b, c, out n));

        /// <summary>The unit surface normal at each point.</summary>
        public double[] Normals() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_curves_normals(Handle, b, c, out n));

        /// <summary>The level value of each polyline.</summary>
        public double[] Levels() =>
            Native.Read((double[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_curves_levels(Handle, b, c, out n));

        /// <summary>Whether each polyline closes on itself.</summary>
        public bool[] Closed() =>
            Array.ConvertAll(Native.Read((byte[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_curves_closed(Handle, b, c, out n)), f => f != 0);

        /// <summary>Releases the native curves (harmless to call twice).</summary>
        public void Dispose() => Handle.Dispose();
    }
}
