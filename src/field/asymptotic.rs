//! `E_asy` of Eq. 13: both chords of the level curve `p̃, v0, q̃` (those of its level jet,
//! [`super::level_jet`]) are tangent to the surface, so the osculating plane is the tangent plane
//! and the level sets are asymptotic curves (θ = 0°). No auxiliary variables.
//!
//! Two rows per regular curve vertex, scaled by `√(λ_angle · A_v)`: `n·ê_p` and `n·ê_q`.

use super::level_jet::{JetStencil, LevelJet};

/// Residual rows per curve vertex.
pub(crate) const ROWS: usize = 2;

/// Evaluates the rows of a regular curve vertex with level jet `chords`; `residuals` and
/// `jacobian` (one column per stencil vertex) come zeroed.
pub(crate) fn evaluate(chords: &LevelJet, stencil: &JetStencil, scale: f64, residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
    let n = chords.normal;
    residuals[0] = scale * n.dot(&chords.to_p.unit());
    residuals[1] = scale * n.dot(&chords.to_q.unit());
    if let Some(jac) = jacobian {
        let columns = jac.len() / ROWS;
        let (first, second) = jac.split_at_mut(columns);
        chords.to_p.add_normalized_dot_partials(stencil, &n, scale, first);
        chords.to_q.add_normalized_dot_partials(stencil, &n, scale, second);
    }
}
