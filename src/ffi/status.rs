//! The status every fallible `lml_*` function returns.

use std::ffi::c_char;

/// Result of an `lml_*` call. `LML_STATUS_OK`, `LML_STATUS_MORE`, `LML_STATUS_CONVERGED` and
/// `LML_STATUS_NO_ACCEPTABLE_FAMILY` are successes (≥ 0: the outputs are valid); every failure
/// is negative, and `lml_last_error_message()` then says what went wrong and names the
/// offending element (vertex, face, byte offset, argument).
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LmlStatus {
    /// Success.
    Ok = 0,
    /// `lml_field_step`: the iteration budget was used up before convergence; step again.
    More = 1,
    /// `lml_field_step` / `lml_field_solve`: the optimisation has converged; further steps do nothing.
    Converged = 2,
    /// `lml_strips_new`: the strips were built (the handle is valid) but miss the target angle
    /// by more than the tolerance somewhere, or have flipped quads: no acceptable family.
    /// `lml_last_error_message()` names the strips and the worst point and says what to try;
    /// `lml_strips_verdict` gives the numbers.
    NoAcceptableFamily = 3,
    /// A NULL or misaligned pointer, a wrong array length, a non-finite or out-of-range
    /// parameter, an unreadable file.
    InvalidArgument = -1,
    /// The triangles or coordinates do not form a valid mesh: non-finite coordinates, indices
    /// out of range, repeated indices, zero-area faces, isolated vertices, non-manifold edges
    /// or vertices, inconsistent orientation, folded faces, slivers, malformed OBJ lines.
    InvalidMesh = -2,
    /// The mesh is valid but not a single topological disk (possibly with holes), which the
    /// method requires (paper Sec. 7): closed, several components, handles.
    NotADisk = -3,
    /// The scalar field has no usable level curves (it is constant or its gradient vanishes).
    SingularField = -4,
    /// The optimisation did not converge: `lml_field_solve` ran out of iterations, or an
    /// iteration failed numerically (non-finite residuals, no damped factorisation; the message
    /// then names the vertices with the largest residuals).
    DidNotConverge = -5,
    /// A caller-owned output buffer is NULL or too small; `*needed` holds the required count.
    BufferTooSmall = -6,
    /// Saved session bytes are truncated, corrupted, or come from another format version.
    CorruptData = -7,
    /// A bug inside the library (e.g. a caught panic). Please report it with the message.
    InternalError = -8,
    /// The guide curves cannot initialise a field: fewer than two, their first and last start at
    /// one point, or (`lml_guides_check_order`) they intersect or are out of order; the message
    /// names the curves.
    InvalidGuides = -9,
    /// The sketched strokes cannot initialise a field: fewer than two, too short, too far from
    /// the surface, or crossing; the message names the stroke and point.
    InvalidStrokes = -10,
}

impl LmlStatus {
    const ALL: [LmlStatus; 14] = [
        LmlStatus::Ok,
        LmlStatus::More,
        LmlStatus::Converged,
        LmlStatus::NoAcceptableFamily,
        LmlStatus::InvalidArgument,
        LmlStatus::InvalidMesh,
        LmlStatus::NotADisk,
        LmlStatus::SingularField,
        LmlStatus::DidNotConverge,
        LmlStatus::BufferTooSmall,
        LmlStatus::CorruptData,
        LmlStatus::InternalError,
        LmlStatus::InvalidGuides,
        LmlStatus::InvalidStrokes,
    ];

    /// The constant's name as a NUL-terminated string.
    fn name(self) -> &'static std::ffi::CStr {
        match self {
            LmlStatus::Ok => c"LML_STATUS_OK",
            LmlStatus::More => c"LML_STATUS_MORE",
            LmlStatus::Converged => c"LML_STATUS_CONVERGED",
            LmlStatus::NoAcceptableFamily => c"LML_STATUS_NO_ACCEPTABLE_FAMILY",
            LmlStatus::InvalidArgument => c"LML_STATUS_INVALID_ARGUMENT",
            LmlStatus::InvalidMesh => c"LML_STATUS_INVALID_MESH",
            LmlStatus::NotADisk => c"LML_STATUS_NOT_A_DISK",
            LmlStatus::SingularField => c"LML_STATUS_SINGULAR_FIELD",
            LmlStatus::DidNotConverge => c"LML_STATUS_DID_NOT_CONVERGE",
            LmlStatus::BufferTooSmall => c"LML_STATUS_BUFFER_TOO_SMALL",
            LmlStatus::CorruptData => c"LML_STATUS_CORRUPT_DATA",
            LmlStatus::InternalError => c"LML_STATUS_INTERNAL_ERROR",
            LmlStatus::InvalidGuides => c"LML_STATUS_INVALID_GUIDES",
            LmlStatus::InvalidStrokes => c"LML_STATUS_INVALID_STROKES",
        }
    }
}

/// The name of a status code, e.g. `"LML_STATUS_NOT_A_DISK"`, or `"LML_STATUS_UNKNOWN"` for a
/// value that is no status. The string is static: never free it. Takes an `int32_t` (the
/// underlying type of `LmlStatus`) so that any value is safe to pass.
#[no_mangle]
pub extern "C" fn lml_status_name(status: i32) -> *const c_char {
    let known = LmlStatus::ALL.iter().find(|s| **s as i32 == status);
    known.map_or(c"LML_STATUS_UNKNOWN", |s| s.name()).as_ptr()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::CStr;

    #[test]
    fn every_status_has_a_distinct_code_and_its_own_name() {
        for (i, a) in LmlStatus::ALL.iter().enumerate() {
            for b in &LmlStatus::ALL[i + 1..] {
                assert_ne!(*a as i32, *b as i32);
            }
            // SAFETY: lml_status_name returns a static NUL-terminated string.
            let name = unsafe { CStr::from_ptr(lml_status_name(*a as i32)) };
            assert_eq!(name, a.name());
        }
        // SAFETY: as above.
        assert_eq!(unsafe { CStr::from_ptr(lml_status_name(42)) }, c"LML_STATUS_UNKNOWN");
    }
}
