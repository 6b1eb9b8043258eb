using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using Grasshopper;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Data;
using Grasshopper.Kernel.Types;
using Lamella.Conversion;
using Lamella.Hosting;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Optimise Web: moves the vertices of a 3-web (Strip Web's Polylines, or any three families of polylines crossing at
    /// shared points) near a reference surface until its rows, columns and diagonals are the asked families exactly
    /// (paper Sec. 3.5 on Sec. 4.2's webs: a level-set web's diagonals are only nearly the asked curves); then every
    /// polyline carries a developable strip of planar quads. Live (Run: the polylines and the web move while it steps, the
    /// strips follow once it converges or stops) or one-shot (Solve), as Optimise Net.
    /// </summary>
    public class OptimiseWebComponent : BaseMeshComponent
    {
        /// <summary>The default θ of the three families: an AAG web.</summary>
        private static readonly double[] DefaultThetas = { 0.0, 0.0, 90.0 };

        public OptimiseWebComponent()
            : base("Optimise Web", "OptWeb",
                "Moves a 3-web's vertices near the reference surface until its rows, columns and diagonals are exact families of angle θ (paper Sec. 3.5 on the webs of Sec. 4.2: 0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics); the level sets of Strip Web make the diagonals only nearly so. Then each polyline carries a developable strip of planar quads. Run optimises live (the web moves while it steps), Solve to convergence at once.",
                "OptimiseWeb")
        {
        }

        public override Guid ComponentGuid => new Guid("b63cae77-6121-429d-a2f8-df63ba7ea943");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Reference", "M", "The surface the web should stay on (the mesh Strip Web was given, cleaned the same way).", GH_ParamAccess.item);
            pManager.AddCurveParameter("Web", "Wb", "The web's polylines, one branch per family in path order: the rows, the columns, the diagonals (Strip Web's Polylines as they are). Where polylines cross they share a point: points within the document's tolerance are welded into one vertex.", GH_ParamAccess.tree);
            pManager.AddNumberParameter("Theta Rows", "θR", "Angle of the rows' family (the first branch), in degrees, in [0, 180]: 0 and 180 asymptotic curves, 90 geodesics. Default 0.", GH_ParamAccess.item, DefaultThetas[0]);
            pManager.AddNumberParameter("Theta Columns", "θC", "Angle of the columns' family (the second branch), as Theta Rows. Default 0.", GH_ParamAccess.item, DefaultThetas[1]);
            pManager.AddNumberParameter("Theta Diagonals", "θD", "Angle of the diagonals' family (the third branch), as Theta Rows. Default 90 (with 0 and 0: an AAG web).", GH_ParamAccess.item, DefaultThetas[2]);
            RegisterSolveInputs(pManager, "web");
            RegisterRunInput(pManager, "web", "Polylines, Web and Report");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddCurveParameter("Polylines", "P", "The optimised web's polylines: branch {0} the rows, {1} the columns, {2} the diagonals." + UpdatedWhileRunning, GH_ParamAccess.tree);
            pManager.AddMeshParameter("Web", "Wb", "The optimised web as a triangle mesh: its triangles are the cycles of one segment of each family." + UpdatedWhileRunning, GH_ParamAccess.item);
            pManager.AddMeshParameter("Strip Meshes", "S", "One planar-quad mesh per polyline that carries a strip: branch {0} the rows, {1} the columns, {2} the diagonals." + BuiltOnceStopped, GH_ParamAccess.tree);
            pManager.AddTextParameter("Report", "R", "Iterations, each family's angle error, the deviation from the reference, the welded vertex count, updated while Run steps; each family's strip verdict once the strips are built.", GH_ParamAccess.item);
        }

        /// <summary>
        /// The points of each family's polylines (x, y, z per point), one family per branch of <paramref name="tree"/>; null
        /// with an error when there are not three branches or a curve is not a polyline.
        /// </summary>
        private double[][][] FamilyPoints(GH_Structure<GH_Curve> tree)
        {
            IList<List<GH_Curve>> branches = tree.Branches;
            if (branches.Count != 3)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture,
                    "Web has {0} branches; a web has three families, one branch each: the rows, the columns, the diagonals (Strip Web's Polylines)", branches.Count));
                return null;
            }
            var families = new double[3][][];
            for (int k = 0; k < 3; k++)
            {
                families[k] = new double[branches[k].Count][];
                for (int l = 0; l < branches[k].Count; l++)
                {
                    var polyline = branches[k][l] == null ? null : branches[k][l].Value as PolylineCurve;
                    if (polyline == null)
                    {
                        AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture,
                            "{0} {1} is not a polyline: the web's vertices are its polylines' points", BaseMeshSolver.FamilyName(k), l));
                        return null;
                    }
                    var points = new Point3d[polyline.PointCount];
                    for (int i = 0; i < points.Length; i++) points[i] = polyline.Point(i);
                    families[k][l] = RhinoConversion.PointsToArray(points);
                }
            }
            return families;
        }

        protected override void SolveLive(IGH_DataAccess DA)
        {
            BaseMeshInputs inputs = ReadInputs(DA, 5, 8);
            GH_Structure<GH_Curve> tree;
            if (inputs == null || !DA.GetDataTree(1, out tree) || tree == null) return;
            double[] thetas = (double[])DefaultThetas.Clone();
            for (int k = 0; k < 3; k++) DA.GetData(2 + k, ref thetas[k]);
            double[][][] points = FamilyPoints(tree);
            if (points == null) return;
            WeldedNet web = NetPolylines.FromPoints(points, WeldTolerance());
            SolverSession<BaseMeshRun, BaseMeshReport> session = BaseMeshSession(DA, inputs, web.Xyz, web.Polylines, thetas, "web", false,
                reference => BaseMeshSolver.Web(reference, web.Xyz, web.Polylines[0], web.Polylines[1], web.Polylines[2], thetas[0], thetas[1], thetas[2]));
            if (session == null) return;

            LiveStep<BaseMeshReport> step = Advance(session, inputs.Run, inputs.SolveNow, inputs.MaxIterations);
            BaseMeshSolver solver = session.Solver.Solver;
            BaseMeshReport report = step.Outcome.Report;
            BaseMeshFamilyReport[] families = Enumerable.Range(0, 3).Select(solver.FamilyReport).ToArray();
            double[] xyz = solver.Positions();
            int[] triangles = solver.Triangles();
            if (!step.Continues && !report.FamiliesMet)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "the families are not met (the library accepts 1°): " + string.Join("; ", families.Select(f => f.ToString())));
            if (triangles.Length == 0)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "no triangle: no segment of a row, a column and a diagonal close one (are the branches the rows, columns and diagonals of one web?)");
            Message = IterationMessage(report, string.Format(CultureInfo.InvariantCulture, "θ error {0:0.##}°", families.Max(f => f.AngleErrorMaxDegrees)));
            DA.SetDataTree(0, FamilyPolylines(xyz, web.Polylines));
            DA.SetData(1, RhinoConversion.TriangleMesh(xyz, triangles));
            var text = new List<string>
            {
                report.Describe(),
                families[2].ToString(),
                string.Format(CultureInfo.InvariantCulture, "web: {0} vertices ({1} points welded), {2} triangles", web.VertexCount, web.WeldedPoints, triangles.Length / 3),
            };
            text.AddRange(StripsOnceStopped(DA, step, solver, inputs, web.Xyz, 2));
            DA.SetData(3, string.Join("\n", text));
        }
    }
}
