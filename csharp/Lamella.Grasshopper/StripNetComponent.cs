using System;
using System.Globalization;
using Grasshopper.Kernel;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Strip Net: a gridshell of two strip families (paper Sec. 4.1 and 5.1). Two fields are started by the default
    /// start search and optimised together, each toward its θ, crossing at no less than a minimum angle; strips are built
    /// on the level curves of both; the quad net where they cross and the nodes (strip ids, arc lengths, node axis, ruling
    /// angle) come out with them. One-shot: solves when Solve is true.
    /// </summary>
    public class StripNetComponent : GridshellComponent
    {
        public StripNetComponent()
            : base("Strip Net", "Net",
                "A gridshell of two strip families (paper Sec. 4.1): two fields optimised together toward their angles θ (0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics), crossing at no less than Min Angle; rectifying strips on both, the quad net where their curves cross and the nodes where the strips cross. Solves when Solve is true.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("8a5c1f27-3e94-4d6b-b0a2-6f4e9d21c7b5");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            RegisterGridshellInputs(pManager,
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
            pManager.AddCurveParameter("Curves", "C", "The strips' centre lines: branch {0} the first family, {1} the second.", GH_ParamAccess.tree);
            pManager.AddMeshParameter("Strip Meshes", "S", "One planar-quad mesh per strip: branch {0} the first family, {1} the second.", GH_ParamAccess.tree);
            pManager.AddMeshParameter("Net", "N", "The quad net: a vertex where a level curve of each family crosses, a quad where four crossings exist.", GH_ParamAccess.item);
            pManager.AddPointParameter("Nodes", "P", "Where a strip of the first family crosses one of the second.", GH_ParamAccess.list);
            pManager.AddVectorParameter("Node Axes", "X", "Per node, the unit node axis (the mean of the two strips' rulings there).", GH_ParamAccess.list);
            pManager.AddTextParameter("Node Data", "D", "Per node: the strips (S<i> of the first family, T<j> of the second), the arc length of the node along each (where its hole goes on the flat strip), the angle between the two rulings (0° for a torsion-free node) and, per strip, the angle atan |k| between its binormal and the ruling of its rectifying developable (Sec. 5.1), flagged where the ruling's singular point is near the strip.", GH_ParamAccess.list);
            pManager.AddBooleanParameter("Acceptable", "A", "Per family, true when its strips meet θ within the library's tolerance without flipped quads.", GH_ParamAccess.list);
            pManager.AddTextParameter("Report", "R", "Iterations, each family's angle error, the crossing angles and each family's verdict.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            GridshellInputs inputs = ReadInputs(DA, new[] { 60.0, 60.0 }, 0, "net");
            if (inputs == null) return;
            double[] thetas = inputs.Thetas;
            LamellaMesh mesh;
            double[][] start = DefaultStart(DA, inputs, out mesh);
            NetSolver net = new NetSolver(mesh, thetas[0], thetas[1], start[0], start[1], inputs.MinAngle);
            NetReport report = SolveNet(DA, net, inputs.MaxIterations);
            FamilyStrips strips = BuildStrips(DA, inputs, k => LevelCurves.OfNet(net, k, inputs.Count, 0.0));
            StripNet grid = Keep(DA, new StripNet(net, strips.Strips[0], strips.Strips[1]));
            Node[] nodes = grid.Nodes();
            Message = string.Format(CultureInfo.InvariantCulture, "{0} nodes · crossing ≥ {1:0.#}°", nodes.Length, report.MinIntersectionDegrees);
            DA.SetDataTree(0, strips.Curves);
            DA.SetDataTree(1, strips.Meshes);
            DA.SetData(2, RhinoConversion.QuadMesh(grid.Vertices(), grid.Quads()));
            SetNodes(DA, 3, nodes, node => NodeText(node, "S", "T"));
            DA.SetDataList(6, strips.Acceptable);
            DA.SetData(7, string.Format(CultureInfo.InvariantCulture,
                "{0} iterations{1}; angle error RMS {2:0.###}° / {3:0.###}°; crossing angle min {4:0.#}°, mean {5:0.#}° ({6} faces below {7:0.#}°)\n{8}",
                report.Iterations, report.IsConverged ? ", converged" : "", report.AngleErrorRmsDegrees[0], report.AngleErrorRmsDegrees[1],
                report.MinIntersectionDegrees, report.MeanIntersectionDegrees, report.FacesBelowMin, inputs.MinAngle, string.Join("\n", strips.Verdicts)));
        }
    }
}
