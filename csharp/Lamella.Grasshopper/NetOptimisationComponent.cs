using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Lamella.Hosting;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// What Optimise Net and Torsion-Free Net share: a quad net (Strip Net's Net, or any quad mesh whose quads form rows
    /// and columns), welded, its rows and columns read from its quads, moved near a reference surface until they are the
    /// asked families exactly (paper Sec. 3.5), with torsion-free nodes (Sec. 5.2.1, Eq. 21) when asked or always
    /// (Torsion-Free Net), or as curves of constant slope about a Slope Axis. Live (Run) or one-shot (Solve) through
    /// <see cref="BaseMeshComponent"/>: the net, its polylines, the nodes with their ruling angles and axes and the report
    /// are output every solution (reading the nodes costs far less than an iteration); the strips once it converges or
    /// stops. Torsion-Free Net also outputs each node's ruling angle on the net as given.
    /// </summary>
    public abstract class NetOptimisationComponent : BaseMeshComponent
    {
        /// <summary>True for Torsion-Free Net: no Torsion-free input (always on), and an Angles Before output.</summary>
        private readonly bool alwaysTorsionFree;

        protected NetOptimisationComponent(string name, string nickname, string description, string iconName, bool alwaysTorsionFree)
            : base(name, nickname, description, iconName)
        {
            this.alwaysTorsionFree = alwaysTorsionFree;
        }

        public override GH_Exposure Exposure => GH_Exposure.secondary;

        /// <summary>The index of Max Iterations: after the Torsion-free input where there is one.</summary>
        private int MaxIterationsInput => alwaysTorsionFree ? 4 : 5;

        /// <summary>Torsion-Free Net shows each node's ruling angle on the net as given, which a saved session does not hold.</summary>
        protected override bool SessionsInDocument => !alwaysTorsionFree;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Reference", "M", "The surface the net should stay on (the mesh Strip Net was given, cleaned the same way).", GH_ParamAccess.item);
            pManager.AddMeshParameter("Net", "N", "The net: a quad mesh whose quads form rows and columns, such as Strip Net's Net. Opposite sides of a quad belong to one family; the first side of the first quad (corner 0 to 1) runs along a row. Vertices at one position are welded.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Theta Rows", "θR", "Angle of the rows' family, in degrees, in [0, 180]: 0 and 180 asymptotic curves, 90 geodesics. Default 60.", GH_ParamAccess.item, 60.0);
            pManager.AddNumberParameter("Theta Columns", "θC", "Angle of the columns' family, as Theta Rows. Default 60.", GH_ParamAccess.item, 60.0);
            if (!alwaysTorsionFree)
                pManager.AddBooleanParameter("Torsion-free", "TF", "True also asks for torsion-free nodes: the strips of a node's row and column share one ruling there (Sec. 5.2.1, Eq. 21). Default false.", GH_ParamAccess.item, false);
            RegisterSolveInputs(pManager, "net");
            int axis = pManager.AddVectorParameter("Slope Axis", "SA", "Optional. When given, Theta Rows and Theta Columns are read as slopes β in degrees, in (−90, 90), against the planes orthogonal to this axis: both families become curves of constant slope, every strip's rulings and every node's axis parallel to the axis (Sec. 5.2.2–5.2.3), torsion-free by construction.", GH_ParamAccess.item);
            pManager[axis].Optional = true;
            RegisterRunInput(pManager, "net", "Net, Polylines, the nodes and Report");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Net", "N", "The optimised net: the input's quads on the moved vertices (welded)." + UpdatedWhileRunning, GH_ParamAccess.item);
            pManager.AddCurveParameter("Polylines", "P", "The net's polylines: branch {0} the rows, {1} the columns." + UpdatedWhileRunning, GH_ParamAccess.tree);
            pManager.AddMeshParameter("Strip Meshes", "S", "One planar-quad mesh per row and column that carries a strip: branch {0} the rows, {1} the columns." + BuiltOnceStopped, GH_ParamAccess.tree);
            pManager.AddPointParameter("Nodes", "X", "Every vertex inside a row and a column." + UpdatedWhileRunning, GH_ParamAccess.list);
            pManager.AddNumberParameter("Node Angles", "A", "Per node, the angle in degrees between the rulings of its row's and its column's strips on the optimised net (0: torsion-free); NaN where a polyline through it carries no strip." + UpdatedWhileRunning, GH_ParamAccess.list);
            if (alwaysTorsionFree)
                pManager.AddNumberParameter("Angles Before", "AB", "Per node, the angle in degrees between the rulings of its row's and its column's strips on the net as given, before the optimisation (NaN where a polyline through it carries no strip then): compare with Node Angles.", GH_ParamAccess.list);
            pManager.AddVectorParameter("Node Axes", "NA", "Per node, the unit node axis (the mean of the two rulings); zero where undefined." + UpdatedWhileRunning, GH_ParamAccess.list);
            pManager.AddTextParameter("Report", "R", "Iterations, each family's angle error, the deviation from the reference, the node ruling angles (with torsion-free nodes also those of the net as given), updated while Run steps; each family's strip verdict once the strips are built.", GH_ParamAccess.item);
        }

        /// <summary>Each node's ruling angle in degrees, NaN where undefined.</summary>
        private static List<double> Angles(IEnumerable<BaseMeshNode> nodes) => nodes.Select(node => node.RulingAngleDegrees ?? double.NaN).ToList();

        protected override void SolveLive(IGH_DataAccess DA)
        {
            int first = MaxIterationsInput;
            BaseMeshInputs inputs = ReadInputs(DA, first, first + 4);
            Mesh netInput = null;
            if (inputs == null || !DA.GetData(1, ref netInput) || netInput == null) return;
            double[] thetas = { 60.0, 60.0 };
            bool torsionFree = alwaysTorsionFree;
            DA.GetData(2, ref thetas[0]);
            DA.GetData(3, ref thetas[1]);
            if (!alwaysTorsionFree) DA.GetData(4, ref torsionFree);
            Vector3d axis = new Vector3d(0, 0, 0);
            bool slopes = DA.GetData(first + 3, ref axis);

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
            double[] targets = { thetas[0], thetas[1], torsionFree ? 1 : 0, slopes ? 1 : 0, axis.X, axis.Y, axis.Z };
            SolverSession<BaseMeshRun, BaseMeshReport> session = BaseMeshSession(DA, inputs, welded.Xyz, polylines, targets, "net", alwaysTorsionFree,
                reference => slopes
                    ? BaseMeshSolver.ConstantSlopes(reference, welded.Xyz, polylines[0], polylines[1], thetas[0], thetas[1], new[] { axis.X, axis.Y, axis.Z })
                    : new BaseMeshSolver(reference, welded.Xyz, polylines[0], polylines[1], thetas[0], thetas[1], torsionFree));
            if (session == null) return;

            LiveStep<BaseMeshReport> step = Advance(session, inputs.Run, inputs.SolveNow, inputs.MaxIterations);
            BaseMeshSolver solver = session.Solver.Solver;
            BaseMeshReport report = step.Outcome.Report;
            double[] xyz = solver.Positions();
            BaseMeshNode[] nodes = solver.Nodes();
            var text = new List<string> { report.Describe() };
            if (torsionFree || slopes)
            {
                BaseMeshReport initial = solver.InitialReport;
                text.Add(string.Format(CultureInfo.InvariantCulture, "node ruling angles of the net as given: max {0:0.###}°, RMS {1:0.###}°",
                    initial.NodeRulingAngleMaxDegrees, initial.NodeRulingAngleRmsDegrees));
            }
            if (!step.Continues && !report.FamiliesMet)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture,
                    "the families are not met: rows up to {0:0.##}°, columns up to {1:0.##}° off θ (the library accepts 1°)", report.AngleErrorMaxDegrees[0], report.AngleErrorMaxDegrees[1]));
            if (!step.Continues && (torsionFree || slopes) && !report.IsTorsionFree)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture,
                    "the nodes are not torsion-free: rulings up to {0:0.##}° apart (the library accepts 0.5°; see Node Angles)", report.NodeRulingAngleMaxDegrees));

            Message = IterationMessage(report, string.Format(CultureInfo.InvariantCulture, "θ error {0:0.##}° · nodes {1:0.##}°",
                Math.Max(report.AngleErrorMaxDegrees[0], report.AngleErrorMaxDegrees[1]), report.NodeRulingAngleMaxDegrees));
            DA.SetData(0, RhinoConversion.QuadMesh(xyz, corners));
            DA.SetDataTree(1, FamilyPolylines(xyz, polylines));
            DA.SetDataList(3, nodes.Select(node => RhinoConversion.Point(xyz, node.Vertex)).ToList());
            DA.SetDataList(4, Angles(nodes));
            int next = 5;
            if (alwaysTorsionFree)
            {
                // The nodes as given, by vertex (both lists hold every vertex inside a row and a column, in vertex order).
                Dictionary<int, BaseMeshNode> before = session.Solver.InitialNodes.ToDictionary(node => node.Vertex);
                DA.SetDataList(next++, Angles(nodes.Select(node => before[node.Vertex])));
            }
            DA.SetDataList(next++, nodes.Select(node => node.Axis == null ? new Vector3d(0, 0, 0) : new Vector3d(node.Axis[0], node.Axis[1], node.Axis[2])).ToList());
            text.AddRange(StripsOnceStopped(DA, step, solver, inputs, welded.Xyz, 2));
            DA.SetData(next, string.Join("\n", text));
        }
    }
}
