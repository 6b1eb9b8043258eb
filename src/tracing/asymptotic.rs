//! The asymptotic limit θ → 0 of the tracing step.
//!
//! Eq. 4 degenerates there: its cone flattens onto the tangent plane, so every sharp turn
//! inside that plane has `b ≈ n`, and a straight asymptotic line (a ruling) has no osculating
//! plane at all. What survives is the defining property of asymptotic curves, zero normal
//! curvature; along a step it reads (Rodrigues, `II(dx, dx) = −dn·dx`)
//! `(n(p_{i+1}) − n_i)·(p_{i+1} − p_i) = 0`, quadratic in the edge parameter `t` when `n(P)` is
//! the (unnormalised) interpolation of the edge's vertex normals. Its two roots per edge are the
//! two asymptotic directions; the caller's turn limit keeps the one the curve is following.

use crate::mesh::{TriMesh, Vec3};

/// The zero-normal-curvature condition at a point with unit `normal`.
pub(crate) struct AsymptoticLimit<'a> {
    pub mesh: &'a TriMesh,
    pub normal: &'a Vec3,
    /// Degrees: a candidate is accepted if `dn` is within this angle of perpendicular to the step.
    pub tolerance: f64,
}

impl AsymptoticLimit<'_> {
    /// `n(P(t)) − n_i` on the edge `[s, e]` (mesh vertices), `P(t) = (1 − t)·v_s + t·v_e`.
    fn normal_change(&self, edge: [u32; 2], t: f64) -> Vec3 {
        let normals = self.mesh.vertex_normals();
        // Internal invariant: candidate edges are mesh edges.
        normals[edge[0] as usize].lerp(&normals[edge[1] as usize], t) - self.normal
    }

    /// Coefficients `(a, b, c)` of `(n(P(t)) − n_i)·(P(t) − p_i)` for `P(t) − p_i = x0 + t·x1`.
    pub fn coefficients(&self, x0: &Vec3, x1: &Vec3, edge: [u32; 2]) -> (f64, f64, f64) {
        let a0 = self.normal_change(edge, 0.0);
        let a1 = self.normal_change(edge, 1.0) - a0;
        (a1.dot(x1), a0.dot(x1) + a1.dot(x0), a0.dot(x0))
    }

    /// Whether the step to `P(t)` on `edge` has zero normal curvature within tolerance (exact
    /// roots always do; an extremum of a root-less edge only if it comes that close).
    pub fn accepts(&self, step: &Vec3, t: f64, edge: [u32; 2]) -> bool {
        let change = self.normal_change(edge, t);
        change.dot(step).abs() <= self.tolerance.to_radians().sin() * change.norm() * step.norm()
    }
}
