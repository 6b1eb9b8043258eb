//! Errors reported by the least-squares engine.
use std::fmt;

/// Why a problem could not be set up or iterated.
#[derive(Clone, Debug, PartialEq)]
pub enum SolverError {
    /// The variable layout is inconsistent (group sizes, counts).
    InvalidLayout { message: String },
    /// Block `block` declares an invalid structure (index out of range, duplicate variable,
    /// more than one local group, ...).
    InvalidProblem { block: usize, message: String },
    /// The variable vector does not have the problem's number of variables.
    WrongVariableCount { expected: usize, found: usize },
    /// The problem's counts changed since [`super::LevenbergMarquardt::new`].
    ProblemChanged { message: String },
    /// The residuals of `block` are not finite at the current variables.
    NonFiniteResidual { block: usize },
    /// The Jacobian of `block` is not finite at the current variables.
    NonFiniteJacobian { block: usize },
    /// No trial of an iteration produced a numerical factorisation, even with increased damping.
    FactorizationFailed { trials: usize },
    /// The symbolic analysis of the reduced normal matrix failed (e.g. out of memory).
    SymbolicAnalysisFailed { message: String },
}

impl fmt::Display for SolverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidLayout { message } => write!(f, "invalid variable layout: {message}"),
            Self::InvalidProblem { block, message } => {
                write!(f, "invalid residual block {block}: {message}")
            }
            Self::WrongVariableCount { expected, found } => {
                write!(f, "expected {expected} variables, found {found}")
            }
            Self::ProblemChanged { message } => {
                write!(f, "problem changed since the solver was built: {message}")
            }
            Self::NonFiniteResidual { block } => {
                write!(f, "residual block {block} is not finite at the current variables")
            }
            Self::NonFiniteJacobian { block } => {
                write!(f, "Jacobian of residual block {block} is not finite at the current variables")
            }
            Self::FactorizationFailed { trials } => {
                write!(f, "Cholesky factorisation failed in all {trials} damped trials")
            }
            Self::SymbolicAnalysisFailed { message } => {
                write!(f, "symbolic Cholesky analysis failed: {message}")
            }
        }
    }
}

impl std::error::Error for SolverError {}
