//! Schur elimination of the local variable groups.
//!
//! For a group L with local Jacobian columns J_L and the group's global columns J_G, the damped
//! normal equations read
//! [H_GG+μI  C_Lᵀ; C_L  D_L+μI] [h_G; h_L] = −[g_G; g_L],  D_L = J_LᵀJ_L,  C_L = J_LᵀJ_G.
//! Eliminating h_L gives the reduced system
//! (H_GG + μI − Σ_L C_Lᵀ(D_L+μI)⁻¹C_L) h_G = −g_G + Σ_L C_Lᵀ(D_L+μI)⁻¹g_L
//! and the back-substitution h_L = −(D_L+μI)⁻¹(g_L + C_L h_G).
//!
//! With the Cholesky factor D_L + μI = L Lᵀ and [Z | z] = L⁻¹[C_L | g_L] (one forward
//! substitution), the Schur terms are W = ZᵀZ and v = Zᵀz, and h_L = −L⁻ᵀ(z + Z h_G).
//! The groups are small (a handful of variables), so everything is hand-rolled on row-major
//! sections of one segment per group, all segments in one buffer (so that the reduced system
//! can gather the Schur terms by flat positions). The elimination works in place (L over D_L,
//! [Z | z] over [C_L | g_L], W − G_L over G_L), which halves the memory every pass streams
//! through.
//!
//! The group's blocks are evaluated right where they are accumulated: each block's Jacobian
//! lives only in a per-thread scratch while its rows are summed into the group system, and only
//! its residuals and Jᵀr are kept (in the group's segment, for the energy and the gradient).
//!
//! A trial with another μ (after a rejected step) eliminates the systems accumulated at the same
//! x again. Where all of them together are small (up to [`KEPT_ACCUMULATION_LIMIT`] values, a
//! field on some 35k vertices), each segment keeps a copy of its accumulated system, taken right
//! after the accumulation while it is in cache, and a retry copies it back: far cheaper than an
//! evaluation. Larger solves evaluate and accumulate the groups again instead: their peak memory
//! is what binds at scale, and there the sparse factorisation outweighs the evaluation in a trial.
//!
//! The global Gram G_L = J_GᵀJ_G of the group's blocks is summed here too (from the same
//! Jacobian rows) rather than scattered into H_GG block by block: the group hands S the single
//! packed term W − G_L on its Schur targets, which cover every global pair of its blocks.
use std::sync::atomic::{AtomicUsize, Ordering};

use super::evaluation::with_jacobian_scratch;
use super::packed_upper::add_outer_product;
use super::segments::try_for_each_segment;
use super::structure::{triangle_len, BlockStructure, GroupStructure};
use super::{LeastSquaresProblem, SolverError};

/// Most values the kept copies of the accumulated systems of all groups may hold (64 MiB):
/// enough for every probe of the start search and for a field on some 35k vertices.
pub(crate) const KEPT_ACCUMULATION_LIMIT: usize = 1 << 23;

/// Dense workspaces of all local groups (group l: k local variables, q coupled global
/// variables), sized once, one segment per group in one buffer.
///
/// A segment holds, in this order: D_L, after elimination its Cholesky factor L (lower triangle
/// of k×k packed row by row); [C_L | g_L], after elimination [Z | z] (k×(q+1)); G_L, after
/// elimination W − G_L (upper triangle of q×q packed row by row, the order of the pattern's Schur
/// targets); v (q); the residuals and Jᵀr of each of the group's blocks, in block order (m + n
/// each); and, where they are kept, a copy of the accumulated D_L, [C_L | g_L] and G_L.
/// All row-major. (A block's Jacobian and the dense row being accumulated live in a per-thread
/// scratch, not in the segment.)
pub(crate) struct GroupSystems {
    /// `buffer[segment_ptr[l]..segment_ptr[l + 1]]`: the segment of group l.
    segment_ptr: Vec<usize>,
    buffer: Vec<f64>,
    /// Whether the segments hold accumulated, not yet eliminated systems.
    accumulated: bool,
    /// Whether each segment keeps a copy of its accumulated system.
    keeps_accumulation: bool,
    /// Position in `buffer` of each block's residuals, followed by its Jᵀr (blocks of a local
    /// group only; 0 for the others).
    product_start: Vec<usize>,
}

/// Mutable views of a group's segment.
struct Sections<'a> {
    /// D_L, then L.
    normal: &'a mut [f64],
    /// [C_L | g_L], then [Z | z].
    coupling: &'a mut [f64],
    /// G_L, then W − G_L.
    gram: &'a mut [f64],
    schur_rhs: &'a mut [f64],
}

/// Section lengths of a group with k local and q global variables, in segment order.
fn section_lengths(k: usize, q: usize) -> [usize; 4] {
    [triangle_len(k), k * (q + 1), triangle_len(q), q]
}

/// Offset of section `index` (see [`section_lengths`]) within a segment.
fn section_offset(k: usize, q: usize, index: usize) -> usize {
    section_lengths(k, q)[..index].iter().sum()
}

const COUPLING: usize = 1;
const GRAM: usize = 2;
const SCHUR_RHS: usize = 3;

/// Length of the accumulated system of a group (D_L, [C_L | g_L], G_L), the start of its segment.
fn system_len(k: usize, q: usize) -> usize {
    section_offset(k, q, SCHUR_RHS)
}

/// A segment without its kept copy (if `keeps`), and that copy.
fn split_kept(k: usize, q: usize, segment: &mut [f64], keeps: bool) -> (&mut [f64], &mut [f64]) {
    let kept = if keeps { system_len(k, q) } else { 0 };
    let at = segment.len() - kept;
    segment.split_at_mut(at)
}

/// The sections of a segment (without its kept copy), and the rest of it: its blocks' residuals
/// and Jᵀr.
fn sections(k: usize, q: usize, segment: &mut [f64]) -> (Sections<'_>, &mut [f64]) {
    let [normal, coupling, gram, schur_rhs] = section_lengths(k, q);
    let (normal_part, rest) = segment.split_at_mut(normal);
    let (coupling_part, rest) = rest.split_at_mut(coupling);
    let (gram_part, rest) = rest.split_at_mut(gram);
    let (schur_rhs_part, products) = rest.split_at_mut(schur_rhs);
    let sections = Sections {
        normal: normal_part,
        coupling: coupling_part,
        gram: gram_part,
        schur_rhs: schur_rhs_part,
    };
    (sections, products)
}

/// k and q of group l.
fn dimensions(groups: &GroupStructure, l: usize) -> (usize, usize) {
    (groups.size(l), groups.globals(l).len())
}

impl GroupSystems {
    /// The workspaces, keeping copies of the accumulated systems if these hold at most
    /// `kept_limit` values in all ([`KEPT_ACCUMULATION_LIMIT`] for a solver).
    pub fn new(blocks: &BlockStructure, groups: &GroupStructure, kept_limit: usize) -> Self {
        let systems: usize = (0..groups.group_count()).map(|l| system_len(groups.size(l), groups.globals(l).len())).sum();
        let keeps_accumulation = systems <= kept_limit;
        let mut segment_ptr = Vec::with_capacity(groups.group_count() + 1);
        segment_ptr.push(0);
        let mut product_start = vec![0; blocks.block_count()];
        for l in 0..groups.group_count() {
            let (k, q) = dimensions(groups, l);
            let mut end = segment_ptr[l] + section_lengths(k, q).iter().sum::<usize>();
            for &b in groups.blocks(l) {
                let b = b as usize;
                product_start[b] = end;
                end += blocks.residual_count(b) + blocks.variables(b).len();
            }
            if keeps_accumulation {
                end += system_len(k, q);
            }
            segment_ptr.push(end);
        }
        let len = segment_ptr[groups.group_count()];
        Self { segment_ptr, buffer: vec![0.0; len], accumulated: false, keeps_accumulation, product_start }
    }

    /// Whether a retried trial copies back kept accumulations (rather than evaluating again).
    #[cfg(test)]
    pub fn keeps_accumulation(&self) -> bool {
        self.keeps_accumulation
    }

    /// The residuals and Jᵀr of block `b` of a local group at the x of the last accumulation.
    pub fn block_products(&self, blocks: &BlockStructure, b: usize) -> (&[f64], &[f64]) {
        let start = self.product_start[b];
        let m = blocks.residual_count(b);
        let n = blocks.variables(b).len();
        self.buffer[start..start + m + n].split_at(m)
    }

    /// The whole buffer (for gathers by [`Self::schur_start`] and [`Self::schur_rhs_start`]).
    pub fn buffer(&self) -> &[f64] {
        &self.buffer
    }

    /// Position in [`Self::buffer`] of group l's W − G_L with W = C_Lᵀ(D_L+μI)⁻¹C_L, upper
    /// triangle packed row by row (valid after an elimination).
    pub fn schur_start(&self, groups: &GroupStructure, l: usize) -> usize {
        let (k, q) = dimensions(groups, l);
        self.segment_ptr[l] + section_offset(k, q, GRAM)
    }

    /// Position in [`Self::buffer`] of group l's v = C_Lᵀ(D_L+μI)⁻¹g_L (valid after an
    /// elimination).
    pub fn schur_rhs_start(&self, groups: &GroupStructure, l: usize) -> usize {
        let (k, q) = dimensions(groups, l);
        self.segment_ptr[l] + section_offset(k, q, SCHUR_RHS)
    }

    /// The diagonal of group l's G_L = J_GᵀJ_G, in the order of its globals (valid after an
    /// accumulation without elimination).
    pub fn gram_diagonal<'a>(&'a self, groups: &GroupStructure, l: usize) -> impl Iterator<Item = f64> + 'a {
        let (k, q) = dimensions(groups, l);
        let gram = self.segment_ptr[l] + section_offset(k, q, GRAM);
        (0..q).map(move |i| self.buffer[gram + packed_upper_index(i, i, q)])
    }

    /// Largest diagonal entry of any D_L (0 without groups; valid after an accumulation without
    /// elimination).
    pub fn max_diagonal(&self, groups: &GroupStructure) -> f64 {
        (0..groups.group_count()).fold(0.0, |m: f64, l| {
            let k = groups.size(l);
            (0..k).fold(m, |m, i| m.max(self.buffer[self.segment_ptr[l] + lower_index(i, i)]))
        })
    }

    /// Evaluates every group's blocks at `x` and accumulates its D_L, C_L, G_L and g_L from them
    /// (in parallel), and, if `mu` is given, eliminates it right away while its segment is in
    /// cache. Returns `Ok(false)` if an elimination fails; errors name the lowest block of a
    /// group whose residuals or Jacobian are not finite.
    pub fn accumulate<P: LeastSquaresProblem>(
        &mut self,
        problem: &P,
        x: &[f64],
        blocks: &BlockStructure,
        groups: &GroupStructure,
        mu: Option<f64>,
    ) -> Result<bool, SolverError> {
        self.accumulated = mu.is_none();
        let keeps = self.keeps_accumulation;
        // 2b for block b's residuals, 2b + 1 for its Jacobian: the lowest over all groups.
        let non_finite = AtomicUsize::new(usize::MAX);
        let failed = try_for_each_segment(&mut self.buffer, &self.segment_ptr, &|l, segment| {
            let (k, q) = dimensions(groups, l);
            let (segment, kept) = split_kept(k, q, segment, keeps);
            let (mut s, products) = sections(k, q, segment);
            let evaluated = with_jacobian_scratch(|jacobian| accumulate_kernel(problem, x, k, q, &mut s, products, blocks, groups.blocks(l), jacobian));
            match evaluated {
                Ok(()) => {
                    if keeps {
                        kept.copy_from_slice(&segment[..kept.len()]);
                    }
                    mu.is_none_or(|mu| eliminate_kernel(k, q, &mut sections(k, q, segment).0, mu))
                }
                Err(code) => {
                    non_finite.fetch_min(code, Ordering::Relaxed);
                    false
                }
            }
        });
        match non_finite.into_inner() {
            usize::MAX => Ok(failed.is_none()),
            code if code % 2 == 0 => Err(SolverError::NonFiniteResidual { block: code / 2 }),
            code => Err(SolverError::NonFiniteJacobian { block: code / 2 }),
        }
    }

    /// Factors every D_L + μI = LLᵀ, solves [Z | z] = L⁻¹[C_L | g_L] and forms W = ZᵀZ,
    /// v = Zᵀz (in parallel). Unless the systems are fresh from [`Self::accumulate`] without μ,
    /// copies the kept accumulations back first, or where none are kept, evaluates and
    /// accumulates the systems at `x` again. Returns `false` if a dense factorisation fails (not
    /// numerically positive definite) or the evaluation does (it succeeded at the same x before).
    pub fn eliminate<P: LeastSquaresProblem>(
        &mut self,
        problem: &P,
        x: &[f64],
        blocks: &BlockStructure,
        groups: &GroupStructure,
        mu: f64,
    ) -> bool {
        let (keeps, restore) = (self.keeps_accumulation, !self.accumulated);
        if restore && !keeps {
            return self.accumulate(problem, x, blocks, groups, Some(mu)).unwrap_or(false);
        }
        self.accumulated = false;
        let failed = try_for_each_segment(&mut self.buffer, &self.segment_ptr, &|l, segment| {
            let (k, q) = dimensions(groups, l);
            let (segment, kept) = split_kept(k, q, segment, keeps);
            if restore {
                segment[..kept.len()].copy_from_slice(kept);
            }
            let (mut s, _) = sections(k, q, segment);
            eliminate_kernel(k, q, &mut s, mu)
        });
        failed.is_none()
    }

    /// h_L = −L⁻ᵀ(z + Z h_G) of every group (in parallel) from the reduced solution
    /// `global_step`, into `local_step` (the local variables in order).
    pub fn back_substitute(&self, groups: &GroupStructure, global_step: &[f64], local_step: &mut [f64]) {
        try_for_each_segment(local_step, &groups.starts, &|l, step| {
            let (k, q) = dimensions(groups, l);
            let segment = &self.buffer[self.segment_ptr[l]..self.segment_ptr[l + 1]];
            let w = q + 1;
            let factor = &segment[..triangle_len(k)];
            let solved_start = section_offset(k, q, COUPLING);
            let solved = &segment[solved_start..solved_start + k * w];
            let globals = groups.globals(l);
            for (h, z_row) in step.iter_mut().zip(solved.chunks_exact(w)) {
                *h = z_row[w - 1] + globals.iter().zip(z_row).map(|(&v, z)| z * global_step[v as usize]).sum::<f64>();
            }
            // Backward substitution with Lᵀ: h'_i = (s_i − Σ_{p>i} L_pi h'_p) / L_ii, then h_L = −h'.
            for i in (0..k).rev() {
                let mut value = step[i];
                for p in i + 1..k {
                    value -= factor[lower_index(p, i)] * step[p];
                }
                step[i] = value / factor[lower_index(i, i)];
            }
            for h in step.iter_mut() {
                *h = -*h;
            }
            true
        });
    }
}

/// D_L, C_L, G_L and g_L of one group from its blocks (in block order, rows in order), each
/// evaluated at `x` into `scratch` (its Jacobian) and `products` (its residuals and Jᵀr) first.
/// Only the group's blocks touch its variables, so g_L equals that part of the full gradient
/// summed in block order. Returns 2b (residuals) or 2b + 1 (Jacobian) for the first block b with
/// a non-finite value.
#[allow(clippy::too_many_arguments)]
fn accumulate_kernel<P: LeastSquaresProblem>(
    problem: &P,
    x: &[f64],
    k: usize,
    q: usize,
    s: &mut Sections<'_>,
    products: &mut [f64],
    blocks: &BlockStructure,
    group_blocks: &[u32],
    scratch: &mut Vec<f64>,
) -> Result<(), usize> {
    let w = q + 1;
    s.normal.fill(0.0);
    s.coupling.fill(0.0);
    s.gram.fill(0.0);
    let mut rest = products;
    for &b in group_blocks {
        let b = b as usize;
        // A block of a group has at least one (local) variable, so n > 0.
        let (m, n) = (blocks.residual_count(b), blocks.variables(b).len());
        let (residuals, tail) = std::mem::take(&mut rest).split_at_mut(m);
        let (gradient, tail) = tail.split_at_mut(n);
        rest = tail;
        residuals.fill(0.0);
        // The block's Jacobian, then the dense local and global entries of the row being
        // accumulated (entries of the group's variables the block does not touch stay zero).
        scratch.clear();
        scratch.resize(m * n + k + q, 0.0);
        let (jacobian, row) = scratch.split_at_mut(m * n);
        let (row_locals, row_globals) = row.split_at_mut(k);
        problem.evaluate_block(b, x, residuals, Some(jacobian));
        if !residuals.iter().all(|v| v.is_finite()) {
            return Err(2 * b);
        }
        // One pass over the Jacobian, row by row: its finiteness, Jᵀr (each entry summed over the
        // rows in order; zero entries add nothing) and the row's entries, scattered densely over
        // the group's locals and globals, accumulated into D_L, C_L and G_L.
        gradient.fill(0.0);
        let mut finite = true;
        let (local_positions, local_offsets) = blocks.local_positions(b);
        let global_positions = blocks.global_positions(b);
        let coupling_index = blocks.coupling_index(b);
        for (row, &r) in jacobian.chunks_exact(n).zip(residuals.iter()) {
            for (&p, &o) in local_positions.iter().zip(local_offsets) {
                let value = row[p as usize];
                row_locals[o as usize] = value;
                if value != 0.0 {
                    finite &= value.is_finite();
                    gradient[p as usize] += value * r;
                }
            }
            let mut any_global = false;
            for (&p, &i) in global_positions.iter().zip(coupling_index) {
                let value = row[p as usize];
                row_globals[i as usize] = value;
                if value != 0.0 {
                    any_global = true;
                    finite &= value.is_finite();
                    gradient[p as usize] += value * r;
                }
            }
            // Structural zeros (auxiliaries absent from a residual row, field values of uncrossed
            // edges) add nothing and are skipped row by row.
            for (a, &va) in row_locals.iter().enumerate() {
                if va == 0.0 {
                    continue;
                }
                for (d, &vc) in s.normal[lower_index(a, 0)..=lower_index(a, a)].iter_mut().zip(row_locals.iter()) {
                    *d += va * vc;
                }
                if any_global {
                    for (c, &vg) in s.coupling[a * w..a * w + q].iter_mut().zip(row_globals.iter()) {
                        *c += va * vg;
                    }
                }
            }
            if any_global {
                add_outer_product(row_globals, s.gram);
            }
        }
        if !finite {
            return Err(2 * b + 1);
        }
        for (&p, &o) in local_positions.iter().zip(local_offsets) {
            s.coupling[o as usize * w + q] += gradient[p as usize];
        }
    }
    Ok(())
}

/// Entries of a row of W − G_L summed side by side in [`eliminate_kernel`].
const LANES: usize = 4;

/// [`GroupSystems::eliminate`] of one group (k local and q global variables).
fn eliminate_kernel(k: usize, q: usize, s: &mut Sections<'_>, mu: f64) -> bool {
    let w = q + 1;
    if !cholesky_lower_in_place(s.normal, mu, k) {
        return false;
    }
    let factor = &*s.normal;
    // Forward substitution in place, row by row: Z_i = (B_i − Σ_{p<i} L_ip Z_p) / L_ii.
    for i in 0..k {
        let (done, rest) = s.coupling.split_at_mut(i * w);
        let current = &mut rest[..w];
        for (p, &lip) in factor[lower_index(i, 0)..lower_index(i, i)].iter().enumerate() {
            for (c, &z) in current.iter_mut().zip(&done[p * w..(p + 1) * w]) {
                *c -= lip * z;
            }
        }
        let diagonal = factor[lower_index(i, i)];
        for c in current.iter_mut() {
            *c /= diagonal;
        }
    }
    // W − G_L = ZᵀZ − G_L (upper, packed, over G_L) and v = Zᵀz, each entry summed over the
    // rows of Z in order (starting from −G_L and 0), in a register; the entries of a row of W are
    // formed [`LANES`] at a time, so that each row of Z is read once per group of lanes.
    let rows = &*s.coupling;
    let mut t = 0;
    for i in 0..q {
        let mut lanes = s.gram[t..t + q - i].chunks_exact_mut(LANES);
        let mut j = i;
        for entries in lanes.by_ref() {
            let mut sums: [f64; LANES] = std::array::from_fn(|e| -entries[e]);
            for z_row in rows.chunks_exact(w) {
                let zi = z_row[i];
                for (sum, &zj) in sums.iter_mut().zip(&z_row[j..j + LANES]) {
                    *sum += zi * zj;
                }
            }
            entries.copy_from_slice(&sums);
            j += LANES;
        }
        for (j, wij) in (j..q).zip(lanes.into_remainder()) {
            *wij = rows.chunks_exact(w).fold(-*wij, |sum, z_row| sum + z_row[i] * z_row[j]);
        }
        t += q - i;
        s.schur_rhs[i] = rows.chunks_exact(w).fold(0.0, |sum, z_row| sum + z_row[i] * z_row[q]);
    }
    true
}

/// Cholesky factor L of `normal + μI` (the lower triangle of k×k packed row by row), computed in
/// place. Returns `false` on a non-positive or non-finite pivot (the matrix is then partly
/// overwritten).
fn cholesky_lower_in_place(normal: &mut [f64], mu: f64, k: usize) -> bool {
    for j in 0..k {
        let (above, rest) = normal.split_at_mut(lower_index(j, 0));
        let row_j = &mut rest[..=j];
        for i in 0..j {
            let row_i = &above[lower_index(i, 0)..lower_index(i, i)];
            let dot: f64 = row_i.iter().zip(&row_j[..i]).map(|(a, b)| a * b).sum();
            row_j[i] = (row_j[i] - dot) / above[lower_index(i, i)];
        }
        let squares: f64 = row_j[..j].iter().map(|v| v * v).sum();
        let pivot = row_j[j] + mu - squares;
        if !(pivot > 0.0 && pivot.is_finite()) {
            return false;
        }
        row_j[j] = pivot.sqrt();
    }
    true
}

/// Index of entry (i, j), j ≤ i, in the row-by-row packed lower triangle of a k×k matrix (the
/// layout of D_L and its factor L).
fn lower_index(i: usize, j: usize) -> usize {
    i * (i + 1) / 2 + j
}

/// Index of entry (i, j), i ≤ j, in the row-by-row packed upper triangle of a q×q matrix.
fn packed_upper_index(i: usize, j: usize, q: usize) -> usize {
    i * (2 * q - i + 1) / 2 + (j - i)
}
