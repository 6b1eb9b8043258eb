//! Several level-set problems of Eq. 12 on one mesh as one sparse least-squares problem, coupled
//! by the intersection-angle term of Sec. 4.1 and, for a 3-web, by Eq. 18.
//!
//! Variables: the fields one after the other (field `k` at `[k n, (k + 1) n)`), then each
//! field's auxiliaries (pseudo-geodesics: `b`, `u` per curve vertex, eliminated by Schur
//! complement). Blocks: every block of the first field's [`FieldProblem`], then the second's (and
//! the third's), then one intersection block per face and pair of fields (a net: the pair 0–1; a
//! 3-web also 0–2 and 1–2, their target rows weightless: only the minimum angle holds there),
//! then for a 3-web one Eq. 18 row per vertex, `√w (F + G + H)`. Each field's problem sees the
//! variables from the start of its own field on (`x[k n..]`), with its auxiliaries placed where
//! they live in the whole vector; its block variables are shifted by `k n` once, here.

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
    /// The pairs of fields whose intersection angle is held: `(0, 1)`, and for a 3-web `(0, 2)`
    /// and `(1, 2)`.
    pairs: Vec<(usize, usize)>,
    /// Per pair and face: the first field at the face's corners, then the second at them.
    face_variables: Vec<u32>,
    /// The intersection term of the pair 0–1; the other pairs hold only its minimum angle.
    intersection: IntersectionTerm,
    /// Per vertex of a 3-web: its value in each field (empty for a net).
    web_variables: Vec<u32>,
    /// `√` of the weight of Eq. 18's rows.
    web_scale: f64,
}

/// The intersection blocks' target rows are weightless for every pair but the first.
fn pair_term(term: &IntersectionTerm, pair: usize) -> IntersectionTerm {
    if pair == 0 { *term } else { IntersectionTerm { target_weight: 0.0, ..*term } }
}

impl NetProblem {
    /// The problem of one field per family on `mesh` (unit-scaled), field `k` with `weights`
    /// times `factors[k]` and the gradient target 1, coupled by `intersection` and, for three
    /// families, by Eq. 18 with weight `web_weight`.
    pub(crate) fn new(mesh: &TriMesh, families: &[Family], weights: Weights, factors: &[f64], intersection: IntersectionTerm, web_weight: f64) -> NetProblem {
        let n = mesh.vertex_count();
        let count = families.len();
        let mut fields: Vec<FieldProblem> = Vec::with_capacity(count);
        let mut auxiliary_start = count * n;
        for (k, &family) in families.iter().enumerate() {
            let field = FieldProblem::with_auxiliary_base(mesh.clone(), family, scaled(weights, factors[k]), 1.0, auxiliary_start - k * n);
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
        let pairs: Vec<(usize, usize)> = if count == 3 { vec![(0, 1), (0, 2), (1, 2)] } else { vec![(0, 1)] };
        let face_variables = pairs
            .iter()
            .flat_map(|&(a, b)| mesh.faces().iter().flat_map(move |face| face.map(|v| v + (a * n) as u32).into_iter().chain(face.map(|v| v + (b * n) as u32))))
            .collect();
        let web_variables = if count == 3 { (0..n as u32).flat_map(|v| [v, v + n as u32, v + 2 * n as u32]).collect() } else { Vec::new() };
        NetProblem { fields, vertex_count: n, block_starts, shifted_offsets, shifted_variables, pairs, face_variables, intersection, web_variables, web_scale: web_weight.sqrt() }
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

    /// Field `k`'s terms get `weights` times `factors[k]`.
    pub(crate) fn set_weights(&mut self, weights: Weights, factors: &[f64]) {
        self.fields.iter_mut().zip(factors).for_each(|(field, &factor)| field.set_weights(scaled(weights, factor)));
    }

    /// Which block `b` is.
    fn locate(&self, b: usize) -> Block {
        let k = self.block_starts.partition_point(|&start| start <= b) - 1;
        if k < self.fields.len() {
            return Block::Field(k, b - self.block_starts[k]);
        }
        let faces = self.mesh().face_count();
        let local = b - self.block_starts[self.fields.len()];
        if local < self.pairs.len() * faces {
            Block::Intersection(local / faces, local % faces)
        } else {
            Block::Web(local - self.pairs.len() * faces)
        }
    }
}

/// What a block of the problem holds.
enum Block {
    /// Field `k`'s block with the given index in its own problem.
    Field(usize, usize),
    /// The intersection rows of pair `p` on face `f`.
    Intersection(usize, usize),
    /// Eq. 18's row at a vertex.
    Web(usize),
}

fn scaled(weights: Weights, factor: f64) -> Weights {
    Weights { fair: weights.fair * factor, grad: weights.grad * factor, angle: weights.angle * factor }
}

impl LeastSquaresProblem for NetProblem {
    fn variable_count(&self) -> usize {
        let auxiliaries: usize = self.fields.iter().map(|f| FieldProblem::auxiliaries_per_vertex(f.family()) * f.curve_vertices().len()).sum();
        self.fields.len() * self.vertex_count + auxiliaries
    }

    fn block_count(&self) -> usize {
        self.block_starts[self.fields.len()] + self.pairs.len() * self.mesh().face_count() + self.web_variables.len() / 3
    }

    fn block_variables(&self, b: usize) -> &[u32] {
        match self.locate(b) {
            Block::Field(0, local) => self.fields[0].block_variables(local),
            Block::Field(k, local) => &self.shifted_variables[k][self.shifted_offsets[k][local]..self.shifted_offsets[k][local + 1]],
            Block::Intersection(p, f) => {
                let at = 6 * (p * self.mesh().face_count() + f);
                &self.face_variables[at..at + 6]
            }
            Block::Web(v) => &self.web_variables[3 * v..3 * v + 3],
        }
    }

    fn block_residual_count(&self, b: usize) -> usize {
        match self.locate(b) {
            Block::Field(k, local) => self.fields[k].block_residual_count(local),
            Block::Intersection(..) => intersection::ROWS,
            Block::Web(_) => 1,
        }
    }

    fn evaluate_block(&self, b: usize, x: &[f64], residuals: &mut [f64], jacobian: Option<&mut [f64]>) {
        let n = self.vertex_count;
        match self.locate(b) {
            Block::Field(k, local) => self.fields[k].evaluate_block(local, &x[self.field_start(k)..], residuals, jacobian),
            Block::Intersection(p, f) => {
                let (a, c) = self.pairs[p];
                let term = pair_term(&self.intersection, p);
                intersection::evaluate(self.mesh(), &term, &x[a * n..(a + 1) * n], &x[c * n..(c + 1) * n], f, residuals, jacobian);
            }
            Block::Web(v) => {
                residuals[0] = self.web_scale * (x[v] + x[n + v] + x[2 * n + v]);
                if let Some(jac) = jacobian {
                    jac.fill(self.web_scale);
                }
            }
        }
    }

    /// The fields' own constant blocks (fairness and fit rows); Eq. 18's row scales with the
    /// third family's growing weight, so it is evaluated every time.
    fn block_jacobian_is_constant(&self, b: usize) -> bool {
        match self.locate(b) {
            Block::Field(k, local) => self.fields[k].block_jacobian_is_constant(local),
            Block::Intersection(..) | Block::Web(_) => false,
        }
    }

    /// The latest of the fields' revisions: every field's change takes a new, larger one.
    fn constant_jacobian_revision(&self) -> u64 {
        self.fields.iter().map(LeastSquaresProblem::constant_jacobian_revision).max().unwrap_or(0)
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
