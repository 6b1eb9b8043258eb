//! What a field optimisation aims at (the curve family) and how hard it pulls on each
//! energy term of Eq. 12, possibly changing the weights in stages (Fig. 15).

use crate::solver::LmOptions;
use serde::{Deserialize, Serialize};

/// The family of curves the level sets should form.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Family {
    /// Pseudo-geodesics: the binormal keeps the signed angle `theta_degrees` to the surface
    /// normal (`E_angle`, Eq. 8–10). `θ` and `180° − θ` are the two mirror families.
    PseudoGeodesic { theta_degrees: f64 },
    /// Geodesics, θ = 90° (`E_geo`, Eq. 13).
    Geodesic,
    /// Asymptotic curves, θ = 0° (`E_asy`, Eq. 13).
    Asymptotic,
    /// Curves of constant slope with respect to `axis` (Sec. 5.2.2–5.2.3, Eq. 22): the level
    /// curves' unit tangents `t` (along `∇F × n`) satisfy `t·d = cos γ = sin β`, `d` the unit
    /// axis and `β = slope_degrees` in (−90°, 90°) the inclination against the planes orthogonal
    /// to `d` (0°: the sections orthogonal to `d`). With `free_slope` the family's β is an
    /// unknown too, started at `slope_degrees` (the least-squares slope of the current field
    /// before every iteration). Regions whose tangent planes are too close to orthogonal to `d`
    /// carry no slope term ([`crate::field::slope_reachable`]).
    ConstantSlope { axis: [f64; 3], slope_degrees: f64, free_slope: bool },
}

impl Family {
    /// The family of curves whose binormal makes the angle `theta_degrees` with the surface
    /// normal, by name: 0° and 180° are the asymptotic curves (`E_asy`, Eq. 13), 90° the geodesics
    /// (`E_geo`), any other angle the pseudo-geodesics of that signed angle (`E_angle`, Eq. 8).
    pub fn from_theta(theta_degrees: f64) -> Family {
        Family::PseudoGeodesic { theta_degrees }.by_name()
    }

    /// This family with the degenerate pseudo-geodesic angles named: θ = 0° or 180° is
    /// [`Family::Asymptotic`], θ = 90° [`Family::Geodesic`] (within 1e-9°). At those angles the
    /// signed-angle rows of Eq. 8 degenerate (`sin θ cos θ = 0`, and at 0° any tangent direction
    /// of the osculating plane satisfies them), while Eq. 13 states the family directly.
    pub fn by_name(self) -> Family {
        match self {
            Family::PseudoGeodesic { theta_degrees } if theta_degrees.abs() < NAMED_ANGLE_TOLERANCE || (theta_degrees - 180.0).abs() < NAMED_ANGLE_TOLERANCE => {
                Family::Asymptotic
            }
            Family::PseudoGeodesic { theta_degrees } if (theta_degrees - 90.0).abs() < NAMED_ANGLE_TOLERANCE => Family::Geodesic,
            other => other,
        }
    }

    /// Target angle between binormal and normal in degrees; for a constant-slope family, which
    /// has no θ, its (start) slope β: the angle its curve term aims at.
    pub fn theta_degrees(&self) -> f64 {
        match *self {
            Family::PseudoGeodesic { theta_degrees } => theta_degrees,
            Family::Geodesic => 90.0,
            Family::Asymptotic => 0.0,
            Family::ConstantSlope { slope_degrees, .. } => slope_degrees,
        }
    }

    /// The unit axis `d` of a constant-slope family (`None` for the others or a zero axis).
    pub fn slope_axis(&self) -> Option<crate::mesh::Vec3> {
        match *self {
            Family::ConstantSlope { axis, .. } => crate::mesh::Vec3::from(axis).try_normalize(0.0),
            _ => None,
        }
    }

    /// The error in degrees of a measured signed angle (Sec. 3.1, in `[0°, 180°]`) against the
    /// target `theta`. Geodesics and asymptotic curves have no sign: for them `θ` and `180° − θ`
    /// are the same family.
    pub fn angle_error_degrees(&self, measured: f64, theta: f64) -> f64 {
        let error = (measured - theta).abs();
        match self {
            Family::PseudoGeodesic { .. } | Family::ConstantSlope { .. } => error,
            Family::Geodesic | Family::Asymptotic => error.min((180.0 - measured - theta).abs()),
        }
    }
}

/// Distance in degrees within which a pseudo-geodesic angle counts as 0°, 90° or 180°.
const NAMED_ANGLE_TOLERANCE: f64 = 1e-9;

/// The weights λ of Eq. 12. `angle` weighs whichever curve term the family uses
/// (`E_angle`, `E_geo` or `E_asy`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Weights {
    pub fair: f64,
    pub grad: f64,
    pub angle: f64,
}

/// Weights held for a number of iterations.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stage {
    pub iterations: usize,
    pub weights: Weights,
}

/// Consecutive slow iterations after which the final stage counts as converged.
pub const SETTLING_ITERATIONS: usize = 3;

/// The final stage has also converged once the unweighted curve terms (`E_angle + E_frame`,
/// Eq. 8–10, or `E_geo` / `E_asy`, Eq. 13, on the normalised problem) fall to this value: the
/// level sets then form the family to well within the paper's accuracy (Table 2: 9e-6), and
/// what the regularisers still change is only the labelling (the spacing) of the curves, which
/// can drift for hundreds of iterations when the guides ask for a spacing the family cannot keep.
pub const SETTLED_CURVE_ENERGY: f64 = 1e-7;

/// The accuracy of the paper's Table 2 (its `E_angle` figures are 9e-6 and below): the largest
/// unweighted curve term alone (`E_angle` of Eq. 8, or Eq. 13's `E_geo`, `E_asy`) that counts as
/// reaching the family, for [`crate::initialisation::auto_design`] and for the outside measure's
/// convergence test (`super::plateau`).
pub const PAPER_ANGLE_ENERGY: f64 = 1e-5;

/// Unweighted curve terms (as for [`SETTLED_CURVE_ENERGY`]) per curve vertex at which the family
/// counts as met for the convergence test: a mean squared angle residual of 1e-5, about 0.2° RMS.
/// Above it, steps that the damping holds back do not count as slow (see
/// [`FieldParams::relative_tolerance`]).
pub const FAMILY_MET_CURVE_ENERGY: f64 = 1e-5;

/// Parameters of a field optimisation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FieldParams {
    pub family: Family,
    /// Warm-up stages (Fig. 15: small λ_angle and larger λ_grad first), run in order before `weights`.
    pub schedule: Vec<Stage>,
    /// The final weights, held until convergence.
    pub weights: Weights,
    /// Target `‖∇F‖` of `E_grad` in field units per caller length unit (strip spacing ≈ 1/r).
    /// `None` keeps the area-weighted mean gradient norm of the initial field.
    pub gradient_target: Option<f64>,
    /// The final stage has converged when [`SETTLING_ITERATIONS`] iterations in a row each lower
    /// the weighted energy `E_pg` by less than this fraction (steps held back by the damping, which
    /// cut μ by half or more, count only once the family is met, [`FAMILY_MET_CURVE_ENERGY`]), or
    /// when Levenberg–Marquardt meets one of its own stopping rules. Past that point the curve
    /// term is met and the small regularisers only drift the spacing of the family, slowly. Two
    /// more tests end the stage whatever this tolerance: the curve terms falling to
    /// [`SETTLED_CURVE_ENERGY`], and, on meshes of 1,000 vertices and more, the level curves
    /// measured from outside no longer improving (`super::plateau`).
    pub relative_tolerance: f64,
    /// Levenberg–Marquardt settings.
    pub lm: LmOptions,
}

impl FieldParams {
    /// Defaults for a family: a short continuation from a small λ_angle (Fig. 15) to the weights
    /// of the paper's Table 2 (λ_fair 1e-3, λ_angle 30) on the normalised problem (mean edge 1,
    /// mean `‖∇F‖` 1), except λ_grad, held at 1e-5 rather than 1e-4 in the final stage. `E_grad`
    /// asks for evenly spaced level sets, which a family of P-curves generally cannot have (on a
    /// cylinder the catenaries' spacing varies along them); at 1e-4 its pull bends the curves
    /// off the family by up to 0.4 % of their length on a cylinder of radius 5 m, at 1e-5 by
    /// 0.1 % (README, method notes). Much weaker, it no longer keeps the field from slowly
    /// collapsing where that lowers `E_fair`.
    pub fn new(family: Family) -> Self {
        let stage = |iterations, fair, grad, angle| Stage { iterations, weights: Weights { fair, grad, angle } };
        FieldParams {
            family,
            schedule: vec![stage(8, 1e-3, 1e-2, 1e-2), stage(8, 1e-3, 1e-3, 1.0)],
            weights: Weights { fair: 1e-3, grad: 1e-5, angle: 30.0 },
            gradient_target: None,
            relative_tolerance: 1e-2,
            lm: LmOptions::default(),
        }
    }

    /// Defaults for the family of target angle `theta_degrees` ([`Family::from_theta`]: the
    /// pseudo-geodesics of that angle, or the asymptotic curves at 0° and 180°, the geodesics at 90°).
    pub fn pseudo_geodesic(theta_degrees: f64) -> Self {
        Self::new(Family::from_theta(theta_degrees))
    }
}

/// Parameters of a family with varying angle (Sec. 3.2, Fig. 16), see
/// [`VaryingAngleSolver`](super::VaryingAngleSolver).
///
/// The target angle is a cubic `θ(F)` fitted to the angles the field's level curves have; every
/// `update_interval` iterations the fit is redone and lowered by `lowering` (5 % in the paper),
/// toward 0°, the asymptotic direction, until `max_updates` lowerings have been made or the
/// caller freezes the profile; then the optimisation converges to the frozen profile `θ(F_v)`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VaryingAngleParams {
    /// Weights, warm-up schedule, `E_grad` target, tolerance and solver settings. Its `family`
    /// is not used: the targets come from the fitted profile.
    pub field: FieldParams,
    /// Fraction by which each update lowers the fitted profile, in `[0, 1)`; the paper uses 0.05.
    pub lowering: f64,
    /// Iterations between two updates of the profile, ≥ 1. The authors' code updates every
    /// iteration; a few iterations let the field follow each target before it is measured again.
    pub update_interval: usize,
    /// Lowerings after which the profile freezes by itself.
    pub max_updates: usize,
    /// Per-vertex targets are clamped to `[min_degrees, max_degrees]`, with
    /// `0 ≤ min_degrees < max_degrees ≤ 180`. The paper's scheme assumes `θ ≤ 90°` (the level
    /// curves bend toward increasing `F`; negate a field that bends the other way).
    pub min_degrees: f64,
    pub max_degrees: f64,
}

impl VaryingAngleParams {
    /// The paper's scheme: 5 % lowering, targets in `[0°, 90°]`, with the default weights of
    /// [`FieldParams::new`], one update every 5 iterations and at most 10 lowerings.
    pub fn new() -> Self {
        VaryingAngleParams {
            field: FieldParams::new(Family::PseudoGeodesic { theta_degrees: 45.0 }),
            lowering: 0.05,
            update_interval: 5,
            max_updates: 10,
            min_degrees: 0.0,
            max_degrees: 90.0,
        }
    }
}

impl Default for VaryingAngleParams {
    fn default() -> Self {
        Self::new()
    }
}
