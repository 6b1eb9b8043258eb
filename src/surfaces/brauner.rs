//! Brauner's surfaces (paper Sec. 5.2.4, Eq. 23): one family of asymptotic curves, the u-lines
//! `v = const`, are curves of constant slope with respect to the vertical, the slope varying from
//! curve to curve. From any solution `f(u, v)` of the heat equation `f_uu = f_v` and a constant
//! `μ > 0`,
//!
//! `x = e^v (f_u sin u + f_v cos u)`, `y = e^v (f_v sin u − f_u cos u)`, `z = μ (f + f_v)`.
//!
//! Differentiating with `f_uu = f_v` gives `x_u = (f_u + f_uv) (e^v cos u, e^v sin u, μ)`: along
//! `v = const` the tangent rises at the constant slope `tan β = μ e^{−v}` (Sec. 5.2.2), and its
//! derivative in u, `(−sin u, cos u, 0)` times `e^v`, is horizontal and orthogonal to the
//! normal `x_u × x_v`, so the u-lines are asymptotic curves with horizontal principal normals
//! (the curves of steepest descent of the surface). The surface is singular where
//! `f_u + f_uv = 0`.
//!
//! The paper's example (Fig. 32), `f = e^{−v} (cos u + u sin u + 2v cos u)`, gives
//! `x = cos²u − 2v`, `y = sin u cos u − u`, `z = 2μ e^{−v} cos u`, regular for `0 < u < π`.

use super::jittered_grid::{jittered_grid, ParameterRectangle};
use super::random::SplitMix64;
use super::{irregularity, positive, GeneratedSurface, SurfaceError};
use crate::mesh::Vec3;
use std::f64::consts::PI;

/// The values of a function `f(u, v)` and the partial derivatives Eq. 23 and its normals need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeatJet {
    pub f: f64,
    pub f_u: f64,
    pub f_v: f64,
    pub f_uv: f64,
    pub f_vv: f64,
}

/// A solution of the heat equation `f_uu = f_v`, the generator of a Brauner surface.
pub trait HeatSolution {
    /// `f` and its partials at `(u, v)`.
    fn jet(&self, u: f64, v: f64) -> HeatJet;
}

/// The paper's solution `f = e^{−v} (cos u + u sin u + 2v cos u)` (Sec. 5.2.4, Fig. 32).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PaperHeatSolution;

impl HeatSolution for PaperHeatSolution {
    fn jet(&self, u: f64, v: f64) -> HeatJet {
        // f = e^{−v} g with g = cos u + u sin u + 2v cos u.
        let (sin, cos) = u.sin_cos();
        let g = cos + u * sin + 2.0 * v * cos;
        let (g_u, g_v, g_uv) = (u * cos - 2.0 * v * sin, 2.0 * cos, -2.0 * sin);
        let e = (-v).exp();
        HeatJet { f: e * g, f_u: e * g_u, f_v: e * (g_v - g), f_uv: e * (g_uv - g_u), f_vv: e * (g - 2.0 * g_v) }
    }
}

/// The point of the Brauner surface of `f` and `mu` at `(u, v)` (Eq. 23).
pub fn brauner_point(f: &impl HeatSolution, mu: f64, u: f64, v: f64) -> Vec3 {
    let j = f.jet(u, v);
    let (sin, cos) = u.sin_cos();
    let e = v.exp();
    Vec3::new(e * (j.f_u * sin + j.f_v * cos), e * (j.f_v * sin - j.f_u * cos), mu * (j.f + j.f_v))
}

/// The partial derivatives `(x_u, x_v)` of the Brauner surface of `f` and `mu` at `(u, v)`.
pub fn brauner_tangents(f: &impl HeatSolution, mu: f64, u: f64, v: f64) -> (Vec3, Vec3) {
    let j = f.jet(u, v);
    let (sin, cos) = u.sin_cos();
    let e = v.exp();
    let (p, q) = (j.f_u + j.f_uv, j.f_v + j.f_vv);
    let x_u = Vec3::new(e * cos, e * sin, mu) * p;
    let x_v = Vec3::new(e * (p * sin + q * cos), e * (q * sin - p * cos), mu * q);
    (x_u, x_v)
}

/// The exact unit normal `x_u × x_v / ‖·‖` at `(u, v)`, `None` where the surface is singular
/// (for the paper's `f` it points down, opposite to the faces of [`brauner_surface`]).
pub fn brauner_normal(f: &impl HeatSolution, mu: f64, u: f64, v: f64) -> Option<Vec3> {
    let (x_u, x_v) = brauner_tangents(f, mu, u, v);
    x_u.cross(&x_v).try_normalize(1e-300)
}

/// The slope β (degrees, against horizontal planes) of the asymptotic u-line `v = const`:
/// `tan β = μ e^{−v}` for every generator `f`.
pub fn brauner_slope_degrees(mu: f64, v: f64) -> f64 {
    (mu * (-v).exp()).atan().to_degrees()
}

/// Parameters of [`brauner_surface`], the paper's example of Eq. 23 over a parameter rectangle.
#[derive(Debug, Clone, PartialEq)]
pub struct BraunerSurface {
    /// The constant μ > 0 of Eq. 23 (vertical scale).
    pub mu: f64,
    /// The u interval, inside `(0, π)` where the paper's surface is regular.
    pub u_range: [f64; 2],
    /// The v interval, finite and increasing.
    pub v_range: [f64; 2],
    /// Approximate number of vertices.
    pub target_vertices: usize,
    /// Jitter of the grid points as a fraction of the cell size.
    pub irregularity: f64,
    pub seed: u64,
}

impl BraunerSurface {
    /// The patch of Fig. 32's surface used by the CLI and the tests: μ = 1, u ∈ [0.6, π − 0.6],
    /// v ∈ [−0.5, 0.5] (slopes of the u-lines 31° to 59°), regular and about 2.4 by 4.2 by 2.
    pub fn paper(target_vertices: usize) -> BraunerSurface {
        BraunerSurface { mu: 1.0, u_range: [0.6, PI - 0.6], v_range: [-0.5, 0.5], target_vertices, irregularity: 0.25, seed: 23 }
    }

    /// The parameters `(u, v)` of the point of the paper's surface above or below `(x, y)`:
    /// `y = sin u cos u − u` decreases strictly on `(0, π)`, so u follows by bisection, then
    /// `v = (cos²u − x) / 2`. `None` if `y` lies outside the values of `u ∈ (0, π)`.
    pub fn parameters_of(x: f64, y: f64) -> Option<(f64, f64)> {
        let plan_y = |u: f64| u.sin() * u.cos() - u;
        if !(x.is_finite() && y.is_finite()) || y > plan_y(0.0) || y < plan_y(PI) {
            return None;
        }
        let (mut lo, mut hi) = (0.0, PI);
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if plan_y(mid) > y {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let u = 0.5 * (lo + hi);
        Some((u, 0.5 * (u.cos().powi(2) - x)))
    }

    /// `count ≥ 2` values of v spread evenly over [`Self::v_range`], ends included: the u-lines
    /// [`Self::u_line`] draws.
    pub fn u_line_levels(&self, count: usize) -> Vec<f64> {
        let [v0, v1] = self.v_range;
        (0..count).map(|k| v0 + (v1 - v0) * k as f64 / (count.max(2) - 1) as f64).collect()
    }

    /// `points ≥ 2` points of the u-line `v = const` of the paper's surface, evenly spaced in u over
    /// [`Self::u_range`]: an asymptotic curve of constant slope [`brauner_slope_degrees`].
    pub fn u_line(&self, v: f64, points: usize) -> Vec<Vec3> {
        let [u0, u1] = self.u_range;
        (0..points).map(|i| brauner_point(&PaperHeatSolution, self.mu, u0 + (u1 - u0) * i as f64 / (points.max(2) - 1) as f64, v)).collect()
    }

    /// The exact upward unit normal of the paper's surface at `(u, v)`:
    /// `(−m cos u, −m sin u, 1) / √(1 + m²)`, `m = μ e^{−v}` (the orientation of the mesh's faces).
    pub fn normal(&self, u: f64, v: f64) -> Vec3 {
        let m = self.mu * (-v).exp();
        Vec3::new(-m * u.cos(), -m * u.sin(), 1.0) / (1.0 + m * m).sqrt()
    }
}

/// The paper's Brauner surface (Eq. 23 with [`PaperHeatSolution`]) over `u_range × v_range`,
/// triangulated by a jittered grid in `(u, v)`. Face normals point up, along
/// [`BraunerSurface::normal`]. The u-lines (`v = const`) are its asymptotic curves of constant
/// slope [`brauner_slope_degrees`].
pub fn brauner_surface(s: &BraunerSurface) -> Result<GeneratedSurface, SurfaceError> {
    let mu = positive("mu", s.mu)?;
    let irregularity = irregularity(s.irregularity)?;
    let [u0, u1] = s.u_range;
    if !(u0 > 0.0 && u0 < PI) {
        return Err(SurfaceError::InvalidParameter { name: "u_range[0]", value: u0 });
    }
    if !(u1 > u0 && u1 < PI) {
        return Err(SurfaceError::InvalidParameter { name: "u_range[1]", value: u1 });
    }
    let [v0, v1] = s.v_range;
    if !(v0.is_finite() && v0.abs() <= MAX_ABS_V) {
        return Err(SurfaceError::InvalidParameter { name: "v_range[0]", value: v0 });
    }
    if !(v1 > v0 && v1 <= MAX_ABS_V) {
        return Err(SurfaceError::InvalidParameter { name: "v_range[1]", value: v1 });
    }
    // ‖x_u‖ ≈ 2 sin u √(1 + m²) and ‖x_v‖ ≈ 2 √(1 + m² cos²u): cells of twice the parameter size
    // are roughly square where sin u is near 1.
    let domain = ParameterRectangle { width: 2.0 * (u1 - u0), height: 2.0 * (v1 - v0) };
    let mut rng = SplitMix64::new(s.seed);
    // u runs backwards along the grid's first axis so that the faces' normals point up.
    Ok(jittered_grid(&domain, s.target_vertices, irregularity, &mut rng, |a, b| brauner_point(&PaperHeatSolution, mu, u1 - 0.5 * a, v0 + 0.5 * b)))
}

/// Largest accepted `|v|`: `e^{|v|}` stays far from overflow and the surface of a reasonable size.
const MAX_ABS_V: f64 = 20.0;
