using System;
using System.IO;
using System.IO.Compression;
using System.Text;

namespace Lamella.Hosting
{
    /// <summary>
    /// The frame of the archives a host document keeps (<see cref="FieldArchive"/>, <see cref="SessionArchive"/>): a
    /// four-letter magic, a 32-bit format version, then the records Deflate-compressed. Reading names the archive
    /// (<c>what</c>) in every <see cref="FormatException"/>: another kind, another version, truncated or damaged.
    /// </summary>
    internal static class ArchiveFraming
    {
        /// <summary>The framed bytes of what <paramref name="records"/> writes.</summary>
        public static byte[] Write(string magic, int version, Action<BinaryWriter> records)
        {
            using (var output = new MemoryStream())
            {
                output.Write(Encoding.ASCII.GetBytes(magic), 0, 4);
                output.Write(BitConverter.GetBytes(version), 0, 4);
                using (var deflate = new DeflateStream(output, CompressionLevel.Optimal, true))
                using (var writer = new BinaryWriter(deflate, Encoding.UTF8))
                {
                    records(writer);
                }
                return output.ToArray();
            }
        }

        /// <summary>
        /// Reads framed <paramref name="bytes"/> of <paramref name="magic"/> with <paramref name="records"/> (given the
        /// version); versions from <paramref name="oldest"/> to <paramref name="newest"/> are read.
        /// </summary>
        public static T Read<T>(byte[] bytes, string magic, int oldest, int newest, string what, Func<BinaryReader, int, T> records)
        {
            if (bytes == null) throw new ArgumentNullException(nameof(bytes));
            if (bytes.Length < 8 || Encoding.ASCII.GetString(bytes, 0, 4) != magic) throw new FormatException("not " + what + " (bad magic number)");
            int version = BitConverter.ToInt32(bytes, 4);
            if (version < oldest || version > newest)
                throw new FormatException(what + " of format version " + version + "; this plugin reads versions " + oldest + " to " + newest);
            try
            {
                using (var input = new MemoryStream(bytes, 8, bytes.Length - 8))
                using (var deflate = new DeflateStream(input, CompressionMode.Decompress))
                using (var reader = new BinaryReader(deflate, Encoding.UTF8))
                {
                    return records(reader, version);
                }
            }
            catch (EndOfStreamException)
            {
                throw new FormatException("the " + what + " are truncated");
            }
            catch (InvalidDataException e)
            {
                throw new FormatException("the " + what + " are damaged (" + e.Message + ")");
            }
            catch (IOException e)
            {
                // Mono reports bad Deflate data as an IOException (.NET as InvalidDataException).
                throw new FormatException("the " + what + " are damaged (" + e.Message + ")");
            }
        }
    }
}
