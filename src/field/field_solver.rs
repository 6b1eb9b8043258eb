//! The stepwise field optimiser (Sec. 3.2.2): create it, `step` it a few iterations at a
//! time, read the field and the binormals in between, change the weights, continue.

use super::auxiliaries::{auxiliary, initialize_auxiliaries, reorient_side_vectors};
use super::darboux::LevelFrame;
use super::error::FieldError;
use super::failure_site::largest_residual_vertices;
use super::gradient_norm::mean_gradient_norm;
use super::params::{Family, FieldParams, Weights, FAMILY_MET_CURVE_ENERGY, PAPER_ANGLE_ENERGY, SETTLED_CURVE_ENERGY, SETTLING_ITERATIONS};
use super::plateau::Plateau;
use super::problem::FieldProblem;
use super::report::{curve_energy, curve_squares, curve_total, problem_frames, Evaluated, StepReport};
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{LeastSquaresProblem, LevenbergMarquardt, LmOptions, SolverError, SplitWork};

/// The factors between the caller's units and the normalised problem.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub(crate) struct Scales {
    /// Internal field = caller field × `field`.
    pub field: f64,
    /// Internal lengths = caller lengths × `length`.
    pub length: f64,
}

/// Largest magnitude of a field value accepted by [`FieldSolver::new`] and by the level-curve
/// functions: 1e100. Far beyond any useful field (values are level labels, e.g. coordinates in
/// metres), and small enough that gradients and their squares stay finite on any valid mesh.
pub const FIELD_VALUE_LIMIT: f64 = 1e100;

/// Optimises a scalar field so that its level sets form the requested curve family.
///
/// The optimisation runs on a copy of the mesh scaled to mean edge length 1, with the field
/// scaled to mean `‖∇F‖` 1 (Sec. 3.2.2), so the default weights suit any input; every value
/// handed back is in the caller's units.
pub struct FieldSolver {
    pub(super) problem: FieldProblem,
    pub(super) lm: LevenbergMarquardt,
    pub(super) params: FieldParams,
    /// Variables of the normalised problem: field, then auxiliaries.
    pub(super) x: Vec<f64>,
    pub(super) scales: Scales,
    pub(super) stage: usize,
    pub(super) stage_iterations: usize,
    /// Consecutive iterations of the current stage that lowered `E_pg` by less than the relative tolerance.
    pub(super) slow_iterations: usize,
    /// The level curves' best measure in the final stage ([`super::plateau`]).
    pub(super) plateau: Plateau,
    /// A short solve of a fixed length ([`Self::set_short_solve`]): no plateau test.
    short_solve: bool,
    pub(super) iterations: usize,
    pub(super) converged: bool,
    pub(super) last_report: StepReport,
    /// Level frames at the curve vertices for the current field values (`None` once the
    /// field has moved): measured for the report, reused by the next orientation test.
    frames: Option<Vec<Option<LevelFrame>>>,
}

impl FieldSolver {
    /// Prepares the optimisation of `initial_field` (one value per vertex) on `mesh`.
    /// The family is taken by name ([`super::Family::by_name`]): a pseudo-geodesic angle of 0°,
    /// 90° or 180° optimises the asymptotic or geodesic energy of Eq. 13.
    pub fn new(mesh: &TriMesh, initial_field: &[f64], params: FieldParams) -> Result<FieldSolver, FieldError> {
        Self::prepare(mesh, initial_field, params, SplitWork::Span)
    }

    /// [`Self::new`] for a solve that runs beside another one, sharing the two cores (a probe of
    /// the start search): its reduced matrix is split only where that lowers the work of both
    /// domains together.
    pub(crate) fn new_sharing_cores(mesh: &TriMesh, initial_field: &[f64], params: FieldParams) -> Result<FieldSolver, FieldError> {
        Self::prepare(mesh, initial_field, params, SplitWork::Total)
    }

    fn prepare(mesh: &TriMesh, initial_field: &[f64], mut params: FieldParams, work: SplitWork) -> Result<FieldSolver, FieldError> {
        validate_params(&params)?;
        params.family = params.family.by_name();
        validate_field(mesh, initial_field)?;
        let (unit_mesh, length_scale) = mesh.unit_scaled();
        let gradient = mean_gradient_norm(&unit_mesh, initial_field);
        if !(gradient > 0.0 && gradient.is_finite()) {
            return Err(FieldError::ConstantField);
        }
        let field_scale = 1.0 / gradient;
        let gradient_target = params.gradient_target.map_or(1.0, |r| r * field_scale / length_scale);
        let mut x: Vec<f64> = initial_field.iter().map(|f| f * field_scale).collect();
        let mut solver = FieldSolver::assemble(unit_mesh, params, gradient_target, Scales { field: field_scale, length: length_scale }, work)?;
        x.resize(solver.x.len(), 0.0);
        solver.x = x;
        solver.initialize_auxiliaries();
        solver.last_report = solver.measure(0, 0, None);
        Ok(solver)
    }

    /// Starts over from `initial_field` with `params` (same family; schedule, weights, gradient
    /// target and tolerances may differ), keeping the prepared problem and the solver's symbolic
    /// analysis: what trying many starts on one mesh needs (see
    /// [`crate::initialisation::StartSearch`]). Errors as [`Self::new`], and
    /// `InvalidParameter { name: "family" }` for another family.
    pub fn restart(&mut self, initial_field: &[f64], mut params: FieldParams) -> Result<(), FieldError> {
        validate_params(&params)?;
        params.family = params.family.by_name();
        if params.family != self.problem.family() {
            return Err(FieldError::InvalidParameter { name: "family", message: "a restart keeps the solver's family".into() });
        }
        validate_field(self.problem.mesh(), initial_field)?;
        let gradient = mean_gradient_norm(self.problem.mesh(), initial_field);
        if !(gradient > 0.0 && gradient.is_finite()) {
            return Err(FieldError::ConstantField);
        }
        let field_scale = 1.0 / gradient;
        let length = self.scales.length;
        self.problem.set_gradient_target(params.gradient_target.map_or(1.0, |r| r * field_scale / length));
        self.scales = Scales { field: field_scale, length };
        self.params = params;
        self.x.iter_mut().for_each(|x| *x = 0.0);
        for (x, f) in self.x.iter_mut().zip(initial_field) {
            *x = f * field_scale;
        }
        self.iterations = 0;
        self.short_solve = false;
        self.frames = None;
        self.enter_stage(0);
        self.initialize_auxiliaries();
        self.last_report = self.measure(0, 0, None);
        Ok(())
    }

    /// A solver in its first stage with all variables zero, on an already unit-scaled mesh, its
    /// reduced matrix split where that lowers `work`.
    pub(crate) fn assemble(unit_mesh: TriMesh, params: FieldParams, gradient_target: f64, scales: Scales, work: SplitWork) -> Result<FieldSolver, FieldError> {
        let (stage, weights) = stage_weights(&params, 0);
        let problem = FieldProblem::new(unit_mesh, params.family, weights, gradient_target);
        let lm = LevenbergMarquardt::with_split_work(&problem, params.lm.clone(), work)?;
        let x = vec![0.0; problem.variable_count()];
        Ok(FieldSolver {
            problem,
            lm,
            params,
            x,
            scales,
            stage,
            stage_iterations: 0,
            slow_iterations: 0,
            plateau: Plateau::default(),
            short_solve: false,
            iterations: 0,
            converged: false,
            last_report: StepReport::default(),
            frames: None,
        })
    }

    /// Runs at most `max_iterations` Levenberg–Marquardt iterations and reports the state.
    pub fn step(&mut self, max_iterations: usize) -> Result<StepReport, FieldError> {
        // On a thread of the rayon pool, the many short parallel passes of an iteration fork
        // from a worker instead of each injecting its work into the pool from outside and
        // sleeping until it is done (which costs a wake-up of both sides per pass).
        rayon::scope(|_| self.run(max_iterations))
    }

    /// A failed iteration's error with the vertices of the largest residuals at the current
    /// variables (unchanged by the failed iteration).
    fn located(&self, error: SolverError) -> FieldError {
        match error {
            SolverError::FactorizationFailed { .. } | SolverError::NonFiniteResidual { .. } | SolverError::NonFiniteJacobian { .. } => {
                let vertices = largest_residual_vertices(&self.problem, &self.x, self.vertex_count());
                FieldError::SolverFailedNear { error, vertices }
            }
            other => FieldError::Solver(other),
        }
    }

    /// [`Self::step`], on the calling thread.
    fn run(&mut self, max_iterations: usize) -> Result<StepReport, FieldError> {
        let mut flips = 0;
        let mut ran = 0;
        // The weights of the last iteration, whose accepted residuals the report can reuse.
        let mut iterated_weights = None;
        while ran < max_iterations && !self.converged {
            flips += self.reorient_side_vectors();
            self.fit_free_slope();
            iterated_weights = Some(self.problem.weights());
            let damping_before = self.lm.damping();
            let outcome = self.lm.iterate(&self.problem, &mut self.x).map_err(|error| self.located(error))?;
            if outcome.accepted {
                self.frames = None;
            }
            ran += 1;
            self.iterations += 1;
            self.stage_iterations += 1;
            let decrease = outcome.energy_before - outcome.energy_after;
            // A small decrease counts as slow unless the damping held the step back (its gain
            // ratio was so good that μ fell by half or more) while the family is still far: a
            // solve that has just entered a stage takes several such steps while μ falls from
            // its restart value. Once the family is met, what is left is the regularisers' drift.
            let slow = decrease <= self.params.relative_tolerance * outcome.energy_before
                && (!outcome.accepted || outcome.damping > 0.5 * damping_before || self.family_met());
            if slow {
                self.slow_iterations += 1;
            } else {
                self.slow_iterations = 0;
            }
            let settled = outcome.converged.is_some() || !outcome.accepted || self.slow_iterations >= SETTLING_ITERATIONS;
            let final_stage = self.stage == self.params.schedule.len();
            if final_stage {
                self.converged = settled || self.curves_settled() || (outcome.accepted && self.level_curves_settled());
            } else if settled || self.stage_iterations >= self.params.schedule[self.stage].iterations {
                self.enter_stage(self.stage + 1);
            }
        }
        self.last_report = self.measure(ran, flips, iterated_weights);
        Ok(self.last_report.clone())
    }

    /// The slope β in degrees a constant-slope family aims at (for a free slope, the one fitted
    /// to the field before the last iteration); `None` for the other families.
    pub fn slope_degrees(&self) -> Option<f64> {
        self.problem.slope_axis().map(|_| self.problem.target(0).degrees)
    }

    /// A free slope (Eq. 22 with γ unknown) is set, before every iteration, to the one that
    /// minimises `E_slope` for the current field: `sin β` the area-weighted mean of `t·d` over the
    /// curve vertices that reach the present slope. Block-coordinate descent on the same energy
    /// the iteration then lowers with β held.
    fn fit_free_slope(&mut self) {
        let Family::ConstantSlope { free_slope: true, .. } = self.problem.family() else { return };
        let Some(axis) = self.problem.slope_axis() else { return };
        let frames = self.take_frames();
        let areas = self.problem.mesh().normalized_vertex_areas();
        let (mut sum, mut weight) = (0.0, 0.0);
        for (k, frame) in frames.iter().enumerate() {
            if let (Some(frame), true) = (frame, self.problem.slope_reachable(k)) {
                let area = areas[self.problem.curve_vertices()[k] as usize];
                sum += area * frame.tangent.dot(&axis);
                weight += area;
            }
        }
        self.frames = Some(frames);
        if weight > 0.0 {
            self.problem.set_slope((sum / weight).clamp(-1.0, 1.0).asin().to_degrees());
        }
    }

    /// The report of the last `step` (or of the initial state).
    pub fn report(&self) -> &StepReport {
        &self.last_report
    }

    /// The current field, one value per vertex, in the scale of the initial field.
    pub fn field(&self) -> Vec<f64> {
        self.x[..self.vertex_count()].iter().map(|f| f / self.scales.field).collect()
    }

    /// Unit binormal per vertex: the auxiliary `b` for pseudo-geodesics, the discrete
    /// binormal of the level polyline otherwise; zero at boundary and singular vertices
    /// and where the level polyline is straight.
    pub fn binormals(&self) -> Vec<Vec3> {
        self.per_curve_vertex(|solver, k, frame| match solver.problem.family() {
            Family::PseudoGeodesic { .. } => solver.auxiliary(k, 0).try_normalize(0.0),
            Family::Geodesic | Family::Asymptotic | Family::ConstantSlope { .. } => frame.binormal,
        })
    }

    /// Unit side vector `u` of the Darboux frame per vertex (Eq. 10); zero at boundary and singular vertices.
    pub fn side_vectors(&self) -> Vec<Vec3> {
        self.per_curve_vertex(|solver, k, frame| match solver.problem.family() {
            Family::PseudoGeodesic { .. } => solver.auxiliary(k, 3).try_normalize(0.0),
            Family::Geodesic | Family::Asymptotic | Family::ConstantSlope { .. } => Some(frame.side),
        })
    }

    /// Marks this solve as a short one of a fixed length (the start search's probes), until the
    /// next [`Self::restart`]: the level curves are not measured for the convergence test
    /// ([`super::plateau`]), so that every probe runs the same iterations.
    pub(crate) fn set_short_solve(&mut self) {
        self.short_solve = true;
    }

    /// Replaces the remaining schedule by constant `weights` held until convergence.
    pub fn set_weights(&mut self, weights: Weights) -> Result<(), FieldError> {
        validate_weights(&weights)?;
        self.params.schedule.clear();
        self.params.weights = weights;
        self.enter_stage(0);
        Ok(())
    }

    /// Gives each curve vertex its own target angle (degrees, one per entry of the problem's
    /// `curve_vertices`, validated by the caller) and restarts the convergence test: the energy changed.
    pub(super) fn retarget(&mut self, degrees: &[f64]) {
        self.problem.set_vertex_targets(degrees);
        self.slow_iterations = 0;
        self.plateau = Plateau::default();
        self.converged = false;
        self.last_report = self.measure(0, 0, None);
    }

    /// The mesh in the caller's units: the solver's unit-scaled copy scaled back (the input
    /// mesh up to rounding, and the same for a session restored by `from_bytes`).
    pub fn mesh(&self) -> TriMesh {
        self.problem.mesh().scaled(1.0 / self.scales.length)
    }

    pub fn params(&self) -> &FieldParams {
        &self.params
    }

    pub fn iterations(&self) -> usize {
        self.iterations
    }

    pub fn is_converged(&self) -> bool {
        self.converged
    }

    fn vertex_count(&self) -> usize {
        self.problem.mesh().vertex_count()
    }

    fn auxiliary(&self, k: usize, offset: usize) -> Vec3 {
        auxiliary(&self.problem, &self.x, k, offset)
    }

    /// `value(self, k, frame)` at each regular curve vertex (the `k`-th, with its level frame);
    /// zero elsewhere.
    fn per_curve_vertex(&self, value: impl Fn(&Self, usize, &LevelFrame) -> Option<Vec3>) -> Vec<Vec3> {
        let mut out = vec![Vec3::zeros(); self.vertex_count()];
        for (k, &v) in self.problem.curve_vertices().iter().enumerate() {
            if let Some(frame) = self.problem.level_frame(k, &self.x) {
                out[v as usize] = value(self, k, &frame).unwrap_or_else(Vec3::zeros);
            }
        }
        out
    }

    fn enter_stage(&mut self, stage: usize) {
        let (stage, weights) = stage_weights(&self.params, stage);
        self.stage = stage;
        self.stage_iterations = 0;
        self.slow_iterations = 0;
        self.plateau = Plateau::default();
        self.converged = false;
        self.problem.set_weights(weights);
        self.lm.reset_damping();
    }

    /// Starts the auxiliaries `b`, `u` (Sec. 3.2.2, [`super::auxiliaries`]).
    fn initialize_auxiliaries(&mut self) {
        initialize_auxiliaries(&self.problem, &mut self.x);
    }

    /// The orientation test of Sec. 3.2.2 ([`reorient_side_vectors`]). The level frames are
    /// those the last report measured at this field, or are measured now.
    fn reorient_side_vectors(&mut self) -> usize {
        let frames = self.take_frames();
        let flips = reorient_side_vectors(&self.problem, &mut self.x, &frames);
        // Still the frames of the current field: only side vectors moved.
        self.frames = Some(frames);
        flips
    }

    /// The level frames of the current field at the curve vertices, measured (in parallel)
    /// unless kept from the last measurement.
    fn take_frames(&mut self) -> Vec<Option<LevelFrame>> {
        let frames = self.frames.take();
        frames.unwrap_or_else(|| problem_frames(&self.problem, &self.x))
    }

    /// [`curve_squares`] at x from the residuals of the accepted iteration.
    fn accepted_curve_squares(&self) -> Vec<(f64, f64)> {
        let accepted = |b| self.lm.accepted_residuals(b);
        let evaluated = Evaluated { weights: self.problem.weights(), residuals: &accepted };
        curve_squares(&self.problem, &self.x, Some(&evaluated))
    }

    /// Whether the unweighted curve terms at x ([`curve_energy`], from the residuals of the
    /// accepted iteration), per curve vertex, are within [`FAMILY_MET_CURVE_ENERGY`].
    fn family_met(&self) -> bool {
        self.family_met_in(&self.accepted_curve_squares())
    }

    /// [`Self::family_met`] for the curve blocks' `squares` ([`curve_squares`]).
    fn family_met_in(&self, squares: &[(f64, f64)]) -> bool {
        let curve_vertices = self.problem.curve_vertices().len().max(1) as f64;
        curve_total(squares) <= FAMILY_MET_CURVE_ENERGY * curve_vertices
    }

    /// Whether the unweighted curve terms at x ([`curve_energy`]) have fallen to
    /// [`SETTLED_CURVE_ENERGY`], after an accepted iteration. The residuals it evaluated at x give
    /// them up to rounding ([`Evaluated`]); only within twice the threshold are they evaluated
    /// again, exactly, with unit weights.
    fn curves_settled(&self) -> bool {
        if curve_total(&self.accepted_curve_squares()) > 2.0 * SETTLED_CURVE_ENERGY {
            return false;
        }
        curve_energy(&self.problem, &self.x, None) <= SETTLED_CURVE_ENERGY
    }

    /// Whether the level curves, measured from outside every few final-stage iterations once the
    /// family is met and `E_angle` is within [`PAPER_ANGLE_ENERGY`], have stopped improving
    /// ([`super::plateau`]). Not for per-vertex targets (a varying angle), which that measure
    /// does not know.
    fn level_curves_settled(&mut self) -> bool {
        let family = self.problem.family();
        let vertices = self.vertex_count();
        if self.short_solve || !Plateau::due(self.stage_iterations, family, vertices) || self.problem.has_vertex_targets() {
            return false;
        }
        let squares = self.accepted_curve_squares();
        if !self.family_met_in(&squares) || squares.iter().map(|(angle, _)| angle).sum::<f64>() > PAPER_ANGLE_ENERGY {
            return false;
        }
        self.plateau.settled(self.problem.mesh(), &self.x[..vertices], family)
    }

    /// The report at x. `iterated_weights`: the weights of the iteration that moved to x, whose
    /// residuals there the solver kept (the energies are taken from them).
    fn measure(&mut self, iterations_this_step: usize, flips: usize, iterated_weights: Option<Weights>) -> StepReport {
        let frames = self.take_frames();
        let accepted = |b| self.lm.accepted_residuals(b);
        let evaluated = iterated_weights.map(|weights| Evaluated { weights, residuals: &accepted });
        let report = StepReport {
            iterations: self.iterations,
            iterations_this_step,
            stage: self.stage,
            flips,
            damping: self.lm.damping(),
            converged: self.converged,
            ..StepReport::measure(&self.problem, &self.x, evaluated.as_ref(), &frames)
        };
        self.frames = Some(frames);
        report
    }
}

pub(crate) fn stage_weights(params: &FieldParams, stage: usize) -> (usize, Weights) {
    match params.schedule.get(stage) {
        Some(s) => (stage, s.weights),
        None => (params.schedule.len(), params.weights),
    }
}

pub(crate) fn validate_field(mesh: &TriMesh, field: &[f64]) -> Result<(), FieldError> {
    if field.len() != mesh.vertex_count() {
        return Err(FieldError::FieldLength { expected: mesh.vertex_count(), actual: field.len() });
    }
    if let Some(vertex) = field.iter().position(|f| !f.is_finite()) {
        return Err(FieldError::NonFiniteValue { vertex });
    }
    if let Some(vertex) = field.iter().position(|f| f.abs() > FIELD_VALUE_LIMIT) {
        return Err(FieldError::ValueOutOfRange { vertex, value: field[vertex] });
    }
    let (min, max) = field.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &f| (lo.min(f), hi.max(f)));
    if max - min <= 1e-12 * max.abs().max(min.abs()) {
        return Err(FieldError::ConstantField);
    }
    Ok(())
}

fn validate_weights(w: &Weights) -> Result<(), FieldError> {
    for (name, value) in [("weights.fair", w.fair), ("weights.grad", w.grad), ("weights.angle", w.angle)] {
        if !(value.is_finite() && value >= 0.0) {
            return Err(FieldError::InvalidParameter { name, message: format!("must be finite and ≥ 0, got {value}") });
        }
    }
    Ok(())
}

pub(crate) fn validate_params(params: &FieldParams) -> Result<(), FieldError> {
    if let Family::ConstantSlope { axis, slope_degrees, .. } = params.family {
        validate_slope(axis, slope_degrees)?;
    } else {
        let theta = params.family.theta_degrees();
        if !(theta.is_finite() && (0.0..=180.0).contains(&theta)) {
            return Err(FieldError::InvalidParameter { name: "theta", message: format!("must lie in [0°, 180°], got {theta}") });
        }
    }
    validate_weights(&params.weights)?;
    for stage in &params.schedule {
        validate_weights(&stage.weights)?;
        if stage.iterations == 0 {
            return Err(FieldError::InvalidParameter { name: "schedule", message: "every stage needs at least one iteration".into() });
        }
    }
    if let Some(r) = params.gradient_target {
        if !(r.is_finite() && r > 0.0) {
            return Err(FieldError::InvalidParameter { name: "gradient_target", message: format!("must be finite and > 0, got {r}") });
        }
    }
    if !(params.relative_tolerance.is_finite() && params.relative_tolerance >= 0.0) {
        return Err(FieldError::InvalidParameter { name: "relative_tolerance", message: "must be finite and ≥ 0".into() });
    }
    validate_lm(&params.lm)
}

/// The axis of a constant-slope family is finite and not zero, its slope finite and in (−90°, 90°).
fn validate_slope(axis: [f64; 3], slope_degrees: f64) -> Result<(), FieldError> {
    let length = Vec3::from(axis).norm();
    if !(axis.iter().all(|a| a.is_finite()) && length > 0.0 && length.is_finite()) {
        return Err(FieldError::InvalidParameter { name: "axis", message: format!("must be finite and not zero, got {axis:?}") });
    }
    if !(slope_degrees.is_finite() && slope_degrees.abs() < 90.0) {
        return Err(FieldError::InvalidParameter { name: "slope", message: format!("must lie in (−90°, 90°), got {slope_degrees}") });
    }
    Ok(())
}

/// Most damped solves one iteration may try ([`LmOptions::max_trials`]): each costs a
/// factorisation, so this bounds the time of an iteration.
pub const MAX_LM_TRIALS: usize = 100;

/// The Levenberg–Marquardt options are finite and ordered, with 1 to [`MAX_LM_TRIALS`] trials.
pub(crate) fn validate_lm(lm: &LmOptions) -> Result<(), FieldError> {
    let bad = |name: &'static str, message: String| Err(FieldError::InvalidParameter { name, message });
    if !(1..=MAX_LM_TRIALS).contains(&lm.max_trials) {
        return bad("lm.max_trials", format!("must be 1 to {MAX_LM_TRIALS}, got {}", lm.max_trials));
    }
    let tolerances = [("lm.gradient_tolerance", lm.gradient_tolerance), ("lm.step_tolerance", lm.step_tolerance), ("lm.energy_tolerance", lm.energy_tolerance)];
    for (name, value) in tolerances {
        if !(value.is_finite() && value >= 0.0) {
            return bad(name, format!("must be finite and ≥ 0, got {value}"));
        }
    }
    let positive = [("lm.tau", lm.tau), ("lm.min_damping", lm.min_damping), ("lm.max_damping", lm.max_damping)];
    for (name, value) in positive {
        if !(value.is_finite() && value > 0.0) {
            return bad(name, format!("must be finite and > 0, got {value}"));
        }
    }
    if lm.min_damping > lm.max_damping {
        return bad("lm.min_damping", format!("{} exceeds lm.max_damping {}", lm.min_damping, lm.max_damping));
    }
    Ok(())
}
