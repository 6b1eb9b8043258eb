using System;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Optimise Net: moves the vertices of a quad net (Strip Net's Net, or any quad mesh whose quads form rows and
    /// columns) near a reference surface until its rows and columns are the asked families exactly (paper Sec. 3.5),
    /// optionally with torsion-free nodes (Sec. 5.2.1, Eq. 21: the strips of a node's row and column share its ruling)
    /// or as curves of constant slope about a Slope Axis; then every polyline carries a developable strip of planar
    /// quads. Live (Run) or one-shot (Solve), see <see cref="NetOptimisationComponent"/>.
    /// </summary>
    public class OptimiseNetComponent : NetOptimisationComponent
    {
        public OptimiseNetComponent()
            : base("Optimise Net", "OptNet",
                "Moves a net's vertices near the reference surface until its rows and columns are exact families of angle θ (paper Sec. 3.5: 0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics) and, with Torsion-free, until the strips of every node's row and column share its ruling (Sec. 5.2.1; Torsion-Free Net always asks for it); with a Slope Axis, until both families have constant slope about it (parallel node axes, Sec. 5.2.2). Then each row and column carries a developable strip of planar quads. Run optimises live (the net and its nodes move while it steps), Solve to convergence at once.",
                "StripField", false)
        {
        }

        public override Guid ComponentGuid => new Guid("b12cb7c8-99fb-454c-b55e-dbf79979dcd4");
    }
}
