namespace Lamella
{
    /// <summary>The result of a native call (<c>LmlStatus</c> in lamella.h): 0 and above is success (outputs valid), negative a failure.</summary>
    public enum Status
    {
        /// <summary>Success.</summary>
        Ok = 0,
        /// <summary>A field step used its iteration budget before convergence: step again.</summary>
        More = 1,
        /// <summary>The field optimisation has converged.</summary>
        Converged = 2,
        /// <summary>
        /// Strips were built (a success: the strips are valid) but some miss θ by more than the tolerance, or have flipped
        /// quads: no acceptable family. <see cref="Strips.Verdict"/> says where; <see cref="Strips.EnsureAcceptable"/>
        /// turns it into a <see cref="NoAcceptableFamilyException"/>.
        /// </summary>
        NoAcceptableFamily = 3,
        /// <summary>A NULL pointer, a wrong array length, a non-finite or out-of-range parameter, an unreadable file.</summary>
        InvalidArgument = -1,
        /// <summary>The triangles or coordinates do not form a valid mesh.</summary>
        InvalidMesh = -2,
        /// <summary>The mesh is valid but not a single topological disk (possibly with holes).</summary>
        NotADisk = -3,
        /// <summary>The scalar field has no usable level curves.</summary>
        SingularField = -4,
        /// <summary>The optimisation did not converge (budget used up, or a numerical failure).</summary>
        DidNotConverge = -5,
        /// <summary>A caller-owned output buffer is too small (the binding sizes its buffers, so this means a bug).</summary>
        BufferTooSmall = -6,
        /// <summary>Saved session bytes are truncated, corrupted or from another format version.</summary>
        CorruptData = -7,
        /// <summary>A bug inside the native library (a caught panic).</summary>
        InternalError = -8,
        /// <summary>Guide curves unfit for the initial field: fewer than two, crossing, self-intersecting or out of order (the message names the curves).</summary>
        InvalidGuides = -9,
        /// <summary>Sketched strokes unfit for a field: too far from the surface, crossing, too short, or fewer than two (the message names stroke and point).</summary>
        InvalidStrokes = -10,
    }
}
