//! Errors of the initialisation from guide curves and sketched strokes, each naming the
//! offending input.

use crate::field::FieldError;
use std::fmt;

/// Why a field could not be initialised from guide curves or strokes.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum InitialisationError {
    /// Fewer than two guide curves: the linear function of Sec. 3.2.2 runs from the first to the last.
    TooFewGuideCurves { count: usize },
    /// Guide curve `curve` has no points.
    EmptyGuideCurve { curve: usize },
    /// Point `point` of guide curve `curve` names a vertex the mesh does not have.
    GuideVertexOutOfRange { curve: usize, point: usize, vertex: u32, vertex_count: usize },
    /// Point `point` of guide curve `curve` lies on `[a, b]`, which is not an edge of the mesh.
    GuideNotAnEdge { curve: usize, point: usize, edge: [u32; 2] },
    /// Point `point` of guide curve `curve` has an edge parameter outside `[0, 1]` (or not finite).
    GuideParameterOutOfRange { curve: usize, point: usize, t: f64 },
    /// The first points of the first and last guide curve map to the same parameter point, so
    /// the linear initial function has no direction.
    CoincidentGuideStarts,
    /// Fewer than two strokes: one stroke fixes a direction but no spacing or orientation of the family.
    TooFewStrokes { count: usize },
    /// Stroke `stroke` has fewer than two usable points (`points`: as given, or distinct triangles after filtering).
    StrokeTooShort { stroke: usize, points: usize },
    /// Point `point` of stroke `stroke` has a NaN or infinite coordinate.
    NonFiniteStrokePoint { stroke: usize, point: usize },
    /// Point `point` of stroke `stroke` is farther than `max_distance` (in the mesh's length unit)
    /// from the surface.
    StrokePointOffSurface { stroke: usize, point: usize, max_distance: f64 },
    /// Strokes `first` and `second` pass through the same triangle `face`: they cross (or touch).
    CrossingStrokes { first: usize, second: usize, face: u32 },
    /// An option is out of range; `name` is the option, `message` says what is allowed.
    InvalidOption { name: &'static str, message: String },
    /// A linear system (named by `stage`) is singular or gave a non-finite solution.
    SingularSystem { stage: &'static str },
    /// No stroke sample in the middle half of its stroke sits next to a regular interior vertex,
    /// so the target angle cannot be measured.
    NoMeasurableAngle,
    /// The pseudo-geodesic field optimisation failed to start or run.
    Field(FieldError),
}

impl fmt::Display for InitialisationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use InitialisationError::*;
        match self {
            TooFewGuideCurves { count } => write!(f, "{count} guide curve(s) given; at least 2 are needed"),
            EmptyGuideCurve { curve } => write!(f, "guide curve {curve} has no points"),
            GuideVertexOutOfRange { curve, point, vertex, vertex_count } => write!(
                f,
                "guide curve {curve}, point {point}: vertex {vertex} does not exist (the mesh has {vertex_count} vertices)"
            ),
            GuideNotAnEdge { curve, point, edge } => {
                write!(f, "guide curve {curve}, point {point}: [{}, {}] is not an edge of the mesh", edge[0], edge[1])
            }
            GuideParameterOutOfRange { curve, point, t } => {
                write!(f, "guide curve {curve}, point {point}: edge parameter t = {t} is not in [0, 1]")
            }
            CoincidentGuideStarts => {
                write!(f, "the first and the last guide curve start at the same point: the initial function has no direction")
            }
            TooFewStrokes { count } => write!(f, "{count} stroke(s) given; at least 2 are needed to fix the spacing of the family"),
            StrokeTooShort { stroke, points } => {
                write!(f, "stroke {stroke} has only {points} usable point(s) (one per triangle); at least 2 are needed")
            }
            NonFiniteStrokePoint { stroke, point } => write!(f, "stroke {stroke}, point {point}: coordinate is not finite"),
            StrokePointOffSurface { stroke, point, max_distance } => {
                write!(f, "stroke {stroke}, point {point}: farther than {max_distance} from the surface")
            }
            CrossingStrokes { first, second, face } => {
                write!(f, "strokes {first} and {second} cross: both pass through triangle {face}")
            }
            InvalidOption { name, message } => write!(f, "option `{name}`: {message}"),
            SingularSystem { stage } => write!(f, "the linear system of the {stage} is singular"),
            NoMeasurableAngle => write!(
                f,
                "no stroke point in the middle half of its stroke is next to a regular interior vertex: the target angle cannot be measured"
            ),
            Field(e) => write!(f, "field optimisation: {e}"),
        }
    }
}

impl std::error::Error for InitialisationError {}

impl From<FieldError> for InitialisationError {
    fn from(e: FieldError) -> Self {
        InitialisationError::Field(e)
    }
}

/// `Ok` if `value` is finite and positive, else an [`InitialisationError::InvalidOption`].
pub(crate) fn positive_option(name: &'static str, value: f64) -> Result<f64, InitialisationError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(InitialisationError::InvalidOption { name, message: format!("must be finite and > 0, got {value}") })
    }
}
