//! The packed upper triangle every Gram-like product of the solver is summed in: a q×q
//! symmetric matrix stored row by row, entries (i, j) with i ≤ j.

/// Writes the Gram product JᵀJ of the row-major `jacobian` with `columns` columns into `packed`
/// (the triangle of that size), summed row by row in order.
pub(crate) fn gram_of_rows(jacobian: &[f64], packed: &mut [f64], columns: usize) {
    packed.fill(0.0);
    for row in jacobian.chunks_exact(columns) {
        add_outer_product(row, packed);
    }
}

/// Adds `row rowᵀ` to the packed upper triangle `packed` (of size `row.len()`), so that each
/// entry is summed over successive rows in their order. Zero entries of `row` skip their row of
/// the triangle (structural zeros of Jacobian rows add nothing). The inner loop runs over
/// contiguous entries, so it vectorises.
pub(crate) fn add_outer_product(row: &[f64], packed: &mut [f64]) {
    let mut t = 0;
    for (i, &vi) in row.iter().enumerate() {
        let rest = &row[i..];
        if vi != 0.0 {
            for (p, &vj) in packed[t..t + rest.len()].iter_mut().zip(rest) {
                *p += vi * vj;
            }
        }
        t += rest.len();
    }
}
