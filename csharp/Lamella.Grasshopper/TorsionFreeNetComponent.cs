using System;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Torsion-Free Net: Optimise Net with torsion-free nodes always asked for (paper Sec. 5.2.1, Eq. 21): the net's
    /// vertices move near the reference until its rows and columns are the asked families and the strips of every node's
    /// row and column share one ruling there, so the two strips can be joined along it. Outputs what Optimise Net does
    /// and, per node, the angle between the two strips' rulings on the net as given (Angles Before) beside the one on the
    /// optimised net (Node Angles). Live (Run) or one-shot (Solve), see <see cref="NetOptimisationComponent"/>.
    /// </summary>
    public class TorsionFreeNetComponent : NetOptimisationComponent
    {
        public TorsionFreeNetComponent()
            : base("Torsion-Free Net", "TFNet",
                "Moves a net's vertices near the reference surface until its rows and columns are exact families of angle θ (paper Sec. 3.5) and the strips of every node's row and column share one ruling there: torsion-free nodes (Sec. 5.2.1, Eq. 21), Optimise Net with Torsion-free always on. Outputs each node's ruling angle before (on the net as given) and after; with a Slope Axis, both families of constant slope about it (parallel node axes, Sec. 5.2.2). Run optimises live (the net and its node angles move while it steps), Solve to convergence at once.",
                "OptimiseWeb", true)
        {
        }

        public override Guid ComponentGuid => new Guid("d5fb83f4-f056-468c-b528-58c46b516dd3");
    }
}
