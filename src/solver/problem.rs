//! The sum-of-squares problem interface driven by [`super::LevenbergMarquardt`].
use super::VariableLayout;
use std::sync::atomic::{AtomicU64, Ordering};

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
    /// Whether block `b`'s residuals are linear in x, so that its Jacobian does not depend on x
    /// (it may depend on the problem's weights; see [`Self::constant_jacobian_revision`]). The
    /// solver then forms its Gram product JᵀJ once and reuses it while the revision stays the
    /// same, evaluating only residuals and Jᵀr (blocks touching a local group are accumulated in
    /// full every iteration all the same). Fixed for the life of the problem, like the block's
    /// variables (it decides how the block is stored; the solver refuses a problem whose answer
    /// changed with [`super::SolverError::ProblemChanged`]). Default: no block is.
    fn block_jacobian_is_constant(&self, _b: usize) -> bool {
        false
    }
    /// A value that changes whenever anything the constant Jacobians of
    /// [`Self::block_jacobian_is_constant`] depend on changes (weights, say), and differs between
    /// problem instances: take it from [`new_revision`] when the problem is made and again on
    /// every such change.
    fn constant_jacobian_revision(&self) -> u64 {
        0
    }
    /// Optional Schur elimination: variables [global_count..variable_count) are split into small
    /// contiguous local groups (e.g. the 6 auxiliaries of one vertex); every block touches at most
    /// one local group. Default: no local variables.
    fn variable_layout(&self) -> VariableLayout {
        VariableLayout::all_global(self.variable_count())
    }
}

/// A revision number no other call returns (in this process), for
/// [`LeastSquaresProblem::constant_jacobian_revision`].
pub fn new_revision() -> u64 {
    static NEXT: AtomicU64 = AtomicU64::new(1);
    NEXT.fetch_add(1, Ordering::Relaxed)
}
