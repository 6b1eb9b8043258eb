//! The rows of one light vertex: `E_block` (Eq. 26) or `E_light` (Eq. 27) with the auxiliary
//! unit binormal `b` (Eq. 9), the light direction `l` held in the light region by squared dummy
//! variables (Eq. 24: `x ≥ a` as `x − a − ψ² = 0`) and, letting light through, the principal
//! normal `n^p` (`n^p·t = n^p·b = 0`, `‖n^p‖ = 1`).
//!
//! `l` is stored in the earth-axis frame (where Eq. 24 is stated) and turned into the model by
//! the site's [`EarthFrame`]. Auxiliaries: `b` (0–2), `l` (3–5), `ψ` (6–10), and for a pass
//! vertex `n^p` (11–13). Rows (constraint rows scaled by `√(λ_c A_v)`, light rows by `√(λ_L A_v)`):
//!
//! | row | residual | equation |
//! |---|---|---|
//! | 0, 1, 2 | `b·ê_p`, `b·ê_q`, `b·b − 1` | Eq. 9 |
//! | 3 | `l·l − 1` | unit light |
//! | 4, 5 | `l_z − z_min − ψ0²`, `z_max − l_z − ψ1²` | Eq. 24, γ |
//! | 6, 7 | `l_y − g_min l_x − ψ2²`, `g_max l_x − l_y − ψ3²` | Eq. 24, δ |
//! | 8 | `l_x − ψ4²` | `l_x ≥ 0`: the side of the earth axis where Eq. 24's ratio is monotonic |
//! | block 9, 10 | `l·t`, `l·b` | Eq. 26 |
//! | pass 9, 10, 11 | `n^p·b`, `n^p·t`, `n^p·n^p − 1` | principal normal |
//! | pass 12 | `l·n^p` | Eq. 27 |

use super::earth_frame::EarthFrame;
use super::light_region::RegionBounds;
use crate::field::{JetStencil, LevelJet};
use crate::mesh::Vec3;

/// Rows and auxiliaries of a blocking vertex.
pub(crate) const BLOCK_ROWS: usize = 11;
pub(crate) const BLOCK_AUXILIARIES: usize = 11;
/// Rows and auxiliaries of a letting-through vertex.
pub(crate) const PASS_ROWS: usize = 13;
pub(crate) const PASS_AUXILIARIES: usize = 14;
/// Offsets of the auxiliaries.
pub(crate) const B: usize = 0;
pub(crate) const L: usize = 3;
pub(crate) const PSI: usize = 6;
pub(crate) const NP: usize = 11;

/// The effect a light vertex asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum LightMode {
    Block,
    Pass,
}

/// Scales of the two kinds of rows.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RowScales {
    pub constraint: f64,
    pub light: f64,
}

fn vec(aux: &[f64], at: usize) -> Vec3 {
    Vec3::new(aux[at], aux[at + 1], aux[at + 2])
}

/// Evaluates the rows of a light vertex with level jet `jet` (columns: the stencil's field
/// values, then the auxiliaries). `residuals` and `jacobian` come zeroed.
#[allow(clippy::too_many_arguments)]
pub(crate) fn evaluate(
    mode: LightMode,
    jet: &LevelJet,
    stencil: &JetStencil,
    frame: &EarthFrame,
    bounds: &RegionBounds,
    aux: &[f64],
    scales: RowScales,
    residuals: &mut [f64],
    jacobian: Option<&mut [f64]>,
) {
    let (c, w) = (scales.constraint, scales.light);
    let b = vec(aux, B);
    let le = vec(aux, L);
    let psi = &aux[PSI..PSI + 5];
    let l = frame.to_model(&le);
    let (ep, eq, t) = (jet.to_p.unit(), jet.to_q.unit(), jet.tangent.unit());
    let mut values = vec![
        c * b.dot(&ep),
        c * b.dot(&eq),
        c * (b.dot(&b) - 1.0),
        c * (le.dot(&le) - 1.0),
        c * (le.z - bounds.z_min - psi[0] * psi[0]),
        c * (bounds.z_max - le.z - psi[1] * psi[1]),
        c * (le.y - bounds.g_min * le.x - psi[2] * psi[2]),
        c * (bounds.g_max * le.x - le.y - psi[3] * psi[3]),
        c * (le.x - psi[4] * psi[4]),
    ];
    let np = (mode == LightMode::Pass).then(|| vec(aux, NP));
    match np {
        None => values.extend([w * l.dot(&t), w * l.dot(&b)]),
        Some(np) => values.extend([c * np.dot(&b), c * np.dot(&t), c * (np.dot(&np) - 1.0), w * l.dot(&np)]),
    }
    residuals.copy_from_slice(&values);
    let Some(jac) = jacobian else { return };
    let aux_column = stencil.vertices.len();
    let columns = aux_column + if np.is_some() { PASS_AUXILIARIES } else { BLOCK_AUXILIARIES };
    let mut set = |row: usize, offset: usize, d: Vec3| {
        for k in 0..3 {
            jac[row * columns + aux_column + offset + k] += d[k];
        }
    };
    set(0, B, ep * c);
    set(1, B, eq * c);
    set(2, B, b * (2.0 * c));
    set(3, L, le * (2.0 * c));
    set(4, L, Vec3::z() * c);
    set(5, L, -Vec3::z() * c);
    set(6, L, Vec3::new(-bounds.g_min, 1.0, 0.0) * c);
    set(7, L, Vec3::new(bounds.g_max, -1.0, 0.0) * c);
    set(8, L, Vec3::x() * c);
    // ∂(l_model·v)/∂l_earth = the earth components of v.
    match np {
        None => {
            set(9, L, frame.to_earth(&t) * w);
            set(10, L, frame.to_earth(&b) * w);
            set(10, B, l * w);
        }
        Some(np) => {
            set(9, B, np * c);
            set(9, NP, b * c);
            set(10, NP, t * c);
            set(11, NP, np * (2.0 * c));
            set(12, L, frame.to_earth(&np) * w);
            set(12, NP, l * w);
        }
    }
    for (k, &p) in psi.iter().enumerate() {
        jac[(4 + k) * columns + aux_column + PSI + k] = -2.0 * c * p;
    }
    jet.to_p.add_normalized_dot_partials(stencil, &b, c, &mut jac[0..columns]);
    jet.to_q.add_normalized_dot_partials(stencil, &b, c, &mut jac[columns..2 * columns]);
    match np {
        None => jet.tangent.add_normalized_dot_partials(stencil, &l, w, &mut jac[9 * columns..10 * columns]),
        Some(np) => jet.tangent.add_normalized_dot_partials(stencil, &np, c, &mut jac[10 * columns..11 * columns]),
    }
}
