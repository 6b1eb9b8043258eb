//! Sparse Cholesky of the reduced normal matrix (faer): AMD ordering and symbolic analysis once,
//! numeric factorisation per damped trial, all workspaces preallocated; sequential (`Par::Seq`)
//! so results are bit-identical for any thread count.
//!
//! The fill-reducing permutation is applied to the sparsity pattern once: the caller writes the
//! values straight into faer's permuted storage (lower triangle, the side its supernodal
//! factorisation works on), guided by the original position of every stored entry, so no trial
//! re-permutes or copies the whole matrix.
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LltRef, SymbolicCholesky, SymmetricOrdering,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};

use super::SolverError;

pub(crate) struct SparseCholesky {
    /// Lower triangle of P S Pᵀ (CSC, sorted rows).
    permuted_pattern: SymbolicSparseColMat<usize>,
    /// `permuted_values[p]` = value `original_position[p]` of the caller's upper pattern.
    original_position: Vec<usize>,
    permuted_values: Vec<f64>,
    /// `new_index[i]`: position of variable `i` in the permuted order.
    new_index: Vec<usize>,
    permuted_rhs: Vec<f64>,
    symbolic: SymbolicCholesky<usize>,
    factor: Vec<f64>,
    scratch: MemBuffer,
}

impl SparseCholesky {
    /// AMD ordering and symbolic analysis of the upper-triangular CSC pattern (sorted rows,
    /// diagonal present).
    pub fn analyse(col_ptr: Vec<usize>, row_idx: Vec<usize>) -> Result<Self, SolverError> {
        let n = col_ptr.len() - 1;
        let failed = |e: &dyn std::fmt::Debug| SolverError::SymbolicAnalysisFailed { message: format!("{e:?}") };
        let pattern = SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx);
        let nnz = pattern.compute_nnz();

        // Fill-reducing ordering (the one faer's `SymmetricOrdering::Amd` computes).
        let mut perm = vec![0usize; n];
        let mut new_index = vec![0usize; n];
        {
            let mut amd_scratch = MemBuffer::try_new(amd::order_maybe_unsorted_scratch::<usize>(n, nnz)).map_err(|e| failed(&e))?;
            amd::order_maybe_unsorted(&mut perm, &mut new_index, pattern.as_ref(), amd::Control::default(), MemStack::new(&mut amd_scratch))
                .map_err(|e| failed(&e))?;
        }

        // The permuted matrix P S Pᵀ: entry (r, c) moves to (new_index[r], new_index[c]). Its upper
        // triangle feeds the symbolic analysis (which expects the upper side without an ordering),
        // its lower triangle the supernodal numeric factorisation.
        let mut low = Vec::with_capacity(nnz);
        let mut high = Vec::with_capacity(nnz);
        for c in 0..n {
            for &r in &pattern.row_idx()[pattern.col_ptr()[c]..pattern.col_ptr()[c + 1]] {
                let (a, b) = (new_index[r], new_index[c]);
                low.push(a.min(b));
                high.push(a.max(b));
            }
        }
        let by_low = counting_sort(n, &low, (0..nnz).collect());
        let upper_order = counting_sort(n, &high, by_low.clone());
        let upper = triangle_pattern(n, upper_order.iter().map(|&e| (high[e], low[e])));
        let symbolic = factorize_symbolic_cholesky(
            upper.as_ref(),
            Side::Upper,
            SymmetricOrdering::Identity,
            CholeskySymbolicParams::default(),
        )
        .map_err(|e| failed(&e))?;
        let lower_order = counting_sort(n, &low, counting_sort(n, &high, by_low));
        let permuted_pattern = triangle_pattern(n, lower_order.iter().map(|&e| (low[e], high[e])));
        let req = StackReq::or(
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        );
        let scratch = MemBuffer::try_new(req).map_err(|e| failed(&e))?;
        let factor = vec![0.0; symbolic.len_val()];
        Ok(Self {
            permuted_pattern,
            original_position: lower_order,
            permuted_values: vec![0.0; nnz],
            new_index,
            permuted_rhs: vec![0.0; n],
            symbolic,
            factor,
            scratch,
        })
    }

    /// For each value of the permuted storage, its position in the caller's upper pattern.
    pub fn original_positions(&self) -> &[usize] {
        &self.original_position
    }

    /// Numeric factorisation of the matrix with the analysed pattern. `fill(values)` writes the
    /// matrix in the permuted storage: `values[p]` is the entry at position
    /// [`Self::original_positions`]`[p]` of the caller's upper pattern. Returns `false` if it is
    /// not numerically positive definite.
    pub fn factorize_with(&mut self, fill: impl FnOnce(&mut [f64])) -> bool {
        fill(&mut self.permuted_values);
        let matrix = SparseColMatRef::new(self.permuted_pattern.as_ref(), &self.permuted_values);
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

    /// Solves S h = rhs in place with the last successful factorisation.
    pub fn solve_in_place(&mut self, rhs: &mut [f64]) {
        let n = rhs.len();
        for (&i, &r) in self.new_index.iter().zip(rhs.iter()) {
            self.permuted_rhs[i] = r;
        }
        LltRef::new(&self.symbolic, &self.factor).solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(&mut self.permuted_rhs, n, 1),
            Par::Seq,
            MemStack::new(&mut self.scratch),
        );
        for (&i, r) in self.new_index.iter().zip(rhs.iter_mut()) {
            *r = self.permuted_rhs[i];
        }
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

/// CSC pattern from (column, row) pairs sorted by column, then row.
fn triangle_pattern(n: usize, entries: impl Iterator<Item = (usize, usize)>) -> SymbolicSparseColMat<usize> {
    let mut col_ptr = vec![0usize; n + 1];
    let mut row_idx = Vec::new();
    for (col, row) in entries {
        col_ptr[col + 1] += 1;
        row_idx.push(row);
    }
    for c in 0..n {
        col_ptr[c + 1] += col_ptr[c];
    }
    SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx)
}
