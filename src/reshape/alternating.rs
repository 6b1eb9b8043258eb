//! The alternating schedule of Sec. 3.3: field steps (Sec. 3.2.2, the surface fixed) and surface
//! steps (the field fixed) in turn, until a round in which both have converged, the surface's
//! deviation from the original held within the tolerance throughout. Stepwise, as the solvers it
//! alternates: create it, `step` a few rounds at a time, read the moved surface and the field in
//! between, continue.

use super::error::ReshapeError;
use super::params::ReshapeParams;
use super::report::ReshapeReport;
use super::solver::ReshapeSolver;
use crate::field::{Family, FieldParams, FieldSolver, StepReport};
use crate::mesh::TriMesh;
use serde::{Deserialize, Serialize};

/// How the rounds of an [`AlternatingSolver`] run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AlternatingParams {
    /// The surface steps' parameters; θ and the tolerance hold for both kinds of step.
    pub reshape: ReshapeParams,
    /// The field steps' parameters (their family is replaced by the pseudo-geodesics of θ); the
    /// warm-up stages of `schedule` run in the first round only.
    pub field: FieldParams,
    /// Most iterations of each field step and of each surface step, ≥ 1.
    pub iterations_per_step: usize,
}

impl AlternatingParams {
    /// Default field and surface parameters for θ, at most 50 iterations per step.
    pub fn new(theta_degrees: f64) -> Self {
        AlternatingParams { reshape: ReshapeParams::new(theta_degrees), field: FieldParams::pseudo_geodesic(theta_degrees), iterations_per_step: 50 }
    }
}

/// State of an [`AlternatingSolver`] after a `step`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct AlternatingReport {
    /// Rounds (a field step and a surface step each) run since the solver was created.
    pub rounds: usize,
    /// Rounds run by this call.
    pub rounds_this_step: usize,
    /// Both steps of the last round converged.
    pub converged: bool,
    /// The last field step (its iterations counted from that step's start).
    pub field: StepReport,
    /// The last surface step; its deviation figures are from the original surface.
    pub surface: ReshapeReport,
}

/// Field and surface steps in turn from a surface and a field (Sec. 3.3).
pub struct AlternatingSolver {
    original: TriMesh,
    mesh: TriMesh,
    field: Vec<f64>,
    field_params: FieldParams,
    reshape_params: ReshapeParams,
    iterations_per_step: usize,
    /// The first round's field solver, built by [`Self::new`] (which validates the input with
    /// it) and taken by the first round.
    first_field_solver: Option<FieldSolver>,
    /// Distance of every vertex of `mesh` from the original surface, caller's units.
    deviations: Vec<f64>,
    report: AlternatingReport,
}

impl AlternatingSolver {
    /// Prepares the rounds from `mesh` and `field` (one value per vertex). Errors name the
    /// offending parameter or vertex, as [`ReshapeSolver::new`] and [`FieldSolver::new`] do.
    pub fn new(mesh: &TriMesh, field: &[f64], params: AlternatingParams) -> Result<AlternatingSolver, ReshapeError> {
        if params.iterations_per_step == 0 {
            return Err(ReshapeError::InvalidParameter { name: "iterations_per_step", message: "must be at least 1".into() });
        }
        let mut field_params = params.field;
        field_params.family = Family::from_theta(params.reshape.theta_degrees);
        // Both kinds of step validate their input here, before any round runs.
        let first_field_solver = FieldSolver::new(mesh, field, field_params.clone())?;
        let surface = ReshapeSolver::new(mesh, field, params.reshape.clone())?;
        Ok(AlternatingSolver {
            original: mesh.clone(),
            mesh: mesh.clone(),
            field: field.to_vec(),
            field_params,
            reshape_params: params.reshape,
            iterations_per_step: params.iterations_per_step,
            first_field_solver: Some(first_field_solver),
            deviations: surface.deviations(),
            report: AlternatingReport { surface: surface.report().clone(), ..AlternatingReport::default() },
        })
    }

    /// Runs at most `max_rounds` rounds, fewer once a round converges, and reports the state.
    /// On an error the state is that of the last whole round.
    pub fn step(&mut self, max_rounds: usize) -> Result<AlternatingReport, ReshapeError> {
        let mut ran = 0;
        while ran < max_rounds && !self.report.converged {
            let mut field_solver = match self.first_field_solver.take() {
                Some(solver) => solver,
                None => FieldSolver::new(&self.mesh, &self.field, self.field_params.clone())?,
            };
            let field_report = field_solver.step(self.iterations_per_step)?;
            // The warm-up (Fig. 15) guards a start against singularities; the later rounds start
            // from the field of the one before and go straight to the final weights.
            self.field_params.schedule.clear();
            let field = field_solver.field();
            let mut surface = ReshapeSolver::resume(&self.original, &self.mesh, &field, self.reshape_params.clone())?;
            let surface_report = surface.step(self.iterations_per_step)?;
            (self.mesh, self.field, self.deviations) = (surface.mesh(), field, surface.deviations());
            ran += 1;
            self.report = AlternatingReport {
                rounds: self.report.rounds + 1,
                rounds_this_step: ran,
                converged: field_report.converged && surface_report.converged,
                field: field_report,
                surface: surface_report,
            };
        }
        self.report.rounds_this_step = ran;
        Ok(self.report.clone())
    }

    /// The report of the last `step` (or of the initial state).
    pub fn report(&self) -> &AlternatingReport {
        &self.report
    }

    /// The current surface (the original's vertices and faces), caller's units.
    pub fn mesh(&self) -> &TriMesh {
        &self.mesh
    }

    /// The current field, one value per vertex.
    pub fn field(&self) -> &[f64] {
        &self.field
    }

    /// Distance of every vertex from the original surface (its closest point there), caller's
    /// units.
    pub fn deviations(&self) -> &[f64] {
        &self.deviations
    }

    /// The original surface.
    pub fn original(&self) -> &TriMesh {
        &self.original
    }

    pub fn is_converged(&self) -> bool {
        self.report.converged
    }
}
