using System;
using System.Globalization;
using Lamella.Interop;

namespace Lamella
{
    /// <summary>How a candidate's initial field is made (<c>LML_START_*</c>).</summary>
    public enum StartKind : uint
    {
        /// <summary>The height along a direction of the surface's principal plane (or minus it).</summary>
        Height = 0,
        /// <summary>The field of guide P-curves traced from one side of the boundary (paper Eq. 5–7).</summary>
        Guides = 1,
    }

    /// <summary>
    /// One candidate start of a <see cref="StartSearch"/> and how its short solve ended (<c>LmlCandidate</c> and its
    /// text). Angles in degrees.
    /// </summary>
    public readonly struct Candidate
    {
        private readonly double[] direction;

        internal Candidate(int index, CandidateRecord record, string text)
        {
            Index = index;
            Kind = (StartKind)record.Kind;
            IsNegated = record.Negated != 0;
            direction = (double[])(record.Direction ?? new double[3]).Clone();
            Side = checked((int)record.Side);
            StartAngleDegrees = record.StartAngleDegrees;
            IsScored = record.Scored != 0;
            IsRejected = record.Rejected != 0;
            Score = record.Score;
            RmsErrorDegrees = record.RmsErrorDegrees;
            MaxErrorDegrees = record.MaxErrorDegrees;
            StraightFraction = record.StraightFraction;
            SingularVertices = checked((long)record.SingularVertices);
            Text = text;
        }

        /// <summary>The candidate's index in probing order.</summary>
        public int Index { get; }
        /// <summary>How its initial field is made.</summary>
        public StartKind Kind { get; }
        /// <summary>Height candidates: true when the field is minus the height (the mirror family of pseudo-geodesics).</summary>
        public bool IsNegated { get; }
        /// <summary>Height candidates: the unit direction (x, y, z; a copy); zero for guide candidates.</summary>
        public double[] Direction => (double[])(direction ?? new double[3]).Clone();
        /// <summary>Guide candidates: the boundary side (of the outer loop split at 30° corners) the guides start from.</summary>
        public int Side { get; }
        /// <summary>Guide candidates: the angle of the guides' first segments against the boundary.</summary>
        public double StartAngleDegrees { get; }
        /// <summary>True when the candidate was scored (<see cref="Score"/> valid).</summary>
        public bool IsScored { get; }
        /// <summary>True when it was rejected (degenerate family, unmeasurable curves, a failed or stalled solve: <see cref="Text"/> says which).</summary>
        public bool IsRejected { get; }
        /// <summary>Lower is better: RMS + a quarter of the max angle error along the level curves, plus penalties for nearly straight pieces and singular vertices.</summary>
        public double Score { get; }
        /// <summary>RMS angle error along the level curves after the short solve.</summary>
        public double RmsErrorDegrees { get; }
        /// <summary>Largest angle error along the level curves after the short solve.</summary>
        public double MaxErrorDegrees { get; }
        /// <summary>Fraction of the measured level-curve points that are nearly straight.</summary>
        public double StraightFraction { get; }
        /// <summary>Singular vertices after the short solve.</summary>
        public long SingularVertices { get; }
        /// <summary>The library's description, e.g. "height along (1.000, 0.000, 0.000): score 1.19" or "…: rejected: degenerate: …".</summary>
        public string Text { get; }

        /// <inheritdoc />
        public override string ToString() => string.Format(CultureInfo.InvariantCulture, "{0}: {1}", Index, Text);
    }

    /// <summary>
    /// The default start search (<c>LmlSearch</c>): for a field without guides or strokes, several initial fields
    /// (heights along the surface's principal directions in both signs, then, if none is good enough, guides from each
    /// boundary side) each get a short solve, their level curves are judged against the smooth surface, and the best
    /// continues as a <see cref="FieldSolver"/>. The family follows θ of the parameters (0° and 180°: asymptotic curves,
    /// 90°: geodesics). Step it (<see cref="Step"/>, about 20 field iterations each) until it returns false, then
    /// <see cref="TakeField"/>. Use from one thread at a time.
    /// </summary>
    public sealed class StartSearch : IDisposable
    {
        internal readonly SearchHandle Handle;
        /// <summary>The winner when the field was taken (the library reads no winner after that).</summary>
        private int? takenWinner;
        private bool taken;

        /// <summary>Prepares a search on <paramref name="mesh"/> (copied; it may be disposed afterwards) for a field of <paramref name="parameters"/> (their gradient target is ignored: each candidate brings its own).</summary>
        public StartSearch(LamellaMesh mesh, FieldParams parameters)
        {
            if (mesh == null) throw new ArgumentNullException(nameof(mesh));
            Native.Check(NativeMethods.lml_search_new(mesh.Handle, ref parameters, out Handle));
        }

        /// <summary>True once <see cref="Step"/> has returned false: every candidate is probed.</summary>
        public bool IsComplete { get; private set; }

        /// <summary>True once <see cref="TakeField"/> succeeded: the search is over, its candidates stay readable.</summary>
        public bool IsFieldTaken => taken;

        /// <summary>
        /// Probes the next candidate (a short solve, about 20 field iterations; a call that solves also runs the short solve
        /// of the next candidate that needs one beside it, on the second core, and that candidate's call only records it). Returns true while candidates remain,
        /// false when the search is complete (further calls probe nothing). Throws <see cref="InvalidOperationException"/>
        /// after <see cref="TakeField"/>.
        /// </summary>
        public bool Step()
        {
            if (taken) throw new InvalidOperationException("the search's field was already taken");
            bool more = Native.Check(NativeMethods.lml_search_step(Handle)) == Status.More;
            IsComplete = !more;
            return more;
        }

        /// <summary>
        /// The vertex count of the coarsening the candidates are probed on (a mesh of more than 1.5 × 1,500 vertices is
        /// searched on a coarsening of about 1,500 of its own vertices, and <see cref="TakeField"/> carries the winner's
        /// field to the full mesh); null when they are probed on the mesh itself.
        /// </summary>
        public int? ProxyVertexCount
        {
            get
            {
                UIntPtr count;
                Native.Check(NativeMethods.lml_search_proxy_vertex_count(Handle, out count));
                int n = Native.Count(count);
                return n == 0 ? (int?)null : n;
            }
        }

        /// <summary>The number of candidates probed so far.</summary>
        public int CandidateCount
        {
            get
            {
                UIntPtr count;
                Native.Check(NativeMethods.lml_search_candidate_count(Handle, out count));
                return Native.Count(count);
            }
        }

        /// <summary>Candidate <paramref name="index"/> (in probing order) with its text.</summary>
        public Candidate Candidate(int index)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index));
            var size = Native.Size(index);
            CandidateRecord record;
            Native.Check(NativeMethods.lml_search_candidate(Handle, size, out record));
            byte[] text = Native.Read((byte[] b, UIntPtr c, out UIntPtr n) => NativeMethods.lml_search_candidate_text(Handle, size, b, c, out n));
            return new Candidate(index, record, Utf8.FromTerminated(text));
        }

        /// <summary>Every candidate probed so far, in probing order.</summary>
        public Candidate[] Candidates
        {
            get
            {
                var all = new Candidate[CandidateCount];
                for (int i = 0; i < all.Length; i++) all[i] = Candidate(i);
                return all;
            }
        }

        /// <summary>
        /// The index of the best candidate so far (also after <see cref="TakeField"/>: the one the field continues from):
        /// the best scored one, or when none is scored the best of those rejected only for nearly straight level curves
        /// (its <see cref="Candidate.IsRejected"/> stays true: every family found is nearly straight over most of the
        /// surface, and the strips' verdict decides); null while there is neither.
        /// </summary>
        public int? Winner
        {
            get
            {
                if (taken) return takenWinner;
                UIntPtr index;
                // The handle is live, so the only invalid argument left is "no winner yet".
                Status status = NativeMethods.lml_search_winner(Handle, out index);
                if (status == Status.InvalidArgument) return null;
                Native.Check(status);
                return Native.Count(index);
            }
        }

        /// <summary>
        /// Takes the field of the best candidate: a new session that continues from where that candidate's short solve
        /// ended, at the final weights; step it to convergence (the caller owns it). Ends the search; its candidates stay
        /// readable. Throws <see cref="LamellaException"/> with <see cref="Status.SingularField"/> when every candidate was
        /// rejected, none only for nearly straight level curves (the message gives each reason; the search stays usable), and <see cref="InvalidOperationException"/>
        /// when the field was already taken.
        /// </summary>
        public FieldSolver TakeField()
        {
            if (taken) throw new InvalidOperationException("the search's field was already taken");
            int? winner = Winner;
            FieldHandle field;
            Native.Check(NativeMethods.lml_search_field(Handle, out field));
            takenWinner = winner;
            taken = true;
            return new FieldSolver(field);
        }

        /// <summary>Releases the native search (harmless to call twice); a field already taken lives on.</summary>
        public void Dispose() => Handle.Dispose();
    }
}
