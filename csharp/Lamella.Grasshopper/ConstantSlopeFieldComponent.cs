using System;
using System.Globalization;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Constant Slope Field: a family of curves whose tangents keep a constant slope β about an axis (paper Sec. 5.2.3,
    /// Eq. 22), for strips whose node axes are all parallel to it. Started from the slope directions, solved, and
    /// returned with the boundary of the region the slope can reach. One-shot: solves when Solve is true.
    /// </summary>
    public class ConstantSlopeFieldComponent : LamellaComponent
    {
        public ConstantSlopeFieldComponent()
            : base("Constant Slope Field", "Slope",
                "Curves of constant slope about an axis (paper Sec. 5.2.3, Eq. 22): their tangents t keep t·d = sin β. Started from the slope directions and solved; regions whose tangent planes are flatter than β (against the planes orthogonal to the axis) cannot reach it and are left out, their border returned as Boundary. Solves when Solve is true.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("16d39e64-f78c-4e55-be30-8bf0caabdfe0");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The surface (triangles or quads; cleaned at the document tolerance).", GH_ParamAccess.item);
            pManager.AddVectorParameter("Axis", "A", "The axis d the slope is measured about (unitless direction, not zero). Default: world z.", GH_ParamAccess.item);
            pManager[1].Optional = true;
            pManager.AddNumberParameter("Slope", "β", "The slope β in degrees, strictly between −90 and 90: the angle of the curves' tangents against the planes orthogonal to the axis (0: the sections orthogonal to it). Default 30.", GH_ParamAccess.item, 30.0);
            pManager.AddBooleanParameter("Free", "F", "True lets the solver choose the slope too, starting at Slope (paper: γ free per family). Default false.", GH_ParamAccess.item, false);
            pManager.AddIntegerParameter("Count", "N", "Number of level curves returned, spread uniformly over the field's range (a count, ≥ 1). Default 20.", GH_ParamAccess.item, 20);
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (a count, ≥ 1). Default 300.", GH_ParamAccess.item, 300);
            pManager.AddBooleanParameter("Solve", "Sv", "True solves within this solution. Default false.", GH_ParamAccess.item, false);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddCurveParameter("Curves", "C", "The level curves of constant slope.", GH_ParamAccess.list);
            pManager.AddCurveParameter("Boundary", "B", "The border of the region the slope can reach (the reachable side is the steeper one); empty when all of the surface reaches it.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Slope", "β", "The slope reached, in degrees (with Free: the one the solver chose).", GH_ParamAccess.item);
            pManager.AddTextParameter("Report", "R", "Iterations and the angle errors of the solve.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh input = null;
            if (!DA.GetData(0, ref input) || input == null) return;
            Vector3d axis = new Vector3d(0, 0, 1);
            double slopeDegrees = 30.0;
            bool free = false, solveNow = false;
            int count = 20, maxIterations = 300;
            DA.GetData(1, ref axis);
            DA.GetData(2, ref slopeDegrees);
            DA.GetData(3, ref free);
            DA.GetData(4, ref count);
            DA.GetData(5, ref maxIterations);
            DA.GetData(6, ref solveNow);
            if (count < 1 || maxIterations < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Count and Max Iterations must be at least 1");
                return;
            }
            if (!solveNow)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "set Solve to true to solve");
                return;
            }
            var d = new[] { axis.X, axis.Y, axis.Z };
            Conversion.CleanMesh clean = CleanMeshInput(input);
            using (LamellaMesh mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
            using (var field = new FieldSolver(mesh, InitialField.FromSlope(mesh, d, slopeDegrees), FieldParams.ConstantSlope(d, slopeDegrees, free)))
            {
                FieldReport report = field.Report;
                while (report.Iterations < (ulong)maxIterations && !report.IsConverged)
                {
                    if (GH_Document.IsEscapeKeyDown()) break;
                    report = field.Step((int)Math.Min(10UL, (ulong)maxIterations - report.Iterations));
                }
                if (!report.IsConverged)
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture, "not converged after {0} iterations", report.Iterations));
                double reached = field.SlopeDegrees;
                using (LevelCurves curves = LevelCurves.Uniform(field, count, 0.0))
                using (LevelCurves boundary = LevelCurves.ReachableBoundary(mesh, d, reached))
                {
                    DA.SetDataList(0, LevelCurvesComponent.ClosedPolylines(curves));
                    DA.SetDataList(1, LevelCurvesComponent.ClosedPolylines(boundary));
                }
                Message = string.Format(CultureInfo.InvariantCulture, "β {0:0.##}° · error {1:0.##}° RMS", reached, report.AngleErrorRmsDegrees);
                DA.SetData(2, reached);
                DA.SetData(3, string.Format(CultureInfo.InvariantCulture, "{0} iterations{1}; slope {2:0.###}°; angle error {3:0.###}° RMS, {4:0.###}° max over {5} vertices",
                    report.Iterations, report.IsConverged ? ", converged" : "", reached, report.AngleErrorRmsDegrees, report.AngleErrorMaxDegrees, report.MeasuredVertices));
            }
        }
    }
}
