//! Sparse Cholesky (faer, supernodal) of one domain's matrix: its interior variables in AMD
//! order, then the separator variables last in their given order, so that the factor's trailing
//! block is the Cholesky factor R of the domain's share of the separator's Schur complement
//! (see [`super::substructured_cholesky`]). Ordering and symbolic analysis once, numeric
//! factorisation per damped trial, all workspaces preallocated; sequential (`Par::Seq`), so
//! results are bit-identical for any thread count.
//!
//! The ordering is applied to the sparsity pattern once: the caller writes the values straight
//! into faer's permuted storage (lower triangle, the side its supernodal factorisation works on),
//! guided by the original position of every stored entry, so no trial re-permutes or copies the
//! matrix.
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};

use super::SolverError;

pub(crate) struct SparseCholesky {
    /// Lower triangle of P A Pᵀ (CSC, sorted rows). Indices, here and in the symbolic analysis,
    /// are 32-bit: half the memory of the pattern and of the factor's row structure.
    permuted_pattern: SymbolicSparseColMat<u32>,
    /// `values[p]` (the caller's storage) = entry `original_position[p]` of the caller's pattern;
    /// handed over by [`Self::take_original_positions`] (only the setup reads it).
    original_position: Vec<usize>,
    /// `variables[i]`: the caller's variable at position `i` of the factor's order.
    variables: Vec<usize>,
    separator_len: usize,
    symbolic: SymbolicCholesky<u32>,
    factor: Vec<f64>,
    scratch: MemBuffer,
}

impl SparseCholesky {
    /// Ordering and symbolic analysis of the matrix over `interior` followed by `separator` (the
    /// caller's variable indices), with the entries of the caller's upper-triangular CSC pattern
    /// (sorted rows, diagonal present) whose row and column both belong to these variables.
    /// `local[v]` must be the index of variable `v` in `interior ++ separator`, or `usize::MAX`.
    pub fn analyse(col_ptr: &[usize], row_idx: &[usize], interior: &[usize], separator: &[usize], local: &[usize]) -> Result<Self, SolverError> {
        let failed = |e: &dyn std::fmt::Debug| SolverError::SymbolicAnalysisFailed { message: format!("{e:?}") };
        let (m, k) = (interior.len() + separator.len(), interior.len());
        // The domain's entries: (original position, local row, local column).
        let entries: Vec<(usize, usize, usize)> = (0..col_ptr.len() - 1)
            .filter(|&c| local[c] != usize::MAX)
            .flat_map(|c| (col_ptr[c]..col_ptr[c + 1]).map(move |t| (t, row_idx[t], c)))
            .filter(|&(_, r, _)| local[r] != usize::MAX)
            .map(|(t, r, c)| (t, local[r], local[c]))
            .collect();

        if m >= INDEX_LIMIT || entries.len() >= INDEX_LIMIT {
            let message = format!("a domain of {m} variables and {} entries exceeds 32-bit indices", entries.len());
            return Err(SolverError::SymbolicAnalysisFailed { message });
        }
        // Fill-reducing ordering of the interior (the one faer's `SymmetricOrdering::Amd`
        // computes); the separator stays last.
        let mut new_index: Vec<usize> = (0..m).collect();
        if k > 0 {
            let mut interior_ptr = vec![0usize; k + 1];
            let interior_entries = || entries.iter().filter(|&&(_, r, c)| r < k && c < k);
            for &(_, _, c) in interior_entries() {
                interior_ptr[c + 1] += 1;
            }
            for c in 0..k {
                interior_ptr[c + 1] += interior_ptr[c];
            }
            let interior_rows: Vec<usize> = interior_entries().map(|&(_, r, _)| r).collect();
            let interior_pattern = SymbolicSparseColMat::new_checked(k, k, interior_ptr, None, interior_rows);
            let mut perm = vec![0usize; k];
            let nnz = interior_pattern.compute_nnz();
            let mut amd_scratch = MemBuffer::try_new(amd::order_maybe_unsorted_scratch::<usize>(k, nnz)).map_err(|e| failed(&e))?;
            amd::order_maybe_unsorted(&mut perm, &mut new_index[..k], interior_pattern.as_ref(), amd::Control::default(), MemStack::new(&mut amd_scratch))
                .map_err(|e| failed(&e))?;
        }
        let mut variables = vec![0usize; m];
        for (i, &v) in interior.iter().chain(separator).enumerate() {
            variables[new_index[i]] = v;
        }

        // The permuted matrix P A Pᵀ: entry (r, c) moves to (new_index[r], new_index[c]). Its upper
        // triangle feeds the symbolic analysis (which expects the upper side without an ordering),
        // its lower triangle the supernodal numeric factorisation.
        let nnz = entries.len();
        let low: Vec<usize> = entries.iter().map(|&(_, r, c)| new_index[r].min(new_index[c])).collect();
        let high: Vec<usize> = entries.iter().map(|&(_, r, c)| new_index[r].max(new_index[c])).collect();
        let by_low = counting_sort(m, &low, (0..nnz).collect());
        let upper_order = counting_sort(m, &high, by_low.clone());
        let upper = triangle_pattern(m, upper_order.iter().map(|&e| (high[e], low[e])));
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
            ..Default::default()
        };
        let symbolic = factorize_symbolic_cholesky(upper.as_ref(), Side::Upper, SymmetricOrdering::Identity, params).map_err(|e| failed(&e))?;
        if !matches!(symbolic.raw(), SymbolicCholeskyRaw::Supernodal(_)) {
            return Err(failed(&"faer chose a simplicial factorisation"));
        }
        let lower_order = counting_sort(m, &low, counting_sort(m, &high, by_low));
        let permuted_pattern = triangle_pattern(m, lower_order.iter().map(|&e| (low[e], high[e])));
        let req = StackReq::or(
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        );
        let scratch = MemBuffer::try_new(req).map_err(|e| failed(&e))?;
        Ok(Self {
            permuted_pattern,
            original_position: lower_order.iter().map(|&e| entries[e].0).collect(),
            variables,
            separator_len: separator.len(),
            factor: vec![0.0; symbolic.len_val()],
            symbolic,
            scratch,
        })
    }

    /// For each value of the permuted storage, its position in the caller's pattern (handed over
    /// once: afterwards empty).
    pub fn take_original_positions(&mut self) -> Vec<usize> {
        std::mem::take(&mut self.original_position)
    }

    /// Floating-point operations of one numeric factorisation, from the supernodal structure:
    /// a supernode of w columns with b rows below them costs w³/3 (its diagonal block), b·w²
    /// (the rows below) and b²·w (its update of the later columns).
    pub fn flops(&self) -> f64 {
        let SymbolicCholeskyRaw::Supernodal(symbolic) = self.symbolic.raw() else { return 0.0 };
        let (begin, end, rows) = (symbolic.supernode_begin(), symbolic.supernode_end(), symbolic.col_ptr_for_row_idx());
        (0..symbolic.n_supernodes())
            .map(|s| {
                let w = (end[s] - begin[s]) as f64;
                let b = (rows[s + 1] - rows[s]) as f64;
                w * w * w / 3.0 + b * w * w + b * b * w
            })
            .sum()
    }

    /// Number of values of the permuted storage.
    pub fn value_count(&self) -> usize {
        self.permuted_pattern.row_idx().len()
    }

    /// The caller's variable at each position of the factor's order (interior, then separator).
    pub fn variables(&self) -> &[usize] {
        &self.variables
    }

    /// Numeric factorisation of the matrix whose permuted storage is `values` (`values[p]` is the
    /// entry at position `p` of [`Self::take_original_positions`] in the caller's pattern).
    /// Returns `false` if it is not numerically positive definite.
    pub fn factorize(&mut self, values: &[f64]) -> bool {
        let matrix = SparseColMatRef::new(self.permuted_pattern.as_ref(), values);
        self.symbolic
            .factorize_numeric_llt(
                &mut self.factor,
                matrix,
                Side::Lower,
                LltRegularization::default(),
                Par::Seq,
                MemStack::new(&mut self.scratch),
                Default::default(),
            )
            .is_ok()
    }

    /// Solves L y = x in place (`x` in the factor's order) with the last successful factorisation.
    pub fn forward_solve(&mut self, x: &mut [f64]) {
        let n = x.len();
        if let Some(factor) = supernodal(&self.symbolic, &self.factor) {
            factor.l_solve_with_conj(Conj::No, MatMut::from_column_major_slice_mut(x, n, 1), Par::Seq, MemStack::new(&mut self.scratch));
        }
    }

    /// Solves Lᵀ y = x in place (`x` in the factor's order).
    pub fn backward_solve(&mut self, x: &mut [f64]) {
        let n = x.len();
        if let Some(factor) = supernodal(&self.symbolic, &self.factor) {
            factor.l_transpose_solve_with_conj(Conj::No, MatMut::from_column_major_slice_mut(x, n, 1), Par::Seq, MemStack::new(&mut self.scratch));
        }
    }

    /// Copies the trailing separator block R of the factor (lower triangular) into `r`
    /// (separator × separator; the strict upper triangle is left untouched).
    pub fn separator_block(&self, mut r: MatMut<'_, f64>) {
        let first = self.variables.len() - self.separator_len;
        let Some(factor) = supernodal(&self.symbolic, &self.factor) else { return };
        for s in 0..factor.symbolic().n_supernodes() {
            let supernode = factor.supernode(s);
            let (start, values) = (supernode.start(), supernode.val());
            let width = values.ncols();
            if start + width <= first {
                continue;
            }
            for j in first.max(start)..start + width {
                let column = j - start;
                // Rows of the supernode: its own columns, then its pattern (all beyond them).
                for i in j..start + width {
                    r[(i - first, j - first)] = values[(i - start, column)];
                }
                for (p, &i) in supernode.pattern().iter().enumerate() {
                    r[(i as usize - first, j - first)] = values[(width + p, column)];
                }
            }
        }
    }
}

/// The supernodal view of a factor (`analyse` accepts only supernodal analyses).
fn supernodal<'a>(symbolic: &'a SymbolicCholesky<u32>, factor: &'a [f64]) -> Option<SupernodalLltRef<'a, u32, f64>> {
    match symbolic.raw() {
        SymbolicCholeskyRaw::Supernodal(symbolic) => Some(SupernodalLltRef::new(symbolic, factor)),
        SymbolicCholeskyRaw::Simplicial(_) => None,
    }
}

/// Stable counting sort of the entries `order` by `key[entry]` (keys below `n`).
fn counting_sort(n: usize, key: &[usize], order: Vec<usize>) -> Vec<usize> {
    let mut start = vec![0usize; n + 1];
    for &e in &order {
        start[key[e] + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut sorted = vec![0usize; order.len()];
    for e in order {
        sorted[start[key[e]]] = e;
        start[key[e]] += 1;
    }
    sorted
}

/// CSC pattern from (column, row) pairs sorted by column, then row (`n` and the pair count below
/// [`INDEX_LIMIT`]).
fn triangle_pattern(n: usize, entries: impl Iterator<Item = (usize, usize)>) -> SymbolicSparseColMat<u32> {
    let mut col_ptr = vec![0u32; n + 1];
    let mut row_idx = Vec::new();
    for (col, row) in entries {
        col_ptr[col + 1] += 1;
        row_idx.push(row as u32);
    }
    for c in 0..n {
        col_ptr[c + 1] += col_ptr[c];
    }
    SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx)
}

/// Dimensions and entry counts of a domain's matrix must stay below this: faer's 32-bit indices
/// are signed-safe up to 2³¹ − 1.
const INDEX_LIMIT: usize = i32::MAX as usize;
