//! Shared helpers of the strip tests: the optimised 60° cylinder field, the analytic P-curves,
//! and an unrolling of 3D strips that is independent of the library's own.
#![allow(dead_code, unused_imports)]

use crate::field_support;

pub use field_support::{catenary_hausdorff, cylinder, development, hausdorff_2d, perturbed_height, RADIUS};
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
