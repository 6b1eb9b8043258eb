//! The level-set optimisation of Eq. 12 as a sparse least-squares problem:
//! `E_pg = λ_fair E_fair + λ_grad E_grad + λ_angle E_angle` over the field values and, for
//! pseudo-geodesics, the auxiliary binormal and side vector of every curve vertex.
//!
//! Variables: `F` at every vertex (global), then `[b, u]` per curve vertex (a local group
//! of six, eliminated by Schur complement in the solver). Blocks, in this order:
//! one Hessian-fairness block per vertex, one gradient block per face, one curve block per curve
//! vertex, one fit block per curve vertex. A curve vertex is an interior vertex whose local fits
//! are well posed (see [`super::level_jet`]); as in the paper, boundary vertices carry no curve
//! term (their one-sided fits are less accurate: on a cylinder their jets end up to 1.6° off
//! where interior ones stay within 0.8°, and the level curves are no closer to the analytic
//! ones with them). Its curve and fit blocks declare the field values of its fit's stencil, so
//! the sparsity pattern is fixed.
//!
//! `E_fair` is the paper's squared Hessian energy (Eq. 6) plus [`FIT_RATIO`] times `E_fit`, the
//! squared residuals of the local quadratic fits the curve terms are measured on: what a
//! quadratic cannot represent around a vertex. Smooth fields have `E_fit` of the order of the
//! edge length to the sixth; oscillations at the scale of an edge, which the fits would read as
//! curvature, pay for it. Without it, on fine meshes (30,000 vertices on a cylinder) the
//! optimiser meets the curve terms with such oscillations instead of bending the level sets.

use super::hessian_energy::HessianEnergy;
use super::params::{Family, Weights};
use super::pseudo_geodesic::TargetAngle;
use super::{asymptotic, constant_slope, geodesic, gradient_norm, pseudo_geodesic};
use super::level_jet::{JetStencil, JetStencils};
use super::level_jet::LevelJet;
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{new_revision, LeastSquaresProblem, VariableLayout};

/// Which energy a block belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Block {
    /// `E_fair` rows of a vertex.
    Fair(usize),
    /// `E_grad` row of a face.
    Grad(usize),
    /// Curve rows (`E_angle`, `E_geo` or `E_asy`) of the `k`-th curve vertex.
    Curve(usize),
    /// `E_fit` rows (part of `E_fair`) of the `k`-th curve vertex.
    Fit(usize),
}

/// The field problem on a unit-scaled mesh.
pub struct FieldProblem {
    mesh: TriMesh,
    fairness: HessianEnergy,
    family: Family,
    /// The family's target angle θ.
    target: TargetAngle,
    /// Per-vertex targets (index `k` as in `curve_vertices`) of a varying-angle family (Fig. 16),
    /// replacing `target`.
    vertex_targets: Option<Vec<TargetAngle>>,
    weights: Weights,
    /// The revision of the weights the constant Jacobians (fairness and fit blocks) scale with
    /// ([`LeastSquaresProblem::constant_jacobian_revision`]).
    revision: u64,
    gradient_target: f64,
    /// The vertices that carry a curve term, in increasing order.
    curve_vertices: Vec<u32>,
    /// The local fits of the field at the curve vertices (index `k` as in `curve_vertices`).
    jets: JetStencils,
    /// The mesh's bounding-box diagonal: curves of larger radius count as straight.
    model_size: f64,
    /// A constant-slope family's unit axis and the curve vertices that can reach its slope.
    slope: Option<SlopeTerm>,
    /// Curve block variables (stencil field values, then auxiliaries), CSR by curve-vertex index.
    curve_offsets: Vec<usize>,
    curve_variables: Vec<u32>,
    /// Index of the first auxiliary variable (`vertex_count` when the problem stands alone; a
    /// multi-field problem places each field's auxiliaries after all the fields, see
    /// [`crate::net`]).
    auxiliary_base: usize,
}

impl FieldProblem {
    /// The problem of Eq. 12 on `mesh` (meant to be unit-scaled: weights assume mean edge length 1),
    /// with the target gradient norm `gradient_target` of `E_grad`.
    pub fn new(mesh: TriMesh, family: Family, weights: Weights, gradient_target: f64) -> Self {
        let base = mesh.vertex_count();
        Self::with_auxiliary_base(mesh, family, weights, gradient_target, base)
    }

    /// [`Self::new`] with the auxiliaries of the `k`-th curve vertex at
    /// `auxiliary_base + AUXILIARIES · k` (≥ the vertex count) instead of right after the field:
    /// how a multi-field problem lays several fields and their auxiliaries out in one vector.
    pub(crate) fn with_auxiliary_base(mesh: TriMesh, family: Family, weights: Weights, gradient_target: f64, auxiliary_base: usize) -> Self {
        debug_assert!(auxiliary_base >= mesh.vertex_count());
        let fairness = HessianEnergy::new(&mesh);
        let auxiliaries = Self::auxiliaries_per_vertex(family);
        let all: Vec<u32> = (0..mesh.vertex_count() as u32).collect();
        let all_jets = JetStencils::new(&mesh, &all, mesh.local_quadrics());
        let curve_vertices: Vec<u32> = all.into_iter().filter(|&v| !mesh.is_boundary_vertex(v as usize) && !all_jets.get(v as usize).vertices.is_empty()).collect();
        let jets = all_jets.select(&curve_vertices);
        let mut curve_offsets = vec![0];
        let mut curve_variables = Vec::new();
        for k in 0..curve_vertices.len() {
            curve_variables.extend_from_slice(jets.get(k).vertices);
            let first_aux = auxiliary_base + auxiliaries * k;
            curve_variables.extend((first_aux..first_aux + auxiliaries).map(|i| i as u32));
            curve_offsets.push(curve_variables.len());
        }
        let mut problem = FieldProblem {
            fairness,
            target: TargetAngle::from_degrees(family.theta_degrees()),
            vertex_targets: None,
            family,
            weights,
            revision: new_revision(),
            gradient_target,
            curve_vertices,
            jets,
            model_size: super::darboux::model_size(&mesh),
            slope: family.slope_axis().map(|axis| SlopeTerm { axis, reachable: Vec::new() }),
            curve_offsets,
            curve_variables,
            auxiliary_base,
            mesh,
        };
        problem.update_reachable();
        problem
    }

    /// The unit axis of a constant-slope family.
    pub(crate) fn slope_axis(&self) -> Option<Vec3> {
        self.slope.as_ref().map(|s| s.axis)
    }

    /// Whether the `k`-th curve vertex carries a slope row (always for other families).
    pub(crate) fn slope_reachable(&self, k: usize) -> bool {
        self.slope.as_ref().is_none_or(|s| s.reachable[k])
    }

    /// Sets the slope β (degrees) of a constant-slope family (its free slope, fitted between
    /// iterations) and the vertices that can reach it.
    pub(crate) fn set_slope(&mut self, degrees: f64) {
        self.target = TargetAngle::from_degrees(degrees);
        self.update_reachable();
    }

    fn update_reachable(&mut self) {
        let Some(slope) = self.slope.as_mut() else { return };
        let normals = self.mesh.smooth_normals();
        slope.reachable = self.curve_vertices.iter().map(|&v| constant_slope::reachable(&normals[v as usize], &slope.axis, self.target.degrees)).collect();
    }

    pub(crate) fn auxiliaries_per_vertex(family: Family) -> usize {
        match family {
            Family::PseudoGeodesic { .. } => pseudo_geodesic::AUXILIARIES,
            Family::Geodesic | Family::Asymptotic | Family::ConstantSlope { .. } => 0,
        }
    }

    fn curve_rows(&self) -> usize {
        match self.family {
            Family::PseudoGeodesic { .. } => pseudo_geodesic::ROWS,
            Family::Geodesic => geodesic::ROWS,
            Family::Asymptotic => asymptotic::ROWS,
            Family::ConstantSlope { .. } => constant_slope::ROWS,
        }
    }

    /// The (unit-scaled) mesh the problem lives on.
    pub fn mesh(&self) -> &TriMesh {
        &self.mesh
    }

    pub fn family(&self) -> Family {
        self.family
    }

    pub fn weights(&self) -> Weights {
        self.weights
    }

    pub(crate) fn set_gradient_target(&mut self, target: f64) {
        self.gradient_target = target;
    }

    /// Target `‖∇F‖` of `E_grad` on this problem's scale.
    pub(crate) fn gradient_target(&self) -> f64 {
        self.gradient_target
    }

    /// Target angle of the `k`-th curve vertex.
    pub(crate) fn target(&self, k: usize) -> TargetAngle {
        match &self.vertex_targets {
            Some(targets) => targets[k],
            None => self.target,
        }
    }

    /// Whether curve vertices have their own target angles ([`Self::set_vertex_targets`]).
    pub(crate) fn has_vertex_targets(&self) -> bool {
        self.vertex_targets.is_some()
    }

    /// Gives each curve vertex its own target angle (degrees, one per entry of `curve_vertices`,
    /// validated by the caller). Only meaningful for pseudo-geodesics.
    pub(crate) fn set_vertex_targets(&mut self, degrees: &[f64]) {
        debug_assert_eq!(degrees.len(), self.curve_vertices.len());
        self.vertex_targets = Some(degrees.iter().map(|&theta| TargetAngle::from_degrees(theta)).collect());
    }

    pub fn set_weights(&mut self, weights: Weights) {
        self.weights = weights;
        self.revision = new_revision();
    }

    /// The vertices that carry a curve term (those whose local fits are well posed), in
    /// increasing order: the owners of the curve blocks.
    pub fn curve_vertices(&self) -> &[u32] {
        &self.curve_vertices
    }

    /// Index of the first auxiliary of the `k`-th curve vertex (pseudo-geodesics only).
    pub fn auxiliary_start(&self, k: usize) -> usize {
        self.auxiliary_base + Self::auxiliaries_per_vertex(self.family) * k
    }

    /// The level jet of the `k`-th curve vertex at `x`; `None` where the vertex is singular
    /// (an interior vertex whose level curve does not cross exactly two star edges, Fig. 7, or a
    /// vanishing fitted gradient).
    pub(crate) fn level_jet(&self, k: usize, x: &[f64]) -> Option<LevelJet> {
        level_jet_at(&self.mesh, &self.jets.get(k), self.curve_vertices[k] as usize, x)
    }

    /// The stencil of the local fit at the `k`-th curve vertex (the field values its level jet reads).
    pub(crate) fn jet_stencil(&self, k: usize) -> JetStencil<'_> {
        self.jets.get(k)
    }

    /// The level frame of the `k`-th curve vertex at `x` (see [`super::darboux`]).
    pub(crate) fn level_frame(&self, k: usize, x: &[f64]) -> Option<super::LevelFrame> {
        Some(super::darboux::frame_of_jet(&self.level_jet(k, x)?, self.model_size))
    }

    pub(crate) fn block(&self, b: usize) -> Block {
        let n = self.mesh.vertex_count();
        let curves = self.curve_vertices.len();
        if b < n {
            Block::Fair(b)
        } else if b < self.first_curve_block() {
            Block::Grad(b - n)
        } else if b < self.first_curve_block() + curves {
            Block::Curve(b - self.first_curve_block())
        } else {
            Block::Fit(b - self.first_curve_block() - curves)
        }
    }

    /// Index of the first curve block (blocks are ordered fairness, gradient, curve).
    pub(crate) fn first_curve_block(&self) -> usize {
        self.mesh.vertex_count() + self.mesh.face_count()
    }

    /// Evaluates block `b` with the given weights (the solver uses the problem's own; reports use 1)
    /// into `residuals` and `jacobian`, which come in zeroed.
    pub(crate) fn evaluate_weighted(&self, b: usize, weights: &Weights, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        match self.block(b) {
            Block::Fair(v) => {
                let scale = weights.fair.sqrt();
                let operator = self.fairness.vertex_operator(v);
                let variables = self.fairness.vertex_variables(v);
                for (row, r) in residuals.iter_mut().enumerate() {
                    let coefficients = &operator[row * variables.len()..(row + 1) * variables.len()];
                    *r = scale * coefficients.iter().zip(variables).map(|(c, &i)| c * x[i as usize]).sum::<f64>();
                }
                if let Some(jac) = jacobian {
                    for (j, c) in jac.iter_mut().zip(operator) {
                        *j = scale * c;
                    }
                }
            }
            Block::Grad(f) => {
                let scale = (weights.grad * self.mesh.face_areas()[f]).sqrt();
                gradient_norm::evaluate(&self.mesh, x, f, self.gradient_target, scale, &mut residuals[0], jacobian);
            }
            Block::Fit(k) => {
                let v = self.curve_vertices[k] as usize;
                let scale = (weights.fair * FIT_RATIO * self.mesh.normalized_vertex_areas()[v]).sqrt();
                self.jets.get(k).fit_residuals(x, scale, residuals, jacobian);
            }
            Block::Curve(k) => {
                let v = self.curve_vertices[k] as usize;
                let scale = (weights.angle * self.mesh.normalized_vertex_areas()[v]).sqrt();
                // Singular vertices keep the zero rows every caller hands in (the contract of
                // `LeastSquaresProblem::evaluate_block`).
                let Some(jet) = self.level_jet(k, x) else { return };
                let stencil = self.jets.get(k);
                match self.family {
                    Family::PseudoGeodesic { .. } => {
                        let start = self.auxiliary_start(k);
                        let aux = &x[start..start + pseudo_geodesic::AUXILIARIES];
                        pseudo_geodesic::evaluate(&jet, &stencil, aux, self.target(k), scale, residuals, jacobian);
                    }
                    Family::Geodesic => geodesic::evaluate(&jet, &stencil, scale, residuals, jacobian),
                    Family::Asymptotic => asymptotic::evaluate(&jet, &stencil, scale, residuals, jacobian),
                    Family::ConstantSlope { .. } => {
                        // Beyond the isophote (and its margin) no tangent has the slope: no row.
                        if let Some(slope) = self.slope.as_ref().filter(|s| s.reachable[k]) {
                            constant_slope::evaluate(&jet, &stencil, &slope.axis, self.target.sin, scale, residuals, jacobian);
                        }
                    }
                }
            }
        }
    }
}

impl LeastSquaresProblem for FieldProblem {
    fn variable_count(&self) -> usize {
        self.mesh.vertex_count() + Self::auxiliaries_per_vertex(self.family) * self.curve_vertices.len()
    }

    fn block_count(&self) -> usize {
        self.mesh.vertex_count() + self.mesh.face_count() + 2 * self.curve_vertices.len()
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        match self.block(b) {
            Block::Fair(v) => self.fairness.vertex_variables(v),
            Block::Grad(f) => &self.mesh.faces()[f],
            Block::Curve(k) => &self.curve_variables[self.curve_offsets[k]..self.curve_offsets[k + 1]],
            Block::Fit(k) => self.jets.get(k).vertices,
        }
    }

    fn block_residual_count(&self, b: usize) -> usize {
        match self.block(b) {
            Block::Fair(_) => HessianEnergy::ROWS_PER_VERTEX,
            Block::Grad(_) => 1,
            Block::Curve(_) => self.curve_rows(),
            Block::Fit(k) => self.jets.get(k).fit_rows(),
        }
    }

    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        self.evaluate_weighted(b, &self.weights, x, residuals, jacobian);
    }

    /// The Hessian-fairness rows (Eq. 6) and the `E_fit` rows are linear in the field values,
    /// with coefficients fixed by the mesh and `λ_fair`.
    fn block_jacobian_is_constant(&self, b: usize) -> bool {
        matches!(self.block(b), Block::Fair(_) | Block::Fit(_))
    }

    fn constant_jacobian_revision(&self) -> u64 {
        self.revision
    }

    fn variable_layout(&self) -> VariableLayout {
        let n = self.mesh.vertex_count();
        let size = Self::auxiliaries_per_vertex(self.family);
        if size == 0 {
            return VariableLayout::all_global(n);
        }
        let sizes = vec![size; self.curve_vertices.len()];
        // Invariant: the groups tile [n, variable_count) exactly, so the layout is valid.
        VariableLayout::with_local_groups(n, &sizes).expect("auxiliary groups tile the local variables")
    }
}

/// The curve term of a constant-slope family (Eq. 22).
struct SlopeTerm {
    axis: Vec3,
    /// Per curve vertex: its tangent plane holds tangents of the slope ([`constant_slope::reachable`]).
    reachable: Vec<bool>,
}

/// Weight of `E_fit` relative to the Hessian energy inside `E_fair` (so λ_fit = 1 at the default
/// λ_fair = 1e-3): on a cylinder of radius 5 m it keeps the level sets within 0.05 % of the
/// catenaries at 3,000 and 30,000 vertices alike, where without it the finer mesh ends 3.4 % off.
pub const FIT_RATIO: f64 = 1e3;

/// The level jet at vertex `v` with its `stencil`, or `None` at a boundary vertex and where `v`
/// is singular: its piecewise-linear level curve does not cross exactly two star edges (Fig. 7:
/// an extremum or saddle of `F` nearby), or the fitted gradient vanishes.
pub(crate) fn level_jet_at(mesh: &TriMesh, stencil: &super::level_jet::JetStencil, v: usize, field: &[f64]) -> Option<LevelJet> {
    super::find_level_crossing(mesh, field, v)?;
    LevelJet::at(stencil, field)
}
