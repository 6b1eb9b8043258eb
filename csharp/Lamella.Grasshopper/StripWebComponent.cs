using System;
using System.Globalization;
using Grasshopper;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Data;
using Lamella.Conversion;
using Lamella.Hosting;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Strip Web: a gridshell of three strip families (paper Sec. 4.2 and 5.1). Fields F and H of the first two families
    /// are started by the default start search, G of the third, the diagonal one, as −F − H; the three are optimised
    /// together, each toward its θ, held to F + G + H = 0 (Eq. 18), every pair crossing at no less than a minimum angle.
    /// Strips are built on the web's even-pace levels of all three; the web where the curves cross (triangles, or with
    /// Kagome triangles and hexagons), its polylines per family and the nodes of every pair of crossing strips come out
    /// with them. Live or one-shot like Strip Net (Run: the level curves of the current fields while it steps).
    /// </summary>
    public class StripWebComponent : GridshellComponent
    {
        /// <summary>Output index of the nodes (then their axes and data).</summary>
        private const int NodesOutput = 4;

        /// <summary>The default θ of the three families: an AAG web.</summary>
        private static readonly double[] DefaultThetas = { 0.0, 0.0, 90.0 };

        /// <summary>The prefix of the strip ids of each family in the Node Data text.</summary>
        private static readonly string[] StripPrefixes = { "S", "T", "U" };

        /// <summary>Above this residual of Eq. 18 (relative to the fields' range) the third family is not the diagonals (as `lamella net`).</summary>
        private const double MaxResidual = 1e-5;

        public StripWebComponent()
            : base("Strip Web", "Web",
                "A gridshell of three strip families, a 3-web (paper Sec. 4.2): the fields of the first two families and of the third, the diagonal one, optimised together toward their angles θ (0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics) with F + G + H = 0 at every vertex, every two crossing at no less than Min Angle; rectifying strips on all three at one even level spacing, the web where their curves cross (triangles; with Kagome the third family shifted by half a spacing: triangles and hexagons, each hexagon output as a fan of four triangles), its polylines and the nodes where two strips cross. Run solves live (the level curves move while it steps), Solve solves to convergence at once.",
                "StripWeb")
        {
        }

        public override Guid ComponentGuid => new Guid("665957b2-1e90-4483-8c0a-ab9d3cdf4f0b");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            RegisterGridshellInputs(pManager, "web",
                new[]
                {
                    "Angle of the first family (F), in degrees, in [0, 180]: 0 and 180 asymptotic curves, 90 geodesics. Default 0.",
                    "Angle of the second family (H), as Theta 1. Default 0.",
                    "Angle of the third family (G, the diagonals of the first two: F + G + H = 0), as Theta 1. Default 90 (with 0 and 0: an AAG web).",
                },
                DefaultThetas,
                "Smallest angle at which any two families may cross, in degrees, in [0, 90). Default 30.",
                "Level curves (strips) of each of the first two families at one even spacing, ≥ 2 (the family with the wider range gets more); the third family's levels are their diagonals. Default 8.",
                1, p => p.AddBooleanParameter("Kagome", "K", "True shifts the third family by half a level spacing: a Kagome pattern of triangles and hexagons, whose curves cross in pairs only. Default false.", GH_ParamAccess.item, false));
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            RegisterGridshellOutputs(pManager, "branch {0} the first family, {1} the second, {2} the third", " at the web's levels", p =>
            {
                p.AddMeshParameter("Web", "Wb", "The web: a vertex where the level curves of two or three families cross, triangles between them; with Kagome also hexagons, each as a fan of four triangles from its first corner (a mesh holds no hexagons)." + BuiltOnceStopped, GH_ParamAccess.item);
                p.AddCurveParameter("Polylines", "P", "The web's polylines along each family's levels, through its vertices: branch {0} the first family, {1} the second, {2} the third." + BuiltOnceStopped, GH_ParamAccess.tree);
            },
                "X", "NA", "Where a strip of one family crosses a strip of another (at a vertex of three families, one node per pair).",
                "the two families, their strips (S<i> of the first family, T<j> of the second, U<k> of the third)",
                "Iterations, each family's angle error, how far F + G + H = 0 (Eq. 18) holds, the crossing angles of every pair and each family's verdict");
        }

        /// <summary>A web node as text: its families (1 to 3) and <see cref="GridshellComponent.NodeText"/> with each family's strip prefix.</summary>
        private static string WebNodeText(WebNode node) =>
            string.Format(CultureInfo.InvariantCulture, "families {0} and {1}: {2}", node.Families[0] + 1, node.Families[1] + 1,
                NodeText(node, StripPrefixes[node.Families[0]], StripPrefixes[node.Families[1]]));

        protected override void SolveLive(IGH_DataAccess DA)
        {
            GridshellInputs inputs = ReadInputs(DA, DefaultThetas, 1);
            if (inputs == null) return;
            bool kagome = false;
            DA.GetData(inputs.FirstExtra, ref kagome);
            double[] thetas = inputs.Thetas;
            int count = inputs.Count;
            SolverSession<NetSolver, NetReport> session = NetSession(DA, inputs, "web",
                (mesh, start) => NetSolver.Web(mesh, thetas[0], thetas[1], thetas[2], start[0], start[1], inputs.MinAngle));
            if (session == null) return;
            NetSolver net = session.Solver;
            Func<int, LevelCurves> curves = k => LevelCurves.OfWeb(net, k, count, count, kagome, 0.0);
            NetReport report = AdvanceOrShowIterate(DA, session, inputs, curves, 8, r => net.WebReport().Describe(r, inputs.MinAngle));
            if (report == null) return;
            WebReport webReport = net.WebReport();
            if (webReport.ResidualMax > MaxResidual)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture,
                    "the fields leave F + G + H = 0 by {0:0.#e+0} of their range (above {1:0e+0}): the third family's strips are not on the diagonals", webReport.ResidualMax, MaxResidual));
            FamilyStrips strips = BuildStrips(DA, inputs, curves);
            StripWeb web = Keep(DA, new StripWeb(net, count, count, kagome, strips.Strips[0], strips.Strips[1], strips.Strips[2]));
            double[] xyz = web.Vertices();
            int[][] faces = web.Faces();
            var polylines = new DataTree<object>();
            for (int k = 0; k < 3; k++) polylines.AddRange(RhinoConversion.Polylines(Packing.Gather(xyz, web.Polylines(k))), new GH_Path(k));
            WebNode[] nodes = web.Nodes();
            Message = string.Format(CultureInfo.InvariantCulture, "{0} nodes · crossing ≥ {1:0.#}°", nodes.Length,
                Math.Min(report.MinIntersectionDegrees, Math.Min(webReport.MinIntersectionDegrees[0], webReport.MinIntersectionDegrees[1])));
            DA.SetDataTree(0, strips.Curves);
            DA.SetDataTree(1, strips.Meshes);
            DA.SetData(2, RhinoConversion.TriangleMesh(xyz, MeshArrays.FanTriangles(faces)));
            DA.SetDataTree(3, polylines);
            SetNodes(DA, NodesOutput, nodes, WebNodeText);
            DA.SetDataList(7, strips.Acceptable);
            DA.SetData(8, webReport.Describe(report, inputs.MinAngle) + "\n" + string.Join("\n", strips.Verdicts));
        }
    }
}
