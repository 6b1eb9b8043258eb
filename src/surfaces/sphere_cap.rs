//! A spherical cap, the positively curved surface of the varying-angle families (Sec. 3.2,
//! Fig. 16): every curve on it has normal curvature `1/R`, so P-curves to a constant small angle
//! cannot form a family.

use super::planar_disk::{planar_disk, PlanarPatch};
use super::{positive, GeneratedSurface, SurfaceError};
use crate::mesh::Vec3;
use std::f64::consts::PI;

/// Parameters of [`sphere_cap`].
#[derive(Debug, Clone, PartialEq)]
pub struct SphereCap {
    /// Sphere radius R > 0.
    pub radius: f64,
    /// Angular radius α of the cap in radians (angle at the centre between the pole and the
    /// boundary circle), `0 < α < π`.
    pub cap_angle: f64,
    /// Approximate number of vertices (rounded to whole rings).
    pub target_vertices: usize,
    /// Jitter of the points as a fraction of the ring spacing, in `[0, MAX_IRREGULARITY]`.
    pub irregularity: f64,
    pub seed: u64,
}

/// The cap of the sphere `‖p‖ = R` around the pole `(0, 0, R)` up to polar angle `α`.
///
/// The irregular disk of [`planar_disk`] with radius `R α` is wrapped onto the sphere by the
/// azimuthal equidistant map, a point at distance `ρ` and polar angle `φ` going to
/// `R (sin ψ cos φ, sin ψ sin φ, cos ψ)` with `ψ = ρ/R`: rings become circles of latitude at equal
/// geodesic spacing and the boundary is exactly the circle `ψ = α`. Face normals point outward.
pub fn sphere_cap(cap: &SphereCap) -> Result<GeneratedSurface, SurfaceError> {
    let radius = positive("radius", cap.radius)?;
    let cap_angle = positive("cap_angle", cap.cap_angle)?;
    if cap_angle >= PI {
        return Err(SurfaceError::InvalidParameter { name: "cap_angle", value: cap_angle });
    }
    let disk = PlanarPatch { radius: radius * cap_angle, target_vertices: cap.target_vertices, irregularity: cap.irregularity, seed: cap.seed };
    let GeneratedSurface { positions, faces } = planar_disk(&disk)?;
    let positions = positions
        .iter()
        .map(|p| {
            let (rho, phi) = (p.x.hypot(p.y), p.y.atan2(p.x));
            let psi = rho / radius;
            Vec3::new(radius * psi.sin() * phi.cos(), radius * psi.sin() * phi.sin(), radius * psi.cos())
        })
        .collect();
    Ok(GeneratedSurface { positions, faces })
}
