using System;
using System.Collections.Generic;

namespace Lamella.Hosting
{
    /// <summary>
    /// The native results of a host's solution, any number per iteration: a component that builds a chain (a mesh, a
    /// session on it, the curves of the session, the strips on the curves) keeps every link alive while downstream
    /// components read the last, and the links of an iteration are released together, last first, when the results
    /// are cleared (a new solution, the component leaving its document). Keeping one result of an iteration never
    /// releases another: with a single result per slot (<see cref="IterationSlots{T}"/>), keeping the session
    /// released the mesh it was built on, and keeping the curves released the session the next family still read.
    /// </summary>
    public sealed class IterationResults : IDisposable
    {
        private readonly IterationSlots<Chain> slots = new IterationSlots<Chain>();

        /// <summary>Keeps <paramref name="result"/> alive with the other results of iteration <paramref name="iteration"/>, and returns it.</summary>
        public T Keep<T>(int iteration, T result) where T : class, IDisposable
        {
            if (result == null) throw new ArgumentNullException(nameof(result));
            Chain chain = slots[iteration];
            if (chain == null)
            {
                chain = new Chain();
                slots.Set(iteration, chain);
            }
            chain.Add(result);
            return result;
        }

        /// <summary>The number of results kept for iteration <paramref name="iteration"/>.</summary>
        public int CountAt(int iteration) => slots[iteration]?.Count ?? 0;

        /// <summary>Releases every kept result.</summary>
        public void Clear() => slots.Clear();

        /// <summary>Same as <see cref="Clear"/>.</summary>
        public void Dispose() => Clear();

        /// <summary>The results of one iteration, released last first.</summary>
        private sealed class Chain : IDisposable
        {
            private readonly List<IDisposable> links = new List<IDisposable>();

            public int Count => links.Count;

            public void Add(IDisposable link)
            {
                if (!links.Contains(link)) links.Add(link);
            }

            public void Dispose()
            {
                for (int i = links.Count - 1; i >= 0; i--) links[i].Dispose();
                links.Clear();
            }
        }
    }
}
