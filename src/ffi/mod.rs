//! The C ABI (`include/lamella.h`): opaque handles, stepwise solving, flat arrays, status codes.
//!
//! Every exported item is named `lml_*` (functions), `Lml*` (types) or `LML_*` (constants).
//! Each function runs inside [`guard::guarded`], which catches panics and turns every failure
//! into an [`LmlStatus`] plus a thread-local message ([`lml_last_error_message`]); no panic and
//! no undefined behaviour caused by a NULL pointer, a wrong length or a non-finite number can
//! reach the caller. Raw pointers are touched only in [`raw`]. The few functions that return a
//! value rather than a status (versions, status names, the error message) cannot fail or panic.
//!
//! The ABI covers the whole pipeline: meshes ([`LmlMesh`]), the default start search
//! ([`LmlSearch`]), field solver sessions ([`LmlField`]), level curves ([`LmlCurves`]) and rectifying strips with their unrollings and
//! metrics ([`LmlStrips`]), each a handle module with `lml_<handle>_new` / `_free` and two-call
//! array outputs, and the initialisation of Sec. 3.2.2: boundary start points, traced guide
//! curves ([`LmlGuides`]) and initial fields from guides or sketched strokes; constant-slope
//! families (Sec. 5.2.3) with their start field and reachable region; and nets of two
//! families ([`LmlNet`], paper Sec. 4.1) with their quad net and nodes ([`LmlStripNet`]), and
//! 3-webs of three (the same session from `lml_web_new`, Sec. 4.2) with their web of triangles or
//! Kagome pattern and nodes ([`LmlStripWeb`]); the
//! optimisation of a net's vertices toward exact families, torsion-free nodes or constant slopes
//! ([`LmlBaseMesh`], Sec. 3.5, 5.2); surface optimisation ([`LmlReshape`], Sec. 3.3);
//! shading designs ([`LmlShading`], Sec. 6: site, labels, strips with one θ per curve, the
//! sun-path check); the Brauner surface of Fig. 32 with its exact asymptotic u-lines; and the
//! interactive 3D viewer page of strips (`lml_strips_view_html`).
//!
//! The header is generated from this module by cbindgen (configuration in `cbindgen.toml`);
//! `tests/ffi_header.rs` fails when the committed header is stale and rewrites it when
//! `LAMELLA_UPDATE_HEADER=1` is set.

// Every exported function is `unsafe extern "C"`: its pointer contract (what cannot be checked:
// that a non-NULL pointer covers the stated count, that a handle is live and used by one thread
// at a time) is the one stated once in the header's top comment and on each function.
#![allow(clippy::missing_safety_doc)]

// Declared in the order of the header: versions and errors first, then one module per handle.
mod version;
mod status;
mod last_error;
mod guard;
mod live_handles;
mod failure;
mod raw;
mod layout;
mod mesh;
mod field_params;
mod report;
mod field;
mod search;
mod session;
mod curves;
mod strip_params;
mod strip_metrics;
mod strips;
mod strip_diagnostics;
mod edge_point;
mod trace_options;
mod boundary_starts;
mod guides;
mod initial_fields;
mod slope;
mod fabrication;
mod net;
mod strip_net;
mod web;
mod strip_web;
mod view;
mod reshape;
mod alternation;
mod base_mesh;
mod surfaces;
mod shading;

pub use alternation::*;
pub use base_mesh::*;
pub use boundary_starts::*;
pub use curves::*;
pub use edge_point::*;
pub use fabrication::*;
pub use field::*;
pub use field_params::*;
pub use guides::*;
pub use guard::lml_debug_trigger_panic;
pub use initial_fields::*;
pub use last_error::lml_last_error_message;
pub use live_handles::lml_debug_live_handles;
pub use mesh::*;
pub use net::*;
pub use report::*;
pub use reshape::*;
pub use shading::*;
pub use search::*;
pub use session::*;
pub use slope::*;
pub use status::*;
pub use strip_diagnostics::*;
pub use strip_metrics::*;
pub use strip_net::*;
pub use strip_web::*;
pub use strip_params::*;
pub use strips::*;
pub use surfaces::*;
pub use trace_options::*;
pub use version::*;
pub use view::*;
pub use web::*;

#[cfg(test)]
mod tests {
    use super::*;

    /// The header promises that handles may move between threads (one thread at a time).
    #[test]
    fn handles_may_move_between_threads() {
        fn movable<T: Send>() {}
        movable::<LmlMesh>();
        movable::<LmlField>();
        movable::<LmlCurves>();
        movable::<LmlStrips>();
        movable::<LmlGuides>();
        movable::<LmlFabrication>();
        movable::<LmlShading>();
        movable::<LmlBaseMesh>();
        movable::<LmlNet>();
        movable::<LmlStripWeb>();
    }
}
