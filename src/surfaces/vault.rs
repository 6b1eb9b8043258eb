//! The doubly curved vault `z = h (1 − (x/a)²)(1 − (y/b)²)` over the rectangle `[−a, a] × [−b, b]`,
//! the positively curved test surface of the initialisation issue: dome-like in the middle, flat
//! along its four edges.

use super::jittered_grid::{jittered_grid, ParameterRectangle};
use super::random::SplitMix64;
use super::{irregularity, positive, GeneratedSurface, SurfaceError};
use crate::mesh::Vec3;

/// Parameters of [`vault`].
#[derive(Debug, Clone, PartialEq)]
pub struct Vault {
    /// Half the extent along x, > 0.
    pub half_length: f64,
    /// Half the extent along y, > 0.
    pub half_width: f64,
    /// Rise h of the crown above the edges, > 0.
    pub rise: f64,
    /// Approximate number of vertices.
    pub target_vertices: usize,
    /// Jitter of the grid points as a fraction of the cell size.
    pub irregularity: f64,
    pub seed: u64,
}

/// The vault triangulated by a jittered grid in plan `(x, y)`. Face normals point up.
pub fn vault(v: &Vault) -> Result<GeneratedSurface, SurfaceError> {
    let a = positive("half_length", v.half_length)?;
    let b = positive("half_width", v.half_width)?;
    let h = positive("rise", v.rise)?;
    let irregularity = irregularity(v.irregularity)?;
    let domain = ParameterRectangle { width: 2.0 * a, height: 2.0 * b };
    let mut rng = SplitMix64::new(v.seed);
    Ok(jittered_grid(&domain, v.target_vertices, irregularity, &mut rng, |u, w| {
        let (x, y) = (u - a, w - b);
        Vec3::new(x, y, h * (1.0 - (x / a).powi(2)) * (1.0 - (y / b).powi(2)))
    }))
}
