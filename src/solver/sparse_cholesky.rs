//! Sparse Cholesky of the reduced normal matrix (faer): AMD ordering and symbolic analysis once,
//! numeric factorisation per damped trial, all workspaces preallocated; sequential (`Par::Seq`)
//! so results are bit-identical for any thread count.
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LltRef, SymbolicCholesky, SymmetricOrdering,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};

use super::SolverError;

pub(crate) struct SparseCholesky {
    pattern: SymbolicSparseColMat<usize>,
    symbolic: SymbolicCholesky<usize>,
    factor: Vec<f64>,
    scratch: MemBuffer,
}

impl SparseCholesky {
    /// Symbolic analysis of the upper-triangular CSC pattern (sorted rows, diagonal present).
    pub fn analyse(col_ptr: Vec<usize>, row_idx: Vec<usize>) -> Result<Self, SolverError> {
        let n = col_ptr.len() - 1;
        let failed = |e: &dyn std::fmt::Debug| SolverError::SymbolicAnalysisFailed { message: format!("{e:?}") };
        let pattern = SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx);
        let symbolic = factorize_symbolic_cholesky(
            pattern.as_ref(),
            Side::Upper,
            SymmetricOrdering::Amd,
            CholeskySymbolicParams::default(),
        )
        .map_err(|e| failed(&e))?;
        let req = StackReq::or(
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        );
        let scratch = MemBuffer::try_new(req).map_err(|e| failed(&e))?;
        let factor = vec![0.0; symbolic.len_val()];
        Ok(Self { pattern, symbolic, factor, scratch })
    }

    /// Numeric factorisation of the matrix with the analysed pattern and upper values `values`.
    /// Returns `false` if it is not numerically positive definite.
    pub fn factorize(&mut self, values: &[f64]) -> bool {
        let matrix = SparseColMatRef::new(self.pattern.as_ref(), values);
        self.symbolic
            .factorize_numeric_llt(
                &mut self.factor,
                matrix,
                Side::Upper,
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
        LltRef::new(&self.symbolic, &self.factor).solve_in_place_with_conj(
            Conj::No,
            MatMut::from_column_major_slice_mut(rhs, n, 1),
            Par::Seq,
            MemStack::new(&mut self.scratch),
        );
    }
}
