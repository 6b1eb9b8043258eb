//! Every raw-pointer access of the C ABI. Each function checks what can be checked (NULL,
//! alignment, size overflow) and reports it as `LML_STATUS_INVALID_ARGUMENT` naming the
//! argument; what cannot be checked (that a non-NULL pointer really points at `count` live
//! elements, or at a live handle) is the caller's contract, stated in the header.

use super::failure::Failure;
use super::live_handles;
use super::status::LmlStatus;
use std::ffi::{c_char, CStr};

fn check_pointer<T>(ptr: *const T, name: &str) -> Result<(), Failure> {
    if ptr.is_null() {
        Err(Failure::argument(name, "is NULL"))
    } else if !ptr.is_aligned() {
        Err(Failure::argument(name, format!("is not aligned to {} bytes", std::mem::align_of::<T>())))
    } else {
        Ok(())
    }
}

/// `count` elements times `per_element` values, or an argument error naming `name`.
pub(crate) fn element_count(count: usize, per_element: usize, name: &str) -> Result<usize, Failure> {
    count.checked_mul(per_element).ok_or_else(|| Failure::argument(name, format!("count {count} is too large")))
}

/// The caller's input array `ptr[0..count]`. NULL is accepted when `count` is 0.
///
/// # Safety
/// A non-NULL `ptr` must point at `count` initialised elements that stay unchanged while the
/// returned slice is used.
pub(crate) unsafe fn input<'a, T>(ptr: *const T, count: usize, name: &str) -> Result<&'a [T], Failure> {
    if count == 0 {
        return Ok(&[]);
    }
    check_pointer(ptr, name)?;
    let bytes = count.checked_mul(std::mem::size_of::<T>()).filter(|b| *b <= isize::MAX as usize);
    if bytes.is_none() {
        return Err(Failure::argument(name, format!("{count} elements exceed the address space")));
    }
    // SAFETY: non-NULL, aligned, size within isize::MAX (checked above); validity is the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(ptr, count) })
}

/// The handle behind `ptr`.
///
/// # Safety
/// A non-NULL `ptr` must come from the matching `lml_*_new` / `_load` and not be freed yet,
/// and no other thread may use it during the call.
pub(crate) unsafe fn handle<'a, T>(ptr: *const T, name: &str) -> Result<&'a T, Failure> {
    check_pointer(ptr, name)?;
    // SAFETY: non-NULL and aligned; liveness is the caller's contract.
    Ok(unsafe { &*ptr })
}

/// The handle behind `ptr`, for changes.
///
/// # Safety
/// As [`handle`].
pub(crate) unsafe fn handle_mut<'a, T>(ptr: *mut T, name: &str) -> Result<&'a mut T, Failure> {
    check_pointer(ptr, name)?;
    // SAFETY: non-NULL and aligned; liveness and exclusive use are the caller's contract.
    Ok(unsafe { &mut *ptr })
}

/// A NUL-terminated UTF-8 string.
///
/// # Safety
/// A non-NULL `ptr` must point at a NUL-terminated string.
pub(crate) unsafe fn utf8<'a>(ptr: *const c_char, name: &str) -> Result<&'a str, Failure> {
    check_pointer(ptr, name)?;
    // SAFETY: non-NULL; termination is the caller's contract.
    let text = unsafe { CStr::from_ptr(ptr) };
    text.to_str().map_err(|e| Failure::argument(name, format!("is not UTF-8 ({e})")))
}

/// An out-parameter, checked once and written with [`Out::set`] (never read).
pub(crate) struct Out<T>(*mut T);

impl<T> Out<T> {
    /// # Safety
    /// A non-NULL `ptr` must be valid for writing one `T` for the rest of the call.
    pub unsafe fn new(ptr: *mut T, name: &str) -> Result<Out<T>, Failure> {
        check_pointer(ptr, name)?;
        Ok(Out(ptr))
    }

    /// Like [`Out::new`], but NULL means "not wanted".
    ///
    /// # Safety
    /// As [`Out::new`].
    pub unsafe fn optional(ptr: *mut T, name: &str) -> Result<Option<Out<T>>, Failure> {
        // SAFETY: forwarded contract.
        (!ptr.is_null()).then(|| unsafe { Out::new(ptr, name) }).transpose()
    }

    pub fn set(&mut self, value: T) {
        // SAFETY: checked non-NULL and aligned in `new`, writable by `new`'s contract; `write`
        // does not read or drop the (possibly uninitialised) old value.
        unsafe { self.0.write(value) }
    }
}

/// The two-call output pattern: sets `*needed` to `values.len()`, then copies `values` into the
/// caller's buffer `out[0..capacity]` if it is large enough, or fails with
/// `LML_STATUS_BUFFER_TOO_SMALL` (also when `out` is NULL, the size query). Nothing to copy
/// always succeeds, whatever `out` is.
///
/// # Safety
/// `needed` must be valid for writing; a non-NULL `out` must be valid for writing `capacity` elements.
pub(crate) unsafe fn copy_out<T: Copy>(values: &[T], out: *mut T, capacity: usize, needed: *mut usize, name: &str) -> Result<LmlStatus, Failure> {
    // SAFETY: forwarded contract.
    unsafe { Out::new(needed, "needed") }?.set(values.len());
    if values.is_empty() {
        return Ok(LmlStatus::Ok);
    }
    if out.is_null() || capacity < values.len() {
        let held = if out.is_null() { "is NULL".to_string() } else { format!("holds {capacity}") };
        return Err(Failure::new(LmlStatus::BufferTooSmall, format!("buffer `{name}` {held}; {} elements needed", values.len())));
    }
    check_pointer(out, name)?;
    // SAFETY: `out` is non-NULL, aligned and (by contract) writable for capacity ≥ len elements;
    // a caller buffer cannot overlap the library's own vector.
    unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), out, values.len()) };
    Ok(LmlStatus::Ok)
}

impl<T> Out<*mut T> {
    /// Hands a new handle owning `value` to the caller, who releases it with [`release`].
    pub fn set_owned(&mut self, value: T) {
        self.set(Box::into_raw(Box::new(value)));
        live_handles::created();
    }
}

/// Drops a handle created by [`Out::set_owned`]; NULL does nothing.
///
/// # Safety
/// A non-NULL `ptr` must come from [`Out::set_owned`] with the same `T` and not be released yet.
pub(crate) unsafe fn release<T>(ptr: *mut T) {
    if !ptr.is_null() {
        // SAFETY: by contract `ptr` is an unreleased `Box<T>` pointer.
        drop(unsafe { Box::from_raw(ptr) });
        live_handles::released();
    }
}
