//! Errors of the surface optimisation.

use crate::field::FieldError;
use crate::mesh::MeshError;
use crate::solver::SolverError;
use std::fmt;

/// Why a surface optimisation could not start or continue.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ReshapeError {
    /// The field is not one finite value per vertex, or is constant (see [`FieldError`]).
    Field(FieldError),
    /// A parameter is out of range; `name` is the parameter, `message` says what is allowed.
    InvalidParameter { name: &'static str, message: String },
    /// No interior vertex has a regular level curve through it (Fig. 7): nothing to optimise.
    NoCurveVertices,
    /// The least-squares solver failed.
    Solver(SolverError),
    /// The mesh rebuilt at the optimised positions was rejected.
    Mesh(MeshError),
}

impl fmt::Display for ReshapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReshapeError::Field(e) => write!(f, "{e}"),
            ReshapeError::InvalidParameter { name, message } => write!(f, "parameter `{name}`: {message}"),
            ReshapeError::NoCurveVertices => write!(f, "no interior vertex has a regular level curve through it: nothing to reshape"),
            ReshapeError::Solver(e) => write!(f, "solver: {e}"),
            ReshapeError::Mesh(e) => write!(f, "mesh: {e}"),
        }
    }
}

impl std::error::Error for ReshapeError {}

impl From<FieldError> for ReshapeError {
    fn from(e: FieldError) -> Self {
        ReshapeError::Field(e)
    }
}

impl From<SolverError> for ReshapeError {
    fn from(e: SolverError) -> Self {
        ReshapeError::Solver(e)
    }
}

impl From<MeshError> for ReshapeError {
    fn from(e: MeshError) -> Self {
        ReshapeError::Mesh(e)
    }
}
