using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Reshape Surface: moves a mesh a little so that the level curves of a Strip Field become P-curves of the angle θ
    /// (paper Sec. 3.3, Fig. 17): the field's values stay fixed, the vertices move within a tolerance of the original
    /// surface. One-shot: solves when Solve is true (no live mode).
    /// </summary>
    public class ReshapeSurfaceComponent : LamellaComponent
    {
        public ReshapeSurfaceComponent()
            : base("Reshape Surface", "Reshape",
                "Moves the surface a little so that the level curves of a field become P-curves of θ (paper Sec. 3.3): the field's values stay fixed, the vertices move within Tolerance of the original surface (paper Table 3 weights). For a θ the surface has no family of, or to change θ of an existing design. Solves when Solve is true.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("3f1d2c9e-6a47-4b1e-9c85-0d7e2b4a6f13");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The surface the field was solved on (the same mesh as Strip Field's input, cleaned the same way).", GH_ParamAccess.item);
            LamellaParam<FieldGoo>.AddTo(pManager, new FieldParam(), "The field from Strip Field: its values stay fixed.");
            pManager.AddNumberParameter("Theta", "θ", "Target angle between the curves' binormals and the surface normal, in degrees, strictly between 0 and 180. Default: the field's θ.", GH_ParamAccess.item);
            pManager[2].Optional = true;
            pManager.AddNumberParameter("Tolerance", "T", "Largest distance of a vertex from the original surface, in percent of the bounding-box diagonal, > 0. Default 1.", GH_ParamAccess.item, 1.0);
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1). Default 300.", GH_ParamAccess.item, 300);
            pManager.AddBooleanParameter("Solve", "Sv", "True solves within this solution. Default false.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The moved surface (the cleaned mesh's vertices and triangles).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Deviation", "D", "Per vertex of the input mesh, its distance from the original surface (NaN at vertices no face uses).", GH_ParamAccess.list);
            pManager.AddNumberParameter("Max Deviation", "MD", "The largest deviation, in document units.", GH_ParamAccess.item);
            pManager.AddTextParameter("Report", "R", "Iterations, angle errors, deviation and edge-length change.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh input = null;
            if (!DA.GetData(0, ref input) || input == null) return;
            FieldData field = GooValue<FieldGoo, FieldData>(DA, 1, "Lamella field");
            if (field == null) return;
            double thetaDegrees = field.ThetaDegrees, tolerancePercent = 1.0;
            int maxIterations = 300;
            bool solveNow = false;
            DA.GetData(2, ref thetaDegrees);
            DA.GetData(3, ref tolerancePercent);
            DA.GetData(4, ref maxIterations);
            DA.GetData(5, ref solveNow);
            if (maxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Max Iterations must be at least 1");
                return;
            }
            if (!solveNow)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "set Solve to true to reshape");
                return;
            }
            CleanMesh clean = CleanMeshInput(input);
            double[] values = field.Solver.Values();
            if (values.Length != clean.VertexCount)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture,
                    "the field has {0} values but the cleaned mesh {1} vertices: connect the mesh the field was solved on", values.Length, clean.VertexCount));
                return;
            }
            ReshapeReport report;
            double[] xyz, deviations;
            using (LamellaMesh mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
            using (var reshape = new ReshapeSolver(mesh, values, thetaDegrees, tolerancePercent / 100.0, true))
            {
                report = reshape.Report;
                while (report.Iterations < maxIterations && !report.IsConverged)
                {
                    if (GH_Document.IsEscapeKeyDown()) break;
                    report = reshape.Step((int)Math.Min(10, maxIterations - report.Iterations));
                }
                xyz = reshape.Positions();
                deviations = reshape.Deviations();
            }
            if (!report.IsConverged)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture, "not converged after {0} iterations", report.Iterations));
            Message = string.Format(CultureInfo.InvariantCulture, "max deviation {0:0.###} · θ error {1:0.##}° RMS", report.MaxDeviation, report.AngleErrorRmsDegrees);
            DA.SetData(0, RhinoConversion.TriangleMesh(xyz, clean.Triangles));
            DA.SetDataList(1, clean.ToInputVertices(deviations, 1, double.NaN));
            DA.SetData(2, report.MaxDeviation);
            DA.SetData(3, string.Format(CultureInfo.InvariantCulture,
                "{0} iterations{1}; vertex angle error {2:0.###}° RMS, {3:0.###}° max; deviation max {4:0.####}, RMS {5:0.####} (tolerance {6:0.####}); edge lengths change by up to {7:0.#} %",
                report.Iterations, report.IsConverged ? ", converged" : "", report.AngleErrorRmsDegrees, report.AngleErrorMaxDegrees,
                report.MaxDeviation, report.RmsDeviation, report.Tolerance, 100 * report.MaxEdgeChange));
        }
    }
}
