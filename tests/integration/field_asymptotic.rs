//! Asymptotic families on the hyperbolic paraboloid z = xy/c, whose asymptotic lines are the
//! straight rulings x = const and y = const.

use crate::field_support;

use field_support::{level_points, levels, saddle};
use lamella::field::{Family, FieldParams, FieldSolver};
use lamella::mesh::TriMesh;

const C: f64 = 5.0;
const HALF_WIDTH: f64 = 5.0;

fn asymptotic_energy(mesh: &TriMesh, field: &[f64]) -> f64 {
    FieldSolver::new(mesh, field, FieldParams::new(Family::Asymptotic)).expect("valid input").report().energies.angle
}

/// Largest x-extent of the level sets of `field`: 0 when every level set is a ruling x = const.
fn largest_x_spread(mesh: &TriMesh, field: &[f64]) -> f64 {
    levels(field, 9)
        .into_iter()
        .map(|level| {
            let points = level_points(mesh, field, level);
            let (lo, hi) = points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| (lo.min(p.x), hi.max(p.x)));
            hi - lo
        })
        .fold(0.0, f64::max)
}

#[test]
fn rulings_minimise_the_asymptotic_energy() {
    let mesh = saddle(C, HALF_WIDTH, 1200);
    // Linear fields F = cos β x + sin β y: level sets are lines of direction β + 90° in plan,
    // asymptotic exactly for β = 0° and 90° (normal curvature 2 sin β cos β / c otherwise).
    let energies: Vec<(f64, f64)> = (0..12)
        .map(|i| {
            let beta = (15 * i) as f64;
            let (sin, cos) = beta.to_radians().sin_cos();
            let field: Vec<f64> = mesh.positions().iter().map(|p| cos * p.x + sin * p.y).collect();
            (beta, asymptotic_energy(&mesh, &field))
        })
        .collect();
    let largest = energies.iter().map(|e| e.1).fold(0.0, f64::max);
    for &(beta, energy) in &energies {
        if beta == 0.0 || beta == 90.0 {
            // ≈ 0 up to the first-order error of chords and vertex normals on a triangle mesh.
            assert!(energy < 0.1 * largest, "β = {beta}°: E_asy = {energy}, largest {largest}");
        } else {
            let ruling = energies.iter().filter(|e| e.0 == 0.0 || e.0 == 90.0).map(|e| e.1).fold(0.0, f64::max);
            assert!(energy > ruling, "β = {beta}°: E_asy = {energy} is not above the rulings' {ruling}");
        }
    }
}

#[test]
fn perturbed_rulings_straighten_again() {
    let mesh = saddle(C, HALF_WIDTH, 4800);
    let start: Vec<f64> =
        mesh.positions().iter().map(|p| p.x + 0.4 * (std::f64::consts::PI * p.y / HALF_WIDTH).sin() + 0.1 * p.y).collect();
    let spread_before = largest_x_spread(&mesh, &start);
    let mut solver = FieldSolver::new(&mesh, &start, FieldParams::new(Family::Asymptotic)).expect("valid input");
    let before = solver.report().energies.angle;
    let report = solver.step(200).expect("solver runs");
    assert!(report.converged, "not converged after {} iterations", report.iterations);
    assert!(report.singular_vertices.is_empty(), "singular vertices {:?}", report.singular_vertices);
    assert!(report.energies.angle < 0.5 * before, "E_asy {before} -> {}", report.energies.angle);
    let spread_after = largest_x_spread(&mesh, &solver.field());
    // Each level set is a ruling x = const again, to 2 % of its length 2a.
    assert!(spread_before > 1.0, "the start is already straight ({spread_before})");
    assert!(spread_after < 0.02 * 2.0 * HALF_WIDTH, "x spread {spread_before} -> {spread_after}");
}
