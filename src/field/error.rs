//! Errors of the field optimisation.

use crate::solver::SolverError;
use std::fmt;

/// Why a field optimisation could not start or continue.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum FieldError {
    /// The initial field does not have one value per mesh vertex.
    FieldLength { expected: usize, actual: usize },
    /// A field value is NaN or infinite.
    NonFiniteValue { vertex: usize },
    /// A field value's magnitude exceeds [`super::FIELD_VALUE_LIMIT`].
    ValueOutOfRange { vertex: usize, value: f64 },
    /// The field is constant (or its gradient vanishes everywhere): it has no level curves.
    ConstantField,
    /// A parameter is out of range; `name` is the parameter, `message` says what is allowed.
    InvalidParameter { name: &'static str, message: String },
    /// Saved session bytes are truncated, corrupted or inconsistent; `message` says where.
    CorruptData { message: String },
    /// Saved session bytes come from a newer (or unknown) format version.
    UnsupportedVersion { found: u32, supported: u32 },
    /// The least-squares solver failed.
    Solver(SolverError),
    /// The least-squares solver failed during an iteration; `vertices` carry the largest
    /// residuals (largest first), where the mesh or the field is most likely at fault.
    SolverFailedNear { error: SolverError, vertices: Vec<u32> },
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FieldError::FieldLength { expected, actual } => {
                write!(f, "the field has {actual} values but the mesh has {expected} vertices")
            }
            FieldError::NonFiniteValue { vertex } => write!(f, "field value at vertex {vertex} is not finite"),
            FieldError::ValueOutOfRange { vertex, value } => {
                write!(f, "field value {value:e} at vertex {vertex} is out of range (allowed: ±{:e})", super::FIELD_VALUE_LIMIT)
            }
            FieldError::ConstantField => write!(f, "the field is constant: it has no level curves"),
            FieldError::InvalidParameter { name, message } => write!(f, "parameter `{name}`: {message}"),
            FieldError::CorruptData { message } => write!(f, "corrupt field session: {message}"),
            FieldError::UnsupportedVersion { found, supported } => {
                write!(f, "field session format version {found} is not supported (this library reads version {supported})")
            }
            FieldError::Solver(e) => write!(f, "solver: {e}"),
            FieldError::SolverFailedNear { error, vertices } => {
                write!(f, "solver: {error}; the largest residuals are at vertices {vertices:?} (look at the mesh there)")
            }
        }
    }
}

impl std::error::Error for FieldError {}

impl From<SolverError> for FieldError {
    fn from(e: SolverError) -> Self {
        FieldError::Solver(e)
    }
}
