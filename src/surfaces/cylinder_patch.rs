//! A patch of a circular cylinder, the developable validation surface of the paper
//! (R = 10, span ≈ 150°, height 15).

use super::jittered_grid::{jittered_grid, ParameterRectangle};
use super::random::SplitMix64;
use super::{irregularity, positive, GeneratedSurface, SurfaceError};
use crate::mesh::Vec3;
use std::f64::consts::TAU;

/// Parameters of [`cylinder_patch`].
#[derive(Debug, Clone, PartialEq)]
pub struct CylinderPatch {
    /// Cylinder radius R > 0.
    pub radius: f64,
    /// Angular extent in radians, `0 < span < 2π`.
    pub span: f64,
    /// Extent along the axis, > 0.
    pub height: f64,
    /// Approximate number of vertices (the grid is rounded to whole rows and columns).
    pub target_vertices: usize,
    /// Jitter of the grid points as a fraction of the cell size, in `[0, MAX_IRREGULARITY]`.
    pub irregularity: f64,
    pub seed: u64,
}

/// The points `(R cos φ, R sin φ, z)`, `φ ∈ [0, span]`, `z ∈ [0, height]`, triangulated by a jittered
/// grid in the development coordinates `(R·φ, z)` (see the module `jittered_grid`). Face normals
/// point away from the axis.
pub fn cylinder_patch(patch: &CylinderPatch) -> Result<GeneratedSurface, SurfaceError> {
    let radius = positive("radius", patch.radius)?;
    let span = positive("span", patch.span)?;
    if span >= TAU {
        return Err(SurfaceError::InvalidParameter { name: "span", value: span });
    }
    let height = positive("height", patch.height)?;
    let irregularity = irregularity(patch.irregularity)?;
    let domain = ParameterRectangle { width: radius * span, height };
    let mut rng = SplitMix64::new(patch.seed);
    Ok(jittered_grid(&domain, patch.target_vertices, irregularity, &mut rng, |arc, z| {
        let phi = arc / radius;
        Vec3::new(radius * phi.cos(), radius * phi.sin(), z)
    }))
}
