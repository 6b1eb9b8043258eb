//! A start for a constant-slope family (Sec. 5.2.3, Eq. 22): the field whose gradient best
//! matches, in least squares, the side vector `u = n × t*` of the slope direction field `t*`.
//!
//! In a tangent plane with unit normal `n` steeper than the slope β against the planes orthogonal
//! to the unit axis `d`, let `e₁` be the steepest ascent direction (`d` projected, normalised) and
//! `e₂ = n × e₁`. The tangents of slope β are `t = a e₁ ± √(1 − a²) e₂` with
//! `a = sin β / ‖d − (d·n) n‖`; this start takes the `+` one (the field's level curves turn left
//! of the ascent, seen from the normal's side; −β gives the other family of slope |β| traversed
//! backwards). Faces beyond the isophote ([`crate::field::slope_reachable`] with the face's
//! normal) get no gradient rows; the fairness energy of Eq. 6, with a small weight, carries the
//! field across them.

use super::error::InitialisationError;
use super::linear_least_squares::LinearRows;
use super::smoothness_rows::push_fairness_rows;
use crate::field::{slope_reachable, FIELD_VALUE_LIMIT};
use crate::mesh::{TriMesh, Vec3};

/// Weight of the fairness rows relative to the area-weighted gradient rows (on the unit-scaled mesh).
const FAIRNESS_WEIGHT: f64 = 1e-3;

/// The tangent of slope `sin_slope` (`sin β`) on the `+` side (see the module) in the tangent plane
/// of unit normal `normal`, for the unit `axis`; `None` where the plane is not steep enough.
pub fn slope_tangent(normal: &Vec3, axis: &Vec3, sin_slope: f64) -> Option<Vec3> {
    let ascent = axis - normal * axis.dot(normal);
    let steepest = ascent.norm();
    let a = sin_slope / steepest;
    if !(steepest > 0.0 && a.abs() <= 1.0) {
        return None;
    }
    let e1 = ascent / steepest;
    Some(e1 * a + normal.cross(&e1) * (1.0 - a * a).sqrt())
}

/// The start field of a constant-slope family of slope `slope_degrees` (in (−90°, 90°)) about
/// `axis` (finite, not zero) on `mesh`, one value per vertex (`‖∇F‖ ≈ 1` on the mesh scaled
/// to mean edge length 1).
/// Errors: a bad axis or slope ([`InitialisationError::InvalidOption`] naming it), no face steep
/// enough for the slope, or a singular system.
pub fn slope_start_field(mesh: &TriMesh, axis: [f64; 3], slope_degrees: f64) -> Result<Vec<f64>, InitialisationError> {
    let axis = Vec3::from(axis);
    let Some(d) = axis.try_normalize(0.0).filter(|d| d.iter().all(|c| c.is_finite())) else {
        return Err(InitialisationError::InvalidOption { name: "axis", message: format!("must be finite and not zero, got {axis:?}") });
    };
    if !(slope_degrees.is_finite() && slope_degrees.abs() < 90.0) {
        return Err(InitialisationError::InvalidOption { name: "slope", message: format!("must lie in (−90°, 90°), got {slope_degrees}") });
    }
    let (unit, _) = mesh.unit_scaled();
    let sin_slope = slope_degrees.to_radians().sin();
    let normals = unit.smooth_normals();
    let mut rows = LinearRows::new();
    let mut reached = 0;
    for (f, face) in unit.faces().iter().enumerate() {
        let Some(normal) = face.iter().map(|&v| normals[v as usize]).sum::<Vec3>().try_normalize(0.0) else { continue };
        if !slope_reachable(&normal, &d, slope_degrees) {
            continue;
        }
        let Some(tangent) = slope_tangent(&normal, &d, sin_slope) else { continue };
        reached += 1;
        let side = normal.cross(&tangent);
        let gradients = unit.face_gradients(f);
        let area = unit.face_areas()[f];
        for c in 0..3 {
            rows.push(face.iter().zip(gradients).map(|(&v, g)| (v as usize, g[c])), side[c], area);
        }
    }
    if reached == 0 {
        return Err(InitialisationError::InvalidOption {
            name: "slope",
            message: format!("no tangent plane of the mesh is steep enough for a slope of {slope_degrees}° about the axis"),
        });
    }
    push_fairness_rows(&mut rows, &unit, FAIRNESS_WEIGHT);
    // The field's constant: the first vertex at 0, weakly.
    rows.push([(0, 1.0)], 0.0, FAIRNESS_WEIGHT);
    let stage = "constant-slope start";
    let field = rows.factorise(unit.vertex_count()).ok_or(InitialisationError::SingularSystem { stage })?.solve(rows.targets()).ok_or(InitialisationError::SingularSystem { stage })?;
    if field.iter().any(|f| f.abs() > FIELD_VALUE_LIMIT) {
        return Err(InitialisationError::SingularSystem { stage });
    }
    Ok(field)
}
