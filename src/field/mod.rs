//! Scalar fields on a mesh whose level sets form a chosen curve family: pseudo-geodesics,
//! geodesics or asymptotic curves (paper Sec. 3.1–3.2.2), curves of constant slope (Sec. 5.2.3,
//! Eq. 22), and P-curve families whose angle varies from level to level (Sec. 3.2, Fig. 16).

mod angle_profile;
mod asymptotic;
pub(crate) mod auxiliaries;
mod constant_slope;
mod crossing;
mod darboux;
mod error;
mod failure_site;
mod field_solver;
mod geodesic;
mod gradient_norm;
pub mod hessian_energy;
mod isophote;
mod level_angles;
mod level_jet;
mod params;
mod plateau;
mod problem;
pub(crate) mod pseudo_geodesic;
mod report;
mod session;
mod varying_angle;

pub use angle_profile::AngleProfile;
pub use constant_slope::{reachable as slope_reachable, slope_degrees, tangent_plane_inclination_degrees, ISOPHOTE_MARGIN_DEGREES};
pub use crossing::{find_level_crossing, EdgeCrossing, LevelCrossing};
pub use darboux::{level_frame, LevelFrame};
pub use error::FieldError;
pub use isophote::reachable_boundary;
pub use field_solver::{FieldSolver, FIELD_VALUE_LIMIT, MAX_LM_TRIALS};
pub(crate) use field_solver::{stage_weights, validate_field, validate_lm, validate_params};
pub(crate) use gradient_norm::mean_gradient_norm;
pub(crate) use level_jet::{JetStencil, LevelJet};
pub(crate) use report::problem_frames;
pub use level_angles::{level_angles, AngleRange, LevelAngles};
pub use problem::FieldProblem;
pub use params::{Family, FieldParams, Stage, VaryingAngleParams, Weights, PAPER_ANGLE_ENERGY, SETTLING_ITERATIONS};
pub use report::{Energies, StepReport};
pub use session::{SESSION_MAGIC, SESSION_VERSION};
pub(crate) use session::{check_damping, corrupt, framed, unframed, MAX_SAVED_ITERATIONS};
pub use varying_angle::{VaryingAngleReport, VaryingAngleSolver, LEVEL_ANGLE_SPACING, SETTLED_TARGET_DEGREES};
