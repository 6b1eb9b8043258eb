//! P-curve families with changing angles (Sec. 3.2, Fig. 16): the pseudo-geodesic optimisation of
//! Eq. 12 towards a per-vertex target `θ_v = θ(F_v)`, where the angle assignment function `θ(F)`
//! is a cubic fitted to the angles the current level curves have, lowered by 5 % at each update.
//!
//! The scheme, supervised by `E_fair` and `E_grad`:
//! 1. measure the signed angle of every regular interior vertex from the field's own level
//!    polyline (as [`StepReport`] does) and fit the cubic [`AngleProfile`] to `(F_v, θ_v)`;
//! 2. the target is that fit times `1 − lowering` (toward 0°, the asymptotic direction), clamped
//!    per vertex to `[min_degrees, max_degrees]`;
//! 3. run `update_interval` iterations towards it, then measure again.
//!
//! The authors' code refits and lowers every iteration; we default to every few iterations so
//! that each measurement sees a field that has followed its previous target (set
//! `update_interval = 1` for their rhythm). At creation the profile is fitted without lowering.
//! After `max_updates` lowerings, or when the caller calls [`VaryingAngleSolver::freeze`], the
//! targets stay fixed and the optimisation converges to them.

use super::angle_profile::AngleProfile;
use super::error::FieldError;
use super::field_solver::FieldSolver;
use super::level_angles::{level_angles, LevelAngles};
use super::params::{Family, VaryingAngleParams};
use super::report::{measured_angles, StepReport};
use crate::curves::CurveError;
use crate::mesh::{TriMesh, Vec3};
use serde::{Deserialize, Serialize};

/// Arc-length step, in mean edge lengths, at which [`VaryingAngleSolver::level_angles`] measures:
/// long enough that the discrete binormal spans several faces (the faceting of the mesh tilts
/// shorter chords noticeably), short enough to follow the curve.
pub const LEVEL_ANGLE_SPACING: f64 = 3.0;

/// State of a varying-angle optimisation after a `step`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VaryingAngleReport {
    /// The underlying field report; its angle errors are measured against each vertex's own target.
    pub field: StepReport,
    /// The last cubic fitted to the measured angles.
    pub fitted: AngleProfile,
    /// The target profile in force: `fitted` lowered (before per-vertex clamping).
    pub target: AngleProfile,
    /// Smallest and largest per-vertex target `clamp(θ(F_v))` in degrees for the current field.
    pub target_range_degrees: [f64; 2],
    /// Profile updates (lowerings) made so far.
    pub updates: usize,
    /// The profile no longer changes.
    pub frozen: bool,
    /// Frozen and converged: further steps do nothing.
    pub converged: bool,
}

/// Optimises a field whose level sets are P-curves with an angle that varies from level to level
/// (Fig. 16). Stepwise like [`FieldSolver`]: create it, `step` it, read the report, `freeze` the
/// profile when the angles are low enough, step on until it converges.
///
/// Its per-vertex targets are not part of a [`FieldSolver`] session (`to_bytes`), which is why the
/// underlying solver is not handed out.
pub struct VaryingAngleSolver {
    solver: FieldSolver,
    params: VaryingAngleParams,
    fitted: AngleProfile,
    target: AngleProfile,
    updates: usize,
    /// Iterations since the last update of the profile.
    since_update: usize,
    frozen: bool,
    last_report: VaryingAngleReport,
}

impl VaryingAngleSolver {
    /// Prepares the optimisation of `initial_field` on `mesh`: fits the first profile to the
    /// angles of its level curves (no lowering yet). Parameters out of range give
    /// [`FieldError::InvalidParameter`]; so does an initial field with fewer than four distinct
    /// values at vertices whose angle can be measured (no cubic can be fitted).
    pub fn new(mesh: &TriMesh, initial_field: &[f64], params: VaryingAngleParams) -> Result<VaryingAngleSolver, FieldError> {
        validate(&params)?;
        let mut field_params = params.field.clone();
        field_params.family = Family::PseudoGeodesic { theta_degrees: 0.5 * (params.min_degrees + params.max_degrees) };
        let solver = FieldSolver::new(mesh, initial_field, field_params)?;
        let fitted = fit_measured(&solver).ok_or_else(|| FieldError::InvalidParameter {
            name: "initial_field",
            message: "fewer than four distinct field values at vertices with a measurable angle: θ(F) cannot be fitted".into(),
        })?;
        let mut varying = VaryingAngleSolver {
            solver,
            params,
            fitted,
            target: fitted,
            updates: 0,
            since_update: 0,
            frozen: false,
            last_report: VaryingAngleReport {
                field: StepReport::default(),
                fitted,
                target: fitted,
                target_range_degrees: [0.0; 2],
                updates: 0,
                frozen: false,
                converged: false,
            },
        };
        varying.apply_target(fitted);
        varying.frozen = varying.params.max_updates == 0;
        varying.last_report = varying.compose_report(varying.solver.report().clone());
        Ok(varying)
    }

    /// Runs at most `max_iterations` iterations, updating the profile every `update_interval`
    /// iterations (and whenever the field has converged to the current target) until it freezes.
    pub fn step(&mut self, max_iterations: usize) -> Result<VaryingAngleReport, FieldError> {
        let (mut ran, mut flips) = (0, 0);
        while ran < max_iterations && !self.is_converged() {
            if !self.frozen && (self.since_update >= self.params.update_interval || self.solver.is_converged()) {
                self.update();
            }
            let burst = if self.frozen { max_iterations - ran } else { (self.params.update_interval - self.since_update).min(max_iterations - ran) };
            let report = self.solver.step(burst.max(1))?;
            ran += report.iterations_this_step;
            flips += report.flips;
            self.since_update += report.iterations_this_step;
        }
        let field = StepReport { iterations_this_step: ran, flips, ..self.solver.report().clone() };
        self.last_report = self.compose_report(field);
        Ok(self.last_report.clone())
    }

    /// Stops lowering: the current targets stay fixed and the optimisation converges to them.
    pub fn freeze(&mut self) {
        self.frozen = true;
        self.last_report.frozen = true;
    }

    /// The report of the last `step` (or of the initial state).
    pub fn report(&self) -> &VaryingAngleReport {
        &self.last_report
    }

    pub fn is_frozen(&self) -> bool {
        self.frozen
    }

    /// The profile is frozen and the field has converged to it.
    pub fn is_converged(&self) -> bool {
        self.frozen && self.solver.is_converged()
    }

    /// The current field, one value per vertex, in the scale of the initial field.
    pub fn field(&self) -> Vec<f64> {
        self.solver.field()
    }

    /// Unit binormal per vertex (the auxiliary `b`), as [`FieldSolver::binormals`].
    pub fn binormals(&self) -> Vec<Vec3> {
        self.solver.binormals()
    }

    /// Unit side vector per vertex (the auxiliary `u`), as [`FieldSolver::side_vectors`].
    pub fn side_vectors(&self) -> Vec<Vec3> {
        self.solver.side_vectors()
    }

    /// The mesh in the caller's units, as [`FieldSolver::mesh`].
    pub fn mesh(&self) -> TriMesh {
        self.solver.mesh()
    }

    /// Iterations run since the solver was created.
    pub fn iterations(&self) -> usize {
        self.solver.iterations()
    }

    pub fn params(&self) -> &VaryingAngleParams {
        &self.params
    }

    /// The angles achieved along the level curves of the current field at `levels` (e.g. from
    /// [`crate::curves::uniform_levels`]), measured every [`LEVEL_ANGLE_SPACING`] mean edge
    /// lengths (see [`level_angles`]).
    pub fn level_angles(&self, levels: &[f64]) -> Result<Vec<LevelAngles>, CurveError> {
        let mesh = self.solver.mesh();
        let spacing = LEVEL_ANGLE_SPACING * mesh.mean_edge_length();
        level_angles(&mesh, &self.solver.field(), levels, spacing)
    }

    /// Refits the profile to the measured angles and lowers it; freezes after `max_updates`.
    /// If no cubic can be fitted (too few regular vertices) the previous profile is lowered again.
    fn update(&mut self) {
        if let Some(fitted) = fit_measured(&self.solver) {
            self.fitted = fitted;
        }
        let lowered = self.fitted.scaled(1.0 - self.params.lowering);
        self.apply_target(lowered);
        self.updates += 1;
        self.since_update = 0;
        self.frozen = self.updates >= self.params.max_updates;
    }

    /// Makes the target of every interior vertex `θ_v = clamp(target(F_v))`, a function of the
    /// vertex's current field value (so the rows of Eq. 8 also depend on `F_v`).
    fn apply_target(&mut self, target: AngleProfile) {
        self.target = target;
        self.solver.retarget(target, self.params.min_degrees, self.params.max_degrees);
    }

    fn compose_report(&self, field: StepReport) -> VaryingAngleReport {
        VaryingAngleReport {
            field,
            fitted: self.fitted,
            target: self.target,
            target_range_degrees: self.solver.target_range_degrees().unwrap_or([self.params.min_degrees, self.params.max_degrees]),
            updates: self.updates,
            frozen: self.frozen,
            converged: self.is_converged(),
        }
    }
}

/// The cubic fitted to `(F_v, θ_v)` over the regular interior vertices with a defined binormal.
fn fit_measured(solver: &FieldSolver) -> Option<AngleProfile> {
    let field = solver.field();
    let interior = solver.problem.interior();
    let angles = measured_angles(solver.problem.mesh(), solver.internal_field(), interior);
    let samples: Vec<(f64, f64)> = interior.iter().zip(angles).filter_map(|(&v, angle)| angle.flatten().map(|theta| (field[v as usize], theta))).collect();
    AngleProfile::fit(&samples)
}

fn validate(params: &VaryingAngleParams) -> Result<(), FieldError> {
    let invalid = |name, message: String| Err(FieldError::InvalidParameter { name, message });
    if !(params.lowering.is_finite() && (0.0..1.0).contains(&params.lowering)) {
        return invalid("lowering", format!("must lie in [0, 1), got {}", params.lowering));
    }
    if params.update_interval == 0 {
        return invalid("update_interval", "must be at least one iteration".into());
    }
    let (lo, hi) = (params.min_degrees, params.max_degrees);
    if !(lo.is_finite() && hi.is_finite() && 0.0 <= lo && lo < hi && hi <= 180.0) {
        return invalid("min_degrees/max_degrees", format!("need 0 ≤ min < max ≤ 180, got [{lo}, {hi}]"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::{check_block_jacobian, LeastSquaresProblem};
    use crate::surfaces::{sphere_cap, SphereCap};

    #[test]
    fn rows_with_a_field_dependent_target_have_exact_jacobians() {
        let cap = SphereCap { radius: 3.0, cap_angle: 0.6, target_vertices: 150, irregularity: 0.3, seed: 2 };
        let mesh = sphere_cap(&cap).expect("valid cap").into_mesh().expect("valid mesh");
        let field: Vec<f64> = mesh.positions().iter().map(|p| 0.8 * p.x + 0.5 * p.z + 0.1 * p.y * p.y).collect();
        let params = VaryingAngleParams { update_interval: 1, ..VaryingAngleParams::new() };
        let mut solver = VaryingAngleSolver::new(&mesh, &field, params).expect("valid input");
        solver.step(3).expect("solver runs");
        let problem = &solver.solver.problem;
        let x = &solver.solver.x;
        let mut varying = 0;
        for b in 0..problem.block_count() {
            let error = check_block_jacobian(problem, x, b, 1e-6);
            assert!(error < 1e-5, "block {b}: Jacobian error {error}");
        }
        for k in 0..problem.interior().len() {
            if problem.target(k, x).derivative != 0.0 {
                varying += 1;
            }
        }
        assert!(varying > 50, "only {varying} vertices have a field-dependent target");
    }
}
