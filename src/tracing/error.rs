//! Input errors of tracing and seeding ([`TraceError`]); each names the offending input.

use std::fmt;

/// A tracing or seeding input that cannot be used.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TraceError {
    /// An edge end `vertex` of a start point is not a vertex of the mesh.
    VertexOutOfRange { vertex: u32, vertex_count: usize },
    /// The start point's edge `{a, b}` is not an edge with a single face.
    NotBoundaryEdge { a: u32, b: u32 },
    /// The start point's edge parameter is non-finite or outside `[0, 1]`.
    EdgeParameterOutOfRange { t: f64 },
    /// The P-curve angle θ is non-finite or outside `[0°, 180°]`.
    ThetaOutOfRange { degrees: f64 },
    /// The start angle α is non-finite or outside the open interval `(0°, 180°)`.
    StartAngleOutOfRange { degrees: f64 },
    /// A [`super::TraceOptions`] field is non-finite or outside its range.
    InvalidOption { name: &'static str, value: f64 },
    /// No segment leaves the start point at angle α into the surface.
    NoFirstSegment { a: u32, b: u32, t: f64, start_angle_degrees: f64 },
    /// Zero start points were requested.
    ZeroCurves,
    /// More start points were requested than [`super::MAX_STARTS`].
    TooManyStarts { count: usize },
    /// Boundary loop `index` does not exist (the mesh has `count`).
    LoopOutOfRange { index: usize, count: usize },
    /// Boundary segment `index` does not exist (there are `count`).
    SegmentOutOfRange { index: usize, count: usize },
    /// An arc-length parameter along a boundary loop is non-finite or outside `[0, 1]`.
    ArcParameterOutOfRange { s: f64 },
    /// The corner threshold (a turning angle) is non-finite or outside `[0°, 180°]`.
    CornerAngleOutOfRange { degrees: f64 },
    /// A query point (e.g. for the nearest boundary point) has a NaN or infinite coordinate.
    NonFinitePoint,
}

impl fmt::Display for TraceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TraceError::VertexOutOfRange { vertex, vertex_count } => {
                write!(f, "start point vertex {vertex} is out of range (the mesh has {vertex_count} vertices)")
            }
            TraceError::NotBoundaryEdge { a, b } => {
                write!(f, "start point edge ({a}, {b}) is not a boundary edge of the mesh")
            }
            TraceError::EdgeParameterOutOfRange { t } => {
                write!(f, "start point edge parameter t = {t} is not in [0, 1]")
            }
            TraceError::ThetaOutOfRange { degrees } => {
                write!(f, "P-curve angle theta = {degrees}° is not in [0°, 180°]")
            }
            TraceError::StartAngleOutOfRange { degrees } => {
                write!(f, "start angle alpha = {degrees}° is not in (0°, 180°)")
            }
            TraceError::InvalidOption { name, value } => {
                write!(f, "tracing option `{name}` = {value} is outside its admissible range")
            }
            TraceError::NoFirstSegment { a, b, t, start_angle_degrees } => write!(
                f,
                "no first segment leaves edge ({a}, {b}) at t = {t} under alpha = {start_angle_degrees}° into the surface"
            ),
            TraceError::ZeroCurves => write!(f, "zero start points requested"),
            TraceError::TooManyStarts { count } => {
                write!(f, "{count} start points requested, at most {} are allowed", super::MAX_STARTS)
            }
            TraceError::LoopOutOfRange { index, count } => {
                write!(f, "boundary loop {index} does not exist (the mesh has {count})")
            }
            TraceError::SegmentOutOfRange { index, count } => {
                write!(f, "boundary segment {index} does not exist (there are {count})")
            }
            TraceError::ArcParameterOutOfRange { s } => {
                write!(f, "arc-length parameter s = {s} is not in [0, 1]")
            }
            TraceError::CornerAngleOutOfRange { degrees } => {
                write!(f, "corner turning angle {degrees}° is not in [0°, 180°]")
            }
            TraceError::NonFinitePoint => write!(f, "query point has a NaN or infinite coordinate"),
        }
    }
}

impl std::error::Error for TraceError {}
