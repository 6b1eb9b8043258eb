using System;
using System.Collections.Generic;
using System.Linq;

namespace Lamella.Hosting
{
    /// <summary>
    /// The field sessions of one host component across its solutions, one per iteration (list item or tree branch of
    /// its inputs: two meshes, a list of θ). A session lives on while its iteration's inputs keep their signature, so
    /// every field of a list keeps converging across live solutions instead of restarting whenever the inputs differ
    /// from the previous iteration's; it restarts when its own inputs change or on reset. Sessions of iterations a
    /// solution no longer reaches are released at its end. Fields saved in a document are restored, without solving,
    /// by the first solution whose inputs match them.
    /// </summary>
    public sealed class FieldSessions : IDisposable
    {
        private readonly IterationSlots<FieldSession> slots = new IterationSlots<FieldSession>();
        private Dictionary<int, SavedField> saved;
        private byte[] savedBytes;
        private int iterations;

        /// <summary>The number of sessions held.</summary>
        public int Count => slots.Stored().Count();

        /// <summary>The session of iteration <paramref name="iteration"/>, or null.</summary>
        public FieldSession this[int iteration] => slots[iteration];

        /// <summary>The iterations the current solution has reached so far (the highest + 1).</summary>
        public int Iterations => iterations;

        /// <summary>Sessions not converged (the ones a live solve still steps).</summary>
        public int RunningCount() => slots.Stored().Count(slot => !slot.Value.Report.IsConverged);

        /// <summary>A solution starts.</summary>
        public void BeginSolution() => iterations = 0;

        /// <summary>
        /// The session of <paramref name="iteration"/> for inputs with <paramref name="signature"/> on the mesh
        /// (<paramref name="xyz"/>, <paramref name="triangles"/>): the held one while its signature matches (unless
        /// <paramref name="reset"/>), else the saved field of this iteration and signature restored, else a session made
        /// by <paramref name="start"/> from the mesh. A replaced session is released.
        /// </summary>
        public FieldSession Session(int iteration, double[] xyz, int[] triangles, string signature, bool reset, Func<LamellaMesh, FieldSession> start)
        {
            if (signature == null) throw new ArgumentNullException(nameof(signature));
            if (start == null) throw new ArgumentNullException(nameof(start));
            Reached(iteration);
            FieldSession session = slots[iteration];
            if (!reset && session != null && session.Signature == signature) return session;
            using (LamellaMesh mesh = LamellaMesh.FromArrays(xyz, triangles))
            {
                SavedField stored;
                bool restore = !reset && saved != null && saved.TryGetValue(iteration, out stored) && stored.Signature == signature && stored.Values.Length == mesh.VertexCount;
                session = restore ? FieldSession.Restore(mesh, saved[iteration]) : start(mesh);
                if (session == null || session.Signature != signature)
                {
                    session?.Dispose();
                    throw new InvalidOperationException("the started session does not carry the signature asked for");
                }
            }
            slots.Set(iteration, session);
            return session;
        }

        /// <summary>Iteration <paramref name="iteration"/> ran without a field (missing or bad inputs): its session, if any, is released.</summary>
        public void Skip(int iteration)
        {
            Reached(iteration);
            slots.Set(iteration, null);
        }

        /// <summary>
        /// The solution ended: sessions of iterations it did not reach are released, and saved fields not restored by now
        /// are dropped (their inputs are gone).
        /// </summary>
        public void EndSolution()
        {
            slots.Trim(iterations);
            saved = null;
            savedBytes = null;
        }

        /// <summary>
        /// What a document stores (see <see cref="FieldArchive"/>): every held field (a session still searching its start
        /// has none: it searches again when the document is reopened), or, before the first solution after
        /// <see cref="Load"/>, the loaded bytes unchanged; null when there is nothing.
        /// </summary>
        public byte[] Save()
        {
            if (Count == 0) return savedBytes;
            var fields = new List<SavedField>();
            foreach (KeyValuePair<int, FieldSession> slot in slots.Stored())
            {
                if (!slot.Value.IsSearching) fields.Add(slot.Value.Save(slot.Key));
            }
            return FieldArchive.Write(fields);
        }

        /// <summary>Reads fields a document stored, to be restored by the next solution; throws <see cref="FormatException"/> (nothing loaded) for bytes it cannot read.</summary>
        public void Load(byte[] bytes)
        {
            saved = null;
            savedBytes = null;
            var fields = new Dictionary<int, SavedField>();
            foreach (SavedField field in FieldArchive.Read(bytes)) fields[field.Iteration] = field;
            saved = fields;
            savedBytes = bytes;
        }

        /// <summary>Releases every session (the component leaves its document, or the document closes).</summary>
        public void Clear() => slots.Clear();

        /// <summary>Same as <see cref="Clear"/>.</summary>
        public void Dispose() => Clear();

        private void Reached(int iteration)
        {
            if (iteration < 0) throw new ArgumentOutOfRangeException(nameof(iteration));
            iterations = Math.Max(iterations, iteration + 1);
        }
    }
}
