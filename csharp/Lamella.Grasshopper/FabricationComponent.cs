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
    /// Fabrication: the bending and twisting check of each strip for a material and thickness, the pieces cut from
    /// stock boards (long strips split with splice overlaps), the bill of materials, and the cut files on a toggle.
    /// </summary>
    public class FabricationComponent : LamellaComponent
    {
        public FabricationComponent()
            : base("Fabrication", "Fab",
                "Workshop data of a strip pattern: per strip the weak-axis bending stress E·t·κ/2 and torsional shear G·t·τ against the material's allowable stress (utilisation, strips over 100 % flagged), the pieces cut from stock boards with splice overlaps (ids strip_<i>-<k>), the bill of materials, and cut.dxf / cut.svg / bom.csv written to a folder when Write is true.",
                "StripQuality")
        {
        }

        public override Guid ComponentGuid => new Guid("5b0f7a52-9d0e-4a8e-b3a4-2f6f3c1d8e71");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            LamellaParam<StripsGoo>.AddTo(pManager, new StripsParam(), "Strips from Rectifying Strips (in metres).");
            pManager.AddTextParameter("Material", "Mat", "timber (C24), plywood (birch), steel (S355) or aluminium (6082 T6).", GH_ParamAccess.item, "timber");
            pManager.AddNumberParameter("Thickness", "t", "Strip thickness in metres, > 0.", GH_ParamAccess.item, 0.006);
            pManager.AddNumberParameter("Stock", "L", "Length of the stock boards in metres, longer than twice the 0.3 m splice overlap.", GH_ParamAccess.item, 4.8);
            pManager.AddBooleanParameter("Write", "W", "Write cut.dxf, cut.svg and bom.csv into Folder.", GH_ParamAccess.item, false);
            pManager.AddTextParameter("Folder", "F", "Folder for the cut files (created if missing).", GH_ParamAccess.item, string.Empty);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddNumberParameter("Utilisation", "U", "Per strip the largest utilisation √(σ² + 3τ²) / allowable stress (1 = 100 %).", GH_ParamAccess.list);
            pManager.AddBooleanParameter("Overstressed", "X", "Per strip: true when it is stressed beyond the allowable stress.", GH_ParamAccess.list);
            pManager.AddMeshParameter("Coloured Strips", "C", "The strips coloured by utilisation: green 0, yellow 50 %, orange 100 %, red over.", GH_ParamAccess.list);
            pManager.AddTextParameter("BOM", "BOM", "The bill of materials, one row per piece: id, length, width, min bending radius, max twist rate, max utilisation, splice partners, board (comma-separated).", GH_ParamAccess.list);
            pManager.AddTextParameter("Columns", "Col", "The names of the BOM's columns.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Yield", "Y", "The pieces' area over the stock boards' area.", GH_ParamAccess.item);
            pManager.AddIntegerParameter("Boards", "B", "Number of stock boards used.", GH_ParamAccess.item);
            pManager.AddTextParameter("Files", "Files", "The files written (empty unless Write is true).", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Strips strips = GooValue<StripsGoo, Strips>(DA, 0, "Lamella strips");
            if (strips == null) return;
            string material = "timber", folder = string.Empty;
            double thickness = 0.006, stock = 4.8;
            bool write = false;
            DA.GetData(1, ref material);
            DA.GetData(2, ref thickness);
            DA.GetData(3, ref stock);
            DA.GetData(4, ref write);
            DA.GetData(5, ref folder);

            Fabrication plan = Keep(DA, Fabrication.Plan(strips, Material.Preset(material), thickness, Stock.Boards(stock)));
            StripCheck[] checks = plan.StripChecks();
            var utilisation = new List<double>(checks.Length);
            var over = new List<bool>(checks.Length);
            var flagged = new List<string>();
            for (int s = 0; s < checks.Length; s++)
            {
                utilisation.Add(checks[s].MaxUtilisation);
                over.Add(checks[s].Overstressed != 0);
                if (checks[s].Overstressed != 0) flagged.Add(string.Format(CultureInfo.InvariantCulture, "strip_{0} ({1:0} %)", s, 100 * checks[s].MaxUtilisation));
            }
            if (flagged.Count > 0)
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "over 100 % utilisation: " + string.Join(", ", flagged) + "; use thinner or more flexible stock");

            int[] vertexOffsets = strips.VertexOffsets(), quadOffsets = strips.QuadOffsets();
            List<Mesh> meshes = RhinoConversion.QuadMeshes(StripArrays.Split(strips.Vertices(), 3, strips.Quads(), vertexOffsets, quadOffsets));
            var coloured = new List<Mesh>(meshes.Count);
            for (int s = 0; s < meshes.Count; s++)
            {
                var argb = new int[vertexOffsets[s + 1] - vertexOffsets[s]];
                for (int v = 0; v < argb.Length; v++) argb[v] = FabricationTable.UtilisationArgb(checks[s].MaxUtilisation);
                coloured.Add(RhinoConversion.ColouredCopy(meshes[s], argb));
            }
            var rows = new List<string>();
            foreach (string[] row in FabricationTable.BomRows(plan)) rows.Add(string.Join(",", row));
            var files = new List<string>();
            if (write)
            {
                if (string.IsNullOrWhiteSpace(folder))
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "Write is true but no Folder is given: nothing written");
                else
                    files.AddRange(FabricationTable.WriteFiles(plan, folder));
            }
            FabricationSummary summary = plan.Summary;
            DA.SetDataList(0, utilisation);
            DA.SetDataList(1, over);
            DA.SetDataList(2, coloured);
            DA.SetDataList(3, rows);
            DA.SetDataList(4, FabricationTable.Columns);
            DA.SetData(5, summary.MaterialYield);
            DA.SetData(6, checked((int)summary.Boards));
            DA.SetDataList(7, files);
        }
    }
}
