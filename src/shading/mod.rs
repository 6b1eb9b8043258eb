//! Shading systems (paper Sec. 6): strips that block the sun or let it through where and when
//! asked. A site (latitude, clock, orientation, dates and hours) gives the sun directions
//! ([`solar_position`], [`sun_samples`]) and the light region `R_l` in the earth-axis frame
//! ([`LightRegion`], Eq. 24); the [`ShadingSolver`] optimises a field for `E_block` / `E_light`
//! (Eq. 25–27) with per-vertex [`VertexLabel`]s; [`most_common_slope`] is the slope vote of the
//! constant-slope initialisation (Fig. 34–35); the sun-path evaluation casts the sun's rays
//! through the strips ([`evaluate_sun_path`]), which is not in the paper.

mod check;
mod common_slope;
mod earth_frame;
mod error;
mod evaluation;
mod labels;
mod light_region;
mod light_rows;
mod params;
mod problem;
mod report;
mod site;
mod solar_position;
mod solver;
mod start;
mod strips;
mod sun_path;

pub use check::{sun_path_check, SunPathCheck, CHECK_HOUR_STEP};
pub use common_slope::{most_common_slope, SlopeVote, SLOPE_BIN_DEGREES, STEEP_FACE_DEGREES};
pub use earth_frame::{light_angles, light_direction, EarthFrame};
pub use error::ShadingError;
pub use evaluation::{evaluate_sun_path, samples_behind, strip_triangles, RegionFractions, SamplePoint, SunPathEvaluation};
pub use labels::{with_transition_ring, VertexLabel};
pub use light_region::{LightRegion, REGION_HOUR_STEP};
pub use params::{ShadingParams, ShadingWeights};
pub use problem::ShadingProblem;
pub use report::{ShadingEnergies, ShadingReport};
pub use site::{DateRange, HourRange, MonthDay, Site};
pub use solar_position::{day_of_year, solar_position, Clock, SolarPosition, DAYS_PER_YEAR};
pub use solver::ShadingSolver;
pub use start::{default_start, ShadingStart, StartKind};
pub use strips::{shading_strips, ShadingStrips};
pub use sun_path::{sun_samples, SunSample};
