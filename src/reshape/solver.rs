//! The stepwise surface optimiser of Sec. 3.3: create it, `step` it a few iterations at a time,
//! read the moved surface and its deviation in between, continue.

use super::curve_star::CurveStar;
use super::error::ReshapeError;
use super::linearisation::{Linearisation, Original};
use super::params::{ReshapeParams, GUARD_GROWTH};
use super::problem::SurfaceProblem;
use super::report::{star_angle_errors, ReshapeEnergies, ReshapeReport};
use crate::field::pseudo_geodesic::AUXILIARIES;
use crate::field::{validate_field, validate_lm, FieldError, SETTLING_ITERATIONS};
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{DampingState, LeastSquaresProblem, LevenbergMarquardt};

/// Most times the tolerance guard is raised ([`GUARD_GROWTH`] each) before the solve stops.
pub const MAX_GUARD_RAISES: usize = 12;

/// Moves the vertices of a mesh so that the level sets of a fixed field become P-curves of the
/// angle θ (Sec. 3.3, Fig. 17), within a bound on the deviation from the original surface.
///
/// The optimisation runs on a copy of the mesh scaled to mean edge length 1, so the default
/// (Table 3) weights suit any input; every value handed back is in the caller's units.
pub struct ReshapeSolver {
    pub(super) problem: SurfaceProblem,
    pub(super) original: Original,
    /// The original surface as given (the caller's units), for saving the session.
    pub(super) given: TriMesh,
    pub(super) lm: LevenbergMarquardt,
    pub(super) params: ReshapeParams,
    /// Positions (xyz per vertex), then `[b, u]` per curve vertex.
    pub(super) x: Vec<f64>,
    /// The variables before the last step, to undo it.
    pub(super) previous: Vec<f64>,
    pub(super) field: Vec<f64>,
    /// Internal lengths = caller lengths × `length_scale`.
    length_scale: f64,
    /// The tolerance in internal lengths.
    tolerance: f64,
    pub(super) iterations: usize,
    pub(super) slow_iterations: usize,
    pub(super) guard_raises: usize,
    pub(super) converged: bool,
    pub(super) last_report: ReshapeReport,
}

impl ReshapeSolver {
    /// Prepares the optimisation of `mesh` for the level sets of `field` (one value per vertex,
    /// fixed). Errors name the offending parameter or vertex.
    pub fn new(mesh: &TriMesh, field: &[f64], params: ReshapeParams) -> Result<ReshapeSolver, ReshapeError> {
        ReshapeSolver::resume(mesh, mesh, field, params)
    }

    /// [`Self::new`] starting from `moved`, an earlier result on `original` (same faces): the
    /// deviation, `v_ori` of Eq. 14 and `l*` of Eq. 15 still refer to `original`. What the
    /// alternating schedule ([`super::AlternatingSolver`]) needs after each field step.
    pub fn resume(original: &TriMesh, moved: &TriMesh, field: &[f64], params: ReshapeParams) -> Result<ReshapeSolver, ReshapeError> {
        validate_params(&params)?;
        validate_field(original, field)?;
        if moved.faces() != original.faces() || moved.vertex_count() != original.vertex_count() {
            return Err(ReshapeError::InvalidParameter { name: "moved", message: "the moved mesh must have the original's vertices and faces".into() });
        }
        let (unit_mesh, length_scale) = original.unit_scaled();
        let (low, high) = original.bounding_box();
        let tolerance = params.tolerance.length((high - low).norm()) * length_scale;
        let curves = CurveStar::all(&unit_mesh, field);
        if curves.is_empty() {
            return Err(ReshapeError::NoCurveVertices);
        }
        let start = moved.try_scaled(length_scale)?;
        let given = original.clone();
        let original = Original::new(unit_mesh.clone());
        let lin = Linearisation::new(start.clone(), &curves, &original);
        let problem = SurfaceProblem::new(&unit_mesh, curves, lin, params.weights, params.theta_degrees);
        let lm = LevenbergMarquardt::new(&problem, params.lm.clone())?;
        let mut x = vec![0.0; problem.variable_count()];
        for (chunk, p) in x.chunks_exact_mut(3).zip(start.positions()) {
            chunk.copy_from_slice(p.as_slice());
        }
        let mut solver = ReshapeSolver {
            previous: x.clone(),
            problem,
            original,
            given,
            lm,
            params,
            x,
            field: field.to_vec(),
            length_scale,
            tolerance,
            iterations: 0,
            slow_iterations: 0,
            guard_raises: 0,
            converged: false,
            last_report: ReshapeReport::default(),
        };
        solver.initialize_auxiliaries();
        solver.last_report = solver.measure(0, 0, 0);
        Ok(solver)
    }

    /// Runs at most `max_iterations` Levenberg–Marquardt iterations and reports the state.
    pub fn step(&mut self, max_iterations: usize) -> Result<ReshapeReport, ReshapeError> {
        rayon::scope(|_| self.run(max_iterations))
    }

    fn run(&mut self, max_iterations: usize) -> Result<ReshapeReport, ReshapeError> {
        let (mut ran, mut flips, mut undone) = (0, 0, 0);
        while ran < max_iterations && !self.converged {
            flips += self.reorient_side_vectors();
            self.previous.copy_from_slice(&self.x);
            let outcome = self.lm.iterate(&self.problem, &mut self.x)?;
            ran += 1;
            self.iterations += 1;
            let mut accepted = outcome.accepted;
            if accepted {
                self.shorten_step();
            }
            if accepted && !self.relinearise() {
                accepted = false;
                undone += 1;
            }
            let slow = !accepted || outcome.energy_before - outcome.energy_after <= self.params.relative_tolerance * outcome.energy_before;
            self.slow_iterations = if slow { self.slow_iterations + 1 } else { 0 };
            self.converged = outcome.converged.is_some()
                || (!outcome.accepted && outcome.trials >= self.params.lm.max_trials)
                || self.slow_iterations >= SETTLING_ITERATIONS
                || self.guard_raises > MAX_GUARD_RAISES;
        }
        self.last_report = self.measure(ran, flips, undone);
        Ok(self.last_report.clone())
    }

    /// Shortens the step just taken so that no vertex moves more than `max_vertex_step`.
    fn shorten_step(&mut self) {
        let n = 3 * self.vertex_count();
        let longest = self.x[..n].chunks_exact(3).zip(self.previous[..n].chunks_exact(3)).fold(0.0f64, |m, (a, b)| {
            m.max(((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt())
        });
        if longest > self.params.max_vertex_step {
            let factor = self.params.max_vertex_step / longest;
            for (x, p) in self.x.iter_mut().zip(&self.previous) {
                *x = p + (*x - p) * factor;
            }
        }
    }

    /// After an accepted step: rebuilds the mesh at the new positions and the frozen quantities
    /// on it. Undoes the step (and returns `false`) when the moved mesh is not valid (the damping
    /// then grows) or leaves the tolerance (the guard on the normal part of Eq. 14 then grows).
    fn relinearise(&mut self) -> bool {
        let positions: Vec<Vec3> = self.x.chunks_exact(3).take(self.vertex_count()).map(Vec3::from_column_slice).collect();
        let moved = TriMesh::from_vertices_and_faces(positions, self.problem.lin.mesh.faces().to_vec());
        let Ok(mesh) = moved else {
            self.x.copy_from_slice(&self.previous);
            let mu = self.lm.damping() * GUARD_GROWTH;
            self.lm.restore_damping(DampingState { mu: Some(mu), nu: 2.0 });
            return false;
        };
        let lin = Linearisation::new(mesh, self.problem.curves(), &self.original);
        if lin.anchors.iter().any(|a| a.distance > self.tolerance) {
            self.x.copy_from_slice(&self.previous);
            self.problem.guard *= GUARD_GROWTH;
            self.guard_raises += 1;
            self.slow_iterations = 0;
            self.lm.reset_damping();
            return false;
        }
        self.problem.lin = lin;
        true
    }

    /// The report of the last `step` (or of the initial state).
    pub fn report(&self) -> &ReshapeReport {
        &self.last_report
    }

    /// The current surface in the caller's units.
    pub fn mesh(&self) -> TriMesh {
        self.problem.lin.mesh.scaled(1.0 / self.length_scale)
    }

    /// The current vertex positions in the caller's units.
    pub fn positions(&self) -> Vec<Vec3> {
        self.problem.lin.mesh.positions().iter().map(|p| p / self.length_scale).collect()
    }

    /// Distance of every vertex from the original surface (its closest point there), in the
    /// caller's units.
    pub fn deviations(&self) -> Vec<f64> {
        self.problem.lin.anchors.iter().map(|a| a.distance / self.length_scale).collect()
    }

    /// The original surface, as given (the caller's units).
    pub fn original(&self) -> &TriMesh {
        &self.given
    }

    /// The fixed field.
    pub fn field(&self) -> &[f64] {
        &self.field
    }

    pub fn params(&self) -> &ReshapeParams {
        &self.params
    }

    pub fn iterations(&self) -> usize {
        self.iterations
    }

    pub fn is_converged(&self) -> bool {
        self.converged
    }

    fn vertex_count(&self) -> usize {
        self.field.len()
    }

    /// The unit chord `q⁺ − p⁺` and normal of the `k`-th curve vertex at the current positions.
    fn tangent_and_normal(&self, k: usize) -> (Vec3, Vec3) {
        let curve = &self.problem.curves()[k];
        let positions = self.problem.lin.mesh.positions();
        let chord = curve.far_q.point(positions) - curve.far_p.point(positions);
        (chord / self.problem.lin.chords[k].tangent, self.problem.lin.normals[curve.vertex as usize])
    }

    /// Starts `u = n × (q⁺ − p⁺)` normalised (it follows +∇F, see [`crate::field::LevelCrossing`])
    /// and `b = cos θ n + sin θ u`, the binormal of the target angle.
    fn initialize_auxiliaries(&mut self) {
        let (sin, cos) = self.params.theta_degrees.to_radians().sin_cos();
        for k in 0..self.problem.curves().len() {
            let (tangent, normal) = self.tangent_and_normal(k);
            let side = normal.cross(&tangent).try_normalize(0.0).unwrap_or_else(Vec3::zeros);
            let b = normal * cos + side * sin;
            let start = self.problem.auxiliary_start(k);
            self.x[start..start + 3].copy_from_slice(b.as_slice());
            self.x[start + 3..start + AUXILIARIES].copy_from_slice(side.as_slice());
        }
    }

    /// The orientation test of Sec. 3.2.2 on the moving mesh: where `det(q − p, u, n) ≤ 0`,
    /// re-initialise `u = n × (q⁺ − p⁺)` normalised. Returns how many side vectors were flipped.
    fn reorient_side_vectors(&mut self) -> usize {
        let mut flips = 0;
        for k in 0..self.problem.curves().len() {
            let (tangent, normal) = self.tangent_and_normal(k);
            let Some(side) = normal.cross(&tangent).try_normalize(0.0) else { continue };
            let start = self.problem.auxiliary_start(k) + 3;
            let u = Vec3::from_column_slice(&self.x[start..start + 3]);
            if u.dot(&side) <= 0.0 {
                self.x[start..start + 3].copy_from_slice(side.as_slice());
                flips += 1;
            }
        }
        flips
    }

    fn measure(&self, iterations_this_step: usize, flips: usize, undone_steps: usize) -> ReshapeReport {
        let [fair, close, angle, edge] = self.problem.energies(&self.x);
        let mesh = &self.problem.lin.mesh;
        let (low, high) = mesh.bounding_box();
        let (squares, max_error, measured) = star_angle_errors(&self.problem, &self.x, self.params.theta_degrees, (high - low).norm());
        let distances = self.deviations();
        let max_deviation = distances.iter().fold(0.0f64, |m, &d| m.max(d));
        let rms_deviation = (distances.iter().map(|d| d * d).sum::<f64>() / distances.len() as f64).sqrt();
        let (now, then) = (mesh.positions(), self.original.mesh.positions());
        let max_edge_change = mesh.edges().iter().fold(0.0f64, |m, &[a, b]| {
            let (a, b) = (a as usize, b as usize);
            let rest = (then[b] - then[a]).norm();
            m.max(((now[b] - now[a]).norm() - rest).abs() / rest)
        });
        ReshapeReport {
            iterations: self.iterations,
            iterations_this_step,
            energies: ReshapeEnergies { fair, close, angle, edge },
            angle_error_rms_degrees: if measured > 0 { (squares / measured as f64).sqrt() } else { 0.0 },
            angle_error_max_degrees: max_error,
            measured_vertices: measured,
            max_deviation,
            rms_deviation,
            tolerance: self.tolerance / self.length_scale,
            max_edge_change,
            guard: self.problem.guard,
            undone_steps,
            flips,
            damping: self.lm.damping(),
            converged: self.converged,
        }
    }
}

fn validate_params(params: &ReshapeParams) -> Result<(), ReshapeError> {
    let bad = |name: &'static str, message: String| Err(ReshapeError::InvalidParameter { name, message });
    let theta = params.theta_degrees;
    if !(theta.is_finite() && (0.0..=180.0).contains(&theta)) {
        return bad("theta", format!("must lie in [0°, 180°], got {theta}"));
    }
    let w = &params.weights;
    for (name, value) in [("weights.fair", w.fair), ("weights.close", w.close), ("weights.angle", w.angle), ("weights.edge", w.edge)] {
        if !(value.is_finite() && value >= 0.0) {
            return bad(name, format!("must be finite and ≥ 0, got {value}"));
        }
    }
    let tolerance = params.tolerance.value();
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return bad("tolerance", format!("must be finite and > 0, got {tolerance}"));
    }
    if !(params.max_vertex_step.is_finite() && params.max_vertex_step > 0.0) {
        return bad("max_vertex_step", format!("must be finite and > 0, got {}", params.max_vertex_step));
    }
    if !(params.relative_tolerance.is_finite() && params.relative_tolerance >= 0.0) {
        return bad("relative_tolerance", format!("must be finite and ≥ 0, got {}", params.relative_tolerance));
    }
    validate_lm(&params.lm).map_err(|e| match e {
        FieldError::InvalidParameter { name, message } => ReshapeError::InvalidParameter { name, message },
        other => ReshapeError::Field(other),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::worst_block_jacobian;
    use crate::surfaces::hall_roof;

    /// Every block's Jacobian against central differences of its residuals (with what an
    /// iteration freezes held fixed), away from the start: positions and auxiliaries perturbed so
    /// that no term sits at its rest value.
    #[test]
    fn every_block_of_the_surface_problem_has_the_jacobian_of_its_residuals() {
        let mesh = hall_roof(150).into_mesh().expect("roof");
        let field: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.1 * p.y * p.y).collect();
        let mut solver = ReshapeSolver::new(&mesh, &field, ReshapeParams::new(45.0)).expect("solver");
        for (i, value) in solver.x.iter_mut().enumerate() {
            // A deterministic perturbation of about a tenth of an edge (the mesh is unit-scaled).
            *value += 0.1 * ((i as f64) * 12.9898).sin();
        }
        let worst = worst_block_jacobian(&solver.problem, &solver.x, 1e-6);
        assert!(worst.0 < 1e-4, "block {} of {}: {}", worst.1, solver.problem.block_count(), worst.0);
    }
}
