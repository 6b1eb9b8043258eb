//! Sparse nonlinear least-squares engine: adaptive Levenberg–Marquardt with a fixed sparsity
//! pattern, Schur elimination of small local variable groups, a sparse Cholesky (faer) split
//! into two domains factorised at the same time, and deterministic parallel assembly. It drives
//! the level-set field optimisation of the paper (Sec. 3.2.2, Eq. 8–12: one scalar per vertex
//! plus the per-vertex auxiliaries b, u).
mod assembly;
mod bisection;
mod error;
mod evaluation;
mod jacobian_check;
mod layout;
mod levenberg_marquardt;
mod normal_pattern;
mod options;
mod outcome;
mod packed_upper;
mod problem;
mod schur;
mod segments;
mod sparse_cholesky;
mod structure;
mod substructured_cholesky;

pub use error::SolverError;
pub use jacobian_check::{check_block_jacobian, worst_block_jacobian};
pub use layout::VariableLayout;
pub use levenberg_marquardt::{DampingState, LevenbergMarquardt};
pub use options::LmOptions;
pub use outcome::{Convergence, IterationOutcome};
pub use problem::{new_revision, LeastSquaresProblem};
pub(crate) use substructured_cholesky::SplitWork;
