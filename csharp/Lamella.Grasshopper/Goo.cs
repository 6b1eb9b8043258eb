using System.Globalization;
using Grasshopper.Kernel.Types;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// A solved (or solving) field as it travels along Grasshopper wires: the native session shared by every
    /// downstream component (no copy per wire), and the θ its curves should keep. The Strip Field component owns it.
    /// </summary>
    public sealed class FieldData
    {
        public FieldData(FieldSolver solver, double thetaDegrees)
        {
            Solver = solver;
            ThetaDegrees = thetaDegrees;
        }

        public FieldSolver Solver { get; }
        public double ThetaDegrees { get; }
    }

    /// <summary>Level curves on a field, with the θ of that field (strips need it).</summary>
    public sealed class CurvesData
    {
        public CurvesData(LevelCurves curves, double thetaDegrees)
        {
            Curves = curves;
            ThetaDegrees = thetaDegrees;
        }

        public LevelCurves Curves { get; }
        public double ThetaDegrees { get; }
    }

    /// <summary>Traced guide curves with the θ they were traced at (the Trace P-Curve component owns them).</summary>
    public sealed class GuidesData
    {
        public GuidesData(GuideCurves guides, double thetaDegrees)
        {
            Guides = guides;
            ThetaDegrees = thetaDegrees;
        }

        public GuideCurves Guides { get; }
        public double ThetaDegrees { get; }
    }

    public sealed class FieldGoo : GH_Goo<FieldData>
    {
        public FieldGoo(FieldData data) : base(data) { }
        public override bool IsValid => Value != null;
        public override string TypeName => "Lamella Field";
        public override string TypeDescription => "A P-curve field on a mesh (a native Lamella solver session)";
        public override IGH_Goo Duplicate() => new FieldGoo(Value);
        public override string ToString() => Value == null ? "no field" : string.Format(CultureInfo.InvariantCulture, "Lamella field, θ = {0:0.###}°", Value.ThetaDegrees);
    }

    public sealed class CurvesGoo : GH_Goo<CurvesData>
    {
        public CurvesGoo(CurvesData data) : base(data) { }
        public override bool IsValid => Value != null;
        public override string TypeName => "Lamella Curves";
        public override string TypeDescription => "Level curves of a Lamella field";
        public override IGH_Goo Duplicate() => new CurvesGoo(Value);
        public override string ToString() => Value == null ? "no curves" : "Lamella level curves";
    }

    public sealed class StripsGoo : GH_Goo<Strips>
    {
        public StripsGoo(Strips strips) : base(strips) { }
        public override bool IsValid => Value != null;
        public override string TypeName => "Lamella Strips";
        public override string TypeDescription => "Rectifying developable strips with their unrollings and metrics";
        public override IGH_Goo Duplicate() => new StripsGoo(Value);
        public override string ToString() => Value == null ? "no strips" : "Lamella strips";
    }

    public sealed class GuidesGoo : GH_Goo<GuidesData>
    {
        public GuidesGoo(GuidesData data) : base(data) { }
        public override bool IsValid => Value != null;
        public override string TypeName => "Lamella Guides";
        public override string TypeDescription => "Traced guide curves (P-curves) on a mesh, in order: the level sets F = 0, 1, 2, … of a start field";
        public override IGH_Goo Duplicate() => new GuidesGoo(Value);
        public override string ToString() => Value == null ? "no guides" : string.Format(CultureInfo.InvariantCulture, "Lamella guides, θ = {0:0.###}°", Value.ThetaDegrees);
    }
}
