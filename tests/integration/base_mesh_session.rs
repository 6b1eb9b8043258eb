//! Saved base-mesh sessions (paper Sec. 3.5, Eq. 21) on the perturbed net of ±45° helices of a
//! cylinder with torsion-free nodes: a session saved in either stage (the families alone, then
//! with the torsion-free rows) and restored steps on to the very bits of the uninterrupted one;
//! damaged, foreign and future-version bytes are errors, never a panic.

use crate::base_mesh_optimisation::helix_net;
use lamella::base_mesh::{BaseMeshError, BaseMeshParams, BaseMeshSolver, BASE_MESH_SESSION_MAGIC, BASE_MESH_SESSION_VERSION};
use lamella::field::{Family, FieldError};
use lamella::net::{NetSolver, NET_SESSION_MAGIC};

fn solver() -> BaseMeshSolver {
    let (net, surface) = helix_net(0.02);
    let mut params = BaseMeshParams::new(Family::Geodesic, Family::Geodesic);
    params.torsion_free = true;
    BaseMeshSolver::new(&net, &surface, params).expect("solver")
}

fn bits(solver: &BaseMeshSolver) -> Vec<u64> {
    solver.positions().iter().flat_map(|p| p.iter().map(|x| x.to_bits()).collect::<Vec<_>>()).collect()
}

/// Saves `original`, restores it and steps both on by 1 and 5 iterations: the same reports and
/// the same bits throughout.
fn restored_steps_in_step(original: &mut BaseMeshSolver) {
    let bytes = original.to_bytes();
    assert_eq!(bytes[..4], BASE_MESH_SESSION_MAGIC);
    let mut restored = BaseMeshSolver::from_bytes(&bytes).expect("restores");
    assert_eq!(restored.to_bytes(), bytes, "saving the restored session gives the same bytes");
    assert_eq!(restored.report(), original.report());
    assert_eq!(restored.initial_report(), original.initial_report());
    assert_eq!(bits(&restored), bits(&original));
    assert_eq!(restored.given_net(), original.given_net());
    for iterations in [1, 5] {
        let (a, b) = (original.step(iterations).expect("steps"), restored.step(iterations).expect("steps"));
        assert_eq!(a, b);
        assert_eq!(bits(&restored), bits(&original), "after {} iterations", a.iterations);
    }
    assert_eq!(restored.nodes(), original.nodes());
}

#[test]
fn a_restored_session_continues_bit_for_bit_in_both_stages() {
    let mut original = solver();
    original.step(5).expect("steps");
    assert!(!original.report().torsion_free_stage, "5 iterations do not settle the families");
    restored_steps_in_step(&mut original);
    while !original.report().torsion_free_stage {
        assert!(original.iterations() < 300, "the families did not settle: {:?}", original.report());
        original.step(1).expect("steps");
    }
    let started = original.iterations();
    restored_steps_in_step(&mut original);
    assert!(original.report().torsion_free_stage && !original.is_converged() && original.iterations() == started + 6, "{:?}", original.report());
}

#[test]
fn damaged_foreign_and_future_bytes_are_errors_never_a_panic() {
    let mut solver = solver();
    solver.step(3).expect("steps");
    let bytes = solver.to_bytes();
    let corrupt = |b: &[u8]| match BaseMeshSolver::from_bytes(b) {
        Err(BaseMeshError::CorruptData { message }) => message,
        other => panic!("not corrupt data: {:?}", other.map(|s| s.iterations())),
    };
    assert!(corrupt(&[]).contains("not a Lamella base-mesh session"));
    for cut in [4, 8, 100, bytes.len() / 2, bytes.len() - 1] {
        corrupt(&bytes[..cut]);
    }
    let mut net_session = bytes.clone();
    net_session[..4].copy_from_slice(&NET_SESSION_MAGIC);
    assert!(corrupt(&net_session).contains("not a Lamella base-mesh session"), "a net session is not a base-mesh session");
    assert!(matches!(NetSolver::from_bytes(&bytes), Err(FieldError::CorruptData { .. })), "nor the other way round");
    let mut future = bytes.clone();
    future[4..8].copy_from_slice(&(BASE_MESH_SESSION_VERSION + 1).to_le_bytes());
    let error = BaseMeshSolver::from_bytes(&future).err().expect("refused");
    assert_eq!(error, BaseMeshError::UnsupportedVersion { found: BASE_MESH_SESSION_VERSION + 1, supported: BASE_MESH_SESSION_VERSION });
    assert!(error.to_string().contains("version 2"), "{error}");
    // A byte flipped in turn, on a sample of positions through the whole session and at every
    // position of its tail (the last report's deviation, node torsion and verdicts): an error or
    // a valid session.
    let tail = bytes.len() - 80;
    let positions = (8..tail).step_by(tail / 40).chain(tail..bytes.len());
    let (mut refused, mut accepted) = (0, 0);
    for i in positions {
        let mut damaged = bytes.clone();
        damaged[i] ^= 0x5A;
        match BaseMeshSolver::from_bytes(&damaged) {
            Ok(mut restored) => {
                accepted += 1;
                assert!(restored.positions().iter().all(|p| p.iter().all(|v| v.is_finite())), "byte {i}");
                let _ = restored.step(1);
            }
            Err(BaseMeshError::CorruptData { message }) => {
                refused += 1;
                assert!(!message.is_empty() && message.len() < 2000, "byte {i}: {message}");
            }
            Err(other) => panic!("byte {i}: {other}"),
        }
    }
    assert!(refused > 20 && accepted > 20, "{refused} damaged sessions refused, {accepted} accepted");
}
