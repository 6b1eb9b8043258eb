using System;
using System.Collections.Generic;
using Grasshopper.Kernel;
using Lamella.Conversion;
using Rhino.Geometry;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// Trace P-Curve: discrete pseudo-geodesics (paper Sec. 3.2.1, Eq. 4) traced on a mesh from points on its boundary,
    /// as polylines and as guides for Strip Field's start field (Sec. 3.2.2).
    /// </summary>
    public class TracePCurveComponent : LamellaComponent
    {
        public TracePCurveComponent()
            : base("Trace P-Curve", "Trace",
                "Traces P-curves on a mesh: from each start point (snapped to the nearest boundary point) a polyline whose binormals keep the angle θ to the surface normal (paper Sec. 3.2.1), until it reaches the boundary. In order, they can guide Strip Field's start field.",
                "TracePCurve")
        {
        }

        public override Guid ComponentGuid => new Guid("2b9912d6-98b4-48bd-b1fd-b3d249c3116d");
        public override GH_Exposure Exposure => GH_Exposure.primary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            pManager.AddMeshParameter("Mesh", "M", StripFieldComponent.MeshDescription, GH_ParamAccess.item);
            pManager.AddPointParameter("Start Points", "P", "One point per curve, each snapped to the nearest point of the mesh boundary (document units). Their order is the guides' order: guide i becomes the level F = i of Strip Field's start field.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Start Angle", "α", "Angle of the start tangent against the boundary direction that has the surface on its left, turned into the surface, in degrees, strictly between 0 and 180 (90: perpendicular to the boundary). Default 90.", GH_ParamAccess.item, 90.0);
            pManager.AddNumberParameter("Theta", "θ", "Angle between the curves' binormals and the surface normal, in degrees, 0–180 (90: geodesics, 0: asymptotic curves; θ and 180 − θ are mirror images). Default 60.", GH_ParamAccess.item, 60.0);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            LamellaParam<GuidesGoo>.AddTo(pManager, new GuidesParam(), "The traced curves as guides for Strip Field (a shared native object).");
            pManager.AddCurveParameter("Polylines", "C", "The traced polylines, one per start point; their points lie on mesh edges.", GH_ParamAccess.list);
            pManager.AddTextParameter("Stops", "S", "Why each curve ended: boundary (the normal end), no candidate (no next point realises θ), length limit or point limit.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Lengths", "L", "The length of each curve, in document units.", GH_ParamAccess.list);
            pManager.AddPointParameter("Starts", "P", "The start points snapped to the boundary.", GH_ParamAccess.list);
            pManager.AddPointParameter("Crossings", "X", "Where curves cross each other or themselves (guides must not).", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            Mesh mesh = null;
            var points = new List<Point3d>();
            if (!DA.GetData(0, ref mesh) || mesh == null) return;
            if (!DA.GetDataList(1, points) || points.Count == 0) return;
            double startAngle = 90, thetaDegrees = 60;
            DA.GetData(2, ref startAngle);
            DA.GetData(3, ref thetaDegrees);

            CleanMesh clean = CleanMeshInput(mesh);
            double[] xyz = clean.Xyz;
            var starts = new EdgePoint[points.Count];
            GuideCurves guides;
            using (var native = LamellaMesh.FromArrays(xyz, clean.Triangles))
            {
                for (int i = 0; i < starts.Length; i++) starts[i] = BoundaryStarts.Nearest(native, points[i].X, points[i].Y, points[i].Z);
                guides = Keep(DA, GuideCurves.Trace(native, starts, thetaDegrees, startAngle));
            }

            TraceStop[] stops = guides.Stops();
            var stopNames = new List<string>(stops.Length);
            for (int i = 0; i < stops.Length; i++)
            {
                stopNames.Add(StopName(stops[i]));
                if (stops[i] != TraceStop.Boundary)
                {
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "curve " + i + " ended before the boundary: " + StopName(stops[i]));
                }
            }
            var snapped = new List<Point3d>(starts.Length);
            foreach (EdgePoint start in starts) snapped.Add(RhinoConversion.Point(start.Position(xyz), 0));
            var crossings = new List<Point3d>();
            foreach (Crossing crossing in guides.Crossings()) crossings.Add(RhinoConversion.Point(crossing.Position, 0));
            if (starts.Length > 1)
            {
                try
                {
                    guides.CheckOrder();
                }
                catch (LamellaException e)
                {
                    AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "not usable as guides: " + e.NativeMessage);
                }
            }

            DA.SetData(0, new GuidesGoo(new GuidesData(guides, thetaDegrees)));
            DA.SetDataList(1, RhinoConversion.Polylines(new Packed(guides.Points(), guides.Offsets(), 3)));
            DA.SetDataList(2, stopNames);
            DA.SetDataList(3, guides.Lengths());
            DA.SetDataList(4, snapped);
            DA.SetDataList(5, crossings);
        }

        private static string StopName(TraceStop stop)
        {
            switch (stop)
            {
                case TraceStop.Boundary: return "boundary";
                case TraceStop.NoCandidate: return "no candidate";
                case TraceStop.LengthLimit: return "length limit";
                case TraceStop.PointLimit: return "point limit";
                default: return "stop " + (uint)stop;
            }
        }
    }
}
