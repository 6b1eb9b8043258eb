using System;
using System.Collections.Generic;
using Lamella.Conversion;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// Start fields for <see cref="FieldSolver"/> from a designer's intent (paper Sec. 3.2.2): traced guide curves
    /// (Eq. 5–7) or strokes sketched on the surface (Fig. 14).
    /// </summary>
    public static class InitialField
    {
        /// <summary>
        /// The field that interpolates the ordered guides (guide i lies on the level set F = i) and is as smooth as
        /// possible elsewhere (paper Eq. 5–7, λ0 = 3, λ1 = 1), one value per vertex of <paramref name="mesh"/>, which must
        /// be the mesh the guides were traced on. <paramref name="gradientTarget"/> is the suggested
        /// <see cref="FieldParams.GradientTarget"/> that keeps the guides' spacing. Fewer than two guides, or guides that
        /// cross, throw <see cref="Status.InvalidGuides"/>.
        /// </summary>
        public static double[] FromGuides(LamellaMesh mesh, GuideCurves guides, out double gradientTarget)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (guides == null) throw new ArgumentNullException(nameof(guides));
            // One value per vertex: sized up front, so the least-squares solve runs once, not once per call of the
            // two-call pattern.
            var values = new double[mesh.VertexCount];
            UIntPtr needed;
            Native.Check(NativeMethods.lml_field_values_from_guides(mesh.Handle, guides.Handle, values, Native.Size(values.Length), out needed, out gradientTarget));
            return values;
        }

        /// <summary>
        /// The start of a constant-slope family (paper Sec. 5.2.3): a smooth field whose level curves follow, wherever the
        /// slope <paramref name="slopeDegrees"/> (in (−90, 90)) about <paramref name="axis"/> (x, y, z; finite, not zero) is
        /// reachable, the tangent directions of that slope. Solve it with <see cref="FieldParams.ConstantSlope"/> of the
        /// same axis and slope. A surface that reaches the slope nowhere throws <see cref="Status.SingularField"/>.
        /// </summary>
        public static double[] FromSlope(LamellaMesh mesh, double[] axis, double slopeDegrees)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            double[] checkedAxis = Vectors.Axis(axis, nameof(axis));
            var values = new double[mesh.VertexCount];
            UIntPtr needed;
            Native.Check(NativeMethods.lml_field_values_from_slope(mesh.Handle, checkedAxis, slopeDegrees, values, Native.Size(values.Length), out needed));
            return values;
        }

        /// <summary>
        /// The smooth field whose level sets follow the strokes (each a polyline, x, y, z per point, drawn near the
        /// surface, in the order the family should run) and the estimated θ in degrees that they suggest.
        /// Strokes too far from the surface, crossing, too short, or fewer than two throw <see cref="Status.InvalidStrokes"/>.
        /// </summary>
        public static double[] FromStrokes(LamellaMesh mesh, IList<double[]> strokes, out double thetaDegrees)
        {
            if (strokes == null) throw new ArgumentNullException(nameof(strokes));
            Packed packed = Packing.Pack(strokes, 3);
            return FromStrokes(mesh, packed.Values, packed.Offsets, out thetaDegrees);
        }

        /// <summary>As <see cref="FromStrokes(LamellaMesh, IList{double[]}, out double)"/>, the strokes packed: points x, y, z each, cut by offsets (count + 1, from 0, in points).</summary>
        public static double[] FromStrokes(LamellaMesh mesh, double[] points, int[] offsets, out double thetaDegrees)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            if (points == null) throw new ArgumentNullException(nameof(points));
            if (offsets == null) throw new ArgumentNullException(nameof(offsets));
            if (points.Length % 3 != 0) throw new ArgumentException("points holds " + points.Length + " values, not a multiple of 3", nameof(points));
            if (offsets.Length == 0) throw new ArgumentException("an offset table has at least one entry (0)", nameof(offsets));
            var sizes = new UIntPtr[offsets.Length];
            for (int i = 0; i < offsets.Length; i++)
            {
                // The library checks the table itself (naming the offset); only negative values cannot be passed on.
                if (offsets[i] < 0) throw new ArgumentOutOfRangeException(nameof(offsets), "offset " + i + " is negative (" + offsets[i] + ")");
                sizes[i] = Native.Size(offsets[i]);
            }
            var values = new double[mesh.VertexCount];
            UIntPtr needed;
            Native.Check(NativeMethods.lml_field_values_from_strokes(mesh.Handle, points, Native.Size(points.Length / 3), sizes,
                Native.Size(offsets.Length - 1), values, Native.Size(values.Length), out needed, out thetaDegrees));
            return values;
        }
    }
}
