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
