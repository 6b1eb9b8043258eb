//! Level curves of a piecewise-linear field (paper Sec. 3.4, first paragraph): extraction at
//! chosen values, chaining into open and closed polylines, and resampling by arc length. These
//! polylines are the base curves of the strips of [`crate::strips`].

mod error;
mod extraction;
mod level_curve;
mod levels;

pub use error::CurveError;
pub use extraction::extract_level_curves;
pub use level_curve::{resample_all, LevelCurve, MAX_CURVE_POINTS};
pub use levels::{field_range, uniform_levels, MAX_LEVELS};
