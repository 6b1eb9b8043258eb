//! Parallel evaluation of the residual blocks: at x into per-block slots (residuals, Jᵀr and
//! the Gram products of the global columns; the Jacobian itself only passes through a per-thread
//! scratch), and at trial points without Jacobians. (The blocks of local groups are evaluated at
//! x by [`super::schur::GroupSystems`].)
use std::cell::Cell;

use rayon::prelude::*;

use super::packed_upper::add_outer_product;
use super::segments::try_for_each_segment;
use super::structure::BlockStructure;
use super::{LeastSquaresProblem, SolverError};

/// ‖r‖² of one block.
pub(crate) fn squared_norm(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// E = Σ_b ‖r_b‖², summed in block order (the one summation order used everywhere).
pub(crate) fn sum_in_block_order(norms: impl Iterator<Item = f64>) -> f64 {
    norms.fold(0.0, |acc, v| acc + v)
}

thread_local! {
    /// The Jacobian of the block being evaluated on this thread (taken while in use, so that a
    /// nested use gets a fresh one rather than a conflict).
    static JACOBIAN: Cell<Vec<f64>> = const { Cell::new(Vec::new()) };
}

/// Runs `f` with this thread's Jacobian scratch, then keeps it (and its capacity) for the next
/// block.
pub(crate) fn with_jacobian_scratch<T>(f: impl FnOnce(&mut Vec<f64>) -> T) -> T {
    let mut jacobian = JACOBIAN.take();
    let result = f(&mut jacobian);
    JACOBIAN.set(jacobian);
    result
}

/// Evaluates every block without a local group at `x` into its slot: residuals, Jᵀr and the
/// Gram products of its columns, from its Jacobian evaluated into a per-thread scratch. Blocks
/// whose Jacobian is constant ([`LeastSquaresProblem::block_jacobian_is_constant`]) get no Gram
/// products here (see [`super::assembly::ConstantHessian`]); with `reuse_constant` (their
/// Jacobian was checked at the same revision) their Jacobian is not checked again. Errors name
/// the lowest non-finite block.
pub(crate) fn evaluate_slots<P: LeastSquaresProblem>(
    problem: &P,
    structure: &BlockStructure,
    x: &[f64],
    slots: &mut [f64],
    reuse_constant: bool,
) -> Result<(), SolverError> {
    let failed = try_for_each_segment(slots, &structure.slot_ptr, &|b, slot| {
        if structure.group[b].is_some() {
            return true;
        }
        let s = structure.split_slot(b, slot);
        let n = s.gradient.len();
        with_jacobian_scratch(|jacobian| {
            s.residuals.fill(0.0);
            jacobian.clear();
            jacobian.resize(s.residuals.len() * n, 0.0);
            problem.evaluate_block(b, x, s.residuals, Some(jacobian));
            if !s.residuals.iter().all(|v| v.is_finite()) {
                return false;
            }
            if n == 0 {
                return true;
            }
            // One pass over the Jacobian, row by row: Jᵀr (each entry summed over the rows in
            // order), the upper Gram of the global columns (in the order of the pattern's gram
            // targets; structurally zero entries are skipped) and the Jacobian's finiteness.
            // Only blocks without a local group and with a varying Jacobian have a Gram part, and
            // all their variables are global, so its columns are the row's own entries in order.
            // A constant Jacobian reused at its revision was checked when it was first evaluated.
            let check = !(reuse_constant && structure.constant_jacobian[b]);
            debug_assert!(s.gram.is_empty() || structure.global_positions(b).iter().enumerate().all(|(i, &p)| p as usize == i));
            s.gradient.fill(0.0);
            s.gram.fill(0.0);
            let mut finite = true;
            for (row, &r) in jacobian.chunks_exact(n).zip(s.residuals.iter()) {
                for (g, &j) in s.gradient.iter_mut().zip(row) {
                    *g += j * r;
                }
                if check {
                    finite &= row.iter().all(|v| v.is_finite());
                }
                if !s.gram.is_empty() {
                    add_outer_product(row, s.gram);
                }
            }
            finite
        })
    });
    match failed {
        None => Ok(()),
        Some(block) => {
            let m = structure.residual_count(block);
            let residuals = &slots[structure.slot_ptr[block]..structure.slot_ptr[block] + m];
            if residuals.iter().all(|v| v.is_finite()) {
                Err(SolverError::NonFiniteJacobian { block })
            } else {
                Err(SolverError::NonFiniteResidual { block })
            }
        }
    }
}

/// E(x) from residuals evaluated into `residuals` (segmented by `residual_ptr`), or `None` if any
/// residual is not finite.
pub(crate) fn evaluate_energy_into<P: LeastSquaresProblem>(
    problem: &P,
    structure: &BlockStructure,
    x: &[f64],
    residuals: &mut [f64],
) -> Option<f64> {
    let failed = try_for_each_segment(residuals, &structure.residual_ptr, &|b, r| {
        r.fill(0.0);
        problem.evaluate_block(b, x, r, None);
        r.iter().all(|v| v.is_finite())
    });
    if failed.is_some() {
        return None;
    }
    let norms = (0..structure.block_count())
        .map(|b| squared_norm(&residuals[structure.residual_ptr[b]..structure.residual_ptr[b + 1]]));
    Some(sum_in_block_order(norms))
}

/// E(x) without any workspace: per-block norms in parallel, summed in block order. Non-finite
/// residuals or a wrong length of `x` give +∞.
pub(crate) fn evaluate_energy_standalone<P: LeastSquaresProblem>(problem: &P, x: &[f64]) -> f64 {
    if x.len() != problem.variable_count() {
        return f64::INFINITY;
    }
    let norms: Vec<f64> = (0..problem.block_count())
        .into_par_iter()
        .map_init(Vec::new, |r, b| {
            r.clear();
            r.resize(problem.block_residual_count(b), 0.0);
            problem.evaluate_block(b, x, r, None);
            squared_norm(r)
        })
        .collect();
    let energy = sum_in_block_order(norms.into_iter());
    if energy.is_finite() {
        energy
    } else {
        f64::INFINITY
    }
}
