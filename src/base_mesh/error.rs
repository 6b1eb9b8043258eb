//! Errors of the base-mesh optimisation.

use crate::solver::SolverError;
use std::fmt;

/// Why a base-mesh optimisation could not start or continue.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum BaseMeshError {
    /// A parameter is out of range; `name` is the parameter, `message` says what is allowed.
    InvalidParameter { name: &'static str, message: String },
    /// The net is not a valid polyline net; `message` names the offending vertex or polyline.
    InvalidNet { message: String },
    /// No vertex is interior to a polyline: there is no curve to hold to its family.
    NothingToOptimise,
    /// The least-squares solver failed.
    Solver(SolverError),
}

impl fmt::Display for BaseMeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BaseMeshError::InvalidParameter { name, message } => write!(f, "parameter `{name}`: {message}"),
            BaseMeshError::InvalidNet { message } => write!(f, "net: {message}"),
            BaseMeshError::NothingToOptimise => write!(f, "no vertex lies inside a row or a column of at least three vertices: nothing to optimise"),
            BaseMeshError::Solver(e) => write!(f, "solver: {e}"),
        }
    }
}

impl std::error::Error for BaseMeshError {}

impl From<SolverError> for BaseMeshError {
    fn from(e: SolverError) -> Self {
        BaseMeshError::Solver(e)
    }
}
