//! Errors of level-curve extraction and resampling.
use std::fmt;

/// Why level curves could not be extracted or resampled.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum CurveError {
    /// The field does not have one value per mesh vertex.
    FieldLength { expected: usize, actual: usize },
    /// A field value is NaN or infinite.
    NonFiniteField { vertex: usize },
    /// The field is constant: it has no level curves.
    ConstantField,
    /// Zero levels were requested.
    NoLevels,
    /// A requested level is NaN or infinite.
    NonFiniteLevel { index: usize },
    /// A requested level lies outside `[min F, max F]`.
    LevelOutOfRange { level: f64, min: f64, max: f64 },
    /// A resampling spacing that is not finite and positive.
    InvalidSpacing { spacing: f64 },
    /// A curve whose number of normals differs from its number of points.
    NormalCount { points: usize, normals: usize },
}

impl fmt::Display for CurveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CurveError::FieldLength { expected, actual } => {
                write!(f, "the field has {actual} values but the mesh has {expected} vertices")
            }
            CurveError::NonFiniteField { vertex } => write!(f, "field value at vertex {vertex} is not finite"),
            CurveError::ConstantField => write!(f, "the field is constant: it has no level curves"),
            CurveError::NoLevels => write!(f, "at least one level is needed"),
            CurveError::NonFiniteLevel { index } => write!(f, "level {index} is not finite"),
            CurveError::LevelOutOfRange { level, min, max } => {
                write!(f, "level {level} lies outside the field's range [{min}, {max}]")
            }
            CurveError::InvalidSpacing { spacing } => write!(f, "spacing must be finite and > 0, got {spacing}"),
            CurveError::NormalCount { points, normals } => write!(f, "curve has {points} points but {normals} normals"),
        }
    }
}

impl std::error::Error for CurveError {}
