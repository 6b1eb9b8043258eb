//! Several level-set problems of Eq. 12 on one mesh as one sparse least-squares problem, coupled
//! by the intersection-angle term of Sec. 4.1.
//!
//! Variables: the fields one after the other (`F` at `[0, n)`, `G` at `[n, 2n)`), then each
//! field's auxiliaries (pseudo-geodesics: `b`, `u` per curve vertex, eliminated by Schur
//! complement). Blocks: every block of the first field's [`FieldProblem`], then the second's,
//! then one intersection block per face. Each field's problem sees the variables from the start
//! of its own field on (`x[k n..]`), with its auxiliaries placed where they live in the whole
//! vector; its block variables are shifted by `k n` once, here.

use super::intersection::{self, IntersectionTerm};
use crate::field::{Family, FieldProblem, Weights};
use crate::mesh::TriMesh;
use crate::solver::{LeastSquaresProblem, VariableLayout};

/// The coupled problem on a unit-scaled mesh.
pub struct NetProblem {
    fields: Vec<FieldProblem>,
    vertex_count: usize,
    /// First block of each field, then the first intersection block.
    block_starts: Vec<usize>,
    /// Block variables of every field but the first, shifted to the whole vector (CSR over the
    /// field's blocks); the first field's are its own.
    shifted_offsets: Vec<Vec<usize>>,
    shifted_variables: Vec<Vec<u32>>,
    /// Per face: `F` at its corners, then `G` at them.
    face_variables: Vec<u32>,
    intersection: IntersectionTerm,
}

impl NetProblem {
    /// The problem of one field per family on `mesh` (unit-scaled), each with `weights` and the
    /// gradient target 1, coupled by `intersection`.
    pub(crate) fn new(mesh: &TriMesh, families: &[Family], weights: Weights, intersection: IntersectionTerm) -> NetProblem {
        let n = mesh.vertex_count();
        let count = families.len();
        let mut fields: Vec<FieldProblem> = Vec::with_capacity(count);
        let mut auxiliary_start = count * n;
        for (k, &family) in families.iter().enumerate() {
            let field = FieldProblem::with_auxiliary_base(mesh.clone(), family, weights, 1.0, auxiliary_start - k * n);
            auxiliary_start += FieldProblem::auxiliaries_per_vertex(family) * field.curve_vertices().len();
            fields.push(field);
        }
        let mut block_starts = vec![0];
        for field in &fields {
            block_starts.push(block_starts.last().copied().unwrap_or(0) + field.block_count());
        }
        let (mut shifted_offsets, mut shifted_variables) = (vec![Vec::new()], vec![Vec::new()]);
        for (k, field) in fields.iter().enumerate().skip(1) {
            let shift = (k * n) as u32;
            let mut offsets = vec![0];
            let mut variables = Vec::new();
            for b in 0..field.block_count() {
                variables.extend(field.block_variables(b).iter().map(|&v| v + shift));
                offsets.push(variables.len());
            }
            shifted_offsets.push(offsets);
            shifted_variables.push(variables);
        }
        let face_variables = mesh.faces().iter().flat_map(|face| face.iter().copied().chain(face.iter().map(|&v| v + n as u32))).collect();
        NetProblem { fields, vertex_count: n, block_starts, shifted_offsets, shifted_variables, face_variables, intersection }
    }

    /// The single-field problems, in order.
    pub fn fields(&self) -> &[FieldProblem] {
        &self.fields
    }

    /// The (unit-scaled) mesh.
    pub fn mesh(&self) -> &TriMesh {
        self.fields[0].mesh()
    }

    /// Start of field `k`'s values in the variables (its problem's view begins there).
    pub fn field_start(&self, k: usize) -> usize {
        k * self.vertex_count
    }

    pub(crate) fn intersection(&self) -> &IntersectionTerm {
        &self.intersection
    }

    pub(crate) fn set_weights(&mut self, weights: Weights) {
        self.fields.iter_mut().for_each(|field| field.set_weights(weights));
    }

    /// Which field block `b` belongs to and its index there; `None` for an intersection block.
    fn locate(&self, b: usize) -> Option<(usize, usize)> {
        let k = self.block_starts.partition_point(|&start| start <= b) - 1;
        (k < self.fields.len()).then(|| (k, b - self.block_starts[k]))
    }
}

impl LeastSquaresProblem for NetProblem {
    fn variable_count(&self) -> usize {
        let auxiliaries: usize = self.fields.iter().map(|f| FieldProblem::auxiliaries_per_vertex(f.family()) * f.curve_vertices().len()).sum();
        self.fields.len() * self.vertex_count + auxiliaries
    }

    fn block_count(&self) -> usize {
        self.block_starts[self.fields.len()] + self.mesh().face_count()
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        match self.locate(b) {
            Some((0, local)) => self.fields[0].block_variables(local),
            Some((k, local)) => &self.shifted_variables[k][self.shifted_offsets[k][local]..self.shifted_offsets[k][local + 1]],
            None => {
                let f = b - self.block_starts[self.fields.len()];
                &self.face_variables[6 * f..6 * f + 6]
            }
        }
    }

    fn block_residual_count(&self, b: usize) -> usize {
        match self.locate(b) {
            Some((k, local)) => self.fields[k].block_residual_count(local),
            None => intersection::ROWS,
        }
    }

    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        match self.locate(b) {
            Some((k, local)) => self.fields[k].evaluate_block(local, &x[self.field_start(k)..], residuals, jacobian),
            None => {
                let f = b - self.block_starts[self.fields.len()];
                let n = self.vertex_count;
                intersection::evaluate(self.mesh(), &self.intersection, &x[..n], &x[n..2 * n], f, residuals, jacobian);
            }
        }
    }

    fn variable_layout(&self) -> VariableLayout {
        let sizes: Vec<usize> = self
            .fields
            .iter()
            .flat_map(|f| std::iter::repeat_n(FieldProblem::auxiliaries_per_vertex(f.family()), f.curve_vertices().len()))
            .filter(|&size| size > 0)
            .collect();
        // Invariant: the groups tile [fields · n, variable_count) exactly, in order.
        VariableLayout::with_local_groups(self.fields.len() * self.vertex_count, &sizes).expect("auxiliary groups tile the local variables")
    }
}
