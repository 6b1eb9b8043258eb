//! The flat array layouts of the C ABI: coordinates one after another, and offset tables that
//! cut a concatenation of variable-length items (polylines, strips) into its items.

use crate::mesh::Vec3;

/// Vectors as the flat `x0 y0 z0 x1 y1 z1 …` layout.
pub(crate) fn flat_xyz(vectors: &[Vec3]) -> Vec<f64> {
    vectors.iter().flat_map(|v| [v.x, v.y, v.z]).collect()
}

/// Plane points as the flat `x0 y0 x1 y1 …` layout.
pub(crate) fn flat_xy(points: &[[f64; 2]]) -> Vec<f64> {
    points.iter().flatten().copied().collect()
}

/// The offset table of items with `counts` elements each: `counts.len() + 1` running sums
/// starting at 0, so item `i` spans elements `offsets[i] .. offsets[i + 1]`.
pub(crate) fn offsets(counts: impl Iterator<Item = usize>) -> Vec<usize> {
    std::iter::once(0).chain(counts.scan(0, |total, n| {
        *total += n;
        Some(*total)
    })).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_are_running_sums_from_zero() {
        assert_eq!(offsets([3, 0, 2].into_iter()), vec![0, 3, 3, 5]);
        assert_eq!(offsets(std::iter::empty()), vec![0]);
    }
}
