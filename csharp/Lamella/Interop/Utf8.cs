using System;
using System.Runtime.InteropServices;
using System.Text;

namespace Lamella.Interop
{
    /// <summary>UTF-8 strings across the C boundary (.NET Framework 4.8 has no PtrToStringUTF8).</summary>
    internal static class Utf8
    {
        /// <summary>Copies a NUL-terminated UTF-8 string owned by the library (never freed here).</summary>
        public static string FromNative(IntPtr text)
        {
            if (text == IntPtr.Zero)
            {
                return string.Empty;
            }
            int length = 0;
            while (Marshal.ReadByte(text, length) != 0)
            {
                length++;
            }
            var bytes = new byte[length];
            Marshal.Copy(text, bytes, 0, length);
            return Encoding.UTF8.GetString(bytes);
        }

        /// <summary>The text of UTF-8 bytes up to their first NUL (all of them without one), as the library's two-call text outputs write them.</summary>
        public static string FromTerminated(byte[] bytes)
        {
            if (bytes == null) throw new ArgumentNullException(nameof(bytes));
            int length = Array.IndexOf(bytes, (byte)0);
            return Encoding.UTF8.GetString(bytes, 0, length < 0 ? bytes.Length : length);
        }

        /// <summary>A NUL-terminated UTF-8 copy of <paramref name="text"/> for a <c>const char *</c> argument.</summary>
        public static byte[] ToNative(string text)
        {
            byte[] encoded = Encoding.UTF8.GetBytes(text);
            var terminated = new byte[encoded.Length + 1];
            Buffer.BlockCopy(encoded, 0, terminated, 0, encoded.Length);
            return terminated;
        }
    }
}
