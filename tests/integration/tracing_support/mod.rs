//! Shared helpers of the tracing tests: test surfaces, start points found geometrically,
//! the cylinder's development and distances between polylines.
#![allow(dead_code)]

use lamella::mesh::{EdgePoint, TriMesh, Vec3};
use lamella::surfaces::{cylinder_patch, hyperbolic_paraboloid, CylinderPatch, HyperbolicParaboloid};

pub const RADIUS: f64 = 10.0;
pub const HEIGHT: f64 = 15.0;

/// The paper's validation cylinder: R = 10, 150° span, height 15, irregular triangulation.
pub fn cylinder(target_vertices: usize, seed: u64) -> TriMesh {
    let patch = CylinderPatch {
        radius: RADIUS,
        span: 150f64.to_radians(),
        height: HEIGHT,
        target_vertices,
        irregularity: 0.5,
        seed,
    };
    cylinder_patch(&patch).expect("valid patch").into_mesh().expect("valid mesh")
}

/// z = xy/c over [−a, a]², irregularly triangulated.
pub fn saddle(c: f64, half_width: f64, target_vertices: usize) -> TriMesh {
    let surface = HyperbolicParaboloid { c, half_width, target_vertices, irregularity: 0.5, seed: 3 };
    hyperbolic_paraboloid(&surface).expect("valid surface").into_mesh().expect("valid mesh")
}

/// Arc length around the axis and height: the isometric development of the cylinder.
pub fn development(p: &Vec3) -> (f64, f64) {
    (RADIUS * p.y.atan2(p.x), p.z)
}

/// The point on the boundary edge `[a, b]` whose endpoints both satisfy `on_side` and whose
/// coordinate `coordinate` passes through `value` (found by scanning the boundary edges).
pub fn boundary_point_where(mesh: &TriMesh, on_side: impl Fn(&Vec3) -> bool, coordinate: impl Fn(&Vec3) -> f64, value: f64) -> EdgePoint {
    let positions = mesh.positions();
    for e in mesh.boundary_edges() {
        let (pa, pb) = (positions[e.from as usize], positions[e.to as usize]);
        if !(on_side(&pa) && on_side(&pb)) {
            continue;
        }
        let (ca, cb) = (coordinate(&pa), coordinate(&pb));
        if (ca - value) * (cb - value) <= 0.0 && ca != cb {
            return EdgePoint { edge: [e.from, e.to], t: (value - ca) / (cb - ca) };
        }
    }
    panic!("no boundary edge passes through {value}");
}

/// The start point on the cylinder's left side (φ = 0) at `height`.
pub fn left_side_point(mesh: &TriMesh, height: f64) -> EdgePoint {
    boundary_point_where(mesh, |p| p.y.abs() < 1e-9 && p.x > 0.0, |p| p.z, height)
}

/// Distance from `q` to the segment `[a, b]` in the plane.
pub fn segment_distance(q: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let s = if len2 > 0.0 { (((q.0 - a.0) * dx + (q.1 - a.1) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    ((q.0 - a.0 - s * dx).powi(2) + (q.1 - a.1 - s * dy).powi(2)).sqrt()
}

/// Distance from `q` to a plane polyline.
pub fn polyline_distance(q: (f64, f64), polyline: &[(f64, f64)]) -> f64 {
    polyline.windows(2).map(|w| segment_distance(q, w[0], w[1])).fold(f64::INFINITY, f64::min)
}

/// Symmetric Hausdorff distance of two plane polylines (vertices against the other polyline).
pub fn hausdorff(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let one_sided = |p: &[(f64, f64)], q: &[(f64, f64)]| p.iter().map(|&x| polyline_distance(x, q)).fold(0.0, f64::max);
    one_sided(a, b).max(one_sided(b, a))
}

/// Length of a plane polyline.
pub fn length_2d(polyline: &[(f64, f64)]) -> f64 {
    polyline.windows(2).map(|w| ((w[1].0 - w[0].0).powi(2) + (w[1].1 - w[0].1).powi(2)).sqrt()).sum()
}

/// Normal interpolated along the edge of `point` from the vertex normals, as documented for the tracer.
pub fn interpolated_normal(mesh: &TriMesh, point: &EdgePoint) -> Vec3 {
    let n = mesh.vertex_normals();
    let [a, b] = point.edge;
    (n[a as usize] * (1.0 - point.t) + n[b as usize] * point.t).normalize()
}

/// Signed binormal–normal angles (degrees) at the interior points of a traced polyline: Eq. 1
/// binormal of consecutive segments, side vector u = n × t, θ = acos(sign(b·u)·(b·n));
/// `None` where the turn is below 10⁻⁵ rad and the binormal undefined.
pub fn binormal_angles(mesh: &TriMesh, points: &[EdgePoint], positions: &[Vec3]) -> Vec<Option<f64>> {
    (1..positions.len() - 1)
        .map(|i| {
            let e_in = (positions[i] - positions[i - 1]).normalize();
            let e_out = (positions[i + 1] - positions[i]).normalize();
            let b = e_in.cross(&e_out);
            if b.norm() < 1e-5 {
                return None;
            }
            let b = b.normalize();
            let t = (e_in + e_out).normalize();
            let n = interpolated_normal(mesh, &points[i]);
            let u = n.cross(&t).normalize();
            let sign = if b.dot(&u) < 0.0 { -1.0 } else { 1.0 };
            Some((sign * b.dot(&n)).clamp(-1.0, 1.0).acos().to_degrees())
        })
        .collect()
}
