//! The thread-local, human-readable message of the last failed call.

use std::cell::RefCell;
use std::ffi::{c_char, CString};

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// Replaces this thread's message (empty after a successful call).
pub(crate) fn set_last_error(message: &str) {
    // A NUL inside the message would cut the C string short; show it instead.
    let text = CString::new(message.replace('\0', "\\0")).unwrap_or_default();
    LAST_ERROR.with(|cell| *cell.borrow_mut() = text);
}

/// The message of the last `lml_*` call on this thread that returned a status other than
/// `LML_STATUS_OK`, `LML_STATUS_MORE` or `LML_STATUS_CONVERGED`; the empty string after a
/// successful call. Never NULL. The message is UTF-8 and names the offending element
/// (e.g. "face 12 corner 1 refers to vertex 99, but there are only 40 vertices").
///
/// Ownership: the string belongs to the library. It stays valid until the next `lml_*` call
/// on the same thread (other threads have their own message) or until the thread exits;
/// copy it if you need it longer. Never free it.
#[no_mangle]
pub extern "C" fn lml_last_error_message() -> *const c_char {
    LAST_ERROR.try_with(|cell| cell.borrow().as_ptr()).unwrap_or(c"".as_ptr())
}
