//! check_block_jacobian against analytic derivatives: passes a right Jacobian, flags a wrong one.
use crate::solver_support;

use lamella::solver::{check_block_jacobian, LeastSquaresProblem};
use solver_support::OneBlock;

/// One block r = (sin(x0) x1, x0² + exp(x1)) over the variables (x2, x0) of three;
/// `wrong` perturbs ∂r1/∂x1.
fn smooth(wrong: bool) -> impl LeastSquaresProblem {
    OneBlock {
        variable_count: 3,
        variables: vec![2, 0],
        residual_count: 2,
        evaluate: move |x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>| {
            let (x0, x1) = (x[2], x[0]);
            r[0] = x0.sin() * x1;
            r[1] = x0 * x0 + x1.exp();
            if let Some(j) = jacobian {
                let d = if wrong { 1.1 } else { 1.0 };
                j.copy_from_slice(&[x0.cos() * x1, x0.sin(), 2.0 * x0, d * x1.exp()]);
            }
        },
    }
}

#[test]
fn right_jacobian_passes_and_wrong_one_is_detected() {
    let x = [0.4, 7.0, -0.8];
    assert!(check_block_jacobian(&smooth(false), &x, 0, 1e-6) < 1e-6);
    assert!(check_block_jacobian(&smooth(true), &x, 0, 1e-6) > 0.05);
}

#[test]
fn invalid_arguments_give_infinity() {
    let p = smooth(false);
    assert_eq!(check_block_jacobian(&p, &[0.0; 3], 1, 1e-6), f64::INFINITY);
    assert_eq!(check_block_jacobian(&p, &[0.0; 2], 0, 1e-6), f64::INFINITY);
    assert_eq!(check_block_jacobian(&p, &[0.0; 3], 0, 0.0), f64::INFINITY);
}
