//! Deterministic reduction of the per-block and per-group products into the normal equations:
//! fixed block order and fixed group order, precomputed scatter and gather positions (no
//! searching).
use rayon::prelude::*;

use super::evaluation::{squared_norm, sum_in_block_order};
use super::normal_pattern::NormalPattern;
use super::schur::GroupSystems;
use super::structure::{BlockStructure, GroupStructure};

/// Sums the block slots in block order: returns E(x), and writes the full gradient g = Jᵀr and
/// the values of H_GG = J_GᵀJ_G of the blocks without a local group on the normal pattern (the
/// groups' blocks add theirs through [`GroupSystem::schur`]).
pub(crate) fn reduce_blocks(
    structure: &BlockStructure,
    pattern: &NormalPattern,
    slots: &[f64],
    gradient: &mut [f64],
    hessian: &mut [f64],
) -> f64 {
    gradient.fill(0.0);
    hessian.fill(0.0);
    let norms = (0..structure.block_count()).map(|b| {
        let slot = structure.slot(b, slots);
        for (&v, &ga) in structure.variables(b).iter().zip(slot.gradient.iter()) {
            gradient[v as usize] += ga;
        }
        let targets = &pattern.gram_targets[pattern.gram_ptr[b]..pattern.gram_ptr[b + 1]];
        for (&t, &value) in targets.iter().zip(slot.gram.iter()) {
            hessian[t] += value;
        }
        squared_norm(slot.residuals)
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
    schur_sources: Vec<usize>,
    /// `rhs_sources[rhs_ptr[v]..rhs_ptr[v + 1]]`: the v_L entries of global variable v.
    rhs_ptr: Vec<usize>,
    rhs_sources: Vec<usize>,
}

impl ReducedGather {
    pub fn new(pattern: &NormalPattern, groups: &GroupStructure, systems: &GroupSystems) -> Self {
        let group_count = groups.group_count();
        let (schur_ptr, schur_sources) = transpose(
            pattern.storage_len(),
            (0..group_count).flat_map(|l| {
                let targets = &pattern.schur_targets[pattern.schur_ptr[l]..pattern.schur_ptr[l + 1]];
                targets.iter().copied().zip(systems.schur_start(groups, l)..)
            }),
        );
        let (rhs_ptr, rhs_sources) = transpose(
            pattern.dimension(),
            (0..group_count).flat_map(|l| {
                groups.globals(l).iter().map(|&v| v as usize).zip(systems.schur_rhs_start(groups, l)..)
            }),
        );
        Self { schur_ptr, schur_sources, rhs_ptr, rhs_sources }
    }
}

/// CSR lists of the `(key, item)` pairs grouped by key (< `n`), each list in input order.
fn transpose(n: usize, pairs: impl Iterator<Item = (usize, usize)> + Clone) -> (Vec<usize>, Vec<usize>) {
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
                    s -= terms[source];
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
                    s += terms[source];
                }
                *r = s;
            }
        });
    }
}
