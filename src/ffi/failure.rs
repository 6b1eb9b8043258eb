//! A failed call: its status and message, and how the library's Rust errors map to statuses.

use super::status::LmlStatus;
use crate::curves::CurveError;
use crate::field::FieldError;
use crate::initialisation::InitialisationError;
use crate::mesh::MeshError;
use crate::solver::SolverError;
use crate::strips::StripError;
use crate::tracing::TraceError;

/// Why an `lml_*` call failed.
#[derive(Debug)]
pub(crate) struct Failure {
    pub status: LmlStatus,
    pub message: String,
}

impl Failure {
    pub fn new(status: LmlStatus, message: impl Into<String>) -> Failure {
        Failure { status, message: message.into() }
    }

    /// `LML_STATUS_INVALID_ARGUMENT` about the argument `name`.
    pub fn argument(name: &str, problem: impl std::fmt::Display) -> Failure {
        Failure::new(LmlStatus::InvalidArgument, format!("argument `{name}`: {problem}"))
    }
}

impl From<MeshError> for Failure {
    fn from(e: MeshError) -> Failure {
        Failure::new(mesh_status(&e), e.to_string())
    }
}

fn mesh_status(e: &MeshError) -> LmlStatus {
    match e {
        MeshError::NotDisk { .. } | MeshError::MultipleComponents { .. } => LmlStatus::NotADisk,
        MeshError::ObjLine { error, .. } => mesh_status(error),
        MeshError::Io { .. } | MeshError::ArrayLength { .. } | MeshError::InvalidScaleFactor { .. } => LmlStatus::InvalidArgument,
        _ => LmlStatus::InvalidMesh,
    }
}

impl From<FieldError> for Failure {
    fn from(e: FieldError) -> Failure {
        let status = match &e {
            FieldError::FieldLength { .. }
            | FieldError::NonFiniteValue { .. }
            | FieldError::ValueOutOfRange { .. }
            | FieldError::InvalidParameter { .. } => LmlStatus::InvalidArgument,
            FieldError::ConstantField => LmlStatus::SingularField,
            FieldError::CorruptData { .. } | FieldError::UnsupportedVersion { .. } => LmlStatus::CorruptData,
            FieldError::Solver(
                SolverError::NonFiniteResidual { .. } | SolverError::NonFiniteJacobian { .. } | SolverError::FactorizationFailed { .. },
            )
            | FieldError::SolverFailedNear { .. } => LmlStatus::DidNotConverge,
            _ => LmlStatus::InternalError,
        };
        Failure::new(status, e.to_string())
    }
}

impl From<CurveError> for Failure {
    fn from(e: CurveError) -> Failure {
        let status = match &e {
            CurveError::NoLevels
            | CurveError::NonFiniteLevel { .. }
            | CurveError::LevelOutOfRange { .. }
            | CurveError::InvalidSpacing { .. }
            | CurveError::TooManyLevels { .. }
            | CurveError::TooManyPoints { .. }
            | CurveError::FieldValueOutOfRange { .. } => LmlStatus::InvalidArgument,
            CurveError::ConstantField => LmlStatus::SingularField,
            // The field and the curves come from the library itself: a mismatch is a bug.
            CurveError::FieldLength { .. } | CurveError::NonFiniteField { .. } | CurveError::NormalCount { .. } => LmlStatus::InternalError,
        };
        Failure::new(status, e.to_string())
    }
}

impl From<StripError> for Failure {
    /// Every strip error is a parameter out of range.
    fn from(e: StripError) -> Failure {
        Failure::new(LmlStatus::InvalidArgument, format!("argument `params`: {e}"))
    }
}

impl From<TraceError> for Failure {
    /// Every tracing and seeding error is an input out of range; the message names it.
    fn from(e: TraceError) -> Failure {
        Failure::new(LmlStatus::InvalidArgument, e.to_string())
    }
}

impl From<InitialisationError> for Failure {
    fn from(e: InitialisationError) -> Failure {
        use InitialisationError::*;
        let status = match &e {
            TooFewGuideCurves { .. } | EmptyGuideCurve { .. } | CoincidentGuideStarts => LmlStatus::InvalidGuides,
            GuideVertexOutOfRange { .. } | GuideNotAnEdge { .. } | GuideParameterOutOfRange { .. } => LmlStatus::InvalidArgument,
            TooFewStrokes { .. } | StrokeTooShort { .. } | StrokePointOffSurface { .. } | CrossingStrokes { .. } => LmlStatus::InvalidStrokes,
            NonFiniteStrokePoint { .. } | InvalidOption { .. } => LmlStatus::InvalidArgument,
            SingularSystem { .. } | NoMeasurableAngle => LmlStatus::SingularField,
            Field(field_error) => return Failure::from(field_error.clone()),
        };
        Failure::new(status, e.to_string())
    }
}
