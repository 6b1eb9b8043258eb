//! Every residual of the field problem (Eq. 6, 8–11, 13) against finite differences.

use crate::field_support;

use field_support::{cylinder, perturbed_height};
use lamella::field::{Family, FieldProblem, Weights};
use lamella::solver::{check_block_jacobian, LeastSquaresProblem};
use lamella::surfaces::SplitMix64;

/// A state with a generic field and auxiliaries that are not yet unit or orthogonal.
fn state(problem: &FieldProblem, field: &[f64]) -> Vec<f64> {
    let mut rng = SplitMix64::new(99);
    let mut x = field.to_vec();
    x.resize(problem.variable_count(), 0.0);
    for value in &mut x[field.len()..] {
        *value = rng.symmetric(1.0);
    }
    x
}

fn check_all_blocks(family: Family) -> usize {
    let (mesh, _) = cylinder(300, 4).unit_scaled();
    let field = perturbed_height(&mesh);
    let weights = Weights { fair: 0.7, grad: 0.3, angle: 2.0 };
    let problem = FieldProblem::new(mesh, family, weights, 0.8);
    let x = state(&problem, &field);
    let mut checked = 0;
    for block in 0..problem.block_count() {
        let error = check_block_jacobian(&problem, &x, block, 1e-6);
        assert!(error < 1e-6, "{family:?}: block {block} Jacobian off by {error}");
        checked += 1;
    }
    checked
}

#[test]
fn pseudo_geodesic_rows_match_finite_differences() {
    assert!(check_all_blocks(Family::PseudoGeodesic { theta_degrees: 60.0 }) > 500);
}

#[test]
fn geodesic_rows_match_finite_differences() {
    assert!(check_all_blocks(Family::Geodesic) > 500);
}

#[test]
fn asymptotic_rows_match_finite_differences() {
    assert!(check_all_blocks(Family::Asymptotic) > 500);
}

/// The blocks the field problem declares constant (for the solver to evaluate their Jacobians once
/// per weight stage) are linear: the same Jacobian at two unrelated states, and residuals that
/// move by exactly J·Δx; and a change of weights gives a new revision.
#[test]
fn declared_constant_blocks_are_linear_and_follow_the_weights() {
    let (mesh, _) = cylinder(300, 4).unit_scaled();
    let field = perturbed_height(&mesh);
    let weights = Weights { fair: 0.7, grad: 0.3, angle: 2.0 };
    let mut problem = FieldProblem::new(mesh, Family::PseudoGeodesic { theta_degrees: 60.0 }, weights, 0.8);
    let x = state(&problem, &field);
    let mut rng = SplitMix64::new(7);
    let y: Vec<f64> = x.iter().map(|v| v + rng.symmetric(0.5)).collect();
    let mut declared = 0;
    for b in (0..problem.block_count()).filter(|&b| problem.block_jacobian_is_constant(b)) {
        let (m, n) = (problem.block_residual_count(b), problem.block_variables(b).len());
        let evaluate = |at: &[f64]| {
            let (mut r, mut j) = (vec![0.0; m], vec![0.0; m * n]);
            problem.evaluate_block(b, at, &mut r, Some(&mut j));
            (r, j)
        };
        let ((rx, jx), (ry, jy)) = (evaluate(&x), evaluate(&y));
        assert_eq!(jx, jy, "block {b}: the Jacobian depends on the state");
        for (row, (a, c)) in rx.iter().zip(&ry).enumerate() {
            let step: f64 = problem.block_variables(b).iter().enumerate().map(|(k, &v)| jx[row * n + k] * (y[v as usize] - x[v as usize])).sum();
            assert!((c - a - step).abs() <= 1e-9 * (1.0 + c.abs()), "block {b} row {row}: not linear ({a} → {c}, J·Δx = {step})");
        }
        declared += 1;
    }
    // Every vertex's fairness block and every curve vertex's fit block; never a curve block.
    let curves = problem.curve_vertices().len();
    assert_eq!(declared, problem.mesh().vertex_count() + curves);
    assert!((0..problem.block_count()).filter(|&b| !problem.block_jacobian_is_constant(b)).count() >= curves);
    let revision = problem.constant_jacobian_revision();
    problem.set_weights(Weights { fair: 0.2, ..weights });
    assert_ne!(problem.constant_jacobian_revision(), revision);
}
