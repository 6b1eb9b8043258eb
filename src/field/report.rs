//! What a field optimisation reports after each call to `step`.

use super::darboux::LevelFrame;
use super::params::{Family, Weights};
use super::problem::{Block, FieldProblem};
use crate::solver::LeastSquaresProblem;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The unweighted energy terms of Eq. 12 on the normalised problem (mean edge length 1,
/// initial mean `‖∇F‖` 1), and the weighted total the solver minimises.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Energies {
    /// `E_fair`: the squared Hessian energy of Eq. 6 plus the local-fit term (see
    /// [`super::problem`], `FIT_RATIO`).
    pub fair: f64,
    /// `E_grad`, Eq. 11 (residual `‖∇F‖² − r²`).
    pub grad: f64,
    /// The curve term: `E_angle` of Eq. 8 for pseudo-geodesics, `E_geo` or `E_asy` of Eq. 13.
    pub angle: f64,
    /// The auxiliary-variable constraints Eq. 9–10 (pseudo-geodesics only; 0 otherwise).
    pub frame: f64,
    /// `λ_fair E_fair + λ_grad E_grad + λ_angle (E_angle + constraints)` with the weights in force.
    pub total: f64,
}

/// State of a field optimisation after a `step`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StepReport {
    /// Iterations run since the solver was created.
    pub iterations: usize,
    /// Iterations run by this call.
    pub iterations_this_step: usize,
    /// Index of the weight stage in force (`schedule.len()` for the final weights).
    pub stage: usize,
    pub energies: Energies,
    /// RMS and maximum of `|θ_measured − θ_v|` in degrees (`θ_v` the vertex's target) over regular curve vertices
    /// with a defined binormal, measured from the field's own level polylines; for a
    /// constant-slope family, of the tangents' slope against β at the vertices that reach β.
    pub angle_error_rms_degrees: f64,
    pub angle_error_max_degrees: f64,
    /// Interior vertices where the angle was measured.
    pub measured_vertices: usize,
    /// Interior vertices whose level curve does not cross exactly two star edges.
    pub singular_vertices: Vec<u32>,
    /// Side vectors re-oriented by the `det(q − p, u, n) > 0` test during this call.
    pub flips: usize,
    /// Levenberg–Marquardt damping μ after the last iteration.
    pub damping: f64,
    /// The final stage has converged; further steps do nothing.
    pub converged: bool,
}

impl StepReport {
    /// Measures energies, angle errors and singular vertices of `x` (variables of `problem`).
    /// `evaluated` holds residuals the solver already evaluated at `x`, if any (see
    /// [`Evaluated`]); `frames` are the [`problem_frames`] of `x`.
    pub(crate) fn measure(problem: &FieldProblem, x: &[f64], evaluated: Option<&Evaluated<'_>>, frames: &[Option<LevelFrame>]) -> StepReport {
        let mut report = StepReport { energies: energies(problem, x, evaluated), ..StepReport::default() };
        let mut sum_squares = 0.0;
        for (k, (&v, frame)) in problem.curve_vertices().iter().zip(frames).enumerate() {
            match frame {
                None => report.singular_vertices.push(v),
                Some(frame) => {
                    let measured = match problem.slope_axis() {
                        // Constant slope: the tangent's slope, where the slope is reachable.
                        Some(axis) => problem.slope_reachable(k).then(|| super::slope_degrees(&frame.tangent, &axis)),
                        None => frame.signed_angle_degrees(),
                    };
                    if let Some(measured) = measured {
                        let error = problem.family().angle_error_degrees(measured, problem.target(k).degrees);
                        sum_squares += error * error;
                        report.angle_error_max_degrees = report.angle_error_max_degrees.max(error);
                        report.measured_vertices += 1;
                    }
                }
            }
        }
        if report.measured_vertices > 0 {
            report.angle_error_rms_degrees = (sum_squares / report.measured_vertices as f64).sqrt();
        }
        report
    }
}

/// The level frames of `x` at the problem's curve vertices (`None` at singular ones), measured
/// in parallel and returned in the order of [`FieldProblem::curve_vertices`] (the result does
/// not depend on the threads).
pub(crate) fn problem_frames(problem: &FieldProblem, x: &[f64]) -> Vec<Option<LevelFrame>> {
    (0..problem.curve_vertices().len()).into_par_iter().map(|k| problem.level_frame(k, x)).collect()
}

/// Residuals the solver evaluated at the current variables, with the weights they carry.
pub(crate) struct Evaluated<'a> {
    pub weights: Weights,
    /// The residuals of block `b`, if evaluated there.
    pub residuals: &'a (dyn Fn(usize) -> Option<&'a [f64]> + Sync),
}

impl Evaluated<'_> {
    /// Block `b`'s squared residual norms with unit weights, split as in [`block_squares`]: the
    /// evaluated residuals carry `√λ` of their term, so their squares over λ are the unit ones
    /// up to rounding. `None` if the block was not evaluated or λ is too small to divide by.
    fn unit_squares(&self, problem: &FieldProblem, b: usize) -> Option<(f64, f64)> {
        let weight = match problem.block(b) {
            // Fit residuals carry √(λ_fair · FIT_RATIO): over λ_fair they give FIT_RATIO · E_fit,
            // the share of E_fair they make.
            Block::Fair(_) | Block::Fit(_) => self.weights.fair,
            Block::Grad(_) => self.weights.grad,
            Block::Curve(_) => self.weights.angle,
        };
        // Below √MIN_POSITIVE, underflow in the weighted squares could matter.
        if weight < f64::MIN_POSITIVE.sqrt() {
            return None;
        }
        let (first, rest) = split_squares(problem, b, (self.residuals)(b)?);
        Some((first / weight, rest / weight))
    }
}

fn energies(problem: &FieldProblem, x: &[f64], evaluated: Option<&Evaluated<'_>>) -> Energies {
    let w = problem.weights();
    let mut e = Energies::default();
    for (b, (first, rest)) in block_squares(problem, x, 0..problem.block_count(), evaluated).into_iter().enumerate() {
        match problem.block(b) {
            Block::Fair(_) | Block::Fit(_) => e.fair += first,
            Block::Grad(_) => e.grad += first,
            Block::Curve(_) => {
                e.angle += first;
                e.frame += rest;
            }
        }
    }
    e.total = w.fair * e.fair + w.grad * e.grad + w.angle * (e.angle + e.frame);
    e
}

/// The unweighted curve terms `E_angle + E_frame` (or `E_geo`, `E_asy`) of `x`: the part of
/// [`Energies`] that says whether the level sets already form the family; from the `evaluated`
/// residuals where there are some.
pub(crate) fn curve_energy(problem: &FieldProblem, x: &[f64], evaluated: Option<&Evaluated<'_>>) -> f64 {
    curve_total(&curve_squares(problem, x, evaluated))
}

/// The sum of both parts of every curve block's `squares` ([`curve_squares`]): [`curve_energy`].
pub(crate) fn curve_total(squares: &[(f64, f64)]) -> f64 {
    squares.iter().map(|(curve, frame)| curve + frame).sum()
}

/// The unweighted squares of each curve block at x, in order: (`E_angle`'s rows of Eq. 8, the
/// auxiliaries' rows of Eq. 9–10) for pseudo-geodesics, (`E_geo` or `E_asy` of Eq. 13, 0)
/// otherwise; from the `evaluated` residuals where there are some.
pub(crate) fn curve_squares(problem: &FieldProblem, x: &[f64], evaluated: Option<&Evaluated<'_>>) -> Vec<(f64, f64)> {
    let first = problem.first_curve_block();
    block_squares(problem, x, first..first + problem.curve_vertices().len(), evaluated)
}

/// Squared residual norms of `blocks` with unit weights, split for pseudo-geodesic curve blocks
/// into the angle rows (Eq. 8) and the frame rows (Eq. 9–10): from the `evaluated` residuals
/// where there are some, otherwise evaluated in parallel. Returned in block order so that sums
/// do not depend on the threads.
fn block_squares(problem: &FieldProblem, x: &[f64], blocks: std::ops::Range<usize>, evaluated: Option<&Evaluated<'_>>) -> Vec<(f64, f64)> {
    let unit = Weights { fair: 1.0, grad: 1.0, angle: 1.0 };
    blocks
        .into_par_iter()
        .map_init(Vec::new, |residuals, b| {
            if let Some(squares) = evaluated.and_then(|e| e.unit_squares(problem, b)) {
                return squares;
            }
            residuals.clear();
            residuals.resize(problem.block_residual_count(b), 0.0);
            problem.evaluate_weighted(b, &unit, x, residuals, None);
            split_squares(problem, b, residuals)
        })
        .collect()
}

/// Squared norms of a block's residuals: (angle rows, frame rows) for a pseudo-geodesic curve
/// block, (all rows, 0) otherwise.
fn split_squares(problem: &FieldProblem, b: usize, residuals: &[f64]) -> (f64, f64) {
    let squares = |r: &[f64]| r.iter().map(|v| v * v).sum::<f64>();
    match (problem.block(b), problem.family()) {
        (Block::Curve(_), Family::PseudoGeodesic { .. }) => (squares(&residuals[..2]), squares(&residuals[2..])),
        _ => (squares(residuals), 0.0),
    }
}
