using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Lamella.Hosting;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Rectifying Strips: a developable strip along each level curve (paper Sec. 3.4): planar quads whose rulings lie
    /// in the curves' rectifying planes, the rulings and outlines, and the strips unrolled flat and laid out on a plane
    /// with cutting outlines and labels that match the strips in space. Strips that miss θ by more than the library's
    /// tolerance (or have flipped quads) are still output, with an error naming them (the verdict) and Acceptable false.
    /// </summary>
    public class RectifyingStripsComponent : LamellaComponent
    {
        public RectifyingStripsComponent()
            : base("Rectifying Strips", "Strips",
                "Rectifying developable strips along level curves: one planar-quad mesh per strip with its rulings and outline, and the strips unrolled flat on a plane with cutting outlines and labels (S0, S1, … in the order of the strips in space).",
                "RectifyingStrips")
        {
        }

        public override Guid ComponentGuid => new Guid("3bf88412-c4e6-47ae-ab7e-d16cbd44c1f1");
        public override GH_Exposure Exposure => GH_Exposure.primary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            LamellaParam<CurvesGoo>.AddTo(pManager, new CurvesParam(), "Level curves from Level Curves (they carry the field's θ).");
            pManager.AddNumberParameter("Width", "W", "Width of each flat strip, in document units, > 0. Default: a round number near 2 % of the curves' extent (named in a remark).", GH_ParamAccess.item);
            pManager[1].Optional = true;
            pManager.AddNumberParameter("Gap", "G", "Distance between the unrolled strips of the flat layout, in document units, ≥ 0. Default: half the width.", GH_ParamAccess.item);
            pManager[2].Optional = true;
            pManager.AddPlaneParameter("Plane", "P", "The plane the flat layout lies on: strips run along its X axis and stack along its Y axis from its origin. Default: world XY.", GH_ParamAccess.item, Plane.WorldXY);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            LamellaParam<StripsGoo>.AddTo(pManager, new StripsParam(), "The strips for Strip Quality.");
            pManager.AddMeshParameter("Strip Meshes", "M", "One planar-quad mesh per strip, in space.", GH_ParamAccess.list);
            pManager.AddLineParameter("Rulings", "R", "The rulings across the strips, boundary to boundary.", GH_ParamAccess.list);
            pManager.AddCurveParameter("Outlines", "O", "Each strip's boundary in space as a closed polyline (for detailing nodes and connections).", GH_ParamAccess.list);
            pManager.AddMeshParameter("Unrolled", "U", "The strips unrolled isometrically and laid out on the plane, one mesh each.", GH_ParamAccess.list);
            pManager.AddCurveParameter("Flat Outlines", "FO", "Each unrolled strip's boundary as a closed polyline on the plane: the cutting line.", GH_ParamAccess.list);
            pManager.AddCurveParameter("Centre Lines", "CL", "The strips' centre lines in space (the optimised curves).", GH_ParamAccess.list);
            pManager.AddTextParameter("Labels", "L", "One label per strip (S0, S1, …), the same for a strip in space and its flat twin.", GH_ParamAccess.list);
            pManager.AddPointParameter("Label Points", "LP", "Where each strip's label goes in space: the middle point of its centre line.", GH_ParamAccess.list);
            pManager.AddPointParameter("Flat Label Points", "FLP", "Where each strip's label goes on the flat layout: the middle point of its unrolled centre line.", GH_ParamAccess.list);
            pManager.AddTextParameter("Metrics", "Q", "Per strip: label, curve, length, diff_θ (°), e_straight, max planarity residual, Appro, strip-plane angle error (°), warnings (paper Table 4).", GH_ParamAccess.list);
            pManager.AddBooleanParameter("Acceptable", "A", "True when every strip's plane meets θ within the library's tolerance (2°) and no quad is flipped: the curves form an acceptable family. False: the strips are still output, but miss θ (see Verdict).", GH_ParamAccess.item);
            pManager.AddTextParameter("Verdict", "V", "One line: for an acceptable pattern the tolerance and the worst quad; otherwise the library's message naming the strips that miss θ, the worst point and what to try.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            CurvesData curves = GooValue<CurvesGoo, CurvesData>(DA, 0, "Lamella curves");
            if (curves == null) return;
            double width = double.NaN, gap = double.NaN;
            Plane plane = Plane.WorldXY;
            bool widthGiven = DA.GetData(1, ref width), gapGiven = DA.GetData(2, ref gap);
            DA.GetData(3, ref plane);
            if (!widthGiven)
            {
                width = StripDefaults.Width(curves.Curves.Points());
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, string.Format(CultureInfo.InvariantCulture,
                    "Width not set: {0:G6} ({1}; about {2:0.#} % of the curves' extent), gap {3:G6}", width,
                    RhinoConversion.DocumentUnits() ?? "document units", 100 * StripDefaults.WidthFraction, gapGiven ? gap : StripDefaults.Gap(width)));
            }
            if (!gapGiven) gap = StripDefaults.Gap(width);
            if (!(gap >= 0) || double.IsInfinity(gap))
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Gap must be finite and ≥ 0");
                return;
            }

            Strips strips = Keep(DA, Strips.Build(curves.Curves, StripParams.Default(curves.ThetaDegrees, width)));
            Verdict verdict = strips.Verdict;
            // Still output: the designer sees where the strips miss θ.
            if (!verdict.IsAcceptable) AddRuntimeMessage(GH_RuntimeMessageLevel.Error, verdict.Message);
            foreach (SkippedCurve skipped in strips.Skipped())
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "curve " + skipped.Curve + " carries no strip: " + skipped.Warnings);
            }
            int[] vertexOffsets = strips.VertexOffsets(), pointOffsets = strips.PointOffsets(), quadOffsets = strips.QuadOffsets(), quads = strips.Quads();
            double[] vertices = strips.Vertices();
            double[] unrolled = strips.UnrolledVertices();
            double[] shifts = StripArrays.FlatLayoutShifts(unrolled, vertexOffsets, gap);
            double[] flat = RhinoConversion.OnPlane(StripArrays.Shift(unrolled, vertexOffsets, shifts), plane);
            double[] flatCentres = RhinoConversion.OnPlane(StripArrays.Shift(strips.UnrolledCentres(), pointOffsets, shifts), plane);
            double[] centres = strips.Centres();

            DA.SetData(0, new StripsGoo(strips));
            DA.SetDataList(1, RhinoConversion.QuadMeshes(StripArrays.Split(vertices, 3, quads, vertexOffsets, quadOffsets)));
            DA.SetDataList(2, RhinoConversion.Lines(StripArrays.RulingSegments(vertices, vertexOffsets)));
            DA.SetDataList(3, RhinoConversion.Polylines(StripArrays.Outlines(vertices, 3, vertexOffsets)));
            DA.SetDataList(4, RhinoConversion.QuadMeshes(StripArrays.Split(flat, 3, quads, vertexOffsets, quadOffsets)));
            DA.SetDataList(5, RhinoConversion.Polylines(StripArrays.Outlines(flat, 3, vertexOffsets)));
            DA.SetDataList(6, RhinoConversion.Polylines(new Packed(centres, pointOffsets, 3)));
            StripMetrics[] metrics = strips.Metrics();
            DA.SetDataList(7, StripLabels.Labels(metrics.Length));
            DA.SetDataList(8, RhinoConversion.Points(StripArrays.MiddlePoints(centres, pointOffsets)));
            DA.SetDataList(9, RhinoConversion.Points(StripArrays.MiddlePoints(flatCentres, pointOffsets)));
            DA.SetDataList(10, StripLabels.Describe(metrics));
            DA.SetData(11, verdict.IsAcceptable);
            DA.SetData(12, verdict.ToString());
        }
    }
}
