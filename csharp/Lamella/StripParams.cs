using System.Runtime.InteropServices;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>The weights of the strip energies (paper Sec. 3.4), each finite and ≥ 0, planarity > 0 (<c>LmlStripWeights</c>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct StripWeights
    {
        /// <summary>Eq. 8 on polyline vertices, and (weighted with Planarity) on the quad normals.</summary>
        public double Angle;
        /// <summary>Eq. 9 on polyline vertices.</summary>
        public double Binormal;
        /// <summary>Distance of the polyline vertices from the surface (default 0.01; Appro reports the distance kept).</summary>
        public double Surface;
        /// <summary>Tangential drift along the surface.</summary>
        public double Slide;
        /// <summary>Fairness of the polyline.</summary>
        public double Fair;
        /// <summary>Eq. 16–17: planar quads.</summary>
        public double Planarity;
        /// <summary>Proximity of the rulings to their initial guess.</summary>
        public double RulingAnchor;
    }

    /// <summary>Parameters of a strip computation (<c>LmlStripParams</c>); start from <see cref="Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct StripParams
    {
        /// <summary>Binormal-strip stage: rounds of (project, optimise).</summary>
        public uint BinormalRounds;
        /// <summary>Iterations per binormal round and in the first rectifying round.</summary>
        public uint IterationsPerRound;
        /// <summary>Iterations of the final rectifying round.</summary>
        public uint FinalIterations;
        /// <summary>Iterations of the closing polish.</summary>
        public uint PolishIterations;
        /// <summary>Target angle θ between binormal and surface normal, degrees: the θ of the field.</summary>
        public double ThetaDegrees;
        /// <summary>Width of the flat strip, > 0, in the mesh's unit.</summary>
        public double Width;
        /// <summary>
        /// The largest angle error in degrees, in (0, 180), of a quad of an acceptable pattern (default 2): beyond it, or
        /// with flipped quads, the strips are built but their <see cref="Strips.Verdict"/> is not acceptable.
        /// </summary>
        public double ToleranceDegrees;
        /// <summary>The strip energy weights.</summary>
        public StripWeights Weights;

        /// <summary>The library's defaults for strips of <paramref name="width"/> along θ-curves.</summary>
        public static StripParams Default(double thetaDegrees, double width)
        {
            StripParams parameters;
            Native.Check(NativeMethods.lml_strip_params_default(thetaDegrees, width, out parameters));
            return parameters;
        }
    }
}
