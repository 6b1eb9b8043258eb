//! Deterministic reduction of the per-block and per-group products into the normal equations:
//! fixed block order and fixed group order, precomputed scatter positions (no searching).
use super::evaluation::{squared_norm, sum_in_block_order};
use super::normal_pattern::NormalPattern;
use super::schur::GroupSystem;
use super::structure::{BlockStructure, GroupStructure};

/// Sums the block slots in block order: returns E(x), and writes the full gradient g = Jᵀr and
/// the values of H_GG = J_GᵀJ_G of the blocks without a local group on the normal pattern (the
/// groups' blocks add theirs through [`GroupSystem::schur`]).
pub(crate) fn reduce_blocks(
    structure: &BlockStructure,
    pattern: &NormalPattern,
    slots: &mut [f64],
    gradient: &mut [f64],
    hessian: &mut [f64],
) -> f64 {
    gradient.fill(0.0);
    hessian.fill(0.0);
    let norms = (0..structure.block_count()).map(|b| {
        let slot = structure.split_slot(b, &mut slots[structure.slot_ptr[b]..structure.slot_ptr[b + 1]]);
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

/// Reduced system for damping μ: `values` = H_GG + μI − Σ_L (W_L − G_L), `rhs` = −g_G + Σ_L v_L
/// (groups in order; `systems` must hold the eliminations for this μ).
pub(crate) fn assemble_reduced(
    pattern: &NormalPattern,
    groups: &GroupStructure,
    systems: &[GroupSystem],
    hessian: &[f64],
    gradient: &[f64],
    mu: f64,
    values: &mut [f64],
    rhs: &mut [f64],
) {
    values.copy_from_slice(hessian);
    for &d in &pattern.diagonal {
        values[d] += mu;
    }
    for (r, &g) in rhs.iter_mut().zip(gradient) {
        *r = -g;
    }
    for (l, system) in systems.iter().enumerate() {
        // The group's target list holds exactly q(q+1)/2 upper pairs, in the packed order of W.
        let targets = &pattern.schur_targets[pattern.schur_ptr[l]..pattern.schur_ptr[l + 1]];
        for (&t, &w) in targets.iter().zip(system.schur()) {
            values[t] -= w;
        }
        for (&v, &r) in groups.globals(l).iter().zip(system.schur_rhs()) {
            rhs[v as usize] += r;
        }
    }
}
