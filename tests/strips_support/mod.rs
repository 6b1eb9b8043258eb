//! Shared helpers of the strip tests: the optimised 60° cylinder field, the analytic P-curves,
//! and an unrolling of 3D strips that is independent of the library's own.
#![allow(dead_code, unused_imports)]

#[path = "../field_support/mod.rs"]
mod field_support;

pub use field_support::{cylinder, development, perturbed_height, RADIUS};
use lamella::field::{FieldParams, FieldSolver};
use lamella::mesh::{TriMesh, Vec3};
use std::sync::OnceLock;

/// The cylinder of the paper (R = 10) with its optimised 60° pseudo-geodesic field, computed once
/// per test binary.
pub fn sixty_degree_cylinder() -> &'static (TriMesh, Vec<f64>) {
    static CYLINDER: OnceLock<(TriMesh, Vec<f64>)> = OnceLock::new();
    CYLINDER.get_or_init(|| {
        let mesh = cylinder(1500, 11);
        let mut solver = FieldSolver::new(&mesh, &perturbed_height(&mesh), FieldParams::pseudo_geodesic(60.0)).expect("valid input");
        let report = solver.step(300).expect("solver runs");
        assert!(report.converged, "field not converged");
        (mesh, solver.field())
    })
}

/// Symmetric Hausdorff distance, in the cylinder's development, between a polyline and the best
/// catenary `z = ±cosh(k (s − s0))/k + c` over the polyline's `s` range (k = cot θ / R).
pub fn catenary_hausdorff(points: &[(f64, f64)], k: f64) -> f64 {
    let vertical = |s0: f64, sign: f64| {
        let residual: Vec<f64> = points.iter().map(|&(s, z)| z - sign * (k * (s - s0)).cosh() / k).collect();
        let (lo, hi) = residual.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &r| (a.min(r), b.max(r)));
        (0.5 * (hi - lo), 0.5 * (hi + lo))
    };
    let s_min = points.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let s_max = points.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let mut best = f64::INFINITY;
    for sign in [-1.0, 1.0] {
        let (mut lo, mut hi) = (-80.0, 110.0);
        let mut s_best = lo;
        for i in 0..=380 {
            let s0 = lo + (hi - lo) * i as f64 / 380.0;
            if vertical(s0, sign).0 < vertical(s_best, sign).0 {
                s_best = s0;
            }
        }
        lo = s_best - 0.5;
        hi = s_best + 0.5;
        let golden = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..60 {
            let (a, b) = (hi - golden * (hi - lo), lo + golden * (hi - lo));
            if vertical(a, sign).0 < vertical(b, sign).0 {
                hi = b;
            } else {
                lo = a;
            }
        }
        let s0 = 0.5 * (lo + hi);
        let offset = vertical(s0, sign).1;
        let curve: Vec<(f64, f64)> = (0..=2000)
            .map(|i| {
                let s = s_min + (s_max - s_min) * i as f64 / 2000.0;
                (s, sign * (k * (s - s0)).cosh() / k + offset)
            })
            .collect();
        best = best.min(hausdorff_2d(points, &curve));
    }
    best
}

fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let length2 = dx * dx + dy * dy;
    let t = if length2 > 0.0 { (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / length2).clamp(0.0, 1.0) } else { 0.0 };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// Symmetric Hausdorff distance between two 2D polylines (vertices to the other polyline).
pub fn hausdorff_2d(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let one_sided = |from: &[(f64, f64)], to: &[(f64, f64)]| {
        from.iter()
            .map(|&p| to.windows(2).map(|w| segment_distance(p, w[0], w[1])).fold(f64::INFINITY, f64::min))
            .fold(0.0, f64::max)
    };
    one_sided(a, b).max(one_sided(b, a))
}

/// Independent check of a strip of quads `(left_j, left_{j+1}, right_{j+1}, right_j)` with the
/// centre points `centre_j` on the segments `left_j right_j`: unrolls it quad by quad from its 3D
/// coordinates, each quad flattened by its own distances (two triangles sharing the diagonal from
/// `centre_{j+1}` to `left_j`), and returns (the largest out-of-plane distance of a quad corner
/// over the quad size, the largest distance of a flattened centre point from the line through the
/// first and last flattened centre points over the strip length).
pub fn unroll_quad_by_quad(centre: &[Vec3], left: &[Vec3], right: &[Vec3]) -> (f64, f64) {
    let mut planarity: f64 = 0.0;
    // 2D positions of centre and left of the current ruling.
    let mut flat_centre = vec![[0.0, 0.0]];
    let mut flat_left = [0.0, (left[0] - centre[0]).norm()];
    for j in 0..centre.len() - 1 {
        let (c0, c1, l0, l1, r1) = (centre[j], centre[j + 1], left[j], left[j + 1], right[j + 1]);
        // Planarity: distance of l1 from the plane through c0, c1, l0, and of r1.
        let normal = (c1 - c0).cross(&(l0 - c0)).normalize();
        let size = (c1 - c0).norm().max((l1 - c0).norm());
        planarity = planarity.max((l1 - c0).dot(&normal).abs() / size).max((r1 - c0).dot(&normal).abs() / size);
        // Place c1 from its distances to c0 and l0, on the forward side of the ruling c0 l0 (the
        // side the first quad fixes), then l1 from c1 and l0, across the diagonal c1 l0 from c0.
        let p0 = flat_centre[j];
        let c1_flat = place(p0, flat_left, (c1 - c0).norm(), (c1 - l0).norm(), -1.0);
        let l1_flat = place(c1_flat, flat_left, (l1 - c1).norm(), (l1 - l0).norm(), -side(c1_flat, flat_left, p0));
        flat_centre.push(c1_flat);
        flat_left = l1_flat;
    }
    let (a, b) = (flat_centre[0], flat_centre[flat_centre.len() - 1]);
    let length: f64 = centre.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let chord = (dx * dx + dy * dy).sqrt();
    let straight = flat_centre.iter().map(|p| ((p[0] - a[0]) * dy - (p[1] - a[1]) * dx).abs() / chord).fold(0.0, f64::max);
    (planarity, straight / length)
}

/// Sign of the turn from `a → b` to `a → p`.
fn side(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])).signum()
}

/// The point at distance `ra` from `a` and `rb` from `b`, on the side `sign` of `a → b`.
fn place(a: [f64; 2], b: [f64; 2], ra: f64, rb: f64, sign: f64) -> [f64; 2] {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let d = (dx * dx + dy * dy).sqrt();
    let along = (ra * ra - rb * rb + d * d) / (2.0 * d);
    let across = (ra * ra - along * along).max(0.0).sqrt();
    let (ux, uy) = (dx / d, dy / d);
    [a[0] + along * ux - sign * across * uy, a[1] + along * uy + sign * across * ux]
}
