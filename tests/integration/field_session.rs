//! Saving and restoring a field optimisation.

use crate::field_support;

use field_support::{cylinder, perturbed_height};
use lamella::field::{FieldError, FieldParams, FieldSolver, SESSION_VERSION};

fn started_solver() -> FieldSolver {
    let mesh = cylinder(400, 3);
    let mut solver = FieldSolver::new(&mesh, &perturbed_height(&mesh), FieldParams::pseudo_geodesic(60.0)).expect("valid input");
    solver.step(12).expect("solver runs");
    solver
}

fn bits(values: &[f64]) -> Vec<u64> {
    values.iter().map(|v| v.to_bits()).collect()
}

#[test]
fn a_restored_session_continues_bit_for_bit() {
    let mut original = started_solver();
    let bytes = original.to_bytes();
    let mut restored = FieldSolver::from_bytes(&bytes).expect("restores");
    assert_eq!(restored.to_bytes(), bytes, "save → load → save is not the identity");
    assert_eq!(bits(&restored.field()), bits(&original.field()));
    assert_eq!(restored.report(), original.report());
    let a = original.step(15).expect("continues");
    let b = restored.step(15).expect("continues");
    assert_eq!(a, b);
    assert_eq!(bits(&restored.field()), bits(&original.field()));
    let (ba, bb) = (original.binormals(), restored.binormals());
    assert!(ba.iter().zip(&bb).all(|(x, y)| x == y));
}

/// The start search probes its candidates on two solvers, each restarted for its next
/// candidate: a candidate's probe must not depend on which solver ran it, or on what it ran before.
#[test]
fn a_restarted_solver_solves_as_a_new_one_does() {
    let mesh = cylinder(400, 3);
    let other: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.3 * p.z).collect();
    let mut params = FieldParams::pseudo_geodesic(60.0);
    params.gradient_target = Some(1.5);
    let mut restarted = started_solver();
    restarted.restart(&other, params.clone()).expect("restarts");
    let mut new = FieldSolver::new(&mesh, &other, params).expect("valid input");
    assert_eq!(restarted.report(), new.report());
    let (a, b) = (restarted.step(15).expect("solver runs"), new.step(15).expect("solver runs"));
    assert_eq!(a, b);
    assert_eq!(bits(&restarted.field()), bits(&new.field()));
    assert!(a.angle_error_max_degrees < 90.0 && a.iterations == 15, "the restarted solve did not run: {a:?}");
}

#[test]
fn truncated_data_is_reported_not_trusted() {
    let bytes = started_solver().to_bytes();
    for cut in [0, 3, 7, 8, 9, bytes.len() / 2, bytes.len() - 1] {
        match FieldSolver::from_bytes(&bytes[..cut]) {
            Err(FieldError::CorruptData { .. }) => {}
            other => panic!("cut at {cut}: {:?}", other.map(|_| "a solver")),
        }
    }
}

#[test]
fn corrupted_bytes_never_panic() {
    let bytes = started_solver().to_bytes();
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    for _ in 0..300 {
        let mut damaged = bytes.clone();
        for _ in 0..4 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let at = 8 + (state as usize) % (damaged.len() - 8);
            damaged[at] ^= (state >> 40) as u8 | 1;
        }
        // Either a clean error or a consistent solver that can step without NaN.
        if let Ok(mut solver) = FieldSolver::from_bytes(&damaged) {
            if let Ok(report) = solver.step(1) {
                assert!(report.energies.total.is_finite() || report.energies.total.is_infinite());
            }
        }
    }
}

#[test]
fn other_formats_are_refused_by_name() {
    let mut bytes = started_solver().to_bytes();
    bytes[4..8].copy_from_slice(&(SESSION_VERSION + 1).to_le_bytes());
    assert!(matches!(FieldSolver::from_bytes(&bytes), Err(FieldError::UnsupportedVersion { found, .. }) if found == SESSION_VERSION + 1));
    bytes[0] = b'X';
    assert!(matches!(FieldSolver::from_bytes(&bytes), Err(FieldError::CorruptData { .. })));
}
