//! `E_angle`, the pseudo-geodesic angle energy of Eq. 8 (to a target angle `θ_v` per vertex), with the auxiliary unit binormal
//! `b` (Eq. 9) and side vector `u` (Eq. 10) of each curve vertex, on the chords of its level jet
//! ([`super::level_jet`]: `e_p = v0 − p̃`, `e_q = v0 − q̃`, tangent `t`, normal `n` of the local quadric).
//!
//! Rows per regular vertex, all scaled by `√(λ_angle · A_v)` (A normalised to mean 1):
//!
//! | row | residual | equation |
//! |---|---|---|
//! | 0 | `(b·n)² − cos²θ` | Eq. 8, first term |
//! | 1 | `(b·n)(b·u) − sinθ cosθ` | Eq. 8, second term: the *signed* angle, telling the two osculating planes of Fig. 8 apart |
//! | 2, 3 | `b·ê_p`, `b·ê_q` with `ê = e/‖e‖`, `e_p = v0 − p`, `e_q = v0 − q` | Eq. 9 |
//! | 4 | `b·b − 1` | Eq. 9 |
//! | 5 | `u·t` with `t` the unit tangent (`∥ q̃ − p̃`) | Eq. 10 |
//! | 6, 7 | `u·n`, `u·u − 1` | Eq. 10 |
//!
//! Rows 2, 3 and 5 use normalised chords with their exact derivatives (no frozen norms).
//! Singular vertices get zero rows (the caller does not evaluate them).

use super::level_jet::{JetStencil, LevelJet};
use crate::mesh::Vec3;

/// Residual rows per curve vertex.
pub(crate) const ROWS: usize = 8;
/// Auxiliary variables per curve vertex: `b` then `u`.
pub(crate) const AUXILIARIES: usize = 6;

/// The target angle `θ_v` between binormal and surface normal at one vertex, in degrees and as
/// `cos θ`, `sin θ`. One global θ (Eq. 8) gives every vertex the same target; the varying-angle
/// families of Fig. 16 give each vertex its own, held constant during each iteration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TargetAngle {
    pub degrees: f64,
    pub cos: f64,
    pub sin: f64,
}

impl TargetAngle {
    pub fn from_degrees(theta: f64) -> Self {
        let r = theta.to_radians();
        TargetAngle { degrees: theta, cos: r.cos(), sin: r.sin() }
    }
}

/// Evaluates the rows of a regular curve vertex with level jet `chords`. `aux = [b, u]`;
/// `residuals` and `jacobian` (if any) come zeroed; the Jacobian is row-major with one column
/// per stencil vertex, then the six auxiliaries.
pub(crate) fn evaluate(
    chords: &LevelJet,
    stencil: &JetStencil,
    aux: &[f64],
    target: TargetAngle,
    scale: f64,
    residuals: &mut [f64],
    jacobian: Option<&mut [f64]>,
) {
    let aux_column = stencil.vertices.len();
    let columns = aux_column + AUXILIARIES;
    let b = Vec3::new(aux[0], aux[1], aux[2]);
    let u = Vec3::new(aux[3], aux[4], aux[5]);
    let unit = [chords.to_p.unit(), chords.to_q.unit(), chords.tangent.unit()];
    let Some(jac) = jacobian else {
        frame_rows(&chords.normal, aux, &unit, target, scale, residuals, None);
        return;
    };
    frame_rows(&chords.normal, aux, &unit, target, scale, residuals, Some((&mut *jac, columns, aux_column)));
    chords.to_p.add_normalized_dot_partials(stencil, &b, scale, &mut jac[2 * columns..3 * columns]);
    chords.to_q.add_normalized_dot_partials(stencil, &b, scale, &mut jac[3 * columns..4 * columns]);
    chords.tangent.add_normalized_dot_partials(stencil, &u, scale, &mut jac[5 * columns..6 * columns]);
}

/// The rows of the table above for the normal `n`, `aux = [b, u]` and the chord directions
/// `[ê_p, ê_q, t]`, scaled by `scale`, into `residuals`; with `jacobian = (J, columns, b_column)`
/// also their partials in `b` and `u` (columns `b_column..b_column + 6` of the row-major `J`).
/// What the rows' dependence on the chords adds to `J` is the caller's: the chords come from
/// the field's level jet here, from the moving mesh in the surface optimisation of Sec. 3.3
/// ([`crate::reshape`]).
pub(crate) fn frame_rows(
    n: &Vec3,
    aux: &[f64],
    [ep, eq, t]: &[Vec3; 3],
    target: TargetAngle,
    scale: f64,
    residuals: &mut [f64],
    jacobian: Option<(&mut [f64], usize, usize)>,
) {
    let b = Vec3::new(aux[0], aux[1], aux[2]);
    let u = Vec3::new(aux[3], aux[4], aux[5]);
    let (bn, bu) = (b.dot(n), b.dot(&u));
    let values = [
        bn * bn - target.cos * target.cos,
        bn * bu - target.sin * target.cos,
        b.dot(ep),
        b.dot(eq),
        b.dot(&b) - 1.0,
        u.dot(t),
        u.dot(n),
        u.dot(&u) - 1.0,
    ];
    for (r, value) in residuals.iter_mut().zip(values) {
        *r = scale * value;
    }
    let Some((jac, columns, bc)) = jacobian else { return };
    let uc = bc + 3;
    let mut set = |row: usize, col: usize, d: Vec3| {
        for k in 0..3 {
            jac[row * columns + col + k] += scale * d[k];
        }
    };
    set(0, bc, n * (2.0 * bn));
    set(1, bc, n * bu + u * bn);
    set(1, uc, b * bn);
    set(2, bc, *ep);
    set(3, bc, *eq);
    set(4, bc, b * 2.0);
    set(5, uc, *t);
    set(6, uc, *n);
    set(7, uc, u * 2.0);
}
