using System;
using System.Runtime.Serialization;
using System.Security.Permissions;

namespace Lamella
{
    /// <summary>
    /// A failed native call: its <see cref="Status"/> and the library's message, which names the offending element.
    /// Serialisable with both (e.g. across application domains or into a log). The one subclass,
    /// <see cref="NoAcceptableFamilyException"/>, reports strips that miss θ.
    /// </summary>
    [Serializable]
    public class LamellaException : Exception
    {
        private const string StatusKey = "Lamella.Status";
        private const string NativeMessageKey = "Lamella.NativeMessage";

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

        /// <summary>Restores a serialised exception with its status and native message.</summary>
        protected LamellaException(SerializationInfo info, StreamingContext context)
            : base(info, context)
        {
            Status = (Status)info.GetInt32(StatusKey);
            NativeMessage = info.GetString(NativeMessageKey);
        }

        /// <summary>Serialises the exception with its status and native message.</summary>
        [SecurityPermission(SecurityAction.Demand, SerializationFormatter = true)]
        public override void GetObjectData(SerializationInfo info, StreamingContext context)
        {
            if (info == null) throw new ArgumentNullException(nameof(info));
            base.GetObjectData(info, context);
            info.AddValue(StatusKey, (int)Status);
            info.AddValue(NativeMessageKey, NativeMessage);
        }
    }
}
