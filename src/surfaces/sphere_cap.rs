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

#[cfg(test)]
mod tests {
    use super::*;

    fn cap(cap_angle: f64, seed: u64) -> SphereCap {
        SphereCap { radius: 4.0, cap_angle, target_vertices: 700, irregularity: 0.3, seed }
    }

    #[test]
    fn lies_on_the_sphere_with_an_exact_boundary_circle_and_outward_normals() {
        for (angle, seed) in [(0.4, 1), (1.2, 2), (2.5, 3)] {
            let surface = sphere_cap(&cap(angle, seed)).expect("valid cap");
            let mesh = surface.clone().into_mesh().expect("valid mesh");
            let n = mesh.vertex_count();
            assert!((n as f64 - 700.0).abs() < 0.1 * 700.0, "{n} vertices");
            for p in mesh.positions() {
                assert!((p.norm() - 4.0).abs() < 1e-12, "off the sphere: {p:?}");
                assert!((p.z / 4.0).acos() <= angle + 1e-12, "outside the cap: {p:?}");
            }
            // Disk topology: one boundary loop and Euler characteristic 1.
            assert_eq!(mesh.boundary_loops().len(), 1);
            assert_eq!(n as i64 - mesh.edges().len() as i64 + mesh.face_count() as i64, 1);
            for &v in &mesh.boundary_loops()[0] {
                let polar = (mesh.positions()[v as usize].z / 4.0).acos();
                assert!((polar - angle).abs() < 1e-12, "boundary vertex at polar angle {polar}");
            }
            for (f, normal) in mesh.face_normals().iter().enumerate() {
                let centroid: Vec3 = mesh.faces()[f].iter().map(|&v| mesh.positions()[v as usize]).sum::<Vec3>() / 3.0;
                assert!(normal.dot(&centroid.normalize()) > 0.9, "face {f} does not point outward");
            }
        }
    }

    #[test]
    fn invalid_parameters_are_rejected() {
        for angle in [0.0, -0.1, PI, f64::NAN] {
            assert!(sphere_cap(&cap(angle, 1)).is_err(), "cap angle {angle}");
        }
        assert!(sphere_cap(&SphereCap { radius: f64::INFINITY, ..cap(1.0, 1) }).is_err());
        assert!(sphere_cap(&SphereCap { irregularity: 2.0, ..cap(1.0, 1) }).is_err());
    }
}
