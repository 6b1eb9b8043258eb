//! The shading design of Eq. 25 as one sparse least-squares problem:
//! `E_tot = λ_fair E_fair + λ_grad E_grad + λ_L E_L`, `E_L` being `E_block` (Eq. 26) at blocking
//! vertices and `E_light` (Eq. 27) at letting-through ones, over the field values and the
//! auxiliaries of [`super::light_rows`] at every light vertex.
//!
//! It reuses the field problem of Eq. 12 ([`FieldProblem`]) for its regularisers: its fairness
//! and gradient blocks, then its fit blocks (part of `E_fair`), followed by one light block per
//! light vertex. The field problem's own curve terms are not used (its family is the geodesic
//! one, which has no auxiliaries). Variables: `F` at every vertex, then the auxiliaries of each
//! light vertex (a local group, eliminated by Schur complement in the solver).

use super::earth_frame::EarthFrame;
use super::labels::VertexLabel;
use super::light_region::RegionBounds;
use super::light_rows::{self, LightMode, RowScales};
use super::params::ShadingWeights;
use crate::field::{Family, FieldProblem, Weights};
use crate::mesh::TriMesh;
use crate::solver::{LeastSquaresProblem, VariableLayout};

/// A curve vertex carrying a light term.
#[derive(Clone, Copy, Debug)]
pub(crate) struct LightVertex {
    /// Index among the field problem's curve vertices.
    pub curve: usize,
    pub mode: LightMode,
    /// First auxiliary variable.
    pub auxiliary: usize,
}

/// The problem on a unit-scaled mesh.
pub struct ShadingProblem {
    field: FieldProblem,
    frame: EarthFrame,
    /// Bounds of Eq. 24 of the block region and of the pass region.
    block_bounds: RegionBounds,
    pass_bounds: RegionBounds,
    weights: ShadingWeights,
    light_vertices: Vec<LightVertex>,
    /// Light block variables (stencil field values, then auxiliaries), CSR by light vertex.
    offsets: Vec<usize>,
    variables: Vec<u32>,
}

impl ShadingProblem {
    /// The problem on `mesh` (unit-scaled) with one label per vertex; boundary and
    /// ill-posed vertices carry no light term, as in the field problem.
    pub(crate) fn new(mesh: TriMesh, labels: &[VertexLabel], frame: EarthFrame, bounds: [RegionBounds; 2], weights: ShadingWeights) -> ShadingProblem {
        let field = FieldProblem::new(mesh, Family::Geodesic, regulariser_weights(&weights), 1.0);
        let n = field.mesh().vertex_count();
        let mut light_vertices = Vec::new();
        let mut offsets = vec![0];
        let mut variables = Vec::new();
        let mut auxiliary = n;
        for (curve, &v) in field.curve_vertices().iter().enumerate() {
            let (mode, size) = match labels[v as usize] {
                VertexLabel::Block => (LightMode::Block, light_rows::BLOCK_AUXILIARIES),
                VertexLabel::Pass => (LightMode::Pass, light_rows::PASS_AUXILIARIES),
                VertexLabel::Free => continue,
            };
            light_vertices.push(LightVertex { curve, mode, auxiliary });
            variables.extend_from_slice(field.jet_stencil(curve).vertices);
            variables.extend((auxiliary..auxiliary + size).map(|i| i as u32));
            offsets.push(variables.len());
            auxiliary += size;
        }
        let [block_bounds, pass_bounds] = bounds;
        ShadingProblem { field, frame, block_bounds, pass_bounds, weights, light_vertices, offsets, variables }
    }

    pub fn mesh(&self) -> &TriMesh {
        self.field.mesh()
    }

    pub(crate) fn field_problem(&self) -> &FieldProblem {
        &self.field
    }

    pub(crate) fn frame(&self) -> &EarthFrame {
        &self.frame
    }

    pub(crate) fn light_vertices(&self) -> &[LightVertex] {
        &self.light_vertices
    }

    pub(crate) fn bounds(&self, mode: LightMode) -> &RegionBounds {
        match mode {
            LightMode::Block => &self.block_bounds,
            LightMode::Pass => &self.pass_bounds,
        }
    }

    pub fn weights(&self) -> ShadingWeights {
        self.weights
    }

    pub(crate) fn set_weights(&mut self, weights: ShadingWeights) {
        self.weights = weights;
        self.field.set_weights(regulariser_weights(&weights));
    }

    /// Blocks of the field problem used here: fairness and gradient, then the fits.
    fn regulariser_blocks(&self) -> usize {
        self.field.first_curve_block() + self.field.curve_vertices().len()
    }

    /// The field problem's block of regulariser block `b`.
    fn field_block(&self, b: usize) -> usize {
        let first_curve = self.field.first_curve_block();
        if b < first_curve {
            b
        } else {
            b + self.field.curve_vertices().len()
        }
    }

    /// Evaluates light block `k` with the light weights of `weights`.
    pub(crate) fn evaluate_light(&self, k: usize, weights: &ShadingWeights, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        let vertex = self.light_vertices[k];
        let v = self.field.curve_vertices()[vertex.curve] as usize;
        let area = self.mesh().normalized_vertex_areas()[v];
        let light = match vertex.mode {
            LightMode::Block => weights.light_block,
            LightMode::Pass => weights.light_pass,
        };
        let scales = RowScales { constraint: (weights.constraint * area).sqrt(), light: (light * area).sqrt() };
        // Singular vertices keep zero rows.
        let Some(jet) = self.field.level_jet(vertex.curve, x) else { return };
        let stencil = self.field.jet_stencil(vertex.curve);
        let size = self.offsets[k + 1] - self.offsets[k] - stencil.vertices.len();
        let aux = &x[vertex.auxiliary..vertex.auxiliary + size];
        light_rows::evaluate(vertex.mode, &jet, &stencil, &self.frame, self.bounds(vertex.mode), aux, scales, residuals, jacobian);
    }
}

/// The field problem's weights: the regularisers of Eq. 25, no curve term.
fn regulariser_weights(weights: &ShadingWeights) -> Weights {
    Weights { fair: weights.fair, grad: weights.grad, angle: 0.0 }
}

impl LeastSquaresProblem for ShadingProblem {
    fn variable_count(&self) -> usize {
        self.light_vertices.last().map_or(self.mesh().vertex_count(), |last| last.auxiliary + auxiliaries(last.mode))
    }

    fn block_count(&self) -> usize {
        self.regulariser_blocks() + self.light_vertices.len()
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        match b.checked_sub(self.regulariser_blocks()) {
            None => self.field.block_variables(self.field_block(b)),
            Some(k) => &self.variables[self.offsets[k]..self.offsets[k + 1]],
        }
    }

    fn block_residual_count(&self, b: usize) -> usize {
        match b.checked_sub(self.regulariser_blocks()) {
            None => self.field.block_residual_count(self.field_block(b)),
            Some(k) => match self.light_vertices[k].mode {
                LightMode::Block => light_rows::BLOCK_ROWS,
                LightMode::Pass => light_rows::PASS_ROWS,
            },
        }
    }

    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        match b.checked_sub(self.regulariser_blocks()) {
            None => self.field.evaluate_block(self.field_block(b), x, residuals, jacobian),
            Some(k) => self.evaluate_light(k, &self.weights, x, residuals, jacobian),
        }
    }

    fn block_jacobian_is_constant(&self, b: usize) -> bool {
        b < self.regulariser_blocks() && self.field.block_jacobian_is_constant(self.field_block(b))
    }

    fn constant_jacobian_revision(&self) -> u64 {
        self.field.constant_jacobian_revision()
    }

    fn variable_layout(&self) -> VariableLayout {
        let n = self.mesh().vertex_count();
        let sizes: Vec<usize> = self.light_vertices.iter().map(|v| auxiliaries(v.mode)).collect();
        // Invariant: the groups tile [n, variable_count) exactly, in order.
        VariableLayout::with_local_groups(n, &sizes).expect("auxiliary groups tile the local variables")
    }
}

pub(crate) fn auxiliaries(mode: LightMode) -> usize {
    match mode {
        LightMode::Block => light_rows::BLOCK_AUXILIARIES,
        LightMode::Pass => light_rows::PASS_AUXILIARIES,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shading::{EarthFrame, LightRegion};
    use crate::solver::check_block_jacobian;
    use crate::surfaces::{hall_roof, SplitMix64};

    #[test]
    fn the_light_blocks_jacobians_match_finite_differences() {
        let (mesh, _) = hall_roof(300).into_mesh().unwrap().unit_scaled();
        let frame = EarthFrame::new(47.4, crate::mesh::Vec3::y(), crate::mesh::Vec3::z()).unwrap();
        let region = LightRegion::new([-40.0, 20.0], [10.0, 23.0]).unwrap();
        let labels: Vec<VertexLabel> = (0..mesh.vertex_count()).map(|v| [VertexLabel::Block, VertexLabel::Pass, VertexLabel::Free][v % 3]).collect();
        let problem = ShadingProblem::new(mesh, &labels, frame, [region.bounds(); 2], crate::shading::ShadingWeights::blocking());
        let mut rng = SplitMix64::new(9);
        let mut x: Vec<f64> = (0..problem.variable_count()).map(|_| rng.symmetric(1.0)).collect();
        for (v, p) in problem.mesh().positions().iter().enumerate() {
            x[v] = p.x + 0.3 * p.y + 0.05 * rng.symmetric(1.0);
        }
        let first_light = problem.block_count() - problem.light_vertices().len();
        let modes: Vec<LightMode> = problem.light_vertices().iter().map(|v| v.mode).collect();
        assert!(modes.contains(&LightMode::Block) && modes.contains(&LightMode::Pass));
        for b in first_light..problem.block_count() {
            let error = check_block_jacobian(&problem, &x, b, 1e-6);
            assert!(error < 1e-5, "block {b}: Jacobian error {error:e}");
        }
    }
}
