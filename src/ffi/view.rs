//! The interactive 3D viewer page of strips ([`crate::view`]) through the C ABI.

use super::curves::LmlCurves;
use super::failure::Failure;
use super::guard::guarded;
use super::raw::{copy_out, handle, input, utf8};
use super::status::LmlStatus;
use super::strips::LmlStrips;
use crate::view::{family_name, view_html, ViewError, ViewScene};

impl From<ViewError> for Failure {
    /// Every viewer error is an input that cannot be drawn; the message names the element.
    fn from(e: ViewError) -> Failure {
        Failure::new(LmlStatus::InvalidArgument, e.to_string())
    }
}

/// Writes the interactive 3D viewer page of `strips` (a view.html as `lamella design` writes):
/// one self-contained HTML file (no network access, no other files) showing the surface, the
/// level curves, the strips (coloured per strip, by the angle error of their rectifying planes,
/// by bending utilisation when given), their rulings and their flat unrollings, with each
/// strip's length and Table 4 measures on hover or click. UTF-8 with a terminating NUL,
/// two-call pattern: `*needed` receives the byte count including the NUL; if `text` is NULL or
/// `capacity` smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The
/// same inputs give the same bytes.
///
/// - `strips`: from `lml_strips_new`; its strips are named `strip_<i>`, their family by the θ
///   they were built for ("θ = 60°").
/// - `curves`: the curves the strips were built on: their surface and polylines are shown; NULL
///   shows the strips alone.
/// - `utilisation`: NULL, or `utilisation_count` finite values, one per strip in order: the
///   largest bending utilisation of each (`max_utilisation` of `lml_fabrication_strip_checks`,
///   1 = the allowable stress). Copied.
/// - `title`: NUL-terminated UTF-8 shown as the page title (the design's name); NULL for
///   "Lamella strips".
///
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT` (NULL
/// `strips` or `needed`, `utilisation_count` not the strip count, a non-finite utilisation
/// (the strip is named), `title` not UTF-8).
#[no_mangle]
pub unsafe extern "C" fn lml_strips_view_html(
    strips: *const LmlStrips,
    curves: *const LmlCurves,
    utilisation: *const f64,
    utilisation_count: usize,
    title: *const std::ffi::c_char,
    text: *mut u8,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): live handles (or NULL `curves`), `utilisation` NULL or
        // `utilisation_count` doubles, `title` NULL or NUL-terminated, `needed` writable, `text`
        // NULL or `capacity` bytes.
        let strips = unsafe { handle(strips, "strips") }?;
        let pattern = &strips.pattern;
        let curves = if curves.is_null() { None } else { Some(unsafe { handle(curves, "curves") }?) };
        let title = if title.is_null() { "Lamella strips" } else { unsafe { utf8(title, "title") }? };
        let utilisation = if utilisation.is_null() {
            None
        } else {
            if utilisation_count != pattern.strips.len() {
                return Err(Failure::argument("utilisation_count", format!("{utilisation_count} values for {} strips", pattern.strips.len())));
            }
            Some(unsafe { input(utilisation, utilisation_count, "utilisation") }?)
        };
        let lines = curves.map_or(&[][..], |c| c.curves.as_slice());
        let mut scene = ViewScene::of_families(title, curves.map(|c| &*c.mesh), &[(&strips.theta_degrees.map_or_else(|| "shading strips".to_string(), family_name), lines, &pattern.strips)]);
        if let Some(values) = utilisation {
            scene.strips.iter_mut().zip(values).for_each(|(s, u)| s.utilisation = Some(*u));
        }
        let mut bytes = view_html(&scene)?.into_bytes();
        bytes.push(0);
        unsafe { copy_out(&bytes, text, capacity, needed, "text") }
    })
}
