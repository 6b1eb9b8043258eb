//! Rectifying strips on doubly curved roofs — the vault z = h(1 − (x/a)²)(1 − (y/b)²) and the hall
//! roof (dome-like in the middle, saddle-like towards the gable ends): every strip made of planar
//! quads, unrolled straight, no flipped quads.

mod strips_support;

use lamella::curves::{extract_level_curves, uniform_levels, LevelCurve};
use lamella::field::{FieldParams, FieldSolver};
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::{rectifying_strips, StripParams};
use lamella::surfaces::{hall_roof, vault, Vault};
use strips_support::unroll_quad_by_quad;

const THETA: f64 = 60.0;

/// Unit normal of the mesh vertex nearest to `p` (a coarse, independent surface normal).
fn nearest_vertex_normal(mesh: &TriMesh, p: &Vec3) -> Vec3 {
    let nearest = (0..mesh.vertex_count())
        .min_by(|&a, &b| (mesh.positions()[a] - p).norm().total_cmp(&(mesh.positions()[b] - p).norm()))
        .expect("non-empty mesh");
    mesh.vertex_normals()[nearest]
}

#[test]
fn vault_strips_are_planar_straight_and_consistently_oriented() {
    let surface = Vault { half_length: 10.0, half_width: 7.0, rise: 4.0, target_vertices: 2000, irregularity: 0.25, seed: 5 };
    // The issue asks planar, straight and unflipped here; the angle bound is the CLI's 2°.
    assert_fabricable_pattern(&vault(&surface).expect("valid vault").into_mesh().expect("valid mesh"), "vault", 2.0, 0.2);
}

#[test]
fn hall_roof_strips_are_planar_straight_and_consistently_oriented() {
    assert_fabricable_pattern(&hall_roof(3000).into_mesh().expect("valid mesh"), "hall roof", 1.5, 0.6);
}

/// `width` must stay below where neighbouring rulings cross (the strips' own warning says where).
fn assert_fabricable_pattern(mesh: &TriMesh, name: &str, max_diff_theta: f64, width: f64) {
    let mesh = mesh.clone();
    // Level sets start as the sections x = const and are optimised into 60° pseudo-geodesics.
    let initial: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
    let mut solver = FieldSolver::new(&mesh, &initial, FieldParams::pseudo_geodesic(THETA)).expect("valid input");
    let report = solver.step(300).expect("solver runs");
    assert!(report.converged && report.singular_vertices.is_empty());
    let field = solver.field();
    let levels = uniform_levels(&mesh, &field, 10).expect("valid field");
    let curves: Vec<LevelCurve> = extract_level_curves(&mesh, &field, &levels)
        .expect("levels in range")
        .iter()
        .map(|c| c.resampled(mesh.mean_edge_length()).expect("valid spacing"))
        .collect();
    assert_eq!(curves.len(), 10, "one arch-crossing curve per level");
    let pattern = rectifying_strips(&mesh, &curves, &StripParams::new(THETA, width)).expect("valid parameters");
    assert!(pattern.skipped.is_empty(), "skipped {:?}", pattern.skipped);
    let m = pattern.metrics;
    eprintln!("{name} Table 4: {m:?}");
    assert_eq!(m.strip_count, 10);
    assert!(m.max_planar <= 1e-6, "max planarity residual {}", m.max_planar);
    assert!(m.max_e_straight <= 1e-3, "max e_straight {}", m.max_e_straight);
    assert!(m.max_diff_theta_degrees <= max_diff_theta, "max diff θ {}°", m.max_diff_theta_degrees);
    assert!(m.appro_percent <= 0.1, "Appro {} %", m.appro_percent);
    assert_eq!(m.flipped_quads, 0);
    for strip in &pattern.strips {
        assert!(strip.warnings.is_empty(), "level {}: {:?}", strip.level, strip.warnings);
        let (planarity, straightness) = unroll_quad_by_quad(&strip.centre, &strip.left, &strip.right);
        assert!(planarity <= 1e-6, "level {}: quad off its plane by {planarity}", strip.level);
        assert!(straightness <= 1e-3, "level {}: unrolled centre line bends by {straightness}", strip.level);
        // No flipped quads, along or across strips: every ruling on the outer side of the roof,
        // every quad turning the same way as its neighbour.
        for (i, (c, d)) in strip.centre.iter().zip(&strip.rulings).enumerate() {
            assert!(d.dot(&nearest_vertex_normal(&mesh, c)) > 0.0, "level {}: ruling {i} points inwards", strip.level);
        }
        let quad_normals: Vec<Vec3> = (0..strip.centre.len() - 1)
            .map(|j| (strip.centre[j + 1] - strip.centre[j]).cross(&(strip.left[j] - strip.centre[j])))
            .collect();
        assert!(quad_normals.windows(2).all(|w| w[0].dot(&w[1]) > 0.0), "level {}: a quad flips", strip.level);
    }
}
