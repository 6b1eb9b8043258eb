using System;
using System.Collections.Generic;

namespace Lamella.Conversion
{
    /// <summary>Items of varying length (polylines, strips) concatenated in one flat array and cut by an offset table.</summary>
    public sealed class Packed
    {
        /// <summary>The concatenated values, <see cref="Dimension"/> per point.</summary>
        public double[] Values { get; }
        /// <summary>Count + 1 offsets from 0, in points: item i spans Offsets[i] .. Offsets[i + 1].</summary>
        public int[] Offsets { get; }
        /// <summary>Values per point (3 in space, 2 in the plane).</summary>
        public int Dimension { get; }

        /// <summary>Wraps packed arrays.</summary>
        public Packed(double[] values, int[] offsets, int dimension)
        {
            Values = values;
            Offsets = offsets;
            Dimension = dimension;
        }

        /// <summary>The number of items.</summary>
        public int Count => Offsets.Length - 1;
    }

    /// <summary>Packing and unpacking of flat arrays with offset tables (the C ABI's layout of polylines and strips).</summary>
    public static class Packing
    {
        /// <summary>Concatenates <paramref name="items"/> (each <paramref name="dimension"/> values per point) into one array with an offset table.</summary>
        public static Packed Pack(IList<double[]> items, int dimension)
        {
            if (items == null) throw new ArgumentNullException(nameof(items));
            if (dimension <= 0) throw new ArgumentOutOfRangeException(nameof(dimension));
            var offsets = new int[items.Count + 1];
            for (int i = 0; i < items.Count; i++)
            {
                if (items[i] == null || items[i].Length % dimension != 0)
                {
                    throw new ArgumentException("item " + i + " does not hold " + dimension + " values per point", nameof(items));
                }
                offsets[i + 1] = offsets[i] + items[i].Length / dimension;
            }
            var values = new double[offsets[items.Count] * dimension];
            for (int i = 0; i < items.Count; i++)
            {
                Array.Copy(items[i], 0, values, offsets[i] * dimension, items[i].Length);
            }
            return new Packed(values, offsets, dimension);
        }

        /// <summary>
        /// The points of <paramref name="xyz"/> (x, y, z each) that each item of <paramref name="indices"/> names, in its
        /// order, packed: polylines given as vertex indices (a net's rows, a web's polylines) as points.
        /// </summary>
        public static Packed Gather(double[] xyz, IList<int[]> indices)
        {
            if (xyz == null) throw new ArgumentNullException(nameof(xyz));
            if (indices == null) throw new ArgumentNullException(nameof(indices));
            var items = new List<double[]>(indices.Count);
            for (int k = 0; k < indices.Count; k++)
            {
                int[] line = indices[k];
                var item = new double[3 * line.Length];
                for (int i = 0; i < line.Length; i++)
                {
                    if (line[i] < 0 || line[i] >= xyz.Length / 3)
                        throw new ArgumentOutOfRangeException(nameof(indices), "item " + k + " names point " + line[i] + ", but there are " + xyz.Length / 3);
                    Array.Copy(xyz, 3 * line[i], item, 3 * i, 3);
                }
                items.Add(item);
            }
            return Pack(items, 3);
        }

        /// <summary>Cuts a packed array back into its items.</summary>
        public static double[][] Unpack(Packed packed)
        {
            if (packed == null) throw new ArgumentNullException(nameof(packed));
            CheckOffsets(packed.Offsets, packed.Values.Length / packed.Dimension);
            var items = new double[packed.Count][];
            for (int i = 0; i < packed.Count; i++)
            {
                int start = packed.Offsets[i] * packed.Dimension, length = (packed.Offsets[i + 1] - packed.Offsets[i]) * packed.Dimension;
                items[i] = new double[length];
                Array.Copy(packed.Values, start, items[i], 0, length);
            }
            return items;
        }

        /// <summary>
        /// The items with their first point repeated at the end where <paramref name="closed"/> is true (one flag per
        /// item), so that polylines built from them close: the library lists a closed polyline's points once.
        /// </summary>
        public static Packed CloseLoops(Packed items, bool[] closed)
        {
            if (items == null) throw new ArgumentNullException(nameof(items));
            if (closed == null) throw new ArgumentNullException(nameof(closed));
            if (closed.Length != items.Count) throw new ArgumentException(closed.Length + " closed flags for " + items.Count + " items", nameof(closed));
            double[][] unpacked = Unpack(items);
            int d = items.Dimension;
            for (int i = 0; i < unpacked.Length; i++)
            {
                double[] item = unpacked[i];
                if (!closed[i] || item.Length == 0) continue;
                var loop = new double[item.Length + d];
                Array.Copy(item, loop, item.Length);
                Array.Copy(item, 0, loop, item.Length, d);
                unpacked[i] = loop;
            }
            return Pack(unpacked, d);
        }

        /// <summary>Throws unless <paramref name="offsets"/> starts at 0, never decreases and ends at <paramref name="total"/>.</summary>
        public static void CheckOffsets(int[] offsets, int total)
        {
            if (offsets == null || offsets.Length == 0 || offsets[0] != 0)
            {
                throw new ArgumentException("an offset table starts at 0");
            }
            for (int i = 1; i < offsets.Length; i++)
            {
                if (offsets[i] < offsets[i - 1]) throw new ArgumentException("offset " + i + " decreases");
            }
            if (offsets[offsets.Length - 1] != total)
            {
                throw new ArgumentException("the offsets end at " + offsets[offsets.Length - 1] + ", the array holds " + total + " points");
            }
        }
    }
}
