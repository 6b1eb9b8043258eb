//! Choosing the level values: `n` values spread uniformly over the field's range (Sec. 3.4).
use super::CurveError;
use crate::mesh::TriMesh;

/// Most levels one extraction accepts ([`uniform_levels`], [`super::extract_level_curves`]).
pub const MAX_LEVELS: usize = 10_000;

/// `(min F, max F)` after checking that `field` has one finite value per vertex, each within
/// ±[`crate::field::FIELD_VALUE_LIMIT`], and is not constant.
pub fn field_range(mesh: &TriMesh, field: &[f64]) -> Result<(f64, f64), CurveError> {
    if field.len() != mesh.vertex_count() {
        return Err(CurveError::FieldLength { expected: mesh.vertex_count(), actual: field.len() });
    }
    if let Some(vertex) = field.iter().position(|f| !f.is_finite()) {
        return Err(CurveError::NonFiniteField { vertex });
    }
    if let Some(vertex) = field.iter().position(|f| f.abs() > crate::field::FIELD_VALUE_LIMIT) {
        return Err(CurveError::FieldValueOutOfRange { vertex, value: field[vertex] });
    }
    let (min, max) = field.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &f| (lo.min(f), hi.max(f)));
    if max <= min {
        return Err(CurveError::ConstantField);
    }
    Ok((min, max))
}

/// The `n` values `min + k (max − min)/(n + 1)`, `k = 1..=n`: uniform over `[min F, max F]` with
/// the two extremes left out (there the level set degenerates to points). `n` is at most
/// [`MAX_LEVELS`] ([`CurveError::TooManyLevels`]; checked before anything is allocated).
pub fn uniform_levels(mesh: &TriMesh, field: &[f64], n: usize) -> Result<Vec<f64>, CurveError> {
    let (min, max) = field_range(mesh, field)?;
    if n == 0 {
        return Err(CurveError::NoLevels);
    }
    if n > MAX_LEVELS {
        return Err(CurveError::TooManyLevels { count: n });
    }
    Ok((1..=n).map(|k| min + (max - min) * k as f64 / (n + 1) as f64).collect())
}
