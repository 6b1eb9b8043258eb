//! Shared helpers of the initialisation tests: analytic P-curves of the cylinder (catenaries in
//! its development) as guide curves on mesh edges and as sketched strokes, plane sections of the
//! vault as guide curves.
#![allow(dead_code, unused_imports)]

use crate::field_support;

pub use field_support::{cylinder, development, RADIUS};
use lamella::mesh::{EdgePoint, TriMesh, Vec3};
use lamella::surfaces::{vault, Vault};

/// Cylinder height (field_support's cylinder: 150° span, height 15).
pub const HEIGHT: f64 = 15.0;
/// Developed width of the cylinder patch.
pub fn width() -> f64 {
    RADIUS * 150f64.to_radians()
}

/// The catenary `z = z0 + (cosh(k (s − s0)) − 1)/k` of the development, `k = tan(90° − θ)/R`,
/// `s0` the middle of the patch: a P-curve of angle θ (Wunderlich), convex towards +z. With the
/// outward normals of the patch and F increasing with `z0`, the signed angle of the family is θ:
/// at the lowest point the tangent is the circumference direction e, the curvature vector is
/// `−n/R + k ẑ`, so `b ∝ e × (−n/R + k ẑ) = ẑ/R + k n` (b·n = cos θ > 0) and the side vector
/// `u = ẑ` (towards growing F) has `b·u > 0`.
pub struct Catenary {
    pub z0: f64,
    pub k: f64,
    pub s0: f64,
}

impl Catenary {
    pub fn new(theta_degrees: f64, z0: f64) -> Catenary {
        Catenary { z0, k: (90.0 - theta_degrees).to_radians().tan() / RADIUS, s0: 0.5 * width() }
    }

    pub fn height(&self, s: f64) -> f64 {
        self.z0 + ((self.k * (s - self.s0)).cosh() - 1.0) / self.k
    }

    /// Signed distance (along z in the development) of a developed point from the curve.
    fn offset(&self, (s, z): (f64, f64)) -> f64 {
        z - self.height(s)
    }

    /// The 3D point of the curve at arc parameter `s` of the development, pushed `lift` along the
    /// outward normal.
    pub fn point(&self, s: f64, lift: f64) -> Vec3 {
        let phi = s / RADIUS;
        Vec3::new((RADIUS + lift) * phi.cos(), (RADIUS + lift) * phi.sin(), self.height(s))
    }

    /// The curve's crossings with the mesh edges (in the development, each edge taken as the
    /// straight segment between its developed ends), ordered along the curve.
    pub fn edge_points(&self, mesh: &TriMesh) -> Vec<EdgePoint> {
        let mut points: Vec<(f64, EdgePoint)> = Vec::new();
        for &[a, b] in mesh.edges() {
            let (da, db) = (development(&mesh.positions()[a as usize]), development(&mesh.positions()[b as usize]));
            let at = |t: f64| (da.0 + t * (db.0 - da.0), da.1 + t * (db.1 - da.1));
            let (ga, gb) = (self.offset(da), self.offset(db));
            if ga * gb >= 0.0 {
                continue;
            }
            // Bisection on the segment (the offset is monotone enough on one short edge).
            let (mut lo, mut hi) = (0.0, 1.0);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if (self.offset(at(mid)) < 0.0) == (ga < 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let t = 0.5 * (lo + hi);
            points.push((at(t).0, EdgePoint { edge: [a, b], t }));
        }
        points.sort_by(|x, y| x.0.total_cmp(&y.0));
        points.into_iter().map(|(_, p)| p).collect()
    }

    /// `count` stroke points along the curve for `s` in `[s_from, s_to]`, `lift` off the surface.
    pub fn stroke(&self, s_from: f64, s_to: f64, count: usize, lift: f64) -> Vec<Vec3> {
        (0..count).map(|i| self.point(s_from + (s_to - s_from) * i as f64 / (count - 1) as f64, lift)).collect()
    }
}

/// The vault of the issue: a = 10, b = 7, h = 4.
pub fn vault_mesh(target_vertices: usize, seed: u64) -> TriMesh {
    let surface = Vault { half_length: 10.0, half_width: 7.0, rise: 4.0, target_vertices, irregularity: 0.25, seed };
    vault(&surface).expect("valid vault").into_mesh().expect("valid mesh")
}

/// The plane section `x = c` of a mesh as points on its edges, ordered by y.
pub fn plane_section(mesh: &TriMesh, c: f64) -> Vec<EdgePoint> {
    let mut points: Vec<(f64, EdgePoint)> = Vec::new();
    for &[a, b] in mesh.edges() {
        let (pa, pb) = (mesh.positions()[a as usize], mesh.positions()[b as usize]);
        if (pa.x - c) * (pb.x - c) < 0.0 {
            let t = (c - pa.x) / (pb.x - pa.x);
            points.push((pa.y + t * (pb.y - pa.y), EdgePoint { edge: [a, b], t }));
        }
    }
    points.sort_by(|x, y| x.0.total_cmp(&y.0));
    points.into_iter().map(|(_, p)| p).collect()
}

/// The piecewise linear field at an edge point.
pub fn value_at(field: &[f64], p: &EdgePoint) -> f64 {
    (1.0 - p.t) * field[p.edge[0] as usize] + p.t * field[p.edge[1] as usize]
}
