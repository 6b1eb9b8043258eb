using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Optimise Net: moves the vertices of a quad net (Strip Net's Net, or any quad mesh whose quads form rows and
    /// columns) near a reference surface until its rows and columns are the asked families exactly (paper Sec. 3.5),
    /// optionally with torsion-free nodes (Sec. 5.2.1, Eq. 21: the strips of a node's row and column share its ruling);
    /// then every polyline carries a developable strip of planar quads. One-shot: solves when Solve is true (no live mode).
    /// </summary>
    public class OptimiseNetComponent : BaseMeshComponent
    {
        public OptimiseNetComponent()
            : base("Optimise Net", "OptNet",
                "Moves a net's vertices near the reference surface until its rows and columns are exact families of angle θ (paper Sec. 3.5: 0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics) and, with Torsion-free, until the strips of every node's row and column share its ruling (Sec. 5.2.1); with a Slope Axis, until both families have constant slope about it (parallel node axes, Sec. 5.2.2). Then each row and column carries a developable strip of planar quads. Solves when Solve is true.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("b12cb7c8-99fb-454c-b55e-dbf79979dcd4");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Reference", "M", "The surface the net should stay on (the mesh Strip Net was given, cleaned the same way).", GH_ParamAccess.item);
            pManager.AddMeshParameter("Net", "N", "The net: a quad mesh whose quads form rows and columns, such as Strip Net's Net. Opposite sides of a quad belong to one family; the first side of the first quad (corner 0 to 1) runs along a row. Vertices at one position are welded.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Theta Rows", "θR", "Angle of the rows' family, in degrees, in [0, 180]: 0 and 180 asymptotic curves, 90 geodesics. Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddNumberParameter("Theta Columns", "θC", "Angle of the columns' family, as Theta Rows. Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddBooleanParameter("Torsion-free", "TF", "True also asks for torsion-free nodes: the strips of a node's row and column share one ruling there (Sec. 5.2.1, Eq. 21). Default false.", GH_ParamAccess.item, false);
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1). Default 300.", GH_ParamAccess.item, 300);
            pManager.AddNumberParameter("Width", "W", "Width of each flat strip, in document units, > 0. Default: a round number near 2 % of the net's extent (named in a remark).", GH_ParamAccess.item);
            pManager[6].Optional = true;
            pManager.AddBooleanParameter("Solve", "Sv", "True solves within this solution. Default false.", GH_ParamAccess.item, false);
            pManager.AddVectorParameter("Slope Axis", "SA", "Optional. When given, Theta Rows and Theta Columns are read as slopes β in degrees, in (−90, 90), against the planes orthogonal to this axis: both families become curves of constant slope, every strip's rulings and every node's axis parallel to the axis (Sec. 5.2.2–5.2.3), torsion-free without Torsion-free.", GH_ParamAccess.item);
            pManager[8].Optional = true;
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Net", "N", "The optimised net: the input's quads on the moved vertices (welded).", GH_ParamAccess.item);
            pManager.AddCurveParameter("Polylines", "P", "The net's polylines: branch {0} the rows, {1} the columns.", GH_ParamAccess.tree);
            pManager.AddMeshParameter("Strip Meshes", "S", "One planar-quad mesh per row and column that carries a strip: branch {0} the rows, {1} the columns.", GH_ParamAccess.tree);
            pManager.AddPointParameter("Nodes", "X", "Every vertex inside a row and a column.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Node Angles", "A", "Per node, the angle in degrees between the rulings of its row's and its column's strips (0: torsion-free); NaN where a polyline through it carries no strip.", GH_ParamAccess.list);
            pManager.AddVectorParameter("Node Axes", "NA", "Per node, the unit node axis (the mean of the two rulings); zero where undefined.", GH_ParamAccess.list);
            pManager.AddTextParameter("Report", "R", "Iterations, each family's angle error, the deviation from the reference, the node ruling angles, each family's strip verdict.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh input = null, netInput = null;
            if (!DA.GetData(0, ref input) || input == null || !DA.GetData(1, ref netInput) || netInput == null) return;
            double[] thetas = { 60.0, 60.0 };
            double width = double.NaN;
            int maxIterations = 300;
            bool torsionFree = false, solveNow = false;
            DA.GetData(2, ref thetas[0]);
            DA.GetData(3, ref thetas[1]);
            DA.GetData(4, ref torsionFree);
            DA.GetData(5, ref maxIterations);
            bool widthGiven = DA.GetData(6, ref width);
            DA.GetData(7, ref solveNow);
            Vector3d axis = new Vector3d(0, 0, 0);
            bool slopes = DA.GetData(8, ref axis);
            if (maxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Max Iterations must be at least 1");
                return;
            }
            if (!solveNow)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "set Solve to true to optimise the net");
                return;
            }
            CleanMesh clean = CleanMeshInput(input);
            // The net's own vertices, welded where they coincide exactly; its quads on them.
            int[] corners = RhinoConversion.FaceCorners(netInput);
            CleanMesh welded = CleanMesh.FromFaces(RhinoConversion.PointsToArray(netInput.Vertices.ToPoint3dArray()), corners, 0);
            for (int k = 0; k < corners.Length; k++)
            {
                if (welded.VertexMap[corners[k]] < 0)
                {
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "net face " + k / 4 + " has no area: a net has quads only");
                    return;
                }
                corners[k] = welded.VertexMap[corners[k]];
            }
            int[][][] polylines = NetPolylines.FromQuads(corners, welded.VertexCount);
            width = StripWidth(widthGiven, width, welded.Xyz);

            BaseMeshReport report;
            double[] xyz;
            BaseMeshNode[] nodes;
            var meshes = new DataTree<object>();
            var verdicts = new List<string>();
            using (LamellaMesh reference = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
            using (var solver = slopes
                ? BaseMeshSolver.ConstantSlopes(reference, welded.Xyz, polylines[0], polylines[1], thetas[0], thetas[1], new[] { axis.X, axis.Y, axis.Z })
                : new BaseMeshSolver(reference, welded.Xyz, polylines[0], polylines[1], thetas[0], thetas[1], torsionFree))
            {
                report = SolveBaseMesh(solver, maxIterations);
                xyz = solver.Positions();
                nodes = solver.Nodes();
                BuildFamilyStrips(solver, width, meshes, verdicts);
            }
            if (!report.FamiliesMet)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture,
                    "the families are not met: rows up to {0:0.##}°, columns up to {1:0.##}° off θ (the library accepts 1°)", report.AngleErrorMaxDegrees[0], report.AngleErrorMaxDegrees[1]));
            if ((torsionFree || slopes) && !report.IsTorsionFree)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture,
                    "the nodes are not torsion-free: rulings up to {0:0.##}° apart (the library accepts 0.5°; see Node Angles)", report.NodeRulingAngleMaxDegrees));

            var points = new List<Point3d>(nodes.Length);
            var angles = new List<double>(nodes.Length);
            var axes = new List<Vector3d>(nodes.Length);
            foreach (BaseMeshNode node in nodes)
            {
                points.Add(RhinoConversion.Point(xyz, node.Vertex));
                angles.Add(node.RulingAngleDegrees ?? double.NaN);
                axes.Add(node.Axis == null ? new Vector3d(0, 0, 0) : new Vector3d(node.Axis[0], node.Axis[1], node.Axis[2]));
            }
            Message = string.Format(CultureInfo.InvariantCulture, "θ error {0:0.##}° · nodes {1:0.##}°",
                Math.Max(report.AngleErrorMaxDegrees[0], report.AngleErrorMaxDegrees[1]), report.NodeRulingAngleMaxDegrees);
            DA.SetData(0, RhinoConversion.QuadMesh(xyz, corners));
            DA.SetDataTree(1, FamilyPolylines(xyz, polylines));
            DA.SetDataTree(2, meshes);
            DA.SetDataList(3, points);
            DA.SetDataList(4, angles);
            DA.SetDataList(5, axes);
            DA.SetData(6, report.Describe() + "\n" + string.Join("\n", verdicts));
        }
    }
}
