//! The alternating schedule of Sec. 3.3: field steps (Sec. 3.2.2, the surface fixed) and surface
//! steps (the field fixed) in turn, until a round in which both have converged, the surface's
//! deviation from the original held within the tolerance throughout.

use super::error::ReshapeError;
use super::params::ReshapeParams;
use super::report::ReshapeReport;
use super::solver::ReshapeSolver;
use crate::field::{Family, FieldParams, FieldSolver, StepReport};
use crate::mesh::TriMesh;
use serde::{Deserialize, Serialize};

/// How the rounds of [`alternate`] run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AlternatingParams {
    /// The surface steps' parameters; θ and the tolerance hold for both kinds of step.
    pub reshape: ReshapeParams,
    /// The field steps' parameters (their family is replaced by the pseudo-geodesics of θ).
    pub field: FieldParams,
    /// Most rounds (a field step and a surface step each), ≥ 1.
    pub rounds: usize,
    /// Most iterations of each field step and of each surface step, ≥ 1.
    pub iterations_per_step: usize,
}

impl AlternatingParams {
    /// Default field and surface parameters for θ, 10 rounds of at most 50 iterations per step.
    pub fn new(theta_degrees: f64) -> Self {
        AlternatingParams { reshape: ReshapeParams::new(theta_degrees), field: FieldParams::pseudo_geodesic(theta_degrees), rounds: 10, iterations_per_step: 50 }
    }
}

/// The state after [`alternate`].
#[derive(Clone, Debug)]
pub struct Alternated {
    /// The moved surface (the original's vertices and faces).
    pub mesh: TriMesh,
    pub field: Vec<f64>,
    pub rounds: usize,
    /// Both steps of the last round converged.
    pub converged: bool,
    pub field_report: StepReport,
    pub reshape_report: ReshapeReport,
}

/// Runs field and surface steps in turn from `mesh` and `field`.
pub fn alternate(mesh: &TriMesh, field: &[f64], params: &AlternatingParams) -> Result<Alternated, ReshapeError> {
    for (name, value) in [("rounds", params.rounds), ("iterations_per_step", params.iterations_per_step)] {
        if value == 0 {
            return Err(ReshapeError::InvalidParameter { name, message: "must be at least 1".into() });
        }
    }
    let mut field_params = params.field.clone();
    field_params.family = Family::from_theta(params.reshape.theta_degrees);
    let mut state = Alternated {
        mesh: mesh.clone(),
        field: field.to_vec(),
        rounds: 0,
        converged: false,
        field_report: StepReport::default(),
        reshape_report: ReshapeReport::default(),
    };
    while state.rounds < params.rounds && !state.converged {
        let mut field_solver = FieldSolver::new(&state.mesh, &state.field, field_params.clone())?;
        state.field_report = field_solver.step(params.iterations_per_step)?;
        state.field = field_solver.field();
        let mut surface = ReshapeSolver::resume(mesh, &state.mesh, &state.field, params.reshape.clone())?;
        state.reshape_report = surface.step(params.iterations_per_step)?;
        state.mesh = surface.mesh();
        state.rounds += 1;
        state.converged = state.field_report.converged && state.reshape_report.converged;
    }
    Ok(state)
}
