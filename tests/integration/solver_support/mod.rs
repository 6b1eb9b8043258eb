//! A least-squares problem made of one residual block given by a closure, for small solver tests.

use lamella::solver::LeastSquaresProblem;

/// `evaluate(x, residuals, jacobian)` writes the residuals and, if asked, the row-major Jacobian
/// with respect to `variables` (in that order).
pub struct OneBlock<F> {
    pub variable_count: usize,
    pub variables: Vec<u32>,
    pub residual_count: usize,
    pub evaluate: F,
}

impl<F: Fn(&[f64], &mut [f64], Option<&mut [f64]>) + Sync> LeastSquaresProblem for OneBlock<F> {
    fn variable_count(&self) -> usize {
        self.variable_count
    }
    fn block_count(&self) -> usize {
        1
    }
    fn block_variables(&self, _b: usize) -> &[u32] {
        &self.variables
    }
    fn block_residual_count(&self, _b: usize) -> usize {
        self.residual_count
    }
    fn evaluate_block(&self, _b: usize, x: &[f64], r: &mut [f64], jacobian: Option<&mut [f64]>) {
        (self.evaluate)(x, r, jacobian)
    }
}
