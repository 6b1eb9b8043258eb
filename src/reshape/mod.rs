//! Co-optimising the reference surface (paper Sec. 3.3): when no family of the asked angle
//! exists on a surface, move the surface a little. With the field F fixed at the vertices, the
//! vertex positions, binormals and side vectors are optimised so that the level sets become
//! P-curves of the angle θ ([`ReshapeSolver`], Fig. 17), within a bound on the deviation from the
//! original surface ([`Tolerance`]); an [`AlternatingSolver`] runs field and surface steps in turn.

mod alternating;
mod curve_star;
mod error;
mod linearisation;
mod params;
mod problem;
mod report;
mod session;
mod solver;

pub use alternating::{AlternatingParams, AlternatingReport, AlternatingSolver};
pub use error::ReshapeError;
pub use params::{ReshapeParams, ReshapeWeights, Tolerance, GUARD_GROWTH};
pub use report::{ReshapeEnergies, ReshapeReport};
pub use session::{RESHAPE_SESSION_MAGIC, RESHAPE_SESSION_VERSION};
pub use solver::{ReshapeSolver, MAX_GUARD_RAISES};
