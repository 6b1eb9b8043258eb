//! Procedural test surfaces: deterministic, irregularly triangulated disk-topology patches of known
//! analytic surfaces, used to validate the discrete operators (e.g. the fairness energy of Eq. 6)
//! against closed-form expectations, the architectural hall roof used by the demo and the
//! benchmarks, and Brauner's surfaces with asymptotic curves of constant slope (Eq. 23).
//!
//! Every generator returns consistently oriented triangles without degenerate faces; the
//! orientation of each generator (outward / upward normals) is documented on it. Randomness comes
//! only from the seedable [`SplitMix64`], so the same parameters give the same bits.

mod brauner;
mod cylinder_patch;
mod hall_roof;
mod hyperbolic_paraboloid;
mod jittered_grid;
mod planar_disk;
mod random;
mod sphere_cap;
mod vault;

pub use brauner::{brauner_normal, brauner_point, brauner_slope_degrees, brauner_surface, brauner_tangents, BraunerSurface, HeatJet, HeatSolution, PaperHeatSolution};
pub use cylinder_patch::{cylinder_patch, CylinderPatch};
pub use hall_roof::{hall_roof, HallRoofSection};
pub use hyperbolic_paraboloid::{hyperbolic_paraboloid, HyperbolicParaboloid};
pub use planar_disk::{planar_disk, PlanarPatch};
pub use random::SplitMix64;
pub use sphere_cap::{sphere_cap, SphereCap};
pub use vault::{vault, Vault};

use crate::mesh::{MeshError, TriMesh, Vec3};

/// Vertex positions and counter-clockwise triangles of a generated surface.
#[derive(Debug, Clone, PartialEq)]
pub struct GeneratedSurface {
    pub positions: Vec<Vec3>,
    pub faces: Vec<[u32; 3]>,
}

impl GeneratedSurface {
    /// Builds (and validates) the triangle mesh.
    pub fn into_mesh(self) -> Result<TriMesh, MeshError> {
        TriMesh::from_vertices_and_faces(self.positions, self.faces)
    }
}

/// A generator parameter outside its documented range.
#[derive(Debug, Clone, PartialEq)]
pub enum SurfaceError {
    /// The named parameter is not finite or outside its admissible range.
    InvalidParameter { name: &'static str, value: f64 },
}

impl std::fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SurfaceError::InvalidParameter { name, value } => {
                write!(f, "surface parameter `{name}` = {value} is outside its admissible range")
            }
        }
    }
}

impl std::error::Error for SurfaceError {}

/// Largest accepted `irregularity`: a jitter of less than half a cell keeps neighbouring grid
/// points ordered.
pub const MAX_IRREGULARITY: f64 = 0.9;

/// `Ok(value)` if `value` is finite and strictly positive.
fn positive(name: &'static str, value: f64) -> Result<f64, SurfaceError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(SurfaceError::InvalidParameter { name, value })
    }
}

/// `Ok(value)` if `value` is an admissible irregularity, `0 ≤ value ≤ MAX_IRREGULARITY`.
fn irregularity(value: f64) -> Result<f64, SurfaceError> {
    if (0.0..=MAX_IRREGULARITY).contains(&value) {
        Ok(value)
    } else {
        Err(SurfaceError::InvalidParameter { name: "irregularity", value })
    }
}
