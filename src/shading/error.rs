//! Errors of the shading design (paper Sec. 6) and of its sun-path evaluation.

use crate::field::FieldError;
use std::fmt;

/// Why a shading design or evaluation could not start or continue.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ShadingError {
    /// A parameter is out of range; `name` is the parameter, `message` says what is allowed.
    InvalidParameter { name: &'static str, message: String },
    /// No sun direction of the site's dates and hours lies above the horizon.
    SunNeverUp,
    /// The field optimisation failed (invalid start field or a solver failure).
    Field(FieldError),
}

impl ShadingError {
    pub(crate) fn invalid(name: &'static str, message: String) -> ShadingError {
        ShadingError::InvalidParameter { name, message }
    }
}

impl fmt::Display for ShadingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ShadingError::InvalidParameter { name, message } => write!(f, "parameter `{name}`: {message}"),
            ShadingError::SunNeverUp => write!(f, "the sun is below the horizon at every sampled date and hour"),
            ShadingError::Field(e) => write!(f, "field: {e}"),
        }
    }
}

impl std::error::Error for ShadingError {}

impl From<FieldError> for ShadingError {
    fn from(e: FieldError) -> Self {
        ShadingError::Field(e)
    }
}
