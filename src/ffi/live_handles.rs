//! A count of the live handles (`LmlMesh`, `LmlField`, `LmlCurves`, `LmlStrips`, `LmlGuides`)
//! of the whole process, for tests of bindings: after every handle is released, by hand or by a
//! finalizer, it is back to zero. Maintained by [`super::raw`], where every handle is created and released.

use std::sync::atomic::{AtomicUsize, Ordering};

static LIVE_HANDLES: AtomicUsize = AtomicUsize::new(0);

/// Records a handle handed to the caller.
pub(crate) fn created() {
    LIVE_HANDLES.fetch_add(1, Ordering::Relaxed);
}

/// Records a handle released by its `lml_*_free`.
pub(crate) fn released() {
    LIVE_HANDLES.fetch_sub(1, Ordering::Relaxed);
}

/// The number of handles (`LmlMesh`, `LmlSearch`, `LmlField`, `LmlCurves`, `LmlStrips` and
/// `LmlGuides` together) created and not yet freed in this process, over all threads: lets bindings and the
/// C test harness check that every handle is released (e.g. by a garbage collector's
/// finalizers). Has no other effect.
#[no_mangle]
pub extern "C" fn lml_debug_live_handles() -> usize {
    LIVE_HANDLES.load(Ordering::Relaxed)
}
