//! Saving a field session to bytes and restoring it (e.g. inside a Grasshopper document).

use super::field::LmlField;
use super::guard::guarded;
use super::raw::{copy_out, handle, input, Out};
use super::status::LmlStatus;
use crate::field::FieldSolver;

/// Serialises the whole session (mesh, field, auxiliary variables, parameters, weight stage,
/// solver damping) as bytes: the magic `"LMLF"`, a little-endian `uint32_t` format version,
/// then the state. The bytes are portable across platforms; a restored session continues bit
/// for bit as the original would have.
///
/// Two-call pattern: `*needed` is always set to the byte count; if `out` is NULL or `capacity`
/// (in bytes) is smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The
/// buffer stays owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_field_save(field: *const LmlField, out: *mut u8, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` bytes; writable `needed`.
        let field = unsafe { handle(field, "field") }?;
        unsafe { copy_out(&field.solver.to_bytes(), out, capacity, needed, "out") }
    })
}

/// Restores a session from `length` bytes written by `lml_field_save` (copied; the caller keeps
/// them). `out` receives the new session, owned by the caller (release with `lml_field_free`);
/// set to NULL on failure.
///
/// Every restored quantity is checked: parameters as in `lml_field_new` (and at most 100 damped
/// trials per iteration), scale factors normal and positive, every value finite, the field
/// within ±1e100 and the mesh valid once un-scaled, counters and damping in range.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_CORRUPT_DATA` (empty, truncated, damaged or
/// inconsistent bytes, a restored quantity out of range, or another format version: the
/// message says which);
/// `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, NULL `bytes` with a non-zero length).
#[no_mangle]
pub unsafe extern "C" fn lml_field_load(bytes: *const u8, length: usize, out: *mut *mut LmlField) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`; `bytes` readable for `length` bytes.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let bytes = unsafe { input(bytes, length, "bytes") }?;
        out.set_owned(LmlField::new(FieldSolver::from_bytes(bytes)?));
        Ok(LmlStatus::Ok)
    })
}
