//! Constant-slope families (paper Sec. 5.2.3, Eq. 22) on the vault z = h(1 − (x/a)²)(1 − (y/b)²):
//! the level curves' tangents keep the slope β against the planes orthogonal to the axis d
//! wherever the tangent planes are steep enough, measured on the extracted level curves (chords
//! every three edges) against the vault's exact normal.

use lamella::curves::{extract_level_curves, uniform_levels};
use lamella::field::{reachable_boundary, slope_reachable, tangent_plane_inclination_degrees, Family, FieldError, FieldParams, FieldSolver, ISOPHOTE_MARGIN_DEGREES};
use lamella::initialisation::{slope_start_field, SearchOptions, StartSearch};
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{vault, Vault};

const SURFACE: Vault = Vault { half_length: 5.0, half_width: 4.0, rise: 3.0, target_vertices: 4000, irregularity: 0.25, seed: 7 };
/// Tilted 53° from the vertical towards +x: the flank x > 0 is too flat for β = 30° there.
const TILTED: [f64; 3] = [0.8, 0.0, 0.6];

fn vault_mesh(target_vertices: usize) -> TriMesh {
    vault(&Vault { target_vertices, ..SURFACE }).expect("valid vault").into_mesh().expect("valid mesh")
}

/// The exact upward unit normal of the vault at (x, y).
fn vault_normal(p: &Vec3) -> Vec3 {
    let (a, b, h) = (SURFACE.half_length, SURFACE.half_width, SURFACE.rise);
    let (u, v) = (1.0 - (p.x / a).powi(2), 1.0 - (p.y / b).powi(2));
    Vec3::new(2.0 * h * p.x / (a * a) * v, 2.0 * h * p.y / (b * b) * u, 1.0).normalize()
}

/// Slopes asin|t·d| in degrees at the inner points of 15 level curves of `field` resampled every
/// three mean edges (t: the chord between the neighbours), where the exact normal reaches β; and
/// the number of inner points that do not.
fn curve_slopes(mesh: &TriMesh, field: &[f64], axis: &Vec3, slope: f64) -> (Vec<f64>, usize) {
    let levels = uniform_levels(mesh, field, 15).expect("levels");
    let curves = extract_level_curves(mesh, field, &levels).expect("curves");
    let (mut slopes, mut unreachable) = (Vec::new(), 0);
    for curve in &curves {
        let points = curve.resampled(3.0 * mesh.mean_edge_length()).expect("valid spacing").points;
        for w in points.windows(3) {
            if slope_reachable(&vault_normal(&w[1]), axis, slope) {
                slopes.push((w[2] - w[0]).normalize().dot(axis).abs().asin().to_degrees());
            } else {
                unreachable += 1;
            }
        }
    }
    (slopes, unreachable)
}

fn max_error(slopes: &[f64], slope: f64) -> f64 {
    slopes.iter().map(|s| (s - slope.abs()).abs()).fold(0.0, f64::max)
}

fn solve(mesh: &TriMesh, family: Family, start: &[f64]) -> FieldSolver {
    let mut solver = FieldSolver::new(mesh, start, FieldParams::new(family)).expect("valid input");
    let report = solver.step(200).expect("solver runs");
    assert!(report.converged, "not converged after {} iterations", report.iterations);
    solver
}

#[test]
fn a_vault_field_keeps_the_slope_to_half_a_degree_where_reachable() {
    let mesh = vault_mesh(SURFACE.target_vertices);
    let (axis, slope) = (Vec3::from(TILTED).normalize(), 30.0);
    let start = slope_start_field(&mesh, TILTED, slope).expect("start");
    let solver = solve(&mesh, Family::ConstantSlope { axis: TILTED, slope_degrees: slope, free_slope: false }, &start);
    let (before, _) = curve_slopes(&mesh, &start, &axis, slope);
    let (after, unreachable) = curve_slopes(&mesh, &solver.field(), &axis, slope);
    // Measured 0.46° (4,000 vertices; 0.81° at 3,000, 2.7° at 1,200, README).
    assert!(max_error(&before, slope) > 1.0, "the start already has the slope ({}°)", max_error(&before, slope));
    assert!(max_error(&after, slope) <= 0.5, "slope error up to {}° over {} points", max_error(&after, slope), after.len());
    assert!(after.len() > 150, "only {} points measured", after.len());
    // The flank beyond the isophote is skipped, and its boundary reported.
    assert!(unreachable > 0, "no curve point beyond the isophote");
    let boundary = reachable_boundary(&mesh, &axis, slope).expect("isophote");
    assert!(!boundary.is_empty(), "no isophote reported");
    for p in boundary.iter().flat_map(|c| &c.points) {
        let psi = tangent_plane_inclination_degrees(&vault_normal(p), &axis);
        assert!((psi - slope - ISOPHOTE_MARGIN_DEGREES).abs() < 1.0, "isophote point {p:?} has inclination {psi}°");
    }
}

#[test]
fn a_free_slope_settles_on_the_slope_its_curves_have() {
    let mesh = vault_mesh(1200);
    let axis = [1.0, 0.0, 0.0];
    // Started from the 30° directions but asked to start at 26°: the fitted slope follows the field.
    let start = slope_start_field(&mesh, axis, 30.0).expect("start");
    let solver = solve(&mesh, Family::ConstantSlope { axis, slope_degrees: 26.0, free_slope: true }, &start);
    let fitted = solver.slope_degrees().expect("a slope family");
    let (slopes, _) = curve_slopes(&mesh, &solver.field(), &Vec3::x(), fitted);
    let mean = slopes.iter().sum::<f64>() / slopes.len() as f64;
    assert!(fitted > 27.0 && fitted < 33.0, "fitted slope {fitted}°");
    assert!((mean - fitted).abs() < 0.5, "the curves' mean slope {mean}° against the fitted {fitted}°");
    assert!(max_error(&slopes, fitted) < 1.5, "slope error up to {}°", max_error(&slopes, fitted));
}

#[test]
fn bad_axes_and_slopes_are_refused_by_name() {
    let mesh = vault_mesh(300);
    let field: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
    for (axis, slope, name) in [([0.0, 0.0, 0.0], 30.0, "axis"), ([f64::NAN, 0.0, 1.0], 30.0, "axis"), ([0.0, 0.0, 1.0], 90.0, "slope"), ([0.0, 0.0, 1.0], f64::INFINITY, "slope")] {
        let family = Family::ConstantSlope { axis, slope_degrees: slope, free_slope: false };
        match FieldSolver::new(&mesh, &field, FieldParams::new(family)) {
            Err(FieldError::InvalidParameter { name: got, .. }) => assert_eq!(got, name),
            Err(other) => panic!("{axis:?}, {slope}: {other}"),
            Ok(_) => panic!("{axis:?}, {slope} accepted"),
        }
        assert!(slope_start_field(&mesh, axis, slope).is_err(), "start for {axis:?}, {slope} accepted");
    }
    // A slope steeper than any tangent plane of the vault (its steepest is 50° against the horizontal).
    assert!(slope_start_field(&mesh, [0.0, 0.0, 1.0], 70.0).is_err());
}

#[test]
fn the_start_search_refuses_a_constant_slope_family_by_name() {
    let mesh = vault_mesh(300);
    let family = Family::ConstantSlope { axis: [0.0, 0.0, 1.0], slope_degrees: 30.0, free_slope: false };
    match StartSearch::new(&mesh, FieldParams::new(family), SearchOptions::default()) {
        Err(FieldError::InvalidParameter { name, message }) => {
            assert_eq!(name, "family");
            assert!(message.contains("slope_start_field"), "{message}");
        }
        Err(other) => panic!("refused for another reason: {other}"),
        Ok(_) => panic!("the search accepted a constant-slope family"),
    }
}
