using System;
using System.Collections.Generic;
using System.Globalization;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Shading Field: a shading system (paper Sec. 6): the field optimised so that its strips block the sun of a site's
    /// dates and hours (or let it through, per vertex), strips with one θ per curve, and the sun-path check through them:
    /// the surface coloured by the blocked share of each vertex's direct-sun hours. One-shot: solves when Solve is true.
    /// </summary>
    public class ShadingFieldComponent : LamellaComponent
    {
        public ShadingFieldComponent()
            : base("Shading Field", "Shading",
                "A shading system (paper Sec. 6): strips along the level curves of a field optimised so that their planes block the sun of the dates and hours at the site (or let it through where the mask says so), and the sun-path check through them (rays every hour of every day from just behind the surface). Starts from the paper's start, or from a given Start Field. Solves when Solve is true.",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("b6a3e0f2-91c4-4d7a-8e25-3c1f7a9d0b64");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The surface.", GH_ParamAccess.item);
            pManager.AddNumberParameter("Latitude", "Lat", "Geographic latitude in degrees, north positive. Default 47.4.", GH_ParamAccess.item, 47.4);
            pManager.AddVectorParameter("North", "N", "North in model coordinates (made horizontal; up is +Z). Default +Y.", GH_ParamAccess.item, new Vector3d(0, 1, 0));
            pManager.AddTextParameter("Dates", "D", "Dates MM-DD..MM-DD, both included. Default 06-01..08-31.", GH_ParamAccess.item, "06-01..08-31");
            pManager.AddTextParameter("Hours", "H", "Daily hours H..H in true solar time (at most 6 h from noon). Default 10..16.", GH_ParamAccess.item, "10..16");
            pManager.AddNumberParameter("Mask", "Mk", "Per vertex of the mesh: 0 blocks, 1 lets the light through, 2 is free (transition). Default: every vertex blocks.", GH_ParamAccess.list);
            pManager[5].Optional = true;
            pManager.AddIntegerParameter("Strips", "S", "Number of strips (level curves), 1 to 1000. Default 10.", GH_ParamAccess.item, 10);
            pManager.AddNumberParameter("Width", "W", "Strip width in document units, > 0.", GH_ParamAccess.item);
            pManager.AddIntegerParameter("Max Iterations", "I", "The most solver iterations (≥ 1). Default 100.", GH_ParamAccess.item, 100);
            pManager.AddBooleanParameter("Solve", "Sv", "True solves within this solution. Default false.", GH_ParamAccess.item, false);
            // Appended after Solve, so that documents saved with the first ten inputs keep their wiring.
            pManager.AddTextParameter("Pass Hours", "PH", "Daily hours H..H whose sun the pass vertices (Mask 1) let through. Empty (the default): the Hours.", GH_ParamAccess.item, "");
            pManager.AddIntegerParameter("Ring", "Rg", "Width in edge rings of the free transition on each side of a block/pass border, ≥ 0. Default 1.", GH_ParamAccess.item, 1);
            // Appended after Ring, so that documents saved with the first twelve inputs keep their wiring.
            pManager.AddNumberParameter("Start Field", "SF",
                "Optional: the field to start from, one value per vertex of the mesh (finite, not constant; vertices welded by the mesh cleaning take the first one's value). Default: the paper's start (the constant-slope family of the slope vote).",
                GH_ParamAccess.list);
            pManager[12].Optional = true;
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddCurveParameter("Curves", "C", "The strips' centre lines (level curves of the field).", GH_ParamAccess.list);
            pManager.AddMeshParameter("Strips", "S", "One quad mesh per strip.", GH_ParamAccess.list);
            pManager.AddMeshParameter("Shading", "Sh", "The surface coloured by the blocked share of each vertex's direct-sun hours (blue 0, red 1; grey: the sun never reaches it).", GH_ParamAccess.item);
            pManager.AddNumberParameter("Fractions", "F", "Per vertex of the mesh, the blocked share of its direct-sun hours (NaN where the sun never reaches it).", GH_ParamAccess.list);
            pManager.AddTextParameter("Report", "R", "Iterations, the strips' θ and verdict, the blocked share per region.", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh input = null;
            if (!DA.GetData(0, ref input) || input == null) return;
            double latitude = 47.4, width = 0.0;
            var north = new Vector3d(0, 1, 0);
            string dates = "06-01..08-31", hours = "10..16", passHours = null;
            var mask = new List<double>();
            var startValues = new List<double>();
            int count = 10, maxIterations = 100, ring = 1;
            bool solveNow = false;
            DA.GetData(1, ref latitude);
            DA.GetData(2, ref north);
            DA.GetData(3, ref dates);
            DA.GetData(4, ref hours);
            DA.GetDataList(5, mask);
            DA.GetData(6, ref count);
            if (!DA.GetData(7, ref width)) return;
            DA.GetData(8, ref maxIterations);
            DA.GetData(9, ref solveNow);
            DA.GetData(10, ref passHours);
            DA.GetData(11, ref ring);
            DA.GetDataList(12, startValues);
            if (maxIterations < 1 || count < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Strips and Max Iterations must be at least 1");
                return;
            }
            if (ring < 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture, "Ring is {0}: it must be at least 0", ring));
                return;
            }
            if (!solveNow)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Remark, "set Solve to true to design the shading");
                return;
            }
            ShadingSite site = ShadingSite.Default().WithDates(dates).WithHours(hours);
            if (!string.IsNullOrWhiteSpace(passHours)) site = site.WithPassHours(passHours);
            site.LatitudeDegrees = latitude;
            site.North = new[] { north.X, north.Y, north.Z };
            CleanMesh clean = CleanMeshInput(input);
            ShadingLabel[] labels = Labels(clean, mask);
            if (labels == null) return;
            double[] startField = null;
            if (startValues.Count > 0)
            {
                startField = StartField(clean, startValues);
                if (startField == null) return;
            }
            ShadingReport report;
            double[] fractions;
            SunPathSummary summary;
            double[] thetas;
            using (LamellaMesh mesh = LamellaMesh.FromArrays(clean.Xyz, clean.Triangles))
            using (var shading = startField == null ? new ShadingSolver(mesh, site, labels, ring) : new ShadingSolver(mesh, site, labels, ring, startField))
            {
                report = shading.Report;
                while (report.Iterations < maxIterations && !report.IsConverged)
                {
                    if (GH_Document.IsEscapeKeyDown()) break;
                    report = shading.Step((int)Math.Min(10, maxIterations - report.Iterations));
                }
                using (Strips strips = shading.BuildStrips(count, width))
                {
                    thetas = shading.Thetas();
                    summary = shading.Evaluate(strips, 0.05 * width);
                    double?[] perVertex = shading.VertexFractions();
                    fractions = Array.ConvertAll(perVertex, f => f ?? double.NaN);
                    Verdict verdict = strips.Verdict;
                    if (!verdict.IsAcceptable) AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, verdict.Message);
                    int[] vertexOffsets = strips.VertexOffsets(), quadOffsets = strips.QuadOffsets();
                    DA.SetDataList(0, RhinoConversion.Polylines(new Packed(strips.Centres(), strips.PointOffsets(), 3)));
                    DA.SetDataList(1, RhinoConversion.QuadMeshes(StripArrays.Split(strips.Vertices(), 3, strips.Quads(), vertexOffsets, quadOffsets)));
                }
            }
            if (!report.IsConverged)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, string.Format(CultureInfo.InvariantCulture, "not converged after {0} iterations", report.Iterations));
            Mesh surface = RhinoConversion.TriangleMesh(clean.Xyz, clean.Triangles);
            DA.SetData(2, RhinoConversion.ColouredCopy(surface, FieldColours.Argb(fractions, 0.0, 1.0)));
            DA.SetDataList(3, clean.ToInputVertices(fractions, 1, double.NaN));
            Message = "blocked " + Share(summary.BlockFraction);
            DA.SetData(4, string.Format(CultureInfo.InvariantCulture,
                "{0} iterations{1}; {2} strips, θ {3}; blocked share of the direct-sun hours: block region {4}, pass region {5} ({6} rays)",
                report.Iterations, report.IsConverged ? ", converged" : "", thetas.Length,
                string.Join(", ", Array.ConvertAll(thetas, t => t.ToString("0.#", CultureInfo.InvariantCulture) + "°")),
                Share(summary.BlockFraction), Share(summary.PassFraction), summary.Rays));
        }

        private static string Share(double? fraction) =>
            fraction.HasValue ? string.Format(CultureInfo.InvariantCulture, "{0:0.#} %", 100 * fraction.Value) : "–";

        /// <summary>
        /// The start field per clean vertex from the values per input vertex: a welded vertex takes the value of the first
        /// input vertex welded into it (whose position it keeps); null after an error message.
        /// </summary>
        private double[] StartField(CleanMesh clean, List<double> values)
        {
            if (values.Count != clean.InputVertexCount)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture,
                    "Start Field has {0} values but the mesh {1} vertices", values.Count, clean.InputVertexCount));
                return null;
            }
            var field = new double[clean.VertexCount];
            var taken = new bool[clean.VertexCount];
            for (int v = 0; v < values.Count; v++)
            {
                int c = clean.VertexMap[v];
                if (c < 0 || taken[c]) continue;
                field[c] = values[v];
                taken[c] = true;
            }
            return field;
        }

        /// <summary>One label per clean vertex from the mask per input vertex (every vertex blocks without a mask); null after an error message.</summary>
        private ShadingLabel[] Labels(CleanMesh clean, List<double> mask)
        {
            var labels = new ShadingLabel[clean.VertexCount];
            if (mask.Count == 0) return labels;
            if (mask.Count != clean.InputVertexCount)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture,
                    "Mask has {0} values but the mesh {1} vertices", mask.Count, clean.InputVertexCount));
                return null;
            }
            for (int v = 0; v < mask.Count; v++)
            {
                if (mask[v] != 0 && mask[v] != 1 && mask[v] != 2)
                {
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Error, string.Format(CultureInfo.InvariantCulture, "Mask[{0}] is {1}: 0 blocks, 1 passes, 2 is free", v, mask[v]));
                    return null;
                }
                if (clean.VertexMap[v] >= 0) labels[clean.VertexMap[v]] = (ShadingLabel)mask[v];
            }
            return labels;
        }
    }
}
