//! The panic guard around every exported function.

use super::failure::Failure;
use super::last_error::set_last_error;
use super::status::LmlStatus;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs the body of an exported function: clears this thread's error message, catches any
/// panic (`LML_STATUS_INTERNAL_ERROR`) and records the message of a failure.
///
/// Unwind safety: after a panic the handle involved may hold a half-updated state; it stays
/// memory-safe (plain Rust data) and may still be freed, which is all the header promises.
pub(crate) fn guarded(body: impl FnOnce() -> Result<LmlStatus, Failure>) -> LmlStatus {
    set_last_error("");
    let failure = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(status)) => return status,
        Ok(Err(failure)) => failure,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown payload".into());
            Failure::new(LmlStatus::InternalError, format!("internal error (panic caught at the C boundary): {what}"))
        }
    };
    set_last_error(&failure.message);
    failure.status
}

/// Panics inside the library on purpose and returns `LML_STATUS_INTERNAL_ERROR`: lets bindings
/// and the C test harness check that no panic ever crosses the C boundary. Has no other effect
/// (the panic message may be printed to stderr).
#[no_mangle]
pub extern "C" fn lml_debug_trigger_panic() -> LmlStatus {
    guarded(|| panic!("lml_debug_trigger_panic was called"))
}
