//! The sum-of-squares problem interface driven by [`super::LevenbergMarquardt`].
use super::VariableLayout;

/// A sum of squared residual blocks: E(x) = Σ_b ‖r_b(x)‖² (no factor 1/2; weights are folded
/// into the residuals by the problem).
pub trait LeastSquaresProblem: Sync {
    fn variable_count(&self) -> usize;
    fn block_count(&self) -> usize;
    /// Variables block `b` may depend on. Fixed for the life of the problem: it defines the
    /// sparsity pattern, so a block declares every variable it could ever touch (Jacobian entries
    /// may be zero). No duplicates.
    fn block_variables(&self, b: usize) -> &[u32];
    fn block_residual_count(&self, b: usize) -> usize;
    /// Residuals of block `b` at `x` into `residuals` (len = block_residual_count), and if
    /// `jacobian` is Some, ∂r/∂x for its variables, row-major: residual_count rows ×
    /// block_variables(b).len() columns. The engine zeroes both buffers before the call.
    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>);
    /// Optional Schur elimination: variables [global_count..variable_count) are split into small
    /// contiguous local groups (e.g. the 6 auxiliaries of one vertex); every block touches at most
    /// one local group. Default: no local variables.
    fn variable_layout(&self) -> VariableLayout {
        VariableLayout::all_global(self.variable_count())
    }
}
