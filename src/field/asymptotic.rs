//! `E_asy` of Eq. 13: both chords of the level polyline `p, v0, q` are tangent to the
//! surface, so the osculating plane is the tangent plane and the level sets are asymptotic
//! curves (θ = 0°). No auxiliary variables.
//!
//! Two rows per regular interior vertex, scaled by `√(λ_angle · A_v)`: `n·ê_p` and `n·ê_q`.

use super::star_chords::clear_rows_at_vertex;
use crate::mesh::TriMesh;

/// Residual rows per interior vertex.
pub(crate) const ROWS: usize = 2;

/// Evaluates the rows of vertex `v`; `jacobian` (if any) has one column per star vertex
/// (centre first, then the ring).
pub(crate) fn evaluate(mesh: &TriMesh, field: &[f64], v: usize, scale: f64, residuals: &mut [f64], mut jacobian: Option<&mut [f64]>) {
    let Some(chords) = clear_rows_at_vertex(mesh, field, v, residuals, &mut jacobian) else {
        return;
    };
    let n = mesh.vertex_normals()[v];
    residuals[0] = scale * n.dot(&chords.to_p.unit());
    residuals[1] = scale * n.dot(&chords.to_q.unit());
    if let Some(jac) = jacobian {
        let columns = jac.len() / ROWS;
        let (first, second) = jac.split_at_mut(columns);
        chords.to_p.add_normalized_dot_partials(&n, scale, first);
        chords.to_q.add_normalized_dot_partials(&n, scale, second);
    }
}
