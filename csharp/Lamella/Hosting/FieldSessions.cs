using System;
using System.Collections.Generic;

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
    public sealed class FieldSessions : ILiveSessions, IDisposable
    {
        private readonly LiveSessions<FieldSession> sessions = new LiveSessions<FieldSession>();
        private Dictionary<int, SavedField> saved;
        private byte[] savedBytes;

        /// <summary>The number of sessions held.</summary>
        public int Count => sessions.Count;

        /// <summary>The session of iteration <paramref name="iteration"/>, or null.</summary>
        public FieldSession this[int iteration] => sessions[iteration];

        /// <summary>The iterations the current solution has reached so far (the highest + 1).</summary>
        public int Iterations => sessions.Iterations;

        /// <summary>Sessions not converged (the ones a live solve still steps).</summary>
        public int RunningCount() => sessions.RunningCount();

        /// <summary>A solution starts.</summary>
        public void BeginSolution() => sessions.BeginSolution();

        /// <summary>
        /// The session of <paramref name="iteration"/> for inputs with <paramref name="signature"/> on the mesh
        /// (<paramref name="xyz"/>, <paramref name="triangles"/>): the held one while its signature matches (unless
        /// <paramref name="reset"/>), else the saved field of this iteration and signature restored, else a session made
        /// by <paramref name="start"/> from the mesh. A replaced session is released.
        /// </summary>
        public FieldSession Session(int iteration, double[] xyz, int[] triangles, string signature, bool reset, Func<LamellaMesh, FieldSession> start)
        {
            if (start == null) throw new ArgumentNullException(nameof(start));
            return sessions.Session(iteration, signature, reset, () =>
            {
                using (LamellaMesh mesh = LamellaMesh.FromArrays(xyz, triangles))
                {
                    SavedField stored;
                    bool restore = !reset && saved != null && saved.TryGetValue(iteration, out stored) && stored.Signature == signature && stored.Values.Length == mesh.VertexCount;
                    return restore ? FieldSession.Restore(mesh, saved[iteration]) : start(mesh);
                }
            });
        }

        /// <summary>Iteration <paramref name="iteration"/> ran without a field (missing or bad inputs): its session, if any, is released.</summary>
        public void Skip(int iteration) => sessions.Skip(iteration);

        /// <summary>
        /// The solution ended: sessions of iterations it did not reach are released, and saved fields not restored by now
        /// are dropped (their inputs are gone).
        /// </summary>
        public void EndSolution()
        {
            sessions.EndSolution();
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
            foreach (KeyValuePair<int, FieldSession> slot in sessions.Stored())
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
        public void Clear() => sessions.Clear();

        /// <summary>Same as <see cref="Clear"/>.</summary>
        public void Dispose() => Clear();
    }
}
