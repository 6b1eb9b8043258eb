//! Judging results as an outside reviewer would (the optimiser's own energies are no proof):
//! curve families measured along the curves at the scale of a few edges against the smooth
//! surface normal ([`family_angles`]), and curves of constant slope ([`slope_angles`]).

mod family;
mod level_set;
mod slope;

pub use family::{family_angles, polyline_family_angles, CurveAngles, FamilyAngles, WorstPoint, DEFAULT_SPACING_EDGES, STRAIGHT_PENALTY_DEGREES};
pub(crate) use level_set::level_set_angles;
pub use slope::{slope_angles, SlopeAngles};
