//! Constant-slope families (paper Sec. 5.2.3, Eq. 22): their start field, and the boundary of the
//! region a slope can reach. The family itself is `LML_FAMILY_CONSTANT_SLOPE` or
//! `LML_FAMILY_FREE_SLOPE` in `LmlFieldParams`.

use std::sync::Arc;

use super::curves::LmlCurves;
use super::failure::Failure;
use super::field::LmlField;
use super::guard::guarded;
use super::mesh::LmlMesh;
use super::raw::{copy_out, handle, input, Out};
use super::status::LmlStatus;
use crate::field::reachable_boundary;
use crate::initialisation::slope_start_field;
use crate::mesh::Vec3;

/// Reads the 3 doubles of an axis: finite and not zero.
///
/// # Safety
/// `axis` is NULL or readable for 3 doubles.
unsafe fn read_axis(axis: *const f64) -> Result<[f64; 3], Failure> {
    // SAFETY: forwarded contract.
    let values = unsafe { input(axis, 3, "axis") }?;
    let axis = [values[0], values[1], values[2]];
    if !(axis.iter().all(|a| a.is_finite()) && Vec3::from(axis).norm() > 0.0) {
        return Err(Failure::argument("axis", format!("must be finite and not zero, got {axis:?}")));
    }
    Ok(axis)
}

/// Computes the start field of a constant-slope family: a smooth field whose level curves follow,
/// wherever the slope `slope_degrees` is reachable, the tangent directions of that slope about
/// `axis`. Pass it to `lml_field_new` with `LML_FAMILY_CONSTANT_SLOPE` (or `_FREE_SLOPE`) params
/// of the same axis and slope.
///
/// - `mesh`: the surface.
/// - `axis`: 3 doubles, the axis `d` (need not be unit; finite, not zero).
/// - `slope_degrees`: the slope β in (−90, 90) against the planes orthogonal to `d`.
/// - `out`: one double per vertex; two-call pattern as `lml_field_values_from_guides`
///   (`*needed` is set to the vertex count; a NULL `out` or a smaller `capacity` copies nothing
///   and returns `LML_STATUS_BUFFER_TOO_SMALL`). The buffer stays owned by the caller.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_BUFFER_TOO_SMALL`; `LML_STATUS_INVALID_ARGUMENT` (NULL
/// pointer, an axis not finite or zero, a slope out of range, named); `LML_STATUS_SINGULAR_FIELD`
/// (no part of the surface reaches the slope, or the linear system is singular).
#[no_mangle]
pub unsafe extern "C" fn lml_field_values_from_slope(
    mesh: *const LmlMesh,
    axis: *const f64,
    slope_degrees: f64,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let axis = unsafe { read_axis(axis) }?;
        let field = slope_start_field(&mesh.mesh, axis, slope_degrees)?;
        unsafe { copy_out(&field, out, capacity, needed, "out") }
    })
}

/// Writes to `*slope_degrees` the slope β the constant-slope session `field` aims at: the given
/// one, or for `LML_FAMILY_FREE_SLOPE` the one fitted to the field before its last iteration (the
/// least-squares slope of its level curves).
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, or a session of
/// another family).
#[no_mangle]
pub unsafe extern "C" fn lml_field_slope(field: *const LmlField, slope_degrees: *mut f64) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live `field` handle, writable `slope_degrees`.
        let field = unsafe { handle(field, "field") }?;
        let mut out = unsafe { Out::new(slope_degrees, "slope_degrees") }?;
        let slope = field.solver.slope_degrees().ok_or_else(|| Failure::argument("field", "is not a constant-slope session"))?;
        out.set(slope);
        Ok(LmlStatus::Ok)
    })
}

/// The boundary of the region where the slope `slope_degrees` about `axis` is reachable (paper
/// Sec. 5.2.3: the isophote where the tangent planes themselves have that slope, moved a little
/// inwards as the field's slope terms are): polylines on `mesh`, read like level curves
/// (`lml_curves_count`, `lml_curves_points`, …; their level is 0). The reachable region lies on
/// the steeper side. No polyline: the whole surface is reachable, or none of it.
///
/// - `axis`: 3 doubles (finite, not zero); `slope_degrees` in (−90, 90).
/// - `out`: receives the new handle (release with `lml_curves_free`), NULL on failure.
///
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, an axis not finite or
/// zero, a slope out of range, named).
#[no_mangle]
pub unsafe extern "C" fn lml_curves_new_reachable_boundary(mesh: *const LmlMesh, axis: *const f64, slope_degrees: f64, out: *mut *mut LmlCurves) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`, live `mesh`, `axis` readable for 3 doubles.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let axis = unsafe { read_axis(axis) }?;
        if !(slope_degrees.is_finite() && slope_degrees.abs() < 90.0) {
            return Err(Failure::argument("slope_degrees", format!("must lie in (−90, 90), got {slope_degrees}")));
        }
        let unit = Vec3::from(axis).normalize();
        let curves = reachable_boundary(&mesh.mesh, &unit, slope_degrees)?;
        out.set_owned(LmlCurves { mesh: Arc::new(mesh.mesh.clone()), curves });
        Ok(LmlStatus::Ok)
    })
}
