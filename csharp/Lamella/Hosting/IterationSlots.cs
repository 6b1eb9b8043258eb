using System;
using System.Collections.Generic;

namespace Lamella.Hosting
{
    /// <summary>
    /// One native result per iteration of a host's solution: a Grasshopper component runs once per item or branch of
    /// its inputs (a list of meshes, a list of θ), and each run needs its own session or result that stays alive while
    /// downstream components read it. Slot i belongs to iteration i. Replacing or trimming a slot disposes what it held;
    /// nothing else does, so results of other iterations are never released under a reader.
    /// </summary>
    public sealed class IterationSlots<T> : IDisposable where T : class, IDisposable
    {
        private readonly List<T> slots = new List<T>();

        /// <summary>The number of slots (the highest iteration stored + 1).</summary>
        public int Count => slots.Count;

        /// <summary>The result of iteration <paramref name="iteration"/>, or null.</summary>
        public T this[int iteration]
        {
            get
            {
                if (iteration < 0) throw new ArgumentOutOfRangeException(nameof(iteration));
                return iteration < slots.Count ? slots[iteration] : null;
            }
        }

        /// <summary>Every stored result with its iteration, in order.</summary>
        public IEnumerable<KeyValuePair<int, T>> Stored()
        {
            for (int i = 0; i < slots.Count; i++)
            {
                if (slots[i] != null) yield return new KeyValuePair<int, T>(i, slots[i]);
            }
        }

        /// <summary>Stores <paramref name="value"/> (may be null) for iteration <paramref name="iteration"/>, disposing what the slot held unless it is the same object.</summary>
        public void Set(int iteration, T value)
        {
            if (iteration < 0) throw new ArgumentOutOfRangeException(nameof(iteration));
            while (slots.Count <= iteration) slots.Add(null);
            T old = slots[iteration];
            slots[iteration] = value;
            if (old != null && !ReferenceEquals(old, value)) old.Dispose();
        }

        /// <summary>Disposes and removes the slots of iterations ≥ <paramref name="count"/> (a solution with fewer iterations than the last).</summary>
        public void Trim(int count)
        {
            if (count < 0) throw new ArgumentOutOfRangeException(nameof(count));
            for (int i = slots.Count - 1; i >= count; i--)
            {
                T old = slots[i];
                slots.RemoveAt(i);
                old?.Dispose();
            }
        }

        /// <summary>Disposes every result (at the start of a new solution, or when the component leaves its document).</summary>
        public void Clear() => Trim(0);

        /// <summary>Same as <see cref="Clear"/>.</summary>
        public void Dispose() => Clear();
    }
}
