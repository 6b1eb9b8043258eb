using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Rectifying Strips: a developable strip along each level curve (paper Sec. 3.4): planar quads whose rulings lie
    /// in the curves' rectifying planes, the rulings, and the strips unrolled flat and laid out on the XY plane.
    /// </summary>
    public class RectifyingStripsComponent : LamellaComponent
    {
        private Strips previous;

        public RectifyingStripsComponent()
            : base("Rectifying Strips", "Strips",
                "Rectifying developable strips along level curves: one planar-quad mesh per strip, the rulings, and the strips unrolled flat on the XY plane.",
                "RectifyingStrips")
        {
        }

        public override Guid ComponentGuid => new Guid("3bf88412-c4e6-47ae-ab7e-d16cbd44c1f1");
        public override GH_Exposure Exposure => GH_Exposure.primary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddGenericParameter("Curves", "C", "Level curves from Level Curves (they carry the field's θ).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Width", "W", "Width of each flat strip, in document units, > 0. Default 1.", GH_ParamAccess.item, 1.0);
            pManager.AddNumberParameter("Gap", "G", "Distance between the unrolled strips on the XY plane, in document units, ≥ 0. Default 0.5.", GH_ParamAccess.item, 0.5);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddGenericParameter("Strips", "S", "The strips for Strip Quality.", GH_ParamAccess.item);
            pManager.AddMeshParameter("Strip Meshes", "M", "One planar-quad mesh per strip.", GH_ParamAccess.list);
            pManager.AddLineParameter("Rulings", "R", "The rulings across the strips, boundary to boundary.", GH_ParamAccess.list);
            pManager.AddMeshParameter("Unrolled", "U", "The strips unrolled isometrically and laid out on the XY plane, one mesh each.", GH_ParamAccess.list);
            pManager.AddCurveParameter("Centre Lines", "CL", "The strips' centre lines (the optimised curves).", GH_ParamAccess.list);
            pManager.AddTextParameter("Metrics", "Q", "Per strip: length, diff_θ (°), e_straight, max planarity residual, warnings (paper Table 4).", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            CurvesData curves = GooValue<CurvesGoo, CurvesData>(DA, 0, "Lamella curves");
            if (curves == null) return;
            double width = 1, gap = 0.5;
            DA.GetData(1, ref width);
            DA.GetData(2, ref gap);
            if (!(gap >= 0) || double.IsInfinity(gap))
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Gap must be finite and ≥ 0");
                return;
            }

            previous?.Dispose();
            previous = Strips.Build(curves.Curves, StripParams.Default(curves.ThetaDegrees, width));
            foreach (SkippedCurve skipped in previous.Skipped())
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "curve " + skipped.Curve + " carries no strip: " + skipped.Warnings);
            }
            int[] vertexOffsets = previous.VertexOffsets(), quadOffsets = previous.QuadOffsets(), quads = previous.Quads();
            double[] vertices = previous.Vertices();
            double[] flat = StripArrays.LayOutFlat(previous.UnrolledVertices(), vertexOffsets, gap);

            DA.SetData(0, new StripsGoo(previous));
            DA.SetDataList(1, Meshes(StripArrays.Split(vertices, 3, quads, vertexOffsets, quadOffsets)));
            DA.SetDataList(2, RhinoConversion.Lines(StripArrays.RulingSegments(vertices, vertexOffsets)));
            DA.SetDataList(3, Meshes(StripArrays.Split(flat, 3, quads, vertexOffsets, quadOffsets)));
            DA.SetDataList(4, RhinoConversion.Polylines(previous.Centres(), previous.PointOffsets()));
            DA.SetDataList(5, Describe(previous.Metrics()));
        }

        private static List<Mesh> Meshes(StripMesh[] strips)
        {
            var meshes = new List<Mesh>(strips.Length);
            foreach (StripMesh strip in strips) meshes.Add(RhinoConversion.QuadMesh(strip.Vertices, strip.Quads));
            return meshes;
        }

        private static List<string> Describe(StripMetrics[] metrics)
        {
            var lines = new List<string>(metrics.Length);
            foreach (StripMetrics m in metrics)
            {
                lines.Add(string.Format(CultureInfo.InvariantCulture,
                    "curve {0}: length {1:0.###}, diff_θ {2:0.###}°, e_straight {3:0.##e+0}, max planar {4:0.##e+0}, Appro {5:0.####}%, warnings {6}",
                    m.Curve, m.Length, m.MaxDiffThetaDegrees, m.EStraight, m.MaxPlanar, m.ApproPercent, m.Warnings));
            }
            return lines;
        }
    }
}
