//! What a shading optimisation reports after each call to `step`.

use super::light_rows::{self, LightMode};
use super::params::ShadingWeights;
use super::problem::ShadingProblem;
use crate::field::Weights;
use crate::solver::{LeastSquaresProblem, LevenbergMarquardt};
use serde::{Deserialize, Serialize};

/// Unweighted terms of Eq. 25 on the normalised problem, and the weighted total minimised.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ShadingEnergies {
    /// `E_fair` (Eq. 6 plus the local-fit term of the field problem).
    pub fair: f64,
    /// `E_grad` (Eq. 11).
    pub grad: f64,
    /// `E_block` (Eq. 26) over the blocking vertices.
    pub block: f64,
    /// `E_light` (Eq. 27) over the letting-through vertices.
    pub light: f64,
    /// The constraints defining `b`, `n^p` and `l ∈ R_l` (Eq. 9, 24).
    pub constraints: f64,
    pub total: f64,
}

/// State of a shading optimisation after a `step`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ShadingReport {
    pub iterations: usize,
    pub iterations_this_step: usize,
    pub converged: bool,
    pub damping: f64,
    pub energies: ShadingEnergies,
    /// Vertices with a light term (blocking / letting through).
    pub block_vertices: usize,
    pub pass_vertices: usize,
    /// Light vertices where the level curve is not regular (no light term at this field).
    pub singular_vertices: usize,
}

impl ShadingReport {
    /// The energies and counts of `problem` at `x`.
    pub(crate) fn measure(problem: &ShadingProblem, x: &[f64]) -> ShadingReport {
        let field = problem.field_problem();
        let unit = Weights { fair: 1.0, grad: 1.0, angle: 0.0 };
        let mut energies = ShadingEnergies { total: LevenbergMarquardt::evaluate_energy(problem, x), ..Default::default() };
        let first_curve = field.first_curve_block();
        let curves = field.curve_vertices().len();
        let mut residuals = Vec::new();
        let regularisers = (0..first_curve).chain(first_curve + curves..first_curve + 2 * curves);
        for b in regularisers {
            residuals.resize(field.block_residual_count(b), 0.0);
            residuals.fill(0.0);
            field.evaluate_weighted(b, &unit, x, &mut residuals, None);
            let sum: f64 = residuals.iter().map(|r| r * r).sum();
            if b < field.mesh().vertex_count() || b >= first_curve {
                energies.fair += sum;
            } else {
                energies.grad += sum;
            }
        }
        let ones = ShadingWeights { fair: 1.0, grad: 1.0, light_block: 1.0, light_pass: 1.0, constraint: 1.0 };
        let (mut block_vertices, mut pass_vertices, mut singular_vertices) = (0, 0, 0);
        for (k, vertex) in problem.light_vertices().iter().enumerate() {
            let (rows, light_rows) = match vertex.mode {
                LightMode::Block => (light_rows::BLOCK_ROWS, 9..11),
                LightMode::Pass => (light_rows::PASS_ROWS, 12..13),
            };
            match vertex.mode {
                LightMode::Block => block_vertices += 1,
                LightMode::Pass => pass_vertices += 1,
            }
            if field.level_jet(vertex.curve, x).is_none() {
                singular_vertices += 1;
                continue;
            }
            residuals.resize(rows, 0.0);
            residuals.fill(0.0);
            problem.evaluate_light(k, &ones, x, &mut residuals, None);
            for (row, r) in residuals.iter().enumerate() {
                let square = r * r;
                match (light_rows.contains(&row), vertex.mode) {
                    (true, LightMode::Block) => energies.block += square,
                    (true, LightMode::Pass) => energies.light += square,
                    (false, _) => energies.constraints += square,
                }
            }
        }
        ShadingReport { energies, block_vertices, pass_vertices, singular_vertices, ..Default::default() }
    }
}
