//! Deterministic reduction of the per-block and per-group products into the normal equations:
//! fixed block order and fixed group order, precomputed scatter and gather positions (no
//! searching).
use rayon::prelude::*;

use super::evaluation::{squared_norm, sum_in_block_order, with_jacobian_scratch};
use super::normal_pattern::{check_positions, NormalPattern};
use super::packed_upper::gram_of_rows;
use super::schur::GroupSystems;
use super::structure::{triangle_len, BlockStructure, GroupStructure};
use super::{LeastSquaresProblem, SolverError};

/// The share of H_GG = J_GᵀJ_G of the blocks without a local group whose Jacobian is constant
/// ([`LeastSquaresProblem::block_jacobian_is_constant`]): summed once per revision of the
/// problem's constant Jacobians, in block order, and the values H_GG starts from every
/// iteration. Those blocks keep no Gram products of their own.
pub(crate) struct ConstantHessian {
    values: Vec<f64>,
    /// One block's residuals and packed Gram product (scratch of [`Self::refresh`]).
    residuals: Vec<f64>,
    gram: Vec<f64>,
}

impl ConstantHessian {
    pub fn new(pattern: &NormalPattern) -> Self {
        Self { values: vec![0.0; pattern.storage_len()], residuals: Vec::new(), gram: Vec::new() }
    }

    /// Sums the constant blocks' Gram products, each formed row by row from its Jacobian at `x`
    /// as [`super::evaluation::evaluate_slots`] forms the other blocks', in block order. The
    /// Jacobians are those [`super::evaluation::evaluate_slots`] has just checked at the same
    /// revision (finite).
    pub fn refresh<P: LeastSquaresProblem>(&mut self, problem: &P, structure: &BlockStructure, pattern: &NormalPattern, x: &[f64]) {
        self.values.fill(0.0);
        for b in (0..structure.block_count()).filter(|&b| structure.constant_jacobian[b] && structure.group[b].is_none()) {
            let n = structure.variables(b).len();
            if n == 0 {
                continue;
            }
            let (residuals, gram) = (&mut self.residuals, &mut self.gram);
            with_jacobian_scratch(|jacobian| {
                residuals.clear();
                residuals.resize(structure.residual_count(b), 0.0);
                jacobian.clear();
                jacobian.resize(residuals.len() * n, 0.0);
                problem.evaluate_block(b, x, residuals, Some(jacobian));
                gram.resize(triangle_len(n), 0.0);
                gram_of_rows(jacobian, gram, n);
            });
            add_gram(pattern, b, &self.gram, &mut self.values);
        }
    }
}

/// Adds block `b`'s packed Gram product `gram` to the values of H_GG.
fn add_gram(pattern: &NormalPattern, b: usize, gram: &[f64], hessian: &mut [f64]) {
    let targets = &pattern.gram_targets[pattern.gram_ptr[b]..pattern.gram_ptr[b + 1]];
    for (&t, &value) in targets.iter().zip(gram) {
        hessian[t as usize] += value;
    }
}

/// Sums the blocks' products in block order (from the slots, and for the blocks of a local
/// group from their group's segment): returns E(x), and writes the full gradient g = Jᵀr and
/// the values of H_GG = J_GᵀJ_G of the blocks without a local group on the normal pattern (the
/// groups' blocks add theirs through [`GroupSystems`]): the constant blocks' share
/// `constant_hessian`, plus the other blocks' Gram products in block order.
pub(crate) fn reduce_blocks(
    structure: &BlockStructure,
    pattern: &NormalPattern,
    slots: &[f64],
    systems: &GroupSystems,
    constant_hessian: &ConstantHessian,
    gradient: &mut [f64],
    hessian: &mut [f64],
) -> f64 {
    gradient.fill(0.0);
    hessian.copy_from_slice(&constant_hessian.values);
    let norms = (0..structure.block_count()).map(|b| {
        let (residuals, block_gradient) = match structure.group[b] {
            Some(_) => systems.block_products(structure, b),
            None => {
                let slot = structure.slot(b, slots);
                // Empty for a constant block (its share is in `constant_hessian`).
                add_gram(pattern, b, slot.gram, hessian);
                (slot.residuals, slot.gradient)
            }
        };
        for (&v, &ga) in structure.variables(b).iter().zip(block_gradient) {
            gradient[v as usize] += ga;
        }
        squared_norm(residuals)
    });
    sum_in_block_order(norms)
}

/// Entries of the reduced system filled by one task.
const CHUNK: usize = 4096;

/// Where the entries of the reduced system gather their group terms from: the transpose of the
/// pattern's Schur targets, as positions in the [`GroupSystems`] buffer, in group order.
pub(crate) struct ReducedGather {
    /// `schur_sources[schur_ptr[t]..schur_ptr[t + 1]]`: the W − G_L entries landing on value
    /// position t.
    schur_ptr: Vec<usize>,
    schur_sources: Vec<u32>,
    /// `rhs_sources[rhs_ptr[v]..rhs_ptr[v + 1]]`: the v_L entries of global variable v.
    rhs_ptr: Vec<usize>,
    rhs_sources: Vec<u32>,
}

impl ReducedGather {
    /// Takes the pattern's Schur targets (nothing else reads them).
    /// Errors: `InvalidLayout` when the group systems' buffer is beyond 32-bit positions.
    pub fn new(pattern: &mut NormalPattern, groups: &GroupStructure, systems: &GroupSystems) -> Result<Self, SolverError> {
        check_positions(systems.buffer().len())?;
        // Positions in the buffer fit 32 bits (checked above).
        let from = |start: usize| (start..).map(|p| p as u32);
        let (target_ptr, targets) = pattern.take_schur_targets();
        let group_count = groups.group_count();
        let (schur_ptr, schur_sources) = transpose(
            pattern.storage_len(),
            (0..group_count).flat_map(|l| {
                let targets = &targets[target_ptr[l]..target_ptr[l + 1]];
                targets.iter().map(|&t| t as usize).zip(from(systems.schur_start(groups, l)))
            }),
        );
        let (rhs_ptr, rhs_sources) = transpose(
            pattern.dimension(),
            (0..group_count).flat_map(|l| groups.globals(l).iter().map(|&v| v as usize).zip(from(systems.schur_rhs_start(groups, l)))),
        );
        Ok(Self { schur_ptr, schur_sources, rhs_ptr, rhs_sources })
    }
}

/// CSR lists of the `(key, item)` pairs grouped by key (< `n`), each list in input order.
fn transpose(n: usize, pairs: impl Iterator<Item = (usize, u32)> + Clone) -> (Vec<usize>, Vec<u32>) {
    let mut ptr = vec![0usize; n + 1];
    for (key, _) in pairs.clone() {
        ptr[key + 1] += 1;
    }
    for i in 0..n {
        ptr[i + 1] += ptr[i];
    }
    let mut fill = ptr.clone();
    let mut items = vec![0; ptr[n]];
    for (key, item) in pairs {
        items[fill[key]] = item;
        fill[key] += 1;
    }
    (ptr, items)
}

/// The reduced system S h_G = rhs for damping μ, from the reduced block products and the group
/// eliminations for this μ: S = H_GG + μI − Σ_L (W_L − G_L), rhs = −g_G + Σ_L v_L. S is
/// written as the sum of its domain matrices (see [`super::substructured_cholesky`]).
pub(crate) struct ReducedSystem<'a> {
    pub pattern: &'a NormalPattern,
    pub gather: &'a ReducedGather,
    pub systems: &'a GroupSystems,
    pub hessian: &'a [f64],
    pub gradient: &'a [f64],
    pub mu: f64,
}

impl ReducedSystem<'_> {
    /// Writes the values of S (in parallel) at the pattern's value positions. Each entry is
    /// summed in the fixed order H_GG, μ, then the groups in order, so the result does not
    /// depend on the threads.
    pub fn fill_values(&self, values: &mut [f64]) {
        let (gather, terms) = (self.gather, self.systems.buffer());
        values.par_chunks_mut(CHUNK).enumerate().for_each(|(c, values)| {
            for (i, value) in values.iter_mut().enumerate() {
                let t = c * CHUNK + i;
                let mut s = self.hessian[t];
                let share = self.pattern.damping_share[t];
                if share != 0.0 {
                    s += self.mu * share;
                }
                for &source in &gather.schur_sources[gather.schur_ptr[t]..gather.schur_ptr[t + 1]] {
                    s -= terms[source as usize];
                }
                *value = s;
            }
        });
    }

    /// Writes the right-hand side (in parallel; one entry per global variable, the groups
    /// summed in order).
    pub fn fill_rhs(&self, rhs: &mut [f64]) {
        let (gather, terms) = (self.gather, self.systems.buffer());
        rhs.par_chunks_mut(CHUNK).enumerate().for_each(|(c, rhs)| {
            for (i, r) in rhs.iter_mut().enumerate() {
                let v = c * CHUNK + i;
                let mut s = -self.gradient[v];
                for &source in &gather.rhs_sources[gather.rhs_ptr[v]..gather.rhs_ptr[v + 1]] {
                    s += terms[source as usize];
                }
                *r = s;
            }
        });
    }
}
