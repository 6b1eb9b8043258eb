using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using Grasshopper.Kernel;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Strip Viewer: the interactive 3D viewer page of a strip pattern (view.html, one self-contained file to open in
    /// any browser, to share with people without Rhino), written to a file when Write is true.
    /// </summary>
    public class StripViewerComponent : LamellaComponent
    {
        public StripViewerComponent()
            : base("Strip Viewer", "View",
                "The interactive 3D viewer page of a strip pattern (view.html): the surface, level curves, strips coloured per strip, by the angle error of their rectifying planes or by bending utilisation, rulings and the flat strips beside them; hover or click a strip for its length and Table 4 figures. One self-contained HTML file, no network needed; written to File when Write is true.",
                "RectifyingStrips")
        {
        }

        public override Guid ComponentGuid => new Guid("cd20d4d7-f52a-4959-ae6e-d9c566821b66");
        public override GH_Exposure Exposure => GH_Exposure.secondary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            LamellaParam<StripsGoo>.AddTo(pManager, new StripsParam(), "Strips from Rectifying Strips (in metres).");
            LamellaParam<CurvesGoo>.AddTo(pManager, new CurvesParam(), "The level curves the strips were built on (their surface is shown too).");
            pManager.AddNumberParameter("Utilisation", "U", "Optional: per strip its bending utilisation (Fabrication's U output), to colour by.", GH_ParamAccess.list);
            pManager[2].Optional = true;
            pManager.AddTextParameter("Title", "T", "The design's name, shown as the page title.", GH_ParamAccess.item, "Lamella strips");
            pManager.AddBooleanParameter("Write", "W", "Write the page to File.", GH_ParamAccess.item, false);
            pManager.AddTextParameter("File", "F", "Path of the HTML file to write (its folder must exist), e.g. C:\\designs\\roof\\view.html.", GH_ParamAccess.item, string.Empty);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddTextParameter("Html", "H", "The page's HTML text.", GH_ParamAccess.item);
            pManager.AddTextParameter("Written", "Wr", "The file written (empty unless Write is true).", GH_ParamAccess.item);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Strips strips = GooValue<StripsGoo, Strips>(DA, 0, "Lamella strips");
            CurvesData curves = GooValue<CurvesGoo, CurvesData>(DA, 1, "Lamella curves");
            if (strips == null || curves == null) return;
            var utilisation = new List<double>();
            string title = "Lamella strips", file = string.Empty;
            bool write = false;
            DA.GetDataList(2, utilisation);
            DA.GetData(3, ref title);
            DA.GetData(4, ref write);
            DA.GetData(5, ref file);

            string html = strips.ViewHtml(curves.Curves, utilisation.Count > 0 ? utilisation.ToArray() : null, title);
            string written = string.Empty;
            if (write)
            {
                if (string.IsNullOrWhiteSpace(file))
                {
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "Write is true but no File is given: nothing written");
                }
                else
                {
                    File.WriteAllText(file, html, new UTF8Encoding(false));
                    written = file;
                }
            }
            DA.SetData(0, html);
            DA.SetData(1, written);
        }
    }
}
