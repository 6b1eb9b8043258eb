//! Errors (the whole computation cannot run) and per-strip warnings of the strip computation.
use std::fmt;

/// A parameter that makes every strip impossible.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum StripError {
    /// The strip width is not finite and positive.
    InvalidWidth { width: f64 },
    /// θ is not finite or outside `[0°, 180°]`.
    InvalidTheta { theta_degrees: f64 },
    /// Another parameter is out of range.
    InvalidParameter { name: &'static str, message: String },
}

impl fmt::Display for StripError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StripError::InvalidWidth { width } => write!(f, "strip width must be finite and > 0, got {width}"),
            StripError::InvalidTheta { theta_degrees } => write!(f, "θ must lie in [0°, 180°], got {theta_degrees}"),
            StripError::InvalidParameter { name, message } => write!(f, "parameter `{name}`: {message}"),
        }
    }
}

impl std::error::Error for StripError {}

/// Something wrong with one strip. Strips with a warning that makes them impossible
/// (too few points, non-finite input, solver failure) are skipped; the others are returned with
/// their warnings.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum StripWarning {
    /// The polyline has fewer than 3 points: no binormal, no strip (skipped).
    TooFewPoints { points: usize },
    /// A point of the polyline is not finite (skipped).
    NonFiniteInput,
    /// Segment `segment` (from point `segment` to the next) has (nearly) zero length, so its
    /// direction and the discrete frame (Eq. 1) are undefined (skipped; resample the curve).
    ZeroLengthSegment { segment: usize },
    /// The optimisation failed (skipped); the message says why.
    SolverFailed { message: String },
    /// The level curve passes the star of these singular field vertices: the level set may branch
    /// there, and the strip may follow a wrong branch or turn sharply.
    SingularVertices { vertices: Vec<u32> },
    /// A closed level curve was cut open at its first vertex (strips are open).
    ClosedCurveOpened,
    /// The requested width exceeds `max_width`, beyond which neighbouring rulings cross inside the
    /// strip and quads fold over (the width is too large for the vertex spacing and the turning of
    /// the rulings).
    WidthTooLarge { width: f64, max_width: f64 },
    /// Quads whose orientation flips against their neighbours or the target binormal side.
    FlippedQuads { count: usize },
}

impl fmt::Display for StripWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StripWarning::TooFewPoints { points } => write!(f, "polyline has {points} points, at least 3 are needed"),
            StripWarning::NonFiniteInput => write!(f, "polyline has non-finite points"),
            StripWarning::ZeroLengthSegment { segment } => write!(f, "segment {segment} of the polyline has zero length"),
            StripWarning::SolverFailed { message } => write!(f, "strip optimisation failed: {message}"),
            StripWarning::SingularVertices { vertices } => {
                write!(f, "level curve passes {} singular field vertices: {vertices:?}", vertices.len())
            }
            StripWarning::ClosedCurveOpened => write!(f, "closed level curve cut open at its first vertex"),
            StripWarning::WidthTooLarge { width, max_width } => {
                write!(f, "width {width} exceeds {max_width}, beyond which the strip folds")
            }
            StripWarning::FlippedQuads { count } => write!(f, "{count} quads are flipped"),
        }
    }
}
