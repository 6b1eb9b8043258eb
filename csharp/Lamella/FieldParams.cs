using System;
using System.Linq;
using System.Runtime.InteropServices;
using Lamella.Conversion;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>The curve family the level sets of a field should form (<c>LML_FAMILY_*</c>).</summary>
    public enum Family : uint
    {
        /// <summary>The binormal keeps the angle θ to the surface normal (paper Eq. 8–10).</summary>
        PseudoGeodesic = 0,
        /// <summary>Geodesics, θ = 90° (paper Eq. 13).</summary>
        Geodesic = 1,
        /// <summary>Asymptotic curves, θ = 0° (paper Eq. 13).</summary>
        Asymptotic = 2,
        /// <summary>
        /// Curves of constant slope β = <see cref="FieldParams.ThetaDegrees"/> in (−90°, 90°) about
        /// <see cref="FieldParams.SlopeAxis"/> (paper Sec. 5.2.3, Eq. 22); start them from <see cref="InitialField.FromSlope"/>.
        /// </summary>
        ConstantSlope = 3,
        /// <summary>As <see cref="ConstantSlope"/>, with the slope an unknown too, started at the given β.</summary>
        FreeSlope = 4,
    }

    /// <summary>The weights λ of the field energy (paper Eq. 12), each finite and ≥ 0 (<c>LmlWeights</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Weights
    {
        /// <summary>λ_fair, fairness (Eq. 6).</summary>
        public double Fair;
        /// <summary>λ_grad, gradient norm (Eq. 11).</summary>
        public double Grad;
        /// <summary>λ_angle, the curve term of the family.</summary>
        public double Angle;

        /// <summary>Creates weights.</summary>
        public Weights(double fair, double grad, double angle)
        {
            Fair = fair;
            Grad = grad;
            Angle = angle;
        }
    }

    /// <summary>Parameters of a field optimisation (<c>LmlFieldParams</c>); start from <see cref="Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FieldParams : IEquatable<FieldParams>
    {
        /// <summary>The curve family.</summary>
        public Family Family;
        /// <summary>1: run the library's warm-up continuation first (paper Fig. 15); 0: use <see cref="Weights"/> from the start.</summary>
        public uint WarmUp;
        /// <summary>Target angle between binormal and surface normal in degrees, in [0, 180] (pseudo-geodesics); the slope β in (−90, 90) of the constant-slope families.</summary>
        public double ThetaDegrees;
        /// <summary>The final weights.</summary>
        public Weights Weights;
        /// <summary>Target gradient norm (strip spacing ≈ 1 / target); 0 keeps the initial field's mean.</summary>
        public double GradientTarget;
        /// <summary>
        /// Convergence: 3 iterations in a row each lower the energy by less than this fraction; the solve also ends when
        /// the curve terms fall to 1e-7, or (meshes of 1,000 vertices and more) when the level curves, measured from
        /// outside every 5 iterations once E_angle ≤ 1e-5, have not improved by 2 % in the last two measures.
        /// </summary>
        public double RelativeTolerance;
        /// <summary>The axis d of the constant-slope families: 3 doubles, finite, not zero (default 0, 0, 1).</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] SlopeAxis;

        /// <summary>The library's defaults for a family (θ is the angle of <see cref="Family.PseudoGeodesic"/>, the slope of the constant-slope families, unused otherwise).</summary>
        public static FieldParams Default(Family family, double thetaDegrees)
        {
            FieldParams parameters;
            Native.Check(NativeMethods.lml_field_params_default((uint)family, thetaDegrees, out parameters));
            return parameters;
        }

        /// <summary>Equal values in every field, the slope axis compared element by element.</summary>
        public bool Equals(FieldParams other) =>
            Family == other.Family && WarmUp == other.WarmUp && ThetaDegrees.Equals(other.ThetaDegrees) && Weights.Equals(other.Weights)
            && GradientTarget.Equals(other.GradientTarget) && RelativeTolerance.Equals(other.RelativeTolerance)
            && (SlopeAxis == other.SlopeAxis || (SlopeAxis != null && other.SlopeAxis != null && SlopeAxis.SequenceEqual(other.SlopeAxis)));

        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is FieldParams other && Equals(other);

        /// <inheritdoc/>
        public override int GetHashCode() => (Family, ThetaDegrees, Weights, GradientTarget, RelativeTolerance).GetHashCode();

        /// <summary>
        /// The defaults of a constant-slope family about <paramref name="axis"/> (3 values) with the slope
        /// <paramref name="slopeDegrees"/>, fixed or (<paramref name="freeSlope"/>) an unknown started there.
        /// </summary>
        public static FieldParams ConstantSlope(double[] axis, double slopeDegrees, bool freeSlope)
        {
            FieldParams parameters = Default(freeSlope ? Family.FreeSlope : Family.ConstantSlope, slopeDegrees);
            parameters.SlopeAxis = Vectors.Axis(axis, nameof(axis));
            return parameters;
        }
    }
}
