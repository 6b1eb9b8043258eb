//! Tracing guide curves (paper Sec. 3.2.1, Eq. 4, Fig. 13): discrete pseudo-geodesics
//! (P-curves) traced point by point on the mesh edges from a start point on the boundary,
//! the seeding helpers that place start points along the boundary, and the intersection and
//! order checks that the level-set initialisation (Sec. 3.2.2) demands of its guide curves.
//!
//! Conventions (Sec. 3.1): a curve travels from its start point; its side vector
//! `u = n × t` points to its left, seen from the side the normal points to, and θ is the signed
//! angle `acos(sign(b·u)·(b·n))` between its discrete binormal (Eq. 1) and the surface normal,
//! so θ and 180° − θ are the two mirror families (Fig. 8, 9). This is the convention of
//! [`crate::field::LevelFrame`]: a field with the curve as a level set and its gradient
//! pointing to the curve's left measures the same θ. Reversing a curve turns θ into 180° − θ.

mod asymptotic;
mod curve;
mod edge_search;
mod error;
mod first_segment;
mod guide_set;
mod intersections;
mod neighbourhood;
mod normal;
mod options;
mod order;
mod quadratic;
mod seeding;
mod start_normal;
mod step;
mod tracer;

pub use curve::{StopReason, TracedCurve};
pub use error::TraceError;
pub use guide_set::{trace_guide_set, GuideSet};
pub use intersections::{intersections, Crossing, IntersectionReport};
pub use options::{TraceOptions, MAX_TRACE_POINTS};
pub use order::{check_order, OrderDefect};
pub use seeding::{
    boundary_segments, boundary_start, evenly_spaced_starts, nearest_boundary_point, BoundarySegment, DEFAULT_CORNER_TURN_DEGREES,
    MAX_STARTS,
};
pub use tracer::Tracer;
