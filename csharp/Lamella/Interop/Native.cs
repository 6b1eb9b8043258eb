using System;

namespace Lamella.Interop
{
    /// <summary>A native output in the two-call pattern: copy into <paramref name="buffer"/> (NULL for a size query).</summary>
    internal delegate Status Copy<T>(T[] buffer, UIntPtr capacity, out UIntPtr needed);

    /// <summary>Status checking and the two-call pattern, shared by every wrapper class.</summary>
    internal static class Native
    {
        /// <summary>Returns a success status; throws <see cref="LamellaException"/> with the native message for a failure.</summary>
        public static Status Check(Status status)
        {
            if ((int)status < 0)
            {
                // Read at once: the message belongs to the last call on this thread.
                throw new LamellaException(status, Utf8.FromNative(NativeMethods.lml_last_error_message()));
            }
            return status;
        }

        /// <summary>Reads a whole native array: a size query, then a copy into a buffer of that size.</summary>
        public static T[] Read<T>(Copy<T> copy)
        {
            UIntPtr needed;
            Status status = copy(null, UIntPtr.Zero, out needed);
            if (status != Status.BufferTooSmall)
            {
                Check(status);
                return new T[0]; // nothing to copy: the library succeeds on an empty output
            }
            var buffer = new T[checked((long)needed.ToUInt64())];
            Check(copy(buffer, needed, out needed));
            return buffer;
        }

        /// <summary>A native count (<c>size_t</c>) as an <see cref="int"/>.</summary>
        public static int Count(UIntPtr count) => checked((int)count.ToUInt64());

        /// <summary>An offset table (<c>size_t[]</c>) as <see cref="int"/> values.</summary>
        public static int[] Offsets(UIntPtr[] offsets)
        {
            var result = new int[offsets.Length];
            for (int i = 0; i < offsets.Length; i++)
            {
                result[i] = Count(offsets[i]);
            }
            return result;
        }

        /// <summary>
        /// Cuts <paramref name="values"/> (indices, one run after another) into runs of <paramref name="sizes"/> values each:
        /// the C ABI's layout of faces and polylines of varying length.
        /// </summary>
        public static int[][] Runs(uint[] sizes, uint[] values)
        {
            var runs = new int[sizes.Length][];
            int at = 0;
            for (int i = 0; i < sizes.Length; i++)
            {
                runs[i] = new int[checked((int)sizes[i])];
                for (int j = 0; j < runs[i].Length; j++) runs[i][j] = checked((int)values[at++]);
            }
            if (at != values.Length) throw new InvalidOperationException("the runs hold " + at + " values, the library wrote " + values.Length);
            return runs;
        }

        /// <summary>An array length as <c>size_t</c>.</summary>
        public static UIntPtr Size(int length) => new UIntPtr((uint)length);
    }
}
