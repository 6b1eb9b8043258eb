//! `E_slope`, the constant-slope condition of Eq. 22 (paper Sec. 5.2.2–5.2.3): the unit tangent
//! `t` of the level curve (that of its level jet, [`super::level_jet`], along `∇F × n`) makes the
//! constant angle `γ` with a fixed axis `d`, `t·d = cos γ`. With the inclination `β = 90° − γ`
//! against the planes orthogonal to `d` (the paper's slope, `tan β = k`, the conical curvature),
//! the row reads `t·d − sin β`. The rectifying developables of such curves are cylinders with
//! rulings parallel to `d`: strips of a net of them meet in torsion-free nodes with parallel axes
//! (Prop. 3). No auxiliary variables.
//!
//! One row per regular curve vertex, scaled by `√(λ_angle · A_v)`. A tangent plane whose
//! steepest direction rises less than `|β|` against the planes orthogonal to `d` holds no
//! tangent of slope `β`: beyond the isophote `ψ = |β|` (`ψ` the tangent plane's own inclination,
//! `cos ψ = |n·d|`) the family does not exist. Vertices with `ψ < |β| +`
//! [`ISOPHOTE_MARGIN_DEGREES`] carry no row ([`reachable`]); the margin keeps the rows away
//! from the isophote itself, where the two tangents of slope `β` merge and the family ends in
//! cusps (Sec. 5.2.3).

use super::level_jet::{JetStencil, LevelJet};
use crate::mesh::Vec3;

/// Residual rows per curve vertex.
pub(crate) const ROWS: usize = 1;

/// Degrees by which a tangent plane must be steeper than the slope `|β|` for its vertex to carry
/// the slope row (see the module).
pub const ISOPHOTE_MARGIN_DEGREES: f64 = 3.0;

/// The inclination `ψ` in degrees, in `[0°, 90°]`, of the tangent plane of unit normal `normal`
/// against the planes orthogonal to the unit `axis`: the largest slope a tangent there can have.
pub fn tangent_plane_inclination_degrees(normal: &Vec3, axis: &Vec3) -> f64 {
    normal.dot(axis).abs().min(1.0).acos().to_degrees()
}

/// Whether a tangent plane of unit normal `normal` holds tangents of slope `slope_degrees` with
/// respect to the unit `axis`, at least [`ISOPHOTE_MARGIN_DEGREES`] inside the isophote.
pub fn reachable(normal: &Vec3, axis: &Vec3, slope_degrees: f64) -> bool {
    tangent_plane_inclination_degrees(normal, axis) >= slope_degrees.abs() + ISOPHOTE_MARGIN_DEGREES
}

/// The slope in degrees, in `[−90°, 90°]`, of the unit tangent `tangent` against the planes
/// orthogonal to the unit `axis`: `asin(t·d)`.
pub fn slope_degrees(tangent: &Vec3, axis: &Vec3) -> f64 {
    tangent.dot(axis).clamp(-1.0, 1.0).asin().to_degrees()
}

/// Evaluates the row of a regular curve vertex with level jet `jet`, for the unit `axis` and
/// `sin β`; `residuals` and `jacobian` (one column per stencil vertex) come zeroed.
pub(crate) fn evaluate(jet: &LevelJet, stencil: &JetStencil, axis: &Vec3, sin_slope: f64, scale: f64, residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
    residuals[0] = scale * (jet.tangent.unit().dot(axis) - sin_slope);
    if let Some(jac) = jacobian {
        jet.tangent.add_normalized_dot_partials(stencil, axis, scale, jac);
    }
}
