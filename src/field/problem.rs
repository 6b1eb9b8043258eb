//! The level-set optimisation of Eq. 12 as a sparse least-squares problem:
//! `E_pg = λ_fair E_fair + λ_grad E_grad + λ_angle E_angle` over the field values and, for
//! pseudo-geodesics, the auxiliary binormal and side vector of every interior vertex.
//!
//! Variables: `F` at every vertex (global), then `[b, u]` per interior vertex (a local group
//! of six, eliminated by Schur complement in the solver). Blocks, in this order:
//! one fairness block per vertex, one gradient block per face, one curve block per interior
//! vertex. A curve block declares the field values of the whole vertex star, so the sparsity
//! pattern stays fixed while the crossed edges `p`, `q` move around the star.

use super::hessian_energy::HessianEnergy;
use super::params::{Family, Weights};
use super::pseudo_geodesic::TargetAngle;
use super::{asymptotic, geodesic, gradient_norm, pseudo_geodesic};
use crate::mesh::TriMesh;
use crate::solver::{LeastSquaresProblem, VariableLayout};

/// Which energy a block belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Block {
    /// `E_fair` rows of a vertex.
    Fair(usize),
    /// `E_grad` row of a face.
    Grad(usize),
    /// Curve rows (`E_angle`, `E_geo` or `E_asy`) of the `k`-th interior vertex.
    Curve(usize),
}

/// The field problem on a unit-scaled mesh.
pub struct FieldProblem {
    mesh: TriMesh,
    fairness: HessianEnergy,
    family: Family,
    /// The family's target angle θ.
    target: TargetAngle,
    /// Per-vertex targets (index `k` as in `interior`) of a varying-angle family (Fig. 16),
    /// replacing `target`.
    vertex_targets: Option<Vec<TargetAngle>>,
    weights: Weights,
    gradient_target: f64,
    /// Interior vertices, in increasing order: the owners of curve blocks.
    interior: Vec<u32>,
    /// Curve block variables (star field values, then auxiliaries), CSR by interior index.
    curve_offsets: Vec<usize>,
    curve_variables: Vec<u32>,
}

impl FieldProblem {
    /// The problem of Eq. 12 on `mesh` (meant to be unit-scaled: weights assume mean edge length 1),
    /// with the target gradient norm `gradient_target` of `E_grad`.
    pub fn new(mesh: TriMesh, family: Family, weights: Weights, gradient_target: f64) -> Self {
        let fairness = HessianEnergy::new(&mesh);
        let interior: Vec<u32> = (0..mesh.vertex_count()).filter(|&v| !mesh.is_boundary_vertex(v)).map(|v| v as u32).collect();
        let auxiliaries = Self::auxiliaries_per_vertex(family);
        let mut curve_offsets = vec![0];
        let mut curve_variables = Vec::new();
        for (k, &v) in interior.iter().enumerate() {
            curve_variables.push(v);
            curve_variables.extend_from_slice(mesh.star(v as usize).neighbours);
            let first_aux = mesh.vertex_count() + auxiliaries * k;
            curve_variables.extend((first_aux..first_aux + auxiliaries).map(|i| i as u32));
            curve_offsets.push(curve_variables.len());
        }
        FieldProblem {
            fairness,
            target: TargetAngle::from_degrees(family.theta_degrees()),
            vertex_targets: None,
            family,
            weights,
            gradient_target,
            interior,
            curve_offsets,
            curve_variables,
            mesh,
        }
    }

    fn auxiliaries_per_vertex(family: Family) -> usize {
        match family {
            Family::PseudoGeodesic { .. } => pseudo_geodesic::AUXILIARIES,
            Family::Geodesic | Family::Asymptotic => 0,
        }
    }

    fn curve_rows(&self) -> usize {
        match self.family {
            Family::PseudoGeodesic { .. } => pseudo_geodesic::ROWS,
            Family::Geodesic => geodesic::ROWS,
            Family::Asymptotic => asymptotic::ROWS,
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

    /// Target `‖∇F‖` of `E_grad` on this problem's scale.
    pub(crate) fn gradient_target(&self) -> f64 {
        self.gradient_target
    }

    /// Target angle of the `k`-th interior vertex.
    pub(crate) fn target(&self, k: usize) -> TargetAngle {
        match &self.vertex_targets {
            Some(targets) => targets[k],
            None => self.target,
        }
    }

    /// Gives each interior vertex its own target angle (degrees, one per entry of `interior`,
    /// validated by the caller). Only meaningful for pseudo-geodesics.
    pub(crate) fn set_vertex_targets(&mut self, degrees: &[f64]) {
        debug_assert_eq!(degrees.len(), self.interior.len());
        self.vertex_targets = Some(degrees.iter().map(|&theta| TargetAngle::from_degrees(theta)).collect());
    }

    pub fn set_weights(&mut self, weights: Weights) {
        self.weights = weights;
    }

    /// Interior vertices, the owners of the curve blocks.
    pub fn interior(&self) -> &[u32] {
        &self.interior
    }

    /// Index of the first auxiliary of the `k`-th interior vertex (pseudo-geodesics only).
    pub fn auxiliary_start(&self, k: usize) -> usize {
        self.mesh.vertex_count() + Self::auxiliaries_per_vertex(self.family) * k
    }

    pub(crate) fn block(&self, b: usize) -> Block {
        let n = self.mesh.vertex_count();
        if b < n {
            Block::Fair(b)
        } else if b < self.first_curve_block() {
            Block::Grad(b - n)
        } else {
            Block::Curve(b - self.first_curve_block())
        }
    }

    /// Index of the first curve block (blocks are ordered fairness, gradient, curve).
    pub(crate) fn first_curve_block(&self) -> usize {
        self.mesh.vertex_count() + self.mesh.face_count()
    }

    /// Evaluates block `b` with the given weights (the solver uses the problem's own; reports use 1).
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
            Block::Curve(k) => {
                let v = self.interior[k] as usize;
                let scale = (weights.angle * self.mesh.normalized_vertex_areas()[v]).sqrt();
                match self.family {
                    Family::PseudoGeodesic { .. } => {
                        let start = self.auxiliary_start(k);
                        let aux = &x[start..start + pseudo_geodesic::AUXILIARIES];
                        let aux_column = 1 + self.mesh.star(v).neighbours.len();
                        pseudo_geodesic::evaluate(&self.mesh, x, v, aux, self.target(k), scale, residuals, jacobian, aux_column);
                    }
                    Family::Geodesic => geodesic::evaluate(&self.mesh, x, v, scale, residuals, jacobian),
                    Family::Asymptotic => asymptotic::evaluate(&self.mesh, x, v, scale, residuals, jacobian),
                }
            }
        }
    }
}

impl LeastSquaresProblem for FieldProblem {
    fn variable_count(&self) -> usize {
        self.mesh.vertex_count() + Self::auxiliaries_per_vertex(self.family) * self.interior.len()
    }

    fn block_count(&self) -> usize {
        self.mesh.vertex_count() + self.mesh.face_count() + self.interior.len()
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        match self.block(b) {
            Block::Fair(v) => self.fairness.vertex_variables(v),
            Block::Grad(f) => &self.mesh.faces()[f],
            Block::Curve(k) => &self.curve_variables[self.curve_offsets[k]..self.curve_offsets[k + 1]],
        }
    }

    fn block_residual_count(&self, b: usize) -> usize {
        match self.block(b) {
            Block::Fair(_) => HessianEnergy::ROWS_PER_VERTEX,
            Block::Grad(_) => 1,
            Block::Curve(_) => self.curve_rows(),
        }
    }

    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        self.evaluate_weighted(b, &self.weights, x, residuals, jacobian);
    }

    fn variable_layout(&self) -> VariableLayout {
        let n = self.mesh.vertex_count();
        let size = Self::auxiliaries_per_vertex(self.family);
        if size == 0 {
            return VariableLayout::all_global(n);
        }
        let sizes = vec![size; self.interior.len()];
        // Invariant: the groups tile [n, variable_count) exactly, so the layout is valid.
        VariableLayout::with_local_groups(n, &sizes).expect("auxiliary groups tile the local variables")
    }
}
