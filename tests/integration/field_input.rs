//! Bad input to the field optimiser gets a clear error; good input gives the same bits every time.

use crate::field_support;

use field_support::{cylinder, perturbed_height};
use lamella::field::{Family, FieldError, FieldParams, FieldSolver, Stage, Weights};

#[test]
fn wrong_field_length_names_both_counts() {
    let mesh = cylinder(200, 1);
    let err = FieldSolver::new(&mesh, &[0.0; 5], FieldParams::pseudo_geodesic(60.0)).err().expect("refused");
    assert_eq!(err, FieldError::FieldLength { expected: mesh.vertex_count(), actual: 5 });
    assert!(err.to_string().contains(&mesh.vertex_count().to_string()));
}

#[test]
fn non_finite_values_name_the_vertex() {
    let mesh = cylinder(200, 1);
    let mut field = perturbed_height(&mesh);
    field[17] = f64::NAN;
    assert_eq!(FieldSolver::new(&mesh, &field, FieldParams::pseudo_geodesic(60.0)).err(), Some(FieldError::NonFiniteValue { vertex: 17 }));
    field[17] = f64::INFINITY;
    assert_eq!(FieldSolver::new(&mesh, &field, FieldParams::pseudo_geodesic(60.0)).err(), Some(FieldError::NonFiniteValue { vertex: 17 }));
}

#[test]
fn a_constant_field_has_no_level_curves() {
    let mesh = cylinder(200, 1);
    let field = vec![3.0; mesh.vertex_count()];
    assert_eq!(FieldSolver::new(&mesh, &field, FieldParams::pseudo_geodesic(60.0)).err(), Some(FieldError::ConstantField));
}

#[test]
fn out_of_range_parameters_are_named() {
    let mesh = cylinder(200, 1);
    let field = perturbed_height(&mesh);
    let name = |params: FieldParams| match FieldSolver::new(&mesh, &field, params).err() {
        Some(FieldError::InvalidParameter { name, .. }) => name,
        other => panic!("expected a parameter error, got {other:?}"),
    };
    assert_eq!(name(FieldParams::pseudo_geodesic(200.0)), "theta");
    assert_eq!(name(FieldParams::pseudo_geodesic(f64::NAN)), "theta");
    let mut p = FieldParams::pseudo_geodesic(60.0);
    p.weights.angle = -1.0;
    assert_eq!(name(p), "weights.angle");
    let mut p = FieldParams::pseudo_geodesic(60.0);
    p.gradient_target = Some(0.0);
    assert_eq!(name(p), "gradient_target");
    let mut p = FieldParams::pseudo_geodesic(60.0);
    p.schedule = vec![Stage { iterations: 0, weights: Weights { fair: 1.0, grad: 1.0, angle: 1.0 } }];
    assert_eq!(name(p), "schedule");
    let mut p = FieldParams::pseudo_geodesic(60.0);
    p.relative_tolerance = f64::INFINITY;
    assert_eq!(name(p), "relative_tolerance");
}

#[test]
fn set_weights_rejects_bad_values_and_keeps_the_session() {
    let mesh = cylinder(200, 1);
    let mut solver = FieldSolver::new(&mesh, &perturbed_height(&mesh), FieldParams::pseudo_geodesic(60.0)).expect("valid");
    let before = solver.field();
    assert!(solver.set_weights(Weights { fair: f64::NAN, grad: 1.0, angle: 1.0 }).is_err());
    assert_eq!(solver.field(), before);
    assert!(solver.step(2).is_ok());
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let mesh = cylinder(600, 2);
    let field = perturbed_height(&mesh);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("pool");
        pool.install(|| {
            let mut solver = FieldSolver::new(&mesh, &field, FieldParams::new(Family::PseudoGeodesic { theta_degrees: 60.0 })).expect("valid");
            solver.step(25).expect("runs");
            solver.field().iter().map(|v| v.to_bits()).collect::<Vec<u64>>()
        })
    };
    let one = run(1);
    assert_eq!(one, run(2));
    assert_eq!(one, run(1));
}
