//! `E_geo` of Eq. 13: the osculating plane of the level curve `p̃, v0, q̃` (the chords of its
//! level jet, [`super::level_jet`]) contains the surface normal, so the level sets are geodesics
//! (θ = 90°). No auxiliary variables.
//!
//! One row per regular curve vertex, scaled by `√(λ_angle · A_v)`:
//! `det(n, e_p, e_q) / (‖e_p‖ ‖e_q‖) = n · (ê_p × ê_q)`.

use super::level_jet::{JetStencil, LevelJet};

/// Residual rows per curve vertex.
pub(crate) const ROWS: usize = 1;

/// Evaluates the row of a regular curve vertex with level jet `chords`; `residuals` and
/// `jacobian` (one column per stencil vertex) come zeroed.
pub(crate) fn evaluate(chords: &LevelJet, stencil: &JetStencil, scale: f64, residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
    let n = chords.normal;
    let (ep, eq) = (chords.to_p.unit(), chords.to_q.unit());
    residuals[0] = scale * n.dot(&ep.cross(&eq));
    if let Some(jac) = jacobian {
        // ∂[n·(ê_p × ê_q)] = (ê_q × n)·∂ê_p + (n × ê_p)·∂ê_q
        chords.to_p.add_normalized_dot_partials(stencil, &eq.cross(&n), scale, jac);
        chords.to_q.add_normalized_dot_partials(stencil, &n.cross(&ep), scale, jac);
    }
}
