//! The family measure of a field's level curves: a handful of evenly spaced level curves
//! extracted and judged by [`family_angles`]. It is how the start search judges a probe and how
//! the field solver tells that its level curves have stopped improving.

use super::family::{family_angles, FamilyAngles};
use crate::curves::{extract_level_curves, uniform_levels};
use crate::field::Family;
use crate::mesh::TriMesh;

/// [`family_angles`] of `levels` evenly spaced level curves of `field` on `mesh`, resampled every
/// `spacing_edges` mean edge lengths, with the bounding-box diagonal as the model's size.
/// `Err(reason)` when the field has no level curve or they cannot be measured.
pub(crate) fn level_set_angles(mesh: &TriMesh, field: &[f64], family: Family, levels: usize, spacing_edges: f64) -> Result<FamilyAngles, String> {
    let levels = uniform_levels(mesh, field, levels).map_err(|e| format!("no level curves: {e}"))?;
    let curves = extract_level_curves(mesh, field, &levels).map_err(|e| format!("no level curves: {e}"))?;
    let (low, high) = mesh.bounding_box();
    let spacing = spacing_edges * mesh.mean_edge_length();
    family_angles(&curves, family, spacing, (high - low).norm()).map_err(|e| format!("level curves not measurable: {e}"))
}
