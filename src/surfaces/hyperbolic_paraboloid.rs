//! A square patch of the hyperbolic paraboloid `z = x·y / c`, a doubly ruled surface of negative
//! Gaussian curvature.

use super::jittered_grid::{jittered_grid, ParameterRectangle};
use super::random::SplitMix64;
use super::{irregularity, positive, GeneratedSurface, SurfaceError};
use crate::mesh::Vec3;

/// Parameters of [`hyperbolic_paraboloid`].
#[derive(Debug, Clone, PartialEq)]
pub struct HyperbolicParaboloid {
    /// Curvature scale `c ≠ 0` of `z = x·y / c`.
    pub c: f64,
    /// Half the side length `a > 0` of the square `[−a, a]²` in plan.
    pub half_width: f64,
    /// Approximate number of vertices (the grid is rounded to whole rows and columns).
    pub target_vertices: usize,
    /// Jitter of the grid points as a fraction of the cell size, in `[0, MAX_IRREGULARITY]`.
    pub irregularity: f64,
    pub seed: u64,
}

/// The graph `z = x·y / c` over `[−a, a]²`, triangulated by a jittered grid in the plan coordinates
/// `(x, y)` (see the module `jittered_grid`; cells are square in plan, so the surface triangles are
/// stretched where the slope `|(y, x)| / c` is large). Face normals point upwards (`n_z > 0`).
pub fn hyperbolic_paraboloid(surface: &HyperbolicParaboloid) -> Result<GeneratedSurface, SurfaceError> {
    let c = surface.c;
    if !c.is_finite() || c == 0.0 {
        return Err(SurfaceError::InvalidParameter { name: "c", value: c });
    }
    let a = positive("half_width", surface.half_width)?;
    let irregularity = irregularity(surface.irregularity)?;
    let domain = ParameterRectangle { width: 2.0 * a, height: 2.0 * a };
    let mut rng = SplitMix64::new(surface.seed);
    Ok(jittered_grid(&domain, surface.target_vertices, irregularity, &mut rng, |u, v| {
        let (x, y) = (u - a, v - a);
        Vec3::new(x, y, x * y / c)
    }))
}
