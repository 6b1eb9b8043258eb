using System;

namespace Lamella
{
    /// <summary>
    /// A failed native call: its <see cref="Status"/> and the library's message, which names the offending element. The one
    /// subclass, <see cref="NoAcceptableFamilyException"/>, reports strips that miss θ.
    /// </summary>
    [Serializable]
    public class LamellaException : Exception
    {
        /// <summary>The failure status returned by the native library (negative; <see cref="Status.NoAcceptableFamily"/> for <see cref="NoAcceptableFamilyException"/>).</summary>
        public Status Status { get; }

        /// <summary>The native message (<c>lml_last_error_message</c>) as returned by the library.</summary>
        public string NativeMessage { get; }

        /// <summary>Creates the exception for a failed call.</summary>
        public LamellaException(Status status, string nativeMessage)
            : base(Library.StatusName(status) + ": " + nativeMessage)
        {
            Status = status;
            NativeMessage = nativeMessage;
        }
    }
}
