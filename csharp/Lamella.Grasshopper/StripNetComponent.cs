using System;
using System.Globalization;
using Grasshopper.Kernel;
using Lamella.Hosting;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Strip Net: a gridshell of two strip families (paper Sec. 4.1 and 5.1). Two fields are started by the default
    /// start search and optimised together, each toward its θ, crossing at no less than a minimum angle; strips are built
    /// on the level curves of both; the quad net where they cross and the nodes (strip ids, arc lengths, node axis, ruling
    /// angle) come out with them. Live like Strip Field (Run: each solution steps the fields within a time budget and
    /// shows their level curves, the strips and nodes follow once it converges or stops) or one-shot (Solve).
    /// </summary>
    public class StripNetComponent : GridshellComponent
    {
        public StripNetComponent()
            : base("Strip Net", "Net",
                "A gridshell of two strip families (paper Sec. 4.1): two fields optimised together toward their angles θ (0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics), crossing at no less than Min Angle; rectifying strips on both, the quad net where their curves cross and the nodes where the strips cross. Run solves live (the level curves move while it steps), Solve solves to convergence at once.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("8a5c1f27-3e94-4d6b-b0a2-6f4e9d21c7b5");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            RegisterGridshellInputs(pManager, "net",
                new[]
                {
                    "Angle of the first family, in degrees, in [0, 180]: 0 and 180 asymptotic curves, 90 geodesics. Default 60.",
                    "Angle of the second family, as Theta 1. Default 60.",
                },
                new[] { 60.0, 60.0 },
                "Smallest angle at which the two families may cross, in degrees, in [0, 90). Default 30.",
                "Level curves (strips) per family, ≥ 2. Default 8.", 0, null);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            RegisterGridshellOutputs(pManager, "branch {0} the first family, {1} the second", "",
                p => p.AddMeshParameter("Net", "N", "The quad net: a vertex where a level curve of each family crosses, a quad where four crossings exist." + BuiltOnceStopped, GH_ParamAccess.item),
                "P", "X", "Where a strip of the first family crosses one of the second.", "the strips (S<i> of the first family, T<j> of the second)",
                "Iterations, each family's angle error, the crossing angles and each family's verdict");
        }

        /// <summary>The state of the net: iterations, each family's angle error, the crossing angles.</summary>
        private static string Describe(NetReport report, double minAngle) =>
            string.Format(CultureInfo.InvariantCulture,
                "{0} iterations{1}; angle error RMS {2:0.###}° / {3:0.###}°; crossing angle min {4:0.#}°, mean {5:0.#}° ({6} faces below {7:0.#}°)",
                report.Iterations, report.IsConverged ? ", converged" : "", report.AngleErrorRmsDegrees[0], report.AngleErrorRmsDegrees[1],
                report.MinIntersectionDegrees, report.MeanIntersectionDegrees, report.FacesBelowMin, minAngle);

        protected override void SolveLive(IGH_DataAccess DA)
        {
            GridshellInputs inputs = ReadInputs(DA, new[] { 60.0, 60.0 }, 0);
            if (inputs == null) return;
            double[] thetas = inputs.Thetas;
            SolverSession<NetSolver, NetReport> session = NetSession(DA, inputs, "net",
                (mesh, start) => new NetSolver(mesh, thetas[0], thetas[1], start[0], start[1], inputs.MinAngle));
            if (session == null) return;
            NetSolver net = session.Solver;
            Func<int, LevelCurves> curves = k => LevelCurves.OfNet(net, k, inputs.Count, 0.0);
            NetReport report = AdvanceOrShowIterate(DA, session, inputs, curves, 7, r => Describe(r, inputs.MinAngle));
            if (report == null) return;
            FamilyStrips strips = BuildStrips(DA, inputs, curves);
            StripNet grid = Keep(DA, new StripNet(net, strips.Strips[0], strips.Strips[1]));
            Node[] nodes = grid.Nodes();
            Message = string.Format(CultureInfo.InvariantCulture, "{0} nodes · crossing ≥ {1:0.#}°", nodes.Length, report.MinIntersectionDegrees);
            DA.SetDataTree(0, strips.Curves);
            DA.SetDataTree(1, strips.Meshes);
            DA.SetData(2, RhinoConversion.QuadMesh(grid.Vertices(), grid.Quads()));
            SetNodes(DA, 3, nodes, node => NodeText(node, "S", "T"));
            DA.SetDataList(6, strips.Acceptable);
            DA.SetData(7, Describe(report, inputs.MinAngle) + "\n" + string.Join("\n", strips.Verdicts));
        }
    }
}
