using Lamella.Interop;

namespace Lamella
{
    /// <summary>Facts about the loaded native library and test hooks.</summary>
    public static class Library
    {
        /// <summary>The C ABI version this binding was written against (<c>LML_ABI_VERSION</c> of lamella.h).</summary>
        public const uint BindingAbiVersion = 3;

        /// <summary>The ABI version the loaded native library implements.</summary>
        public static uint AbiVersion => NativeMethods.lml_abi_version();

        /// <summary>The native library's version, e.g. "0.1.0".</summary>
        public static string Version => Utf8.FromNative(NativeMethods.lml_version());

        /// <summary>The C name of a status, e.g. "LML_STATUS_NOT_A_DISK".</summary>
        public static string StatusName(Status status) => Utf8.FromNative(NativeMethods.lml_status_name((int)status));

        /// <summary>Throws when the loaded library implements another ABI version than this binding expects.</summary>
        public static void CheckAbiVersion()
        {
            uint loaded = AbiVersion;
            if (loaded != BindingAbiVersion)
            {
                throw new System.InvalidOperationException(
                    "the native Lamella library implements C ABI version " + loaded + ", this binding needs version " + BindingAbiVersion);
            }
        }

        /// <summary>Handles (meshes, fields, searches, curves, strips, guides) alive in the native library: for tests that check every handle is released.</summary>
        public static long DebugLiveHandles => (long)NativeMethods.lml_debug_live_handles().ToUInt64();

        /// <summary>Makes the native library panic on purpose; the panic surfaces as a <see cref="LamellaException"/> with <see cref="Status.InternalError"/>.</summary>
        public static void DebugTriggerPanic() => Native.Check(NativeMethods.lml_debug_trigger_panic());
    }
}
