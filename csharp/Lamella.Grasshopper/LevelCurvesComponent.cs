using System;
using System.Collections.Generic;
using Grasshopper.Kernel;
using Lamella.Conversion;

namespace Lamella.Grasshopper
{
    /// <summary>Level Curves: the level polylines of a field, at a count of uniform levels or at given values; closed levels come out closed.</summary>
    public class LevelCurvesComponent : LamellaComponent
    {
        public LevelCurvesComponent()
            : base("Level Curves", "Levels",
                "The level curves of a Lamella field as polylines: a count of levels spread uniformly over the field's range, or given level values. Levels that close on themselves come out as closed polylines.",
                "LevelCurves")
        {
        }

        public override Guid ComponentGuid => new Guid("7c3489b9-392b-4ea7-a9cd-409a7ac0d9fc");
        public override GH_Exposure Exposure => GH_Exposure.primary;

        protected override void RegisterInputParams(GH_InputParamManager pManager)
        {
            LamellaParam<FieldGoo>.AddTo(pManager, new FieldParam(), "A field from Strip Field.");
            pManager.AddIntegerParameter("Count", "N", "Number of levels spread uniformly over the field's range, its extremes left out (a count). Ignored when Values are given. Default 10.", GH_ParamAccess.item, 10);
            pManager.AddNumberParameter("Values", "V", "Optional level values (field units), each inside the field's range; they replace Count.", GH_ParamAccess.list);
            pManager[2].Optional = true;
            pManager.AddNumberParameter("Spacing", "S", "Resample each polyline at about this arc length (document units), which sets the strips' quad length; 0 keeps one point per crossed mesh edge. Default 0.", GH_ParamAccess.item, 0.0);
        }

        protected override void RegisterOutputParams(GH_OutputParamManager pManager)
        {
            LamellaParam<CurvesGoo>.AddTo(pManager, new CurvesParam(), "The level curves for Rectifying Strips.");
            pManager.AddCurveParameter("Polylines", "P", "The level polylines (a level may give several pieces); closed levels are closed polylines.", GH_ParamAccess.list);
            pManager.AddNumberParameter("Levels", "L", "The level value of each polyline (field units).", GH_ParamAccess.list);
        }

        protected override void Solve(IGH_DataAccess DA)
        {
            FieldData field = GooValue<FieldGoo, FieldData>(DA, 0, "a Lamella field");
            if (field == null) return;
            int count = 10;
            double spacing = 0;
            var values = new List<double>();
            DA.GetData(1, ref count);
            DA.GetDataList(2, values);
            DA.GetData(3, ref spacing);
            if (values.Count == 0 && count < 1)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Error, "Count must be at least 1");
                return;
            }

            LevelCurves curves = Keep(DA, values.Count > 0
                ? LevelCurves.AtLevels(field.Solver, values.ToArray(), spacing)
                : LevelCurves.Uniform(field.Solver, count, spacing));
            if (curves.Count == 0)
            {
                AddRuntimeMessage(GH_RuntimeMessageLevel.Warning, "no level crosses the surface in more than a point");
            }
            DA.SetData(0, new CurvesGoo(new CurvesData(curves, field.ThetaDegrees)));
            DA.SetDataList(1, ClosedPolylines(curves));
            DA.SetDataList(2, curves.Levels());
        }

        /// <summary>The curves as polylines, closed ones with their first point repeated.</summary>
        internal static List<Rhino.Geometry.PolylineCurve> ClosedPolylines(LevelCurves curves) =>
            RhinoConversion.Polylines(Packing.CloseLoops(new Packed(curves.Points(), curves.Offsets(), 3), curves.Closed()));
    }
}
