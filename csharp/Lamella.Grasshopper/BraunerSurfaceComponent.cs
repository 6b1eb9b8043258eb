using System;
using System.Collections.Generic;
using Grasshopper.Kernel;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Brauner Surface: the surface of the paper's Fig. 32 (Sec. 5.2.4, Eq. 23) as a mesh, with its u-lines, asymptotic
    /// curves of constant slope computed exactly: a validation case for Constant Slope Field and the asymptotic family,
    /// and a start for designs whose node axes are all vertical.
    /// </summary>
    public class BraunerSurfaceComponent : LamellaComponent
    {
        public BraunerSurfaceComponent()
            : base("Brauner Surface", "Brauner",
                "The Brauner surface of the paper's Fig. 32 (Eq. 23): x = cos²u − 2v, y = sin u cos u − u, z = 2μ e^(−v) cos u over u in [0.6, π − 0.6], v in [−0.5, 0.5]. Its u-lines v = const are asymptotic curves rising at the constant slope atan(μ e^(−v)).",
                "StripField")
        {
        }

        public override Guid ComponentGuid => new Guid("aba16994-3553-4af1-8edb-a9726ee40baf");
        public override GH_Exposure Exposure => GH_Exposure.tertiary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddIntegerParameter("Vertices", "V", "Approximate number of mesh vertices, 100 to 1,000,000. Default 3000.", GH_ParamAccess.item, 3000);
            pManager.AddNumberParameter("Mu", "μ", "The vertical scale μ > 0 of Eq. 23. Default 1.", GH_ParamAccess.item, 1.0);
            pManager.AddIntegerParameter("Lines", "N", "Number of u-lines, at least 2, spread evenly over v. Default 11.", GH_ParamAccess.item, 11);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", "The surface, triangulated by a jittered grid in (u, v), faces oriented upwards.", GH_ParamAccess.item);
            pManager.AddCurveParameter("U-Lines", "U", "The u-lines v = const, computed exactly: asymptotic curves of constant slope.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Slopes", "β", "The slope of each u-line against the horizontal, in degrees: atan(μ e^(−v)).", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            int vertices = 3000, count = 11;
            double mu = 1.0;
            DA.GetData(0, ref vertices);
            DA.GetData(1, ref mu);
            DA.GetData(2, ref count);
            if (count < 2)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Lines must be at least 2");
                return;
            }
            using (LamellaMesh mesh = LamellaMesh.Brauner(vertices, mu))
            {
                DA.SetData(0, RhinoConversion.TriangleMesh(mesh.Positions(), mesh.Triangles()));
            }
            var lines = new List<PolylineCurve>(count);
            var slopes = new List<double>(count);
            double[][] uLines = LamellaMesh.BraunerULines(mu, count, 200);
            for (int k = 0; k < count; k++)
            {
                lines.Add(new PolylineCurve(RhinoConversion.Points(uLines[k])));
                double v = -0.5 + k / (double)(count - 1);
                slopes.Add(Math.Atan(mu * Math.Exp(-v)) * 180.0 / Math.PI);
            }
            DA.SetDataList(1, lines);
            DA.SetDataList(2, slopes);
        }
    }
}
