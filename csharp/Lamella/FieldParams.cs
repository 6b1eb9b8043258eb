using System.Runtime.InteropServices;
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
    public struct FieldParams
    {
        /// <summary>The curve family.</summary>
        public Family Family;
        /// <summary>1: run the library's warm-up continuation first (paper Fig. 15); 0: use <see cref="Weights"/> from the start.</summary>
        public uint WarmUp;
        /// <summary>Target angle between binormal and surface normal in degrees, in [0, 180] (pseudo-geodesics).</summary>
        public double ThetaDegrees;
        /// <summary>The final weights.</summary>
        public Weights Weights;
        /// <summary>Target gradient norm (strip spacing ≈ 1 / target); 0 keeps the initial field's mean.</summary>
        public double GradientTarget;
        /// <summary>Convergence: 3 iterations in a row each lower the energy by less than this fraction.</summary>
        public double RelativeTolerance;

        /// <summary>The library's defaults for a family (θ is used by <see cref="Family.PseudoGeodesic"/> only).</summary>
        public static FieldParams Default(Family family, double thetaDegrees)
        {
            FieldParams parameters;
            Native.Check(NativeMethods.lml_field_params_default((uint)family, thetaDegrees, out parameters));
            return parameters;
        }
    }
}
