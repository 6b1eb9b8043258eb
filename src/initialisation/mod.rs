//! Initial fields (paper Sec. 3.2.2, Fig. 12 b–c and Fig. 14): from ordered guide curves
//! (Eq. 5–7) and from sketched strokes, plus the automatic interactive design that estimates the
//! target angle from the strokes and hands over to the pseudo-geodesic optimisation of
//! [`crate::field`], the default start search that tries several starts when none is given
//! ([`StartSearch`]), and the start of a constant-slope family from its slope directions.
//!
//! Both initialisations map the mesh to the plane with a least-squares conformal map, start from
//! a linear function there, and solve linear least-squares problems with a sparse Cholesky
//! factorisation, on a copy of the mesh scaled to mean edge length 1 (the scale the default
//! weights assume).

mod auto_design;
mod conformal_map;
mod error;
mod guide_curves;
mod linear_least_squares;
mod proxy;
mod slope_start;
mod smoothness_rows;
mod start_search;
mod stroke_field;
mod strokes;
mod surface_locator;
mod target_angle;

pub use auto_design::{auto_design, AutoDesign, AutoDesignOptions, DesignStatus};
pub use error::InitialisationError;
pub use guide_curves::{field_from_guide_curves, GuideCurveOptions, GuideField};
pub use slope_start::{slope_start_field, slope_tangent};
pub use start_search::{search_start, Candidate, SearchError, SearchOptions, SearchOutcome, StartKind, StartSearch};
pub(crate) use proxy::{carried_to, search_proxy};
pub(crate) use start_search::{family_judgement, keep_lower, level_curve_measure, principal_plane, FamilyJudgement};
pub use stroke_field::{field_from_strokes, StrokeField, StrokeOptions};
pub use strokes::{project_strokes, StrokeSample};
pub use target_angle::estimate_target_angle;

use crate::mesh::TriMesh;

/// The least-squares conformal map (LSCM) of `mesh` to the plane, one point per vertex, with the
/// first vertex of the outer boundary loop at (0, 0) and the loop vertex farthest from it at
/// (1, 0) (see the module `conformal_map`).
pub fn conformal_map(mesh: &TriMesh) -> Result<Vec<[f64; 2]>, InitialisationError> {
    conformal_map::least_squares_conformal_map(mesh).ok_or(InitialisationError::SingularSystem { stage: "conformal map" })
}
