using System;
using GH_IO.Serialization;
using Lamella.Hosting;

namespace Lamella.Grasshopper
{
    /// <summary>What a live component keeps in its Grasshopper document beyond its inputs (see <see cref="LiveComponent.DocumentState"/>).</summary>
    public interface IDocumentState
    {
        /// <summary>A solution ended.</summary>
        void EndSolution();
        void Write(GH_IWriter writer);
        void Read(GH_IReader reader);
    }

    /// <summary>
    /// A live component's sessions as its Grasshopper document keeps them: each held session whole (the solver's own
    /// bytes, in a <see cref="SessionArchive"/>), restored without stepping by the first solution whose iteration and
    /// inputs match, so a reopened definition shows the result it was saved with and continues where it stopped.
    /// </summary>
    public sealed class DocumentSessions<TSolver, TReport> : IDocumentState where TSolver : class, IDisposable
    {
        private readonly string key;
        private readonly LiveSessions<SolverSession<TSolver, TReport>> sessions;
        private readonly Func<TSolver, byte[]> save;
        private readonly Func<byte[], string, SolverSession<TSolver, TReport>> load;
        private readonly StoredSessions stored = new StoredSessions();

        /// <summary>
        /// The sessions under <paramref name="key"/> in the document: <paramref name="save"/> writes a solver,
        /// <paramref name="load"/> reads one back as a held session of the given signature.
        /// </summary>
        public DocumentSessions(string key, LiveSessions<SolverSession<TSolver, TReport>> sessions, Func<TSolver, byte[]> save,
            Func<byte[], string, SolverSession<TSolver, TReport>> load)
        {
            this.key = key ?? throw new ArgumentNullException(nameof(key));
            this.sessions = sessions ?? throw new ArgumentNullException(nameof(sessions));
            this.save = save ?? throw new ArgumentNullException(nameof(save));
            this.load = load ?? throw new ArgumentNullException(nameof(load));
        }

        /// <summary>Holds again the session the document saved for this iteration and signature, if any (call before the live session is asked for).</summary>
        public void Restore(int iteration, string signature)
        {
            byte[] bytes = stored.Take(iteration, signature);
            if (bytes == null) return;
            try
            {
                sessions.Session(iteration, signature, false, () => load(bytes, signature));
            }
            catch (LamellaException)
            {
                // A session that does not load (damaged, another version) is started again from the inputs.
            }
        }

        /// <summary>A solution ended: saved sessions no iteration took belong to inputs that are gone.</summary>
        public void EndSolution() => stored.EndSolution();

        public void Write(GH_IWriter writer)
        {
            try
            {
                byte[] bytes = stored.Save(sessions, save);
                if (bytes != null) writer.SetByteArray(key, bytes);
            }
            catch (Exception)
            {
                // A session that cannot be saved is not stored; the document saves without it and solves again.
            }
        }

        public void Read(GH_IReader reader)
        {
            if (!reader.ItemExists(key)) return;
            try
            {
                stored.Load(reader.GetByteArray(key));
            }
            catch (FormatException)
            {
                // Damaged or from another format version: solved again from the inputs.
            }
        }
    }
}
