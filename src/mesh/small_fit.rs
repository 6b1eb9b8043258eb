//! Small dense least-squares fits (a handful of unknowns over a vertex neighbourhood), solved
//! through the normal equations: the fits behind [`super::LocalQuadric`] and the field's level
//! jets. Each vertex's fit is set up once per mesh, so this is on the path of every solver's
//! preparation; the normal equations of a well-conditioned design (checked) cost a small fraction
//! of a singular value decomposition.

use nalgebra::{SMatrix, SVector};

/// The normal-equation inverse `(DᵀD)⁻¹` of a design `D` with `K` columns, if `D` is well
/// conditioned: its smallest singular value above `condition` times its largest (the
/// eigenvalues of `DᵀD` are the squared singular values).
pub(crate) fn normal_inverse<const K: usize>(rows: &[[f64; K]], condition: f64) -> Option<SMatrix<f64, K, K>> {
    if rows.len() < K {
        return None;
    }
    let mut gram = SMatrix::<f64, K, K>::zeros();
    for row in rows {
        let r = SVector::<f64, K>::from_row_slice(row);
        gram += r * r.transpose();
    }
    let eigenvalues = nalgebra::DMatrix::from_column_slice(K, K, gram.as_slice()).symmetric_eigenvalues();
    let (smallest, largest) = eigenvalues.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &e| (lo.min(e), hi.max(e)));
    if smallest.is_nan() || smallest <= condition * condition * largest {
        return None;
    }
    let inverse = gram.cholesky()?.inverse();
    inverse.iter().all(|x| x.is_finite()).then_some(inverse)
}

/// The least-squares solution of `D c ≈ values` for `D` given by `rows`, with `inverse` its
/// [`normal_inverse`].
pub(crate) fn solve<const K: usize>(rows: &[[f64; K]], values: &[f64], inverse: &SMatrix<f64, K, K>) -> SVector<f64, K> {
    let mut rhs = SVector::<f64, K>::zeros();
    for (row, value) in rows.iter().zip(values) {
        rhs += SVector::<f64, K>::from_row_slice(row) * *value;
    }
    inverse * rhs
}

/// Rows `L` ((m − K) × m, row-major) with `LᵀL = I − H`, `H = D (DᵀD)⁻¹ Dᵀ` the fit's hat matrix:
/// an orthonormal basis of what the fit cannot represent, by modified Gram–Schmidt over the
/// columns of `I − H` in order (deterministic). Empty if the complement does not come out whole.
pub(crate) fn residual_basis<const K: usize>(rows: &[[f64; K]], inverse: &SMatrix<f64, K, K>) -> Vec<f64> {
    let m = rows.len();
    let vectors: Vec<SVector<f64, K>> = rows.iter().map(|r| SVector::<f64, K>::from_row_slice(r)).collect();
    let projector = |i: usize, j: usize| f64::from(u8::from(i == j)) - vectors[i].dot(&(inverse * vectors[j]));
    let mut basis: Vec<Vec<f64>> = Vec::with_capacity(m.saturating_sub(K));
    for j in 0..m {
        if basis.len() == m.saturating_sub(K) {
            break;
        }
        let mut column: Vec<f64> = (0..m).map(|i| projector(i, j)).collect();
        for q in &basis {
            let along: f64 = q.iter().zip(&column).map(|(a, b)| a * b).sum();
            column.iter_mut().zip(q).for_each(|(c, a)| *c -= along * a);
        }
        let norm = column.iter().map(|c| c * c).sum::<f64>().sqrt();
        // A column of a projector has norm at most 1; what is left after the basis so far is
        // either a new direction or rounding.
        if norm > 1e-6 {
            basis.push(column.iter().map(|c| c / norm).collect());
        }
    }
    if basis.len() == m.saturating_sub(K) {
        basis.concat()
    } else {
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_residual_basis_spans_what_the_fit_cannot_represent() {
        let rows: Vec<[f64; 3]> = (0..7).map(|i| { let x = i as f64 * 0.3 - 1.0; [1.0, x, x * x] }).collect();
        let inverse = normal_inverse(&rows, 1e-6).unwrap();
        let basis = residual_basis(&rows, &inverse);
        assert_eq!(basis.len(), 4 * 7);
        // Orthonormal rows, orthogonal to every column of the design.
        for a in 0..4 {
            for b in 0..4 {
                let dot: f64 = (0..7).map(|i| basis[a * 7 + i] * basis[b * 7 + i]).sum();
                assert!((dot - f64::from(u8::from(a == b))).abs() < 1e-12);
            }
            let column_dot = |c: usize| (0..7).map(|i| basis[a * 7 + i] * rows[i][c]).sum::<f64>();
            assert!((0..3).all(|c| column_dot(c).abs() < 1e-12));
        }
        // A quadratic is fitted exactly.
        let values: Vec<f64> = rows.iter().map(|r| 2.0 - r[1] + 0.5 * r[2]).collect();
        let c = solve(&rows, &values, &inverse);
        assert!((c - SVector::<f64, 3>::new(2.0, -1.0, 0.5)).norm() < 1e-12);
        // Too few or dependent rows are refused.
        assert!(normal_inverse(&rows[..2], 1e-6).is_none());
        assert!(normal_inverse(&[[1.0, 2.0, 3.0]; 5], 1e-6).is_none());
    }
}
