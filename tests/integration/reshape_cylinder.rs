//! Surface optimisation (paper Sec. 3.3, Fig. 17): the level sets of a cylinder's 60°
//! pseudo-geodesic field are pulled towards a 45° family by moving the surface, the field held
//! fixed; judged from outside (the level curves resampled at three edge lengths against the
//! mesh's second-order normals), with the deviation checked by a brute-force closest-point
//! search written here.

use crate::field_support;

use field_support::{cylinder, perturbed_height};
use lamella::curves::{extract_level_curves, uniform_levels};
use lamella::field::{Family, FieldParams, FieldSolver};
use lamella::mesh::{TriMesh, Vec3};
use lamella::quality::{family_angles, FamilyAngles, DEFAULT_SPACING_EDGES};
use lamella::reshape::{AlternatingParams, AlternatingSolver, ReshapeError, ReshapeParams, ReshapeSolver, ReshapeWeights, Tolerance};
use std::sync::OnceLock;

/// The cylinder (R = 10, 150°, height 15, 1000 vertices) with its optimised 60° field.
fn sixty_degree_cylinder() -> &'static (TriMesh, Vec<f64>) {
    static CYLINDER: OnceLock<(TriMesh, Vec<f64>)> = OnceLock::new();
    CYLINDER.get_or_init(|| {
        let mesh = cylinder(1000, 11);
        let mut solver = FieldSolver::new(&mesh, &perturbed_height(&mesh), FieldParams::pseudo_geodesic(60.0)).expect("valid input");
        let report = solver.step(300).expect("solver runs");
        assert!(report.converged, "field not converged");
        (mesh, solver.field())
    })
}

/// The outside measure of ten level curves of `field` on `mesh` against θ.
fn outside_measure(mesh: &TriMesh, field: &[f64], theta: f64) -> FamilyAngles {
    outside_measure_at(mesh, field, theta, DEFAULT_SPACING_EDGES)
}

/// [`outside_measure`] with the curves resampled every `edges` mean edge lengths.
fn outside_measure_at(mesh: &TriMesh, field: &[f64], theta: f64, edges: f64) -> FamilyAngles {
    let levels = uniform_levels(mesh, field, 10).expect("valid field");
    let curves = extract_level_curves(mesh, field, &levels).expect("levels in range");
    let (low, high) = mesh.bounding_box();
    let spacing = edges * mesh.mean_edge_length();
    family_angles(&curves, Family::PseudoGeodesic { theta_degrees: theta }, spacing, (high - low).norm()).expect("valid curves")
}

/// Distance from `p` to the segment `a b`.
fn segment_distance(p: &Vec3, a: &Vec3, b: &Vec3) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
    (p - (a + ab * t)).norm()
}

/// Distance from `p` to the triangle `a b c`: to its plane where the foot lies inside (all three
/// edge tests agree with the normal), else to the nearest edge.
fn triangle_distance(p: &Vec3, a: &Vec3, b: &Vec3, c: &Vec3) -> f64 {
    let normal = (b - a).cross(&(c - a)).normalize();
    let foot = p - normal * (p - a).dot(&normal);
    let inside = [(a, b), (b, c), (c, a)].iter().all(|(u, v)| (*v - *u).cross(&(foot - *u)).dot(&normal) >= 0.0);
    if inside {
        (p - foot).norm()
    } else {
        segment_distance(p, a, b).min(segment_distance(p, b, c)).min(segment_distance(p, c, a))
    }
}

/// Distance of every point to the mesh, by trying every face.
pub(crate) fn brute_force_distances(points: &[Vec3], mesh: &TriMesh) -> Vec<f64> {
    let x = mesh.positions();
    points
        .iter()
        .map(|p| mesh.faces().iter().map(|f| triangle_distance(p, &x[f[0] as usize], &x[f[1] as usize], &x[f[2] as usize])).fold(f64::INFINITY, f64::min))
        .collect()
}

/// The settings of the cylinder runs: Table 3's λ_angle and λ_close, with λ_fair 0.05 and λ_edge
/// 0.05, and a tolerance of 5 % of the diagonal. With Table 3's 0.02 and 2e-3 the curves meet θ
/// as well (0.31° RMS from outside) but the edges stretch by 53 % and the curves flatten (28 % of
/// the resampled points straight at the model's scale).
fn cylinder_params() -> ReshapeParams {
    let mut params = ReshapeParams::new(45.0);
    params.weights = ReshapeWeights { fair: 0.05, edge: 0.05, ..ReshapeWeights::default() };
    params.tolerance = Tolerance::DiagonalFraction(0.05);
    params
}

#[test]
fn sixty_degree_family_moves_towards_forty_five_degrees() {
    let (mesh, field) = sixty_degree_cylinder();
    let before = outside_measure(mesh, field, 45.0);
    // The start is the 60° family: 15° off everywhere.
    assert!(before.rms_error_degrees > 14.0 && before.straight == 0, "{before:?}");
    let mut solver = ReshapeSolver::new(mesh, field, cylinder_params()).expect("valid input");
    let report = solver.step(300).expect("solver runs");
    assert!(report.converged, "not converged after {} iterations", report.iterations);
    let moved = solver.mesh();
    let after = outside_measure(&moved, field, 45.0);
    let per_curve: Vec<String> = after.curves.iter().map(|c| format!("{:.1}", c.rms_error_degrees)).collect();
    eprintln!(
        "{} iterations; star measure {:.2}° RMS; outside {:.2}° RMS, {:.2}° max, per curve [{}]; max deviation {:.3} ({:.2} % of the diagonal), largest edge change {:.1} %",
        report.iterations,
        report.angle_error_rms_degrees,
        after.rms_error_degrees,
        after.max_error_degrees,
        per_curve.join(", "),
        report.max_deviation,
        100.0 * report.max_deviation / report.tolerance * 0.05,
        100.0 * report.max_edge_change
    );
    // The paper's target: the curves meet 45° within 1° (measured 0.36° RMS, 1.5° at worst, the
    // worst on the short curve in a corner). Before the normal of the angle rows followed the
    // moving ring and the chords reached three edges: 2.3° RMS, 7.6° at worst.
    assert!(after.rms_error_degrees < 1.0 && after.max_error_degrees < 2.0, "outside {:.2}° RMS, {:.2}° max", after.rms_error_degrees, after.max_error_degrees);
    // Every curve with measured points meets it on its own (measured ≤ 1.1° RMS per curve).
    for (i, curve) in after.curves.iter().enumerate().filter(|(_, c)| c.measured > 0) {
        assert!(curve.rms_error_degrees < 1.5, "curve {i}: {:.2}° RMS", curve.rms_error_degrees);
    }
    // Not only at the scale the optimiser's chords span: resampled every two edges the curves
    // still meet θ (measured 0.74° RMS; the original 60° field there: 0.37°).
    let finer = outside_measure_at(&moved, field, 45.0, 2.0);
    assert!(finer.rms_error_degrees < 1.0, "every two edges: {:.2}° RMS", finer.rms_error_degrees);
    // The curves stay curves: a straight family would satisfy no P-curve angle. Straight at the
    // model's scale are at most two resampled points per curve (measured: the first and last
    // inner points, by the boundary, where no vertex has angle rows; 14 of 94 in all).
    for (i, curve) in after.curves.iter().enumerate() {
        assert!(curve.straight <= 2, "curve {i}: {} of {} points straight", curve.straight, curve.straight + curve.measured);
    }
    assert!(report.max_deviation <= report.tolerance, "deviation {} over the tolerance {}", report.max_deviation, report.tolerance);
    // Measured 20.8 %: a fixed field's curves reach 45° on this cylinder only by stretching.
    assert!(report.max_edge_change <= 0.25, "edge lengths change by {} %", 100.0 * report.max_edge_change);
}

#[test]
fn deviation_figures_are_the_closest_point_distances_to_the_original() {
    let (mesh, field) = sixty_degree_cylinder();
    let mut solver = ReshapeSolver::new(mesh, field, cylinder_params()).expect("valid input");
    let report = solver.step(40).expect("solver runs");
    let independent = brute_force_distances(&solver.positions(), mesh);
    let reported = solver.deviations();
    assert_eq!(reported.len(), mesh.vertex_count());
    for (v, (a, b)) in reported.iter().zip(&independent).enumerate() {
        assert!((a - b).abs() <= 1e-9 * (1.0 + b), "vertex {v}: reported {a}, brute force {b}");
    }
    let max = independent.iter().copied().fold(0.0, f64::max);
    let rms = (independent.iter().map(|d| d * d).sum::<f64>() / independent.len() as f64).sqrt();
    assert!(max > 0.1, "the surface barely moved ({max})");
    assert!((report.max_deviation - max).abs() <= 1e-9 * max, "max {} vs {max}", report.max_deviation);
    assert!((report.rms_deviation - rms).abs() <= 1e-9 * rms, "rms {} vs {rms}", report.rms_deviation);
}

#[test]
fn a_tight_tolerance_holds() {
    let (mesh, field) = sixty_degree_cylinder();
    let mut params = cylinder_params();
    params.tolerance = Tolerance::Absolute(0.05);
    let mut solver = ReshapeSolver::new(mesh, field, params).expect("valid input");
    let report = solver.step(60).expect("solver runs");
    let independent = brute_force_distances(&solver.positions(), mesh).into_iter().fold(0.0, f64::max);
    assert!(independent <= 0.05 + 1e-12, "deviation {independent} over 0.05");
    // The bound was met by the guard on E_close, not because nothing moved.
    assert!(report.guard > 1.0 && independent > 0.02, "guard {}, deviation {independent}", report.guard);
}

#[test]
fn same_input_same_bits() {
    let (mesh, field) = sixty_degree_cylinder();
    let run = || {
        let mut solver = ReshapeSolver::new(mesh, field, cylinder_params()).expect("valid input");
        solver.step(15).expect("solver runs");
        solver.positions()
    };
    assert_eq!(run(), run());
}

#[test]
fn bad_input_names_the_culprit() {
    let (mesh, field) = sixty_degree_cylinder();
    let error = |params: ReshapeParams, field: &[f64]| ReshapeSolver::new(mesh, field, params).err().expect("rejected").to_string();
    let mut nan_theta = cylinder_params();
    nan_theta.theta_degrees = f64::NAN;
    assert!(error(nan_theta, field).contains("theta"));
    let mut negative = cylinder_params();
    negative.tolerance = Tolerance::DiagonalFraction(-0.01);
    assert!(error(negative, field).contains("tolerance"));
    let mut weight = cylinder_params();
    weight.weights.edge = f64::INFINITY;
    assert!(error(weight, field).contains("weights.edge"));
    let mut step = cylinder_params();
    step.max_vertex_step = 0.0;
    assert!(error(step, field).contains("max_vertex_step"));
    assert!(error(cylinder_params(), &field[1..]).contains("values"));
    let mut broken = field.clone();
    broken[7] = f64::NAN;
    assert!(error(cylinder_params(), &broken).contains("vertex 7"));
    let constant = vec![1.0; mesh.vertex_count()];
    assert!(matches!(ReshapeSolver::new(mesh, &constant, cylinder_params()), Err(ReshapeError::Field(_))));
}

#[test]
fn alternating_schedule_keeps_the_tolerance() {
    let (mesh, field) = sixty_degree_cylinder();
    let mut params = AlternatingParams::new(45.0);
    params.reshape = cylinder_params();
    params.reshape.tolerance = Tolerance::DiagonalFraction(0.01);
    params.iterations_per_step = 30;
    let mut solver = AlternatingSolver::new(mesh, field, params).expect("valid input");
    // Stepwise: one round, then two more; the state in between is a whole round's.
    let first = solver.step(1).expect("runs");
    assert_eq!((first.rounds, first.rounds_this_step), (1, 1));
    for (v, (a, b)) in solver.deviations().iter().zip(brute_force_distances(solver.mesh().positions(), mesh)).enumerate() {
        assert!((a - b).abs() <= 1e-9 * (1.0 + b), "vertex {v}: reported {a}, brute force {b}");
    }
    let report = solver.step(2).expect("runs");
    assert_eq!(report.rounds, first.rounds + report.rounds_this_step);
    let after = outside_measure(solver.mesh(), solver.field(), 45.0);
    let deviation = brute_force_distances(solver.mesh().positions(), mesh).into_iter().fold(0.0, f64::max);
    let (low, high) = mesh.bounding_box();
    eprintln!("alternating: {} rounds, converged {}; outside {:.2}° RMS, {:.2}° max, straight fraction {:.3}; deviation {deviation:.3}", report.rounds, report.converged, after.rms_error_degrees, after.max_error_degrees, after.straight_fraction());
    assert!(deviation <= 0.01 * (high - low).norm() + 1e-12, "deviation {deviation}");
    assert!((report.surface.max_deviation - deviation).abs() <= 1e-9 * deviation.max(1.0));
    // The field steps are free to reach 45° on the cylinder (the family exists there). Measured:
    // 0.33° RMS, 0.91° at worst after two rounds; the straight points are those of the short
    // corner curves.
    assert!(after.rms_error_degrees < 1.0 && after.max_error_degrees < 2.0, "{after:?}");
    assert!(after.measured > 50 && after.straight_fraction() < 0.25, "measured {}, straight {}", after.measured, after.straight);
}

#[test]
fn alternating_rejects_bad_input_by_name() {
    let (mesh, field) = sixty_degree_cylinder();
    let mut params = AlternatingParams::new(45.0);
    params.iterations_per_step = 0;
    let error = AlternatingSolver::new(mesh, field, params).err().expect("rejected").to_string();
    assert!(error.contains("iterations_per_step"), "{error}");
    let mut nan = field.clone();
    nan[3] = f64::NAN;
    let error = AlternatingSolver::new(mesh, &nan, AlternatingParams::new(45.0)).err().expect("rejected").to_string();
    assert!(error.contains("vertex 3"), "{error}");
}
