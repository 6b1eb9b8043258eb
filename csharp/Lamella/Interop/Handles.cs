using System;
using Microsoft.Win32.SafeHandles;

namespace Lamella.Interop
{
    /// <summary>
    /// An owned native handle. <c>Dispose</c> or, failing that, the finalizer releases it exactly once
    /// (SafeHandle guarantees both). A new handle type is one subclass naming its <c>_free</c> function.
    /// </summary>
    internal abstract class LamellaHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        protected LamellaHandle() : base(true) { }
    }

    internal sealed class MeshHandle : LamellaHandle
    {
        public MeshHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_mesh_free(handle); return true; }
    }

    internal sealed class FieldHandle : LamellaHandle
    {
        public FieldHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_field_free(handle); return true; }
    }

    internal sealed class CurvesHandle : LamellaHandle
    {
        public CurvesHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_curves_free(handle); return true; }
    }

    internal sealed class StripsHandle : LamellaHandle
    {
        public StripsHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_strips_free(handle); return true; }
    }

    internal sealed class SearchHandle : LamellaHandle
    {
        public SearchHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_search_free(handle); return true; }
    }

    internal sealed class GuidesHandle : LamellaHandle
    {
        public GuidesHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_guides_free(handle); return true; }
    }

    internal sealed class FabricationHandle : LamellaHandle
    {
        public FabricationHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_fabrication_free(handle); return true; }
    }

    internal sealed class NetHandle : LamellaHandle
    {
        public NetHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_net_free(handle); return true; }
    }

    internal sealed class StripNetHandle : LamellaHandle
    {
        public StripNetHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_strip_net_free(handle); return true; }
    }

    internal sealed class StripWebHandle : LamellaHandle
    {
        public StripWebHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_strip_web_free(handle); return true; }
    }

    internal sealed class ReshapeHandle : LamellaHandle
    {
        public ReshapeHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_reshape_free(handle); return true; }
    }

    internal sealed class AlternationHandle : LamellaHandle
    {
        public AlternationHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_alternation_free(handle); return true; }
    }

    internal sealed class BaseMeshHandle : LamellaHandle
    {
        public BaseMeshHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_base_mesh_free(handle); return true; }
    }

    internal sealed class ShadingHandle : LamellaHandle
    {
        public ShadingHandle() { }
        protected override bool ReleaseHandle() { NativeMethods.lml_shading_free(handle); return true; }
    }
}
