//! The smooth surface a triangle mesh samples, seen from each vertex: a quadric height function
//! `z = ½ (L x² + 2 M x y + N y²)` over the tangent plane, fitted by least squares to the vertex's
//! two-ring. Its tangent plane gives a second-order accurate normal (the angle-weighted vertex
//! normal is only first-order on irregular triangulations), its Hessian the second fundamental form
//! `II`, from which normal curvatures `κ_n = II(t, t)` follow (Sec. 2.2).
//!
//! The same tangent-plane chart carries the local fits of scalar fields (see
//! [`crate::field`]'s level jets): the vertex's neighbours have chart coordinates equal to their
//! projections onto the tangent plane, and the chart's metric is the identity up to second order
//! at the vertex, so curvatures measured in it at the origin are those of the surface.
//! [`TriMesh::local_quadrics`] fits them once per mesh.

use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;

use super::{TriMesh, Vec3};

/// Fewest neighbourhood vertices for a fit (the height fit has five unknowns).
const MIN_POINTS: usize = 9;
/// Smallest singular value of the design matrix relative to its largest that counts as well posed.
const CONDITION: f64 = 1e-4;
/// Rings grown at most when the two-ring is too small or badly spread (boundary corners).
const MAX_RINGS: usize = 4;

/// The osculating quadric of the surface at one vertex.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalQuadric {
    /// Unit normal, on the side of the mesh's vertex normal.
    pub normal: Vec3,
    /// Orthonormal tangent basis with `tangents[0] × tangents[1] = normal`.
    pub tangents: [Vec3; 2],
    /// `(L, M, N)`: the second fundamental form in the tangent basis, in 1/length, so that the
    /// normal curvature of a unit tangent `x t₀ + y t₁` is `L x² + 2 M x y + N y²`.
    pub second_form: [f64; 3],
    /// Rings of neighbours the fit used (2, more where the two-ring was too small).
    pub rings: usize,
}

impl LocalQuadric {
    /// Normal curvature `II(t, t)` of a unit tangent vector `t` (its normal component is ignored).
    pub fn normal_curvature(&self, t: &Vec3) -> f64 {
        let (x, y) = (t.dot(&self.tangents[0]), t.dot(&self.tangents[1]));
        let [l, m, n] = self.second_form;
        l * x * x + 2.0 * m * x * y + n * y * y
    }

    /// Chart coordinates of a point: its projection onto the tangent plane at `origin`.
    pub fn chart(&self, origin: &Vec3, point: &Vec3) -> (f64, f64) {
        let d = point - origin;
        (d.dot(&self.tangents[0]), d.dot(&self.tangents[1]))
    }
}

/// The vertices within `rings` edges of `v` (`v` included), sorted by index.
pub fn vertex_neighbourhood(mesh: &TriMesh, v: usize, rings: usize) -> Vec<u32> {
    let mut set = vec![v as u32];
    let mut frontier = vec![v as u32];
    for _ in 0..rings {
        let mut next = Vec::new();
        for &u in &frontier {
            for &w in mesh.star(u as usize).neighbours {
                if !set.contains(&w) && !next.contains(&w) {
                    next.push(w);
                }
            }
        }
        set.extend_from_slice(&next);
        frontier = next;
    }
    set.sort_unstable();
    set
}

/// The osculating quadric at every vertex (in parallel; the result does not depend on the threads).
pub(crate) fn local_quadrics(mesh: &TriMesh) -> Vec<LocalQuadric> {
    (0..mesh.vertex_count()).into_par_iter().map(|v| local_quadric(mesh, v)).collect()
}

/// The osculating quadric at vertex `v`: fitted over its two-ring, grown ring by ring (up to
/// four) where that is too small or badly spread; the vertex normal with zero curvature where no
/// fit is well posed.
fn local_quadric(mesh: &TriMesh, v: usize) -> LocalQuadric {
    let rough = mesh.vertex_normals()[v];
    for rings in 2..=MAX_RINGS {
        let neighbourhood = vertex_neighbourhood(mesh, v, rings);
        if neighbourhood.len() < MIN_POINTS {
            continue;
        }
        if let Some(fit) = fit_in_frame(mesh, v, &neighbourhood, &rough).and_then(|first| fit_in_frame(mesh, v, &neighbourhood, &first.normal)) {
            if fit.normal.dot(&rough) > 0.5 {
                return LocalQuadric { rings, ..fit };
            }
        }
    }
    LocalQuadric { normal: rough, tangents: tangent_basis(&rough), second_form: [0.0; 3], rings: 0 }
}

/// An orthonormal tangent basis `(t₀, t₁)` with `t₀ × t₁ = normal`.
pub fn tangent_basis(normal: &Vec3) -> [Vec3; 2] {
    // Cross with the coordinate axis least aligned with n, which is far from parallel to it.
    let axis = normal.iamin();
    let t0 = Vec3::ith(axis, 1.0).cross(normal).normalize();
    [t0, normal.cross(&t0)]
}

/// Fits `z = g₀ x + g₁ y + ½ (L x² + 2 M x y + N y²)` (through the vertex) in the frame of
/// `axis`, in units of the mean edge length; returns the quadric whose normal is the fit's.
fn fit_in_frame(mesh: &TriMesh, v: usize, neighbourhood: &[u32], axis: &Vec3) -> Option<LocalQuadric> {
    let tangents = tangent_basis(axis);
    let origin = mesh.positions()[v];
    let scale = mesh.mean_edge_length();
    let others: Vec<u32> = neighbourhood.iter().copied().filter(|&u| u as usize != v).collect();
    let mut design = DMatrix::zeros(others.len(), 5);
    let mut heights = DVector::zeros(others.len());
    for (row, &u) in others.iter().enumerate() {
        let d = (mesh.positions()[u as usize] - origin) / scale;
        let (x, y) = (d.dot(&tangents[0]), d.dot(&tangents[1]));
        for (column, value) in [x, y, 0.5 * x * x, x * y, 0.5 * y * y].into_iter().enumerate() {
            design[(row, column)] = value;
        }
        heights[row] = d.dot(axis);
    }
    let svd = design.svd(true, true);
    let largest = svd.singular_values.max();
    if !(svd.singular_values.min() > CONDITION * largest) {
        return None;
    }
    let c = svd.solve(&heights, 0.0).ok()?;
    if !c.iter().all(|x| x.is_finite()) {
        return None;
    }
    let normal = (axis - tangents[0] * c[0] - tangents[1] * c[1]).try_normalize(0.0)?;
    // The Hessian of the height over the tilted plane differs from the fitted one by terms of
    // the order of the tilt squared: the second, re-framed fit has a tilt of rounding size.
    let tilt = 1.0 + c[0] * c[0] + c[1] * c[1];
    let second_form = [c[2] / (scale * tilt), c[3] / (scale * tilt), c[4] / (scale * tilt)];
    let t0 = (tangents[0] - normal * tangents[0].dot(&normal)).try_normalize(0.0)?;
    Some(LocalQuadric { normal, tangents: [t0, normal.cross(&t0)], second_form, rings: 0 })
}
