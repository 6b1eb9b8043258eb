//! `E_geo` of Eq. 13: the osculating plane of the level polyline `p, v0, q` contains the
//! surface normal, so the level sets are geodesics (θ = 90°). No auxiliary variables.
//!
//! One row per regular interior vertex, scaled by `√(λ_angle · A_v)`:
//! `det(n, e_p, e_q) / (‖e_p‖ ‖e_q‖) = n · (ê_p × ê_q)`.

use super::star_chords::clear_rows_at_vertex;
use crate::mesh::TriMesh;

/// Residual rows per interior vertex.
pub(crate) const ROWS: usize = 1;

/// Evaluates the row of vertex `v`; `jacobian` (if any) has one column per star vertex
/// (centre first, then the ring).
pub(crate) fn evaluate(mesh: &TriMesh, field: &[f64], v: usize, scale: f64, residuals: &mut [f64], mut jacobian: Option<&mut [f64]>) {
    let Some(chords) = clear_rows_at_vertex(mesh, field, v, residuals, &mut jacobian) else {
        return;
    };
    let n = mesh.vertex_normals()[v];
    let (ep, eq) = (chords.to_p.unit(), chords.to_q.unit());
    residuals[0] = scale * n.dot(&ep.cross(&eq));
    if let Some(jac) = jacobian {
        // ∂[n·(ê_p × ê_q)] = (ê_q × n)·∂ê_p + (n × ê_p)·∂ê_q
        chords.to_p.add_normalized_dot_partials(&eq.cross(&n), scale, jac);
        chords.to_q.add_normalized_dot_partials(&n.cross(&ep), scale, jac);
    }
}
