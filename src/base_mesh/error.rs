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
    /// Saved session bytes are not a base-mesh session, are truncated or damaged, or restore a
    /// quantity out of range; `message` says which.
    CorruptData { message: String },
    /// Saved session bytes come from a newer (or unknown) format version.
    UnsupportedVersion { found: u32, supported: u32 },
}

impl fmt::Display for BaseMeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BaseMeshError::InvalidParameter { name, message } => write!(f, "parameter `{name}`: {message}"),
            BaseMeshError::InvalidNet { message } => write!(f, "net: {message}"),
            BaseMeshError::NothingToOptimise => write!(f, "no vertex lies inside a row or a column of at least three vertices: nothing to optimise"),
            BaseMeshError::Solver(e) => write!(f, "solver: {e}"),
            BaseMeshError::CorruptData { message } => write!(f, "corrupt base-mesh session: {message}"),
            BaseMeshError::UnsupportedVersion { found, supported } => {
                write!(f, "base-mesh session format version {found} is not supported (this library reads version {supported})")
            }
        }
    }
}

impl std::error::Error for BaseMeshError {}

impl From<SolverError> for BaseMeshError {
    fn from(e: SolverError) -> Self {
        BaseMeshError::Solver(e)
    }
}
