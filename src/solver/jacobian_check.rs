//! Finite-difference verification of a block's analytic Jacobian.
use super::LeastSquaresProblem;

/// Central-difference check of block `block`'s Jacobian at `x` with step `h`: returns
/// max |∂r_i/∂x_j (analytic) − (r_i(x + h e_j) − r_i(x − h e_j)) / 2h| / max(1, |analytic|).
/// Returns +∞ for an out-of-range block, a wrong length of `x`, a non-positive `h` or
/// non-finite values.
pub fn check_block_jacobian<P: LeastSquaresProblem>(problem: &P, x: &[f64], block: usize, h: f64) -> f64 {
    if block >= problem.block_count() || x.len() != problem.variable_count() || h.is_nan() || h <= 0.0 {
        return f64::INFINITY;
    }
    let variables = problem.block_variables(block);
    let m = problem.block_residual_count(block);
    let n = variables.len();
    if variables.iter().any(|&v| v as usize >= x.len()) {
        return f64::INFINITY;
    }
    let mut residuals = vec![0.0; m];
    let mut jacobian = vec![0.0; m * n];
    problem.evaluate_block(block, x, &mut residuals, Some(&mut jacobian));
    let mut point = x.to_vec();
    let mut plus = vec![0.0; m];
    let mut minus = vec![0.0; m];
    let mut worst: f64 = 0.0;
    for (c, &v) in variables.iter().enumerate() {
        let v = v as usize;
        point[v] = x[v] + h;
        plus.fill(0.0);
        problem.evaluate_block(block, &point, &mut plus, None);
        point[v] = x[v] - h;
        minus.fill(0.0);
        problem.evaluate_block(block, &point, &mut minus, None);
        point[v] = x[v];
        for r in 0..m {
            let analytic = jacobian[r * n + c];
            let numeric = (plus[r] - minus[r]) / (2.0 * h);
            let difference = (analytic - numeric).abs() / analytic.abs().max(1.0);
            if !difference.is_finite() {
                return f64::INFINITY;
            }
            worst = worst.max(difference);
        }
    }
    worst
}

/// [`check_block_jacobian`] over every block of `problem`: the largest error and its block
/// (`(0, 0)` for a problem without blocks).
pub fn worst_block_jacobian<P: LeastSquaresProblem>(problem: &P, x: &[f64], h: f64) -> (f64, usize) {
    (0..problem.block_count()).map(|b| (check_block_jacobian(problem, x, b, h), b)).fold((0.0, 0), |worst, this| if this.0 > worst.0 { this } else { worst })
}
