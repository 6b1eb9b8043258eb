//! The boundary of the region a constant-slope family can reach (Sec. 5.2.3): the isophote on
//! which the tangent planes have the slope `|β|` itself, moved inwards by
//! [`ISOPHOTE_MARGIN_DEGREES`] as the field's slope rows are ([`super::slope_reachable`]).

use super::constant_slope::{tangent_plane_inclination_degrees, ISOPHOTE_MARGIN_DEGREES};
use crate::curves::{extract_level_curves, CurveError, LevelCurve};
use crate::mesh::{TriMesh, Vec3};

/// The level curves of `ψ − (|β| + margin)` at 0 (`ψ` the tangent planes' inclination against the
/// planes orthogonal to the unit `axis`, from the mesh's smooth normals, linear on the faces): the
/// reachable region of slope `slope_degrees` lies on the steeper side. Empty when the whole mesh
/// is reachable or none of it is.
pub fn reachable_boundary(mesh: &TriMesh, axis: &Vec3, slope_degrees: f64) -> Result<Vec<LevelCurve>, CurveError> {
    let limit = slope_degrees.abs() + ISOPHOTE_MARGIN_DEGREES;
    let excess: Vec<f64> = mesh.smooth_normals().iter().map(|n| tangent_plane_inclination_degrees(n, axis) - limit).collect();
    let (low, high) = excess.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &e| (a.min(e), b.max(e)));
    if !(low < 0.0 && high > 0.0) {
        return Ok(Vec::new());
    }
    extract_level_curves(mesh, &excess, &[0.0])
}
