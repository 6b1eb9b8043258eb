//! The stepwise net optimiser (Sec. 4.1–4.2): two fields (a net) or three (a 3-web, held to
//! Eq. 18) optimised together, each toward its family (Eq. 12), crossing at a controlled angle.
//! Stepped like [`crate::field::FieldSolver`].

use super::intersection::{self, IntersectionTerm};
use super::params::NetParams;
use super::problem::NetProblem;
use super::report::{IntersectionReport, NetReport, WebReport};
use crate::field::auxiliaries::{initialize_auxiliaries, reorient_side_vectors};
use crate::field::{problem_frames, stage_weights, FieldError, StepReport, Weights, SETTLING_ITERATIONS};
use crate::mesh::TriMesh;
use crate::solver::{LeastSquaresProblem, LevenbergMarquardt};

/// Optimises two fields on one mesh so that their level sets form a net of the requested
/// families, or three so that they form a 3-web.
///
/// As [`crate::field::FieldSolver`], it works on a copy of the mesh scaled to mean edge length 1,
/// each field scaled to mean `‖∇‖` 1. A net's fields are handed back in the scale of their start
/// fields; a 3-web's in one common scale (mean `‖∇‖` 1 in the mesh's units at the start), so
/// that `F + G + H = 0` holds in what is handed back.
pub struct NetSolver {
    /// The mesh as given (the caller's units).
    pub(super) given: TriMesh,
    pub(super) problem: NetProblem,
    pub(super) lm: LevenbergMarquardt,
    pub(super) params: NetParams,
    pub(super) x: Vec<f64>,
    /// Internal field `k` = caller field `k` × `field_scales[k]` (lengths are scaled to mean edge 1).
    pub(super) field_scales: Vec<f64>,
    pub(super) stage: usize,
    pub(super) stage_iterations: usize,
    pub(super) slow_iterations: usize,
    pub(super) iterations: usize,
    pub(super) converged: bool,
    pub(super) last_report: NetReport,
}

impl NetSolver {
    /// Prepares the optimisation of `fields` (one value per vertex each) on `mesh`: one field per
    /// family of `params` for a net; for a 3-web the first two (`F`, `H`), the third starting as
    /// `G := −F − H` after both are scaled to mean `‖∇‖` 1 (Sec. 4.2). A target intersection
    /// angle γ is read in the orientation the start fields have: of `±γ` and `±(180° − γ)`, the
    /// oriented angle nearest to their mean one.
    /// Errors: `InvalidParameter` naming the parameter, `FieldLength`, `NonFiniteValue`,
    /// `ValueOutOfRange` or `ConstantField` for a field (the first one found).
    pub fn new(mesh: &TriMesh, fields: &[Vec<f64>], mut params: NetParams) -> Result<NetSolver, FieldError> {
        params.validate()?;
        params.families.iter_mut().for_each(|f| *f = f.by_name());
        let given_fields = if params.is_web() { 2 } else { params.families.len() };
        if fields.len() != given_fields {
            let what = if params.is_web() { "a 3-web starts from its first two fields" } else { "a net needs one field per family" };
            return Err(FieldError::InvalidParameter { name: "fields", message: format!("{what}: expected {given_fields}, got {}", fields.len()) });
        }
        for field in fields {
            crate::field::validate_field(mesh, field)?;
        }
        let (unit_mesh, unit) = mesh.unit_scaled();
        let given = mesh.clone();
        let mut normalising = Vec::with_capacity(fields.len());
        for field in fields {
            let gradient = crate::field::mean_gradient_norm(&unit_mesh, field);
            if !(gradient > 0.0 && gradient.is_finite()) {
                return Err(FieldError::ConstantField);
            }
            normalising.push(1.0 / gradient);
        }
        let target = oriented_target(&unit_mesh, fields, &params);
        // A web's fields share one scale (mean ‖∇‖ 1 in the caller's units), as Eq. 18 needs.
        let field_scales = if params.is_web() { vec![unit; 3] } else { normalising.clone() };
        let mut solver = NetSolver::assemble(given, params, target, field_scales, 0)?;
        let n = mesh.vertex_count();
        for (k, (field, scale)) in fields.iter().zip(&normalising).enumerate() {
            let start = solver.problem.field_start(k);
            solver.x[start..start + n].iter_mut().zip(field).for_each(|(x, f)| *x = f * scale);
        }
        if solver.params.is_web() {
            let (first, third) = solver.x.split_at_mut(2 * n);
            for v in 0..n {
                third[v] = -first[v] - first[n + v];
            }
        }
        for (k, field) in solver.problem.fields().iter().enumerate() {
            initialize_auxiliaries(field, &mut solver.x[solver.problem.field_start(k)..]);
        }
        solver.last_report = solver.measure(0, 0);
        Ok(solver)
    }

    /// A solver on `given` (scaled to mean edge 1 inside) in weight stage `stage` with every
    /// variable zero, for the oriented target `(cos γ, sin γ)` of the intersection term.
    pub(super) fn assemble(
        given: TriMesh,
        params: NetParams,
        target: (f64, f64),
        field_scales: Vec<f64>,
        stage: usize,
    ) -> Result<NetSolver, FieldError> {
        let (unit_mesh, _) = given.unit_scaled();
        let (stage, weights) = stage_weights(&params.field, stage);
        let problem = NetProblem::new(&unit_mesh, &params.families, weights, &field_factors(&params, stage), intersection_term(&params, target), params.web_weight);
        let lm = LevenbergMarquardt::new(&problem, params.field.lm.clone())?;
        let x = vec![0.0; problem.variable_count()];
        Ok(NetSolver {
            given,
            problem,
            lm,
            params,
            x,
            field_scales,
            stage,
            stage_iterations: 0,
            slow_iterations: 0,
            iterations: 0,
            converged: false,
            last_report: NetReport::default(),
        })
    }

    /// Runs at most `max_iterations` Levenberg–Marquardt iterations and reports the state.
    pub fn step(&mut self, max_iterations: usize) -> Result<NetReport, FieldError> {
        rayon::scope(|_| self.run(max_iterations))
    }

    fn run(&mut self, max_iterations: usize) -> Result<NetReport, FieldError> {
        let mut ran = 0;
        let mut flips = 0;
        while ran < max_iterations && !self.converged {
            flips += self.reorient_side_vectors();
            let damping_before = self.lm.damping();
            let outcome = self.lm.iterate(&self.problem, &mut self.x).map_err(FieldError::Solver)?;
            ran += 1;
            self.iterations += 1;
            self.stage_iterations += 1;
            let decrease = outcome.energy_before - outcome.energy_after;
            // As in the single-field solver: a step the damping held back (its gain was so good
            // that μ fell by half or more) does not count as slow.
            if decrease <= self.params.field.relative_tolerance * outcome.energy_before && (!outcome.accepted || outcome.damping > 0.5 * damping_before) {
                self.slow_iterations += 1;
            } else {
                self.slow_iterations = 0;
            }
            let settled = outcome.converged.is_some() || !outcome.accepted || self.slow_iterations >= SETTLING_ITERATIONS;
            if self.stage == self.params.field.schedule.len() {
                self.converged = settled;
            } else if settled || self.stage_iterations >= self.params.field.schedule[self.stage].iterations {
                self.enter_stage(self.stage + 1);
            }
        }
        self.last_report = self.measure(ran, flips);
        Ok(self.last_report.clone())
    }

    /// The report of the last `step` (or of the initial state).
    pub fn report(&self) -> &NetReport {
        &self.last_report
    }

    /// Field `k`'s current values, one per vertex, in the scale of its initial field (a 3-web's:
    /// in their common scale). Panics if `k` is not below the family count.
    pub fn field(&self, k: usize) -> Vec<f64> {
        let start = self.problem.field_start(k);
        self.x[start..start + self.vertex_count()].iter().map(|f| f / self.field_scales[k]).collect()
    }

    /// Every field, in order.
    pub fn fields(&self) -> Vec<Vec<f64>> {
        (0..self.params.families.len()).map(|k| self.field(k)).collect()
    }

    /// The mesh in the caller's units, as given.
    pub fn mesh(&self) -> TriMesh {
        self.given.clone()
    }

    pub fn params(&self) -> &NetParams {
        &self.params
    }

    pub fn iterations(&self) -> usize {
        self.iterations
    }

    pub fn is_converged(&self) -> bool {
        self.converged
    }

    /// Replaces the remaining schedule by constant `weights` (every field's), held until convergence.
    pub fn set_weights(&mut self, weights: Weights) -> Result<(), FieldError> {
        let mut params = self.params.clone();
        params.field.schedule.clear();
        params.field.weights = weights;
        params.validate()?;
        self.params = params;
        self.enter_stage(0);
        Ok(())
    }

    fn vertex_count(&self) -> usize {
        self.problem.mesh().vertex_count()
    }

    fn enter_stage(&mut self, stage: usize) {
        let (stage, weights) = stage_weights(&self.params.field, stage);
        (self.stage, self.stage_iterations, self.slow_iterations, self.converged) = (stage, 0, 0, false);
        self.problem.set_weights(weights, &field_factors(&self.params, stage));
        self.lm.reset_damping();
    }

    /// The orientation test of Sec. 3.2.2 for every pseudo-geodesic field.
    fn reorient_side_vectors(&mut self) -> usize {
        let mut flips = 0;
        for (k, field) in self.problem.fields().iter().enumerate() {
            let view = &mut self.x[self.problem.field_start(k)..];
            let frames = problem_frames(field, view);
            flips += reorient_side_vectors(field, view, &frames);
        }
        flips
    }

    fn measure(&self, iterations_this_step: usize, flips: usize) -> NetReport {
        let families: Vec<StepReport> = self
            .problem
            .fields()
            .iter()
            .enumerate()
            .map(|(k, field)| {
                let view = &self.x[self.problem.field_start(k)..];
                StepReport::measure(field, view, None, &problem_frames(field, view))
            })
            .collect();
        let intersection = self.measure_intersection(0, 1);
        let web = self.params.is_web().then(|| self.measure_web());
        let total_energy = LevenbergMarquardt::evaluate_energy(&self.problem, &self.x);
        NetReport {
            iterations: self.iterations,
            iterations_this_step,
            stage: self.stage,
            families: families.into_iter().map(|r| StepReport { iterations: self.iterations, iterations_this_step, stage: self.stage, flips, damping: self.lm.damping(), converged: self.converged, ..r }).collect(),
            intersection,
            web,
            total_energy,
            damping: self.lm.damping(),
            converged: self.converged,
        }
    }

    /// How fields `a` and `b` cross (the target rows count for the pair 0–1 only).
    fn measure_intersection(&self, a: usize, b: usize) -> IntersectionReport {
        let mesh = self.problem.mesh();
        let n = self.vertex_count();
        let (f_field, g_field) = (&self.x[a * n..(a + 1) * n], &self.x[b * n..(b + 1) * n]);
        let targeted = (a, b) == (0, 1) && self.params.intersection_degrees.is_some();
        let unit = IntersectionTerm { target_weight: 1.0, min_weight: 1.0, ..*self.problem.intersection() };
        let mut report = IntersectionReport { min_degrees: 90.0, ..IntersectionReport::default() };
        let (mut weighted, mut area) = (0.0, 0.0);
        let mut residuals = [0.0; intersection::ROWS];
        for (f, angle) in intersection::intersection_angles(mesh, f_field, g_field).into_iter().enumerate() {
            let Some(angle) = angle else { continue };
            report.min_degrees = report.min_degrees.min(angle);
            weighted += angle * mesh.face_areas()[f];
            area += mesh.face_areas()[f];
            if angle < self.params.min_intersection_degrees {
                report.faces_below_min += 1;
            }
            residuals.fill(0.0);
            intersection::evaluate(mesh, &unit, f_field, g_field, f, &mut residuals, None);
            if targeted {
                report.target_energy += residuals[0] * residuals[0] + residuals[1] * residuals[1];
            }
            report.min_energy += residuals[2] * residuals[2];
        }
        report.mean_degrees = if area > 0.0 { weighted / area } else { 0.0 };
        report
    }

    /// Eq. 18's residual and how the third family crosses the other two.
    fn measure_web(&self) -> WebReport {
        let n = self.vertex_count();
        let range = (0..3)
            .map(|k| {
                let field = &self.x[k * n..(k + 1) * n];
                let (low, high) = field.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| (l.min(v), h.max(v)));
                high - low
            })
            .fold(0.0, f64::max);
        let (mut max, mut squares) = (0.0f64, 0.0);
        for v in 0..n {
            let r = (self.x[v] + self.x[n + v] + self.x[2 * n + v]).abs();
            max = max.max(r);
            squares += r * r;
        }
        let relative = |r: f64| if range > 0.0 { r / range } else { 0.0 };
        WebReport {
            residual_max: relative(max),
            residual_rms: relative((squares / n as f64).sqrt()),
            third_family_factor: field_factors(&self.params, self.stage)[2],
            intersections: [self.measure_intersection(0, 2), self.measure_intersection(1, 2)],
        }
    }
}

/// The factor on each field's terms in weight stage `stage`: 1, and for a 3-web's third field
/// [`NetParams::third_family_factor`].
fn field_factors(params: &NetParams, stage: usize) -> Vec<f64> {
    let mut factors = vec![1.0; params.families.len()];
    if params.is_web() {
        factors[2] = params.third_family_factor(stage);
    }
    factors
}

/// The target `(cos γ, sin γ)` of `params` for the start `fields`, oriented as the fields' mean
/// oriented angle is (see [`NetSolver::new`]); `(0, 1)` without a target.
fn oriented_target(mesh: &TriMesh, fields: &[Vec<f64>], params: &NetParams) -> (f64, f64) {
    match (params.intersection_degrees, intersection::mean_orientation(mesh, &fields[0], &fields[1])) {
        (Some(gamma), mean) => {
            let (c, s) = mean.unwrap_or((0.0, 1.0));
            let (sin, cos) = gamma.to_radians().sin_cos();
            let choices = [(cos, sin), (cos, -sin), (-cos, sin), (-cos, -sin)];
            // The first of the nearest choices (a strict comparison keeps the order's tie-break).
            choices.into_iter().fold((f64::NEG_INFINITY, (cos, sin)), |best, t| {
                let agreement = t.0 * c + t.1 * s;
                if agreement > best.0 { (agreement, t) } else { best }
            }).1
        }
        (None, _) => (0.0, 1.0),
    }
}

/// How far above the asked minimum intersection angle its hinge starts (degrees): a penalty
/// settles a little inside the region it penalises, and the margin makes that region lie above the
/// asked minimum, so the families cross at no less than it (on the hall roof's PP60 net the
/// smallest crossing was 29.96° of an asked 30° without it).
const MIN_ANGLE_MARGIN_DEGREES: f64 = 0.5;

/// The intersection term of `params` with the oriented `target`.
fn intersection_term(params: &NetParams, target: (f64, f64)) -> IntersectionTerm {
    let hinge_degrees = if params.min_intersection_degrees > 0.0 { (params.min_intersection_degrees + MIN_ANGLE_MARGIN_DEGREES).min(90.0) } else { 0.0 };
    let min_sine = hinge_degrees.to_radians().sin();
    let target_weight = if params.intersection_degrees.is_some() { params.intersection_weight } else { 0.0 };
    IntersectionTerm { target, target_weight, min_sine, min_weight: params.min_intersection_weight }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Family;
    use crate::solver::worst_block_jacobian;
    use crate::surfaces::hall_roof;

    #[test]
    fn every_block_of_a_net_has_the_jacobian_of_its_residuals() {
        let mesh = hall_roof(150).into_mesh().expect("roof");
        let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.1 * p.y * p.y).collect();
        let g: Vec<f64> = mesh.positions().iter().map(|p| p.y - 0.05 * p.x * p.x).collect();
        let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
        let mut params = NetParams::new(theta, theta);
        params.min_intersection_degrees = 89.0;
        params.intersection_degrees = Some(80.0);
        let solver = NetSolver::new(&mesh, &[f, g], params).expect("solver");
        let worst = worst_block_jacobian(&solver.problem, &solver.x, 1e-6);
        assert!(worst.0 < 1e-4, "block {} of {}: {}", worst.1, solver.problem.block_count(), worst.0);
    }

    #[test]
    fn every_block_of_a_web_has_the_jacobian_of_its_residuals() {
        let mesh = hall_roof(150).into_mesh().expect("roof");
        let f: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.1 * p.y * p.y).collect();
        let h: Vec<f64> = mesh.positions().iter().map(|p| p.y - 0.05 * p.x * p.x).collect();
        let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
        let mut params = NetParams::web(theta, Family::Asymptotic, Family::Geodesic);
        params.min_intersection_degrees = 89.0;
        params.intersection_degrees = Some(80.0);
        let mut solver = NetSolver::new(&mesh, &[f, h], params).expect("solver");
        // Off Eq. 18, so that its rows are not zero.
        let n = mesh.vertex_count();
        solver.x[2 * n..3 * n].iter_mut().enumerate().for_each(|(v, g)| *g += 0.01 * (v % 7) as f64);
        let worst = worst_block_jacobian(&solver.problem, &solver.x, 1e-6);
        assert!(worst.0 < 1e-4, "block {} of {}: {}", worst.1, solver.problem.block_count(), worst.0);
    }
}
