using System.Runtime.InteropServices;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>
    /// The weights of a base-mesh optimisation's terms (paper Sec. 3.5; its Table 3 gives them per figure), on the net
    /// scaled to mean segment length 1 (<c>LmlBaseMeshWeights</c>): each finite and ≥ 0, <see cref="Curve"/> > 0, and
    /// <see cref="Torsion"/> > 0 for torsion-free nodes. Start from <see cref="Default"/>; set them with
    /// <see cref="BaseMeshSolver.SetWeights"/> before the first step.
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct BaseMeshWeights
    {
        /// <summary>The curve conditions: vertex normals, binormals and each family's own rows. Default 1.</summary>
        public double Curve;
        /// <summary>Fairness ‖v_back − 2v + v_front‖² along each polyline. Default 1e-3.</summary>
        public double Fair;
        /// <summary>Closeness: the distance to the reference along its normal (and, past its boundary, the tangential offset). Default 1.</summary>
        public double Close;
        /// <summary>
        /// The pull ‖v − v_start‖² to the start positions: what holds a net's extent (a net that cannot meet its families
        /// where it was extracted shrinks toward its centre). Default 1e-4.
        /// </summary>
        public double Pull;
        /// <summary>The torsion-free node rows of Eq. 21 (torsion-free sessions only). Default 1.</summary>
        public double Torsion;

        /// <summary>The library's defaults, a session's own unless set (<c>lml_base_mesh_weights_default</c>).</summary>
        public static BaseMeshWeights Default()
        {
            BaseMeshWeights weights;
            Native.Check(NativeMethods.lml_base_mesh_weights_default(out weights));
            return weights;
        }
    }
}
