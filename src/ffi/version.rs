//! Library and ABI versions.

use std::ffi::c_char;

/// Version of the C ABI described by this header. It changes whenever a function signature,
/// a struct layout or the meaning of a constant changes incompatibly; compare it with
/// `lml_abi_version()` at start-up to detect a header / library mismatch.
pub const LML_ABI_VERSION: u32 = 3;

/// The ABI version the loaded library implements (`LML_ABI_VERSION` of its own header).
#[no_mangle]
pub extern "C" fn lml_abi_version() -> u32 {
    LML_ABI_VERSION
}

/// The library version as a static NUL-terminated string, e.g. `"0.1.0"`. Never free it.
#[no_mangle]
pub extern "C" fn lml_version() -> *const c_char {
    const VERSION: &str = concat!(env!("CARGO_PKG_VERSION"), "\0");
    VERSION.as_ptr().cast()
}
