using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Data;
using Lamella.Conversion;
using Lamella.Hosting;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Strip Net: a gridshell of two strip families (paper Sec. 4.1 and 5.1). Two fields are started by the default
    /// start search and optimised together, each toward its θ, crossing at no less than a minimum angle; strips are built
    /// on the level curves of both; the quad net where they cross and the nodes (strip ids, arc lengths, node axis, ruling
    /// angle) come out with them. One-shot: solves when Solve is true.
    /// </summary>
    public class StripNetComponent : LamellaComponent
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
            pManager.AddMeshParameter("Mesh", "M", "The surface (triangulated and cleaned like Strip Field's input).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Theta 1", "θ1", "Angle of the first family, in degrees, in [0, 180]: 0 and 180 asymptotic curves, 90 geodesics. Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddNumberParameter("Theta 2", "θ2", "Angle of the second family, as Theta 1. Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddNumberParameter("Min Angle", "MA", "Smallest angle at which the two families may cross, in degrees, in [0, 90). Default 30.", GH_ParamAccess.item, 30.0);
            pManager.AddIntegerParameter("Count", "N", "Level curves (strips) per family, ≥ 2. Default 8.", GH_ParamAccess.item, 8);
            pManager.AddNumberParameter("Width", "W", "Width of each flat strip, in document units, > 0. Default: a round number near 2 % of the curves' extent (named in a remark).", GH_ParamAccess.item);
            pManager[5].Optional = true;
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1). Default 300.", GH_ParamAccess.item, 300);
            pManager.AddBooleanParameter("Solve", "Sv", "True solves within this solution. Default false.", GH_ParamAccess.item, false);
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

        /// <summary>
        /// Strip <paramref name="k"/>'s angle atan |k| at the node, "straight" where it has none, and a warning when the
        /// singular point of its ruling is near the strip.
        /// </summary>
        private static string DiagnosticText(Node node, int k)
        {
            string angle = node.DarbouxAngleDegrees[k].HasValue
                ? string.Format(CultureInfo.InvariantCulture, "{0:0.#}°", node.DarbouxAngleDegrees[k].Value)
                : "straight";
            return node.SingularPointNear[k] ? angle + " (singular point near)" : angle;
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh input = null;
            if (!DA.GetData(0, ref input) || input == null) return;
            double[] thetas = { 60.0, 60.0 };
            double minAngle = 30.0, width = double.NaN;
            int count = 8, maxIterations = 300;
            bool solveNow = false;
            DA.GetData(1, ref thetas[0]);
            DA.GetData(2, ref thetas[1]);
            DA.GetData(3, ref minAngle);
            DA.GetData(4, ref count);
            bool widthGiven = DA.GetData(5, ref width);
            DA.GetData(6, ref maxIterations);
            DA.GetData(7, ref solveNow);
            if (count < 2 || maxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, count < 2 ? "Count must be at least 2" : "Max Iterations must be at least 1");
                return;
            }
            if (!solveNow)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "set Solve to true to design the net");
                return;
            }
            CleanMesh clean = CleanMeshInput(input);
            LamellaMesh mesh = Keep(DA, LamellaMesh.FromArrays(clean.Xyz, clean.Triangles));
            double[][] start = NetSolver.DefaultStart(mesh, thetas[0], thetas[1], minAngle);
            NetSolver net = Keep(DA, new NetSolver(mesh, thetas[0], thetas[1], start[0], start[1], minAngle));
            NetReport report = net.Report;
            while (report.Iterations < maxIterations && !report.IsConverged)
            {
                if (GH_Document.IsEscapeKeyDown()) break;
                report = net.Step((int)Math.Min(10, maxIterations - report.Iterations));
            }
            if (!report.IsConverged)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture, "not converged after {0} iterations", report.Iterations));

            var strips = new Strips[2];
            var curves = new DataTree<object>();
            var meshes = new DataTree<object>();
            var acceptable = new List<bool>();
            var verdicts = new List<string>();
            for (int k = 0; k < 2; k++)
            {
                LevelCurves levels = Keep(DA, LevelCurves.OfNet(net, k, count, 0.0));
                if (!widthGiven)
                {
                    width = StripDefaults.Width(levels.Points());
                    widthGiven = true;
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                        "Width not set: {0:G6} ({1}; about {2:0.#} % of the curves' extent)", width,
                        RhinoConversion.DocumentUnits() ?? "document units", 100 * StripDefaults.WidthFraction));
                }
                strips[k] = Keep(DA, Strips.Build(levels, StripParams.Default(thetas[k], width)));
                Verdict verdict = strips[k].Verdict;
                if (!verdict.IsAcceptable) AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "family " + (k + 1) + ": " + verdict.Message);
                acceptable.Add(verdict.IsAcceptable);
                verdicts.Add("family " + (k + 1) + ": " + verdict);
                int[] vertexOffsets = strips[k].VertexOffsets();
                curves.AddRange(RhinoConversion.Polylines(new Packed(strips[k].Centres(), strips[k].PointOffsets(), 3)), new GH_Path(k));
                meshes.AddRange(RhinoConversion.QuadMeshes(StripArrays.Split(strips[k].Vertices(), 3, strips[k].Quads(), vertexOffsets, strips[k].QuadOffsets())), new GH_Path(k));
            }
            StripNet grid = Keep(DA, new StripNet(net, strips[0], strips[1]));
            Node[] nodes = grid.Nodes();
            var axes = new List<Vector3d>();
            var data = new List<string>();
            var positions = new double[3 * nodes.Length];
            for (int i = 0; i < nodes.Length; i++)
            {
                Node node = nodes[i];
                Array.Copy(node.Position, 0, positions, 3 * i, 3);
                axes.Add(new Vector3d(node.Axis[0], node.Axis[1], node.Axis[2]));
                data.Add(string.Format(CultureInfo.InvariantCulture, "S{0} at {1:0.###}, T{2} at {3:0.###}; rulings {4:0.#}° apart; binormal to developable ruling (Sec. 5.1): S {5}, T {6}",
                    node.Strips[0], node.ArcLengths[0], node.Strips[1], node.ArcLengths[1], node.RulingAngleDegrees,
                    DiagnosticText(node, 0), DiagnosticText(node, 1)));
            }
            Message = string.Format(CultureInfo.InvariantCulture, "{0} nodes · crossing ≥ {1:0.#}°", nodes.Length, report.MinIntersectionDegrees);
            DA.SetDataTree(0, curves);
            DA.SetDataTree(1, meshes);
            DA.SetData(2, RhinoConversion.QuadMesh(grid.Vertices(), grid.Quads()));
            DA.SetDataList(3, RhinoConversion.Points(positions));
            DA.SetDataList(4, axes);
            DA.SetDataList(5, data);
            DA.SetDataList(6, acceptable);
            DA.SetData(7, string.Format(CultureInfo.InvariantCulture,
                "{0} iterations{1}; angle error RMS {2:0.###}° / {3:0.###}°; crossing angle min {4:0.#}°, mean {5:0.#}° ({6} faces below {7:0.#}°)\n{8}",
                report.Iterations, report.IsConverged ? ", converged" : "", report.AngleErrorRmsDegrees[0], report.AngleErrorRmsDegrees[1],
                report.MinIntersectionDegrees, report.MeanIntersectionDegrees, report.FacesBelowMin, minAngle, string.Join("\n", verdicts)));
        }
    }
}
