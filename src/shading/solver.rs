//! The stepwise shading optimiser (Sec. 6, Eq. 25–27): create it, `step` it, read the field,
//! the binormals and the light directions. Stepped like [`crate::field::FieldSolver`].

use super::error::ShadingError;
use super::labels::VertexLabel;
use super::light_rows::{self, LightMode};
use super::params::{ShadingParams, ShadingWeights};
use super::problem::ShadingProblem;
use super::report::ShadingReport;
use crate::field::SETTLING_ITERATIONS;
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{LeastSquaresProblem, LevenbergMarquardt};

/// Optimises a scalar field so that the rectifying planes of its level curves block the light
/// of the block region at `Block` vertices and contain the light of the pass region at `Pass`
/// vertices. Works on a copy of the mesh scaled to mean edge length 1 with the field scaled to
/// mean `‖∇F‖` 1; every value handed back is in the caller's units.
pub struct ShadingSolver {
    problem: ShadingProblem,
    lm: LevenbergMarquardt,
    params: ShadingParams,
    labels: Vec<VertexLabel>,
    x: Vec<f64>,
    /// Internal field = caller field × `field_scale`.
    field_scale: f64,
    length_scale: f64,
    slow_iterations: usize,
    iterations: usize,
    converged: bool,
    last_report: ShadingReport,
}

impl ShadingSolver {
    /// Prepares the optimisation of `initial_field` (one value per vertex) on `mesh` with one
    /// label per vertex. Errors name the offending parameter, or are the field's (length, a
    /// non-finite value, a constant field).
    pub fn new(mesh: &TriMesh, initial_field: &[f64], labels: &[VertexLabel], params: ShadingParams) -> Result<ShadingSolver, ShadingError> {
        params.validate()?;
        crate::field::validate_field(mesh, initial_field)?;
        if labels.len() != mesh.vertex_count() {
            return Err(ShadingError::invalid("labels", format!("{} labels for {} vertices", labels.len(), mesh.vertex_count())));
        }
        if labels.iter().all(|&l| l == VertexLabel::Free) {
            return Err(ShadingError::invalid("labels", "every vertex is free: nothing to block or let through".to_string()));
        }
        let (unit_mesh, length_scale) = mesh.unit_scaled();
        let gradient = crate::field::mean_gradient_norm(&unit_mesh, initial_field);
        if !(gradient > 0.0 && gradient.is_finite()) {
            return Err(crate::field::FieldError::ConstantField.into());
        }
        let field_scale = 1.0 / gradient;
        let bounds = [params.block_region.bounds(), params.pass_region.bounds()];
        let problem = ShadingProblem::new(unit_mesh, labels, params.frame, bounds, params.weights);
        let lm = LevenbergMarquardt::new(&problem, params.lm.clone()).map_err(crate::field::FieldError::from)?;
        let mut x = vec![0.0; problem.variable_count()];
        x.iter_mut().zip(initial_field).for_each(|(x, f)| *x = f * field_scale);
        let mut solver = ShadingSolver {
            problem,
            lm,
            params,
            labels: labels.to_vec(),
            x,
            field_scale,
            length_scale,
            slow_iterations: 0,
            iterations: 0,
            converged: false,
            last_report: ShadingReport::default(),
        };
        solver.initialize_auxiliaries();
        solver.last_report = solver.measure(0);
        Ok(solver)
    }

    /// Runs at most `max_iterations` Levenberg–Marquardt iterations and reports the state.
    pub fn step(&mut self, max_iterations: usize) -> Result<ShadingReport, ShadingError> {
        rayon::scope(|_| self.run(max_iterations))
    }

    fn run(&mut self, max_iterations: usize) -> Result<ShadingReport, ShadingError> {
        let mut ran = 0;
        while ran < max_iterations && !self.converged {
            let outcome = self.lm.iterate(&self.problem, &mut self.x).map_err(crate::field::FieldError::from)?;
            ran += 1;
            self.iterations += 1;
            let decrease = outcome.energy_before - outcome.energy_after;
            if decrease <= self.params.relative_tolerance * outcome.energy_before {
                self.slow_iterations += 1;
            } else {
                self.slow_iterations = 0;
            }
            self.converged = outcome.converged.is_some() || self.slow_iterations >= SETTLING_ITERATIONS;
        }
        self.last_report = self.measure(ran);
        Ok(self.last_report.clone())
    }

    /// The report of the last `step` (or of the initial state).
    pub fn report(&self) -> &ShadingReport {
        &self.last_report
    }

    /// The current field, one value per vertex, in the scale of the initial field.
    pub fn field(&self) -> Vec<f64> {
        self.x[..self.vertex_count()].iter().map(|f| f / self.field_scale).collect()
    }

    /// Unit binormal `b` per vertex (the auxiliary of Eq. 9: with the tangent it spans the
    /// rectifying plane); zero at free, boundary and singular vertices.
    pub fn binormals(&self) -> Vec<Vec3> {
        self.per_light_vertex(|aux, _| Vec3::new(aux[0], aux[1], aux[2]).try_normalize(0.0))
    }

    /// Unit light direction `l` per vertex in model coordinates (in the vertex's region up to the
    /// dummy constraints); zero at free, boundary and singular vertices.
    pub fn light_directions(&self) -> Vec<Vec3> {
        let frame = *self.problem.frame();
        self.per_light_vertex(move |aux, _| frame.to_model(&Vec3::new(aux[light_rows::L], aux[light_rows::L + 1], aux[light_rows::L + 2])).try_normalize(0.0))
    }

    /// The labels in force, one per vertex.
    pub fn labels(&self) -> &[VertexLabel] {
        &self.labels
    }

    /// The mesh in the caller's units.
    pub fn mesh(&self) -> TriMesh {
        self.problem.mesh().scaled(1.0 / self.length_scale)
    }

    pub fn params(&self) -> &ShadingParams {
        &self.params
    }

    pub fn iterations(&self) -> usize {
        self.iterations
    }

    pub fn is_converged(&self) -> bool {
        self.converged
    }

    /// Replaces the weights and restarts the convergence test.
    pub fn set_weights(&mut self, weights: ShadingWeights) -> Result<(), ShadingError> {
        weights.validate()?;
        self.params.weights = weights;
        self.problem.set_weights(weights);
        self.lm.reset_damping();
        (self.slow_iterations, self.converged) = (0, false);
        Ok(())
    }

    fn vertex_count(&self) -> usize {
        self.problem.mesh().vertex_count()
    }

    fn per_light_vertex(&self, value: impl Fn(&[f64], LightMode) -> Option<Vec3>) -> Vec<Vec3> {
        let mut out = vec![Vec3::zeros(); self.vertex_count()];
        let field = self.problem.field_problem();
        for vertex in self.problem.light_vertices() {
            if field.level_jet(vertex.curve, &self.x).is_some() {
                let v = field.curve_vertices()[vertex.curve] as usize;
                out[v] = value(&self.x[vertex.auxiliary..], vertex.mode).unwrap_or_else(Vec3::zeros);
            }
        }
        out
    }

    /// Starts `l` at the central direction of the vertex's region (Sec. 6), `b` at the level
    /// curve's discrete binormal (where the curve is straight: orthogonal to `l_c` and `t` when
    /// blocking, in the plane of `l_c` and `t` when letting through), `n^p = b × t`, and the
    /// dummies at the square roots of their slacks.
    fn initialize_auxiliaries(&mut self) {
        let frame = *self.problem.frame();
        let field = self.problem.field_problem();
        let mut updates = Vec::new();
        for vertex in self.problem.light_vertices() {
            let region = match vertex.mode {
                LightMode::Block => &self.params.block_region,
                LightMode::Pass => &self.params.pass_region,
            };
            let le = region.central_direction();
            let l = frame.to_model(&le);
            let v = field.curve_vertices()[vertex.curve] as usize;
            let level = field.level_frame(vertex.curve, &self.x);
            let t = level.map_or_else(|| any_orthogonal(&field.mesh().smooth_normals()[v]), |f| f.tangent);
            let straight = match vertex.mode {
                LightMode::Block => t.cross(&l),
                LightMode::Pass => l - t * l.dot(&t),
            };
            let b = level.and_then(|f| f.binormal).or_else(|| straight.try_normalize(1e-9)).unwrap_or_else(|| any_orthogonal(&t));
            let bounds = self.problem.bounds(vertex.mode);
            let slacks = [le.z - bounds.z_min, bounds.z_max - le.z, le.y - bounds.g_min * le.x, bounds.g_max * le.x - le.y, le.x];
            let mut aux = vec![0.0; super::problem::auxiliaries(vertex.mode)];
            aux[light_rows::B..light_rows::B + 3].copy_from_slice(b.as_slice());
            aux[light_rows::L..light_rows::L + 3].copy_from_slice(le.as_slice());
            for (k, s) in slacks.iter().enumerate() {
                aux[light_rows::PSI + k] = s.max(0.0).sqrt();
            }
            if vertex.mode == LightMode::Pass {
                let np = b.cross(&t).try_normalize(1e-12).unwrap_or_else(|| any_orthogonal(&b));
                aux[light_rows::NP..light_rows::NP + 3].copy_from_slice(np.as_slice());
            }
            updates.push((vertex.auxiliary, aux));
        }
        for (start, aux) in updates {
            self.x[start..start + aux.len()].copy_from_slice(&aux);
        }
    }

    fn measure(&self, iterations_this_step: usize) -> ShadingReport {
        ShadingReport {
            iterations: self.iterations,
            iterations_this_step,
            converged: self.converged,
            damping: self.lm.damping(),
            ..ShadingReport::measure(&self.problem, &self.x)
        }
    }
}

fn any_orthogonal(v: &Vec3) -> Vec3 {
    let helper = if v.x.abs() < 0.9 { Vec3::x() } else { Vec3::y() };
    v.cross(&helper).normalize()
}
