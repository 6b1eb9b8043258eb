using System;
using System.Collections.Generic;
using Grasshopper.Kernel;

namespace Lamella.Grasshopper
{
    /// <summary>Strip Quality: the paper's Table 4 measures of a strip pattern as named values.</summary>
    public class StripQualityComponent : LamellaComponent
    {
        public StripQualityComponent()
            : base("Strip Quality", "Quality",
                "The quality measures of a strip pattern (paper Table 4): angle accuracy, straightness of the unrolled strips, planarity, distance from the surface.",
                "StripQuality")
        {
        }

        public override Guid ComponentGuid => new Guid("fd88b925-b5c6-4e85-ad6f-e50ad2f533b0");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            LamellaParam<StripsGoo>.AddTo(pManager, new StripsParam(), "Strips from Rectifying Strips.");
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddIntegerParameter("Strip Count", "|Strip|", "The number of strips built (a count).", GH_ParamAccess.item);
            pManager.AddIntegerParameter("Skipped", "Sk", "Curves no strip could be built on (a count).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Diff Theta", "diff_θ", "Max over the strips of |θ_measured − θ| at the centre points, in degrees.", GH_ParamAccess.item);
            pManager.AddNumberParameter("E Straight", "e_straight", "Max over the strips of the unrolled centre line's deviation from a straight line, relative to its length (unitless).", GH_ParamAccess.item);
            pManager.AddNumberParameter("E Planar", "E_planar", "Sum over all quads of det(d̂_j, d̂_j+1, ê_j)² (unitless).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Max Planar", "maxPlanar", "The largest planarity residual |det(d̂_j, d̂_j+1, ê_j)| of one quad (unitless).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Appro", "Appro", "Max distance of the centre points from the surface, in % of the surface's bounding-box diagonal.", GH_ParamAccess.item);
            pManager.AddIntegerParameter("Flipped Quads", "Flip", "Quads whose orientation flips (a count).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Per-Strip Diff Theta", "diff_θ[i]", "diff_θ of each strip, in degrees.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Per-Strip E Straight", "e_straight[i]", "e_straight of each strip (unitless).", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Strips strips = GooValue<StripsGoo, Strips>(DA, 0, "Lamella strips");
            if (strips == null) return;
            PatternMetrics pattern = strips.PatternMetrics;
            StripMetrics[] metrics = strips.Metrics();
            var diffTheta = new List<double>(metrics.Length);
            var straight = new List<double>(metrics.Length);
            foreach (StripMetrics m in metrics)
            {
                diffTheta.Add(m.MaxDiffThetaDegrees);
                straight.Add(m.EStraight);
            }
            DA.SetData(0, checked((int)pattern.StripCount));
            DA.SetData(1, checked((int)pattern.SkippedCount));
            DA.SetData(2, pattern.MaxDiffThetaDegrees);
            DA.SetData(3, pattern.MaxEStraight);
            DA.SetData(4, pattern.EPlanar);
            DA.SetData(5, pattern.MaxPlanar);
            DA.SetData(6, pattern.ApproPercent);
            DA.SetData(7, checked((int)pattern.FlippedQuads));
            DA.SetDataList(8, diffTheta);
            DA.SetDataList(9, straight);
        }
    }
}
