//! What a surface optimisation (Sec. 3.3) aims at and how hard it pulls on each term of
//! `E^M_pg = λ_fair E^S_fair + λ_close E^S_close + λ_angle E^S_angle + λ_edge E^S_edge`.

use crate::solver::LmOptions;
use serde::{Deserialize, Serialize};

/// The weights λ of `E^M_pg` (Sec. 3.3) on the normalised problem (mean edge length 1).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReshapeWeights {
    /// `E^S_fair = E^S_H + E^S_uni + E^S_c`.
    pub fair: f64,
    /// `E^S_close`, Eq. 14.
    pub close: f64,
    /// `E^S_angle` (Eq. 8–10 with F fixed).
    pub angle: f64,
    /// `E^S_edge`, Eq. 15.
    pub edge: f64,
}

impl Default for ReshapeWeights {
    /// The paper's Table 3 weights of Fig. 17(b), a 60° family turned into 45°:
    /// λ_fair 0.02, λ_edge 2e-3, λ_close 3e-4, λ_angle 30.
    fn default() -> Self {
        ReshapeWeights { fair: 0.02, close: 3e-4, angle: 30.0, edge: 2e-3 }
    }
}

/// How far the surface may move from the original: the largest distance of a vertex from the
/// original surface (its closest point there).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Tolerance {
    /// In the mesh's length units.
    Absolute(f64),
    /// A fraction of the original mesh's bounding-box diagonal (0.005 for 0.5 %).
    DiagonalFraction(f64),
}

impl Tolerance {
    /// The tolerance in length units on a mesh of bounding-box diagonal `diagonal`.
    pub fn length(&self, diagonal: f64) -> f64 {
        match *self {
            Tolerance::Absolute(length) => length,
            Tolerance::DiagonalFraction(fraction) => fraction * diagonal,
        }
    }

    pub(crate) fn value(&self) -> f64 {
        match *self {
            Tolerance::Absolute(v) | Tolerance::DiagonalFraction(v) => v,
        }
    }
}

/// Parameters of a [`super::ReshapeSolver`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ReshapeParams {
    /// The target angle θ between the binormals of the level curves and the surface normal, in
    /// degrees, strictly between 0° and 180° (a pseudo-geodesic family, Eq. 8).
    pub theta_degrees: f64,
    pub weights: ReshapeWeights,
    /// The bound on the deviation from the original surface. A step that would exceed it is
    /// undone and the normal part of `E^S_close` (Eq. 14) is weighted [`GUARD_GROWTH`] times more.
    pub tolerance: Tolerance,
    /// Largest move of a vertex in one iteration, in mean edge lengths of the original mesh: a
    /// longer step is shortened to it (the authors' "Max Mesh Step Length"), which keeps the
    /// quantities frozen for the iteration ([`super::linearisation`]) close to the moved mesh's.
    /// Default 0.1.
    pub max_vertex_step: f64,
    /// Converged when [`SETTLING_ITERATIONS`](crate::field::SETTLING_ITERATIONS) iterations in a
    /// row each lower the weighted energy by less than this fraction. Default 1e-4.
    pub relative_tolerance: f64,
    /// Levenberg–Marquardt settings.
    pub lm: LmOptions,
}

impl ReshapeParams {
    /// Table 3 weights, 1 % of the bounding-box diagonal as tolerance.
    pub fn new(theta_degrees: f64) -> Self {
        ReshapeParams {
            theta_degrees,
            weights: ReshapeWeights::default(),
            tolerance: Tolerance::DiagonalFraction(0.01),
            max_vertex_step: 0.1,
            relative_tolerance: 1e-4,
            lm: LmOptions::default(),
        }
    }
}

/// Factor by which the normal part of `E^S_close` is raised each time a step would leave the
/// tolerance.
pub const GUARD_GROWTH: f64 = 10.0;
