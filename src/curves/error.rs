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
    /// A field value's magnitude exceeds [`crate::field::FIELD_VALUE_LIMIT`].
    FieldValueOutOfRange { vertex: usize, value: f64 },
    /// More levels were requested than [`super::MAX_LEVELS`].
    TooManyLevels { count: usize },
    /// Resampling at this spacing would give a polyline more points than [`super::MAX_CURVE_POINTS`].
    TooManyPoints { spacing: f64, points: f64 },
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
            CurveError::FieldValueOutOfRange { vertex, value } => write!(
                f,
                "field value {value:e} at vertex {vertex} is out of range (allowed: ±{:e})",
                crate::field::FIELD_VALUE_LIMIT
            ),
            CurveError::TooManyLevels { count } => write!(f, "{count} levels requested, at most {} are allowed", super::MAX_LEVELS),
            CurveError::TooManyPoints { spacing, points } => write!(
                f,
                "spacing {spacing:e} would give a polyline of {points:.3e} points, more than {} allowed",
                super::MAX_CURVE_POINTS
            ),
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
