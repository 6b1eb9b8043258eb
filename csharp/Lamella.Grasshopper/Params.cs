using System;
using System.Drawing;
using Grasshopper.Kernel;
using Grasshopper.Kernel.Types;

namespace Lamella.Grasshopper
{
    /// <summary>
    /// A typed parameter for Lamella data (a field, level curves, strips, guides): wires and tooltips name the type, and
    /// Grasshopper refuses other data at the input with its own conversion message instead of passing it on. Hidden
    /// from the tab: the parameters exist on the components.
    /// </summary>
    public abstract class LamellaParam<TGoo> : GH_Param<TGoo> where TGoo : class, IGH_Goo
    {
        private readonly string iconName;

        protected LamellaParam(string name, string nickname, string description, string iconName)
            : base(name, nickname, description, LamellaInfo.Category, "Params", GH_ParamAccess.item)
        {
            this.iconName = iconName;
        }

        public override GH_Exposure Exposure => GH_Exposure.hidden;

        protected override Bitmap Icon => Icons.Load(iconName);

        /// <summary>Registers a parameter of this type as an input.</summary>
        public static int AddTo(GH_Component.GH_InputParamManager inputs, LamellaParam<TGoo> parameter, string description) =>
            inputs.AddParameter(parameter, parameter.Name, parameter.NickName, description, GH_ParamAccess.item);

        /// <summary>Registers a parameter of this type as an output.</summary>
        public static int AddTo(GH_Component.GH_OutputParamManager outputs, LamellaParam<TGoo> parameter, string description) =>
            outputs.AddParameter(parameter, parameter.Name, parameter.NickName, description, GH_ParamAccess.item);
    }

    /// <summary>Parameter for a Lamella field (Strip Field → Level Curves).</summary>
    public sealed class FieldParam : LamellaParam<FieldGoo>
    {
        public FieldParam() : base("Field", "F", "A Lamella field: a P-curve field on a mesh.", "StripField") { }
        public override Guid ComponentGuid => new Guid("afbde111-4f73-4bf1-971a-0d45a153eb36");
        // Grasshopper instantiates T to cast incoming data; the goo types have no empty constructor.
        protected override FieldGoo InstantiateT() => new FieldGoo(null);
    }

    /// <summary>Parameter for Lamella level curves (Level Curves → Rectifying Strips).</summary>
    public sealed class CurvesParam : LamellaParam<CurvesGoo>
    {
        public CurvesParam() : base("Curves", "C", "Lamella level curves of a field, with its θ.", "LevelCurves") { }
        public override Guid ComponentGuid => new Guid("a7d26e6e-1104-4085-8472-cde1721483b6");
        protected override CurvesGoo InstantiateT() => new CurvesGoo(null);
    }

    /// <summary>Parameter for Lamella strips (Rectifying Strips → Strip Quality).</summary>
    public sealed class StripsParam : LamellaParam<StripsGoo>
    {
        public StripsParam() : base("Strips", "S", "Lamella rectifying strips with their unrollings and metrics.", "RectifyingStrips") { }
        public override Guid ComponentGuid => new Guid("4e8bdf1c-0c64-4dbe-be3e-a6c20f0192ee");
        protected override StripsGoo InstantiateT() => new StripsGoo(null);
    }

    /// <summary>Parameter for Lamella guides (Trace P-Curve → Strip Field).</summary>
    public sealed class GuidesParam : LamellaParam<GuidesGoo>
    {
        public GuidesParam() : base("Guides", "G", "Lamella guides: traced P-curves in order.", "TracePCurve") { }
        public override Guid ComponentGuid => new Guid("518b165b-e1e6-4c86-b5c3-9ee473ca12f3");
        protected override GuidesGoo InstantiateT() => new GuidesGoo(null);
    }
}
