//! Sparse linear least squares `min_x Σ_r w_r (a_r · x − t_r)²`, solved through its normal
//! equations `(Σ w_r a_r a_rᵀ) x = Σ w_r a_r t_r` with faer's sparse Cholesky (AMD ordering,
//! sequential, so the result does not depend on the thread count).
//!
//! The rows (`a_r`, `w_r`) are fixed once the system is factorised; the targets `t_r` can change
//! from one solve to the next, which is what the iterative stroke fit of Sec. 3.2.2 needs.

use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};
use faer::{Mat, Side};

/// The rows of a linear least-squares problem: coefficients, weights and default targets.
#[derive(Clone, Debug, Default)]
pub(crate) struct LinearRows {
    /// Coefficients of row r: `entries[start[r]..start[r + 1]]` as (variable, coefficient).
    start: Vec<usize>,
    entries: Vec<(usize, f64)>,
    weights: Vec<f64>,
    targets: Vec<f64>,
}

impl LinearRows {
    pub(crate) fn new() -> LinearRows {
        LinearRows { start: vec![0], ..LinearRows::default() }
    }

    /// Appends the row `weight · (Σ coefficient · x_variable − target)²`; returns its index.
    pub(crate) fn push(&mut self, entries: impl IntoIterator<Item = (usize, f64)>, target: f64, weight: f64) -> usize {
        self.entries.extend(entries);
        self.start.push(self.entries.len());
        self.weights.push(weight);
        self.targets.push(target);
        self.weights.len() - 1
    }

    pub(crate) fn len(&self) -> usize {
        self.weights.len()
    }

    /// The targets the rows were pushed with.
    pub(crate) fn targets(&self) -> &[f64] {
        &self.targets
    }

    fn row(&self, r: usize) -> &[(usize, f64)] {
        &self.entries[self.start[r]..self.start[r + 1]]
    }

    /// Factorises the normal matrix over `variable_count` variables; `None` when it is not
    /// numerically positive definite (the rows do not determine every variable).
    pub(crate) fn factorise(&self, variable_count: usize) -> Option<FactorisedRows<'_>> {
        let mut triplets = Vec::new();
        for r in 0..self.len() {
            let row = self.row(r);
            let w = self.weights[r];
            for &(i, a) in row {
                for &(j, b) in row {
                    // Lower triangle only: the side the factorisation reads.
                    if i >= j {
                        triplets.push(Triplet::new(i, j, w * a * b));
                    }
                }
            }
        }
        let matrix = SparseColMat::<usize, f64>::try_new_from_triplets(variable_count, variable_count, &triplets).ok()?;
        let llt = matrix.sp_cholesky(Side::Lower).ok()?;
        Some(FactorisedRows { rows: self, llt, variable_count })
    }
}

/// A factorised normal matrix, ready to solve for any targets.
pub(crate) struct FactorisedRows<'a> {
    rows: &'a LinearRows,
    llt: faer::sparse::linalg::solvers::Llt<usize, f64>,
    variable_count: usize,
}

impl FactorisedRows<'_> {
    /// The least-squares solution for `targets` (one per row); `None` if it is not finite.
    pub(crate) fn solve(&self, targets: &[f64]) -> Option<Vec<f64>> {
        let mut rhs = Mat::<f64>::zeros(self.variable_count, 1);
        for (r, &t) in targets.iter().enumerate().take(self.rows.len()) {
            let wt = self.rows.weights[r] * t;
            for &(j, a) in self.rows.row(r) {
                rhs[(j, 0)] += a * wt;
            }
        }
        self.llt.solve_in_place(rhs.as_mut());
        let x: Vec<f64> = (0..self.variable_count).map(|j| rhs[(j, 0)]).collect();
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_a_line_through_noisy_points() {
        // x0 + x1·s ≈ y at s = 0..4 with y = 1 + 2s ± 0.1: the normal equations give the usual fit.
        let ys = [1.1, 2.9, 5.1, 6.9, 9.0];
        let mut rows = LinearRows::new();
        for (s, &y) in ys.iter().enumerate() {
            rows.push([(0, 1.0), (1, s as f64)], y, 1.0);
        }
        let x = rows.factorise(2).expect("full rank").solve(rows.targets()).expect("finite");
        // Closed form: slope = Σ(s − s̄)(y − ȳ)/Σ(s − s̄)², intercept = ȳ − slope s̄.
        let mean_y = ys.iter().sum::<f64>() / 5.0;
        let slope = ys.iter().enumerate().map(|(s, y)| (s as f64 - 2.0) * (y - mean_y)).sum::<f64>() / 10.0;
        assert!((x[1] - slope).abs() < 1e-12);
        assert!((x[0] - (mean_y - 2.0 * slope)).abs() < 1e-12);
    }

    #[test]
    fn rank_deficient_rows_do_not_factorise() {
        let mut rows = LinearRows::new();
        rows.push([(0, 1.0), (1, 1.0)], 1.0, 1.0);
        assert!(rows.factorise(2).is_none());
    }
}
