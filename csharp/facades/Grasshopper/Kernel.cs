// COMPILE-TIME FACADE of Grasshopper (never shipped): only the members Lamella.Grasshopper uses, with
// the real namespaces, signatures, nesting and enum values; every body throws.
using System;
using System.Collections;
using System.Collections.Generic;
using System.Drawing;
using System.Runtime.CompilerServices;
using GH_IO.Serialization;

namespace Grasshopper
{
    public static class Instances
    {
        public static Grasshopper.Kernel.GH_ComponentServer ComponentServer { get { throw new NotSupportedException("facade"); } }
    }
}

namespace Grasshopper
{
    public class DataTree<T> : Grasshopper.Kernel.Data.IGH_DataTree
    {
        public DataTree() { throw new NotSupportedException("facade"); }
        public void AddRange(IEnumerable<T> data, Grasshopper.Kernel.Data.GH_Path path) { throw new NotSupportedException("facade"); }
    }
}

namespace Grasshopper.Kernel.Data
{
    public interface IGH_DataTree
    {
    }

    public class GH_Path
    {
        public GH_Path(int index) { throw new NotSupportedException("facade"); }
    }

    public class GH_Structure<T> where T : Grasshopper.Kernel.Types.IGH_Goo
    {
        public GH_Structure() { throw new NotSupportedException("facade"); }
        public IList<List<T>> Branches { get { throw new NotSupportedException("facade"); } }
    }
}

namespace Grasshopper.Kernel
{
    public enum GH_ParamAccess { item = 0, list = 1, tree = 2 }

    public enum GH_RuntimeMessageLevel { Blank = 0, Warning = 10, Error = 20, Remark = 255 }

    public enum GH_DocumentContext { Unknown = 0, None = 1, Open = 2, Close = 3, Loaded = 4, Unloaded = 5, Lock = 6, Unlock = 7 }

    public enum GH_LoadingInstruction { Proceed = 0, Abort = 1 }

    [Flags]
    public enum GH_Exposure
    {
        hidden = -1, primary = 2, secondary = 4, tertiary = 8, quarternary = 16, quinary = 32, senary = 64, septenary = 128, obscure = 65536,
    }

    public abstract class GH_AssemblyInfo
    {
        public virtual string Name { get { throw new NotSupportedException("facade"); } }
        public virtual string Description { get { throw new NotSupportedException("facade"); } }
        public virtual Guid Id { get { throw new NotSupportedException("facade"); } }
        public virtual string AuthorName { get { throw new NotSupportedException("facade"); } }
        public virtual string AuthorContact { get { throw new NotSupportedException("facade"); } }
        public virtual string Version { get { throw new NotSupportedException("facade"); } }
        public virtual Bitmap Icon { get { throw new NotSupportedException("facade"); } }
        public string Location { get { throw new NotSupportedException("facade"); } }
    }

    public abstract class GH_AssemblyPriority
    {
        protected GH_AssemblyPriority() { throw new NotSupportedException("facade"); }
        public abstract GH_LoadingInstruction PriorityLoad();
    }

    public class GH_ComponentServer
    {
        internal GH_ComponentServer() { throw new NotSupportedException("facade"); }
        public GH_AssemblyInfo FindAssembly(Guid libraryId) { throw new NotSupportedException("facade"); }
        public void AddCategoryIcon(string fullCategoryName, Bitmap icon) { throw new NotSupportedException("facade"); }
        public void AddCategoryShortName(string fullCategoryName, string categoryAbbreviation) { throw new NotSupportedException("facade"); }
        public void AddCategorySymbolName(string fullCategoryName, char symbol) { throw new NotSupportedException("facade"); }
    }

    public interface IGH_Param
    {
        bool Optional { get; set; }
    }

    public interface IGH_DataAccess
    {
        bool GetData<T>(int index, ref T destination);
        bool GetDataList<T>(int index, List<T> list);
        bool GetDataTree<T>(int index, out Grasshopper.Kernel.Data.GH_Structure<T> tree) where T : Grasshopper.Kernel.Types.IGH_Goo;
        bool SetData(int paramIndex, object data);
        bool SetDataList(int paramIndex, IEnumerable data);
        bool SetDataTree(int paramIndex, Grasshopper.Kernel.Data.IGH_DataTree tree);
        int Iteration { get; }
    }

    public class GH_Document
    {
        internal GH_Document() { throw new NotSupportedException("facade"); }
        public delegate void GH_ScheduleDelegate(GH_Document doc);
        public void ScheduleSolution(int delay, GH_Document.GH_ScheduleDelegate callback) { throw new NotSupportedException("facade"); }
        public static bool IsEscapeKeyDown() { throw new NotSupportedException("facade"); }
    }

    public abstract class GH_InstanceDescription
    {
        internal GH_InstanceDescription() { throw new NotSupportedException("facade"); }
        public string Name { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public string NickName { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public virtual bool Write(GH_IWriter writer) { throw new NotSupportedException("facade"); }
        public virtual bool Read(GH_IReader reader) { throw new NotSupportedException("facade"); }
    }

    public abstract class GH_DocumentObject : GH_InstanceDescription
    {
        internal GH_DocumentObject() { throw new NotSupportedException("facade"); }
        public abstract Guid ComponentGuid { get; }
        public virtual GH_Exposure Exposure { get { throw new NotSupportedException("facade"); } }
        protected virtual Bitmap Icon { get { throw new NotSupportedException("facade"); } }
        public GH_Document OnPingDocument() { throw new NotSupportedException("facade"); }
        public virtual void ExpireSolution(bool recompute) { throw new NotSupportedException("facade"); }
        public virtual void RemovedFromDocument(GH_Document document) { throw new NotSupportedException("facade"); }
        public virtual void DocumentContextChanged(GH_Document document, GH_DocumentContext context) { throw new NotSupportedException("facade"); }
        // The real GH_DocumentObject overrides its base's serialisation: base.Write/Read in a subclass must bind here or lower.
        public override bool Write(GH_IWriter writer) { throw new NotSupportedException("facade"); }
        public override bool Read(GH_IReader reader) { throw new NotSupportedException("facade"); }
    }

    public abstract class GH_ActiveObject : GH_DocumentObject
    {
        internal GH_ActiveObject() { throw new NotSupportedException("facade"); }
        public void AddRuntimeMessage(GH_RuntimeMessageLevel level, string text) { throw new NotSupportedException("facade"); }
        public override void ExpireSolution(bool recompute) { throw new NotSupportedException("facade"); }
        public override bool Write(GH_IWriter writer) { throw new NotSupportedException("facade"); }
        public override bool Read(GH_IReader reader) { throw new NotSupportedException("facade"); }
    }

    public abstract class GH_Param<T> : GH_ActiveObject, IGH_Param where T : class, Grasshopper.Kernel.Types.IGH_Goo
    {
        protected GH_Param(string name, string nickname, string description, string category, string subcategory, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
        public bool Optional { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        protected virtual T InstantiateT() { throw new NotSupportedException("facade"); }
    }

    public abstract class GH_Component : GH_ActiveObject
    {
        protected GH_Component(string name, string nickname, string description, string category, string subCategory) { throw new NotSupportedException("facade"); }
        public string Message { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        protected abstract void RegisterInputParams(GH_Component.GH_InputParamManager pManager);
        protected abstract void RegisterOutputParams(GH_Component.GH_OutputParamManager pManager);
        protected abstract void SolveInstance(IGH_DataAccess DA);
        protected virtual void BeforeSolveInstance() { throw new NotSupportedException("facade"); }
        protected virtual void AfterSolveInstance() { throw new NotSupportedException("facade"); }
        protected static double DocumentTolerance() { throw new NotSupportedException("facade"); }
        // Real plugins' base.Write/Read calls reference GH_Component::Write/Read: the real GH_Component overrides them.
        public override bool Write(GH_IWriter writer) { throw new NotSupportedException("facade"); }
        public override bool Read(GH_IReader reader) { throw new NotSupportedException("facade"); }
        public override void RemovedFromDocument(GH_Document document) { throw new NotSupportedException("facade"); }
        public override void DocumentContextChanged(GH_Document document, GH_DocumentContext context) { throw new NotSupportedException("facade"); }

        public class GH_InputParamManager
        {
            internal GH_InputParamManager() { throw new NotSupportedException("facade"); }
            // The real indexer is named Param (get_Param in the IL), not the C# default Item.
            [IndexerName("Param")]
            public IGH_Param this[int index] { get { throw new NotSupportedException("facade"); } }
            public int AddMeshParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddNumberParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddNumberParameter(string name, string nickname, string description, GH_ParamAccess access, double @default) { throw new NotSupportedException("facade"); }
            public int AddIntegerParameter(string name, string nickname, string description, GH_ParamAccess access, int @default) { throw new NotSupportedException("facade"); }
            public int AddBooleanParameter(string name, string nickname, string description, GH_ParamAccess access, bool @default) { throw new NotSupportedException("facade"); }
            public int AddTextParameter(string name, string nickname, string description, GH_ParamAccess access, string @default) { throw new NotSupportedException("facade"); }
            public int AddVectorParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddVectorParameter(string name, string nickname, string description, GH_ParamAccess access, Rhino.Geometry.Vector3d @default) { throw new NotSupportedException("facade"); }
            public int AddPointParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddCurveParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddGenericParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddPlaneParameter(string name, string nickname, string description, GH_ParamAccess access, Rhino.Geometry.Plane @default) { throw new NotSupportedException("facade"); }
            public int AddParameter(IGH_Param param, string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
        }

        public class GH_OutputParamManager
        {
            internal GH_OutputParamManager() { throw new NotSupportedException("facade"); }
            public int AddMeshParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddCurveParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddLineParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddPointParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddNumberParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddIntegerParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddTextParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddBooleanParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddGenericParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddVectorParameter(string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
            public int AddParameter(IGH_Param param, string name, string nickname, string description, GH_ParamAccess access) { throw new NotSupportedException("facade"); }
        }
    }
}

namespace Grasshopper.Kernel.Types
{
    public interface IGH_Goo
    {
        bool IsValid { get; }
        string TypeName { get; }
        string TypeDescription { get; }
        IGH_Goo Duplicate();
    }

    public abstract class GH_Goo<T> : IGH_Goo
    {
        protected GH_Goo() { throw new NotSupportedException("facade"); }
        protected GH_Goo(T internal_data) { throw new NotSupportedException("facade"); }
        public virtual T Value { get { throw new NotSupportedException("facade"); } set { throw new NotSupportedException("facade"); } }
        public abstract bool IsValid { get; }
        public abstract string TypeName { get; }
        public abstract string TypeDescription { get; }
        public abstract IGH_Goo Duplicate();
        public abstract override string ToString();
    }

    // The real GH_Curve derives from GH_GeometricGoo<Curve> (itself a GH_Goo<Curve>); the plugin only reads Value.
    public class GH_Curve : GH_Goo<Rhino.Geometry.Curve>
    {
        public GH_Curve() { throw new NotSupportedException("facade"); }
        public override bool IsValid { get { throw new NotSupportedException("facade"); } }
        public override string TypeName { get { throw new NotSupportedException("facade"); } }
        public override string TypeDescription { get { throw new NotSupportedException("facade"); } }
        public override IGH_Goo Duplicate() { throw new NotSupportedException("facade"); }
        public override string ToString() { throw new NotSupportedException("facade"); }
    }
}
