using System;
using System.Collections.Generic;

namespace Lamella.Hosting
{
    /// <summary>A whole native session as a host document keeps it: its bytes (the solver's <c>Save</c>), the host
    /// iteration (data-tree item) it belongs to and the signature of the inputs it was started from.</summary>
    public sealed class SavedSession
    {
        public SavedSession(int iteration, string signature, byte[] bytes)
        {
            if (iteration < 0) throw new ArgumentOutOfRangeException(nameof(iteration));
            Iteration = iteration;
            Signature = signature ?? throw new ArgumentNullException(nameof(signature));
            Bytes = bytes ?? throw new ArgumentNullException(nameof(bytes));
        }

        public int Iteration { get; }
        public string Signature { get; }
        /// <summary>The native session (e.g. <see cref="ReshapeSolver.Save"/>), which checks itself when loaded.</summary>
        public byte[] Bytes { get; }
    }

    /// <summary>
    /// The byte format of saved native sessions: "LMLS", a format version, then Deflate-compressed records (iteration,
    /// signature, the session's bytes). For components whose state is more than a field (a moved surface, an optimised
    /// net): unlike <see cref="FieldArchive"/> it keeps the whole session, so a reopened document continues where it
    /// stopped, bit for bit.
    /// </summary>
    public static class SessionArchive
    {
        private const string Magic = "LMLS";
        /// <summary>The format version written and read.</summary>
        public const int Version = 1;
        private const int MaxSessions = 1 << 20;
        private const int MaxSessionBytes = 1 << 30;

        /// <summary>The sessions as bytes.</summary>
        public static byte[] Write(IList<SavedSession> sessions)
        {
            if (sessions == null) throw new ArgumentNullException(nameof(sessions));
            return ArchiveFraming.Write(Magic, Version, writer =>
            {
                writer.Write(sessions.Count);
                foreach (SavedSession session in sessions)
                {
                    if (session == null) throw new ArgumentException("a saved session is null", nameof(sessions));
                    writer.Write(session.Iteration);
                    writer.Write(session.Signature);
                    writer.Write(session.Bytes.Length);
                    writer.Write(session.Bytes);
                }
            });
        }

        /// <summary>
        /// Reads sessions written by <see cref="Write"/>. Bytes of another kind, another version, truncated or damaged
        /// throw <see cref="FormatException"/> saying which. The sessions' own bytes are checked when they are loaded.
        /// </summary>
        public static List<SavedSession> Read(byte[] bytes) => ArchiveFraming.Read(bytes, Magic, Version, Version, "saved Lamella sessions", (reader, version) =>
        {
            int count = reader.ReadInt32();
            if (count < 0 || count > MaxSessions) throw new FormatException("the saved sessions claim " + count + " entries");
            var sessions = new List<SavedSession>(Math.Min(count, 1024));
            for (int i = 0; i < count; i++)
            {
                int iteration = reader.ReadInt32();
                string signature = reader.ReadString();
                int length = reader.ReadInt32();
                if (length < 0 || length > MaxSessionBytes) throw new FormatException("saved session " + i + " claims " + length + " bytes");
                byte[] session = reader.ReadBytes(length);
                if (session.Length != length) throw new FormatException("saved session " + i + " is truncated");
                if (iteration < 0) throw new FormatException("saved session " + i + " has iteration " + iteration);
                sessions.Add(new SavedSession(iteration, signature, session));
            }
            return sessions;
        });
    }

    /// <summary>
    /// The native sessions a host document stored for one component, until the solution that restores them: each is
    /// handed out once, to the iteration and input signature it was saved for (<see cref="Take"/>); the rest are dropped
    /// at the end of that solution (<see cref="EndSolution"/>), their inputs being gone. Before that solution,
    /// <see cref="Save"/> gives the loaded bytes back unchanged, so a document saved again without solving loses nothing.
    /// </summary>
    public sealed class StoredSessions
    {
        private Dictionary<int, SavedSession> loaded;
        private byte[] loadedBytes;

        /// <summary>Reads what a document stored; throws <see cref="FormatException"/> (nothing loaded) for bytes it cannot read.</summary>
        public void Load(byte[] bytes)
        {
            loaded = null;
            loadedBytes = null;
            var sessions = new Dictionary<int, SavedSession>();
            foreach (SavedSession session in SessionArchive.Read(bytes)) sessions[session.Iteration] = session;
            loaded = sessions;
            loadedBytes = bytes;
        }

        /// <summary>The stored session bytes of <paramref name="iteration"/> if they were saved for <paramref name="signature"/>, once; else null.</summary>
        public byte[] Take(int iteration, string signature)
        {
            SavedSession session;
            if (loaded == null || !loaded.TryGetValue(iteration, out session) || session.Signature != signature) return null;
            loaded.Remove(iteration);
            return session.Bytes;
        }

        /// <summary>A solution ended: sessions not taken by now are dropped.</summary>
        public void EndSolution()
        {
            loaded = null;
            loadedBytes = null;
        }

        /// <summary>
        /// What the document stores: the held <paramref name="sessions"/> saved by <paramref name="save"/>, or, while none
        /// is held and nothing was restored yet, the loaded bytes unchanged; null when there is nothing.
        /// </summary>
        public byte[] Save<TSolver, TReport>(LiveSessions<SolverSession<TSolver, TReport>> sessions, Func<TSolver, byte[]> save)
            where TSolver : class, IDisposable
        {
            if (sessions == null) throw new ArgumentNullException(nameof(sessions));
            if (save == null) throw new ArgumentNullException(nameof(save));
            if (sessions.Count == 0) return loadedBytes;
            var saved = new List<SavedSession>();
            foreach (KeyValuePair<int, SolverSession<TSolver, TReport>> slot in sessions.Stored())
            {
                saved.Add(new SavedSession(slot.Key, slot.Value.Signature, save(slot.Value.Solver)));
            }
            return SessionArchive.Write(saved);
        }
    }
}
