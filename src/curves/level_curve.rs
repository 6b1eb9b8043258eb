//! One connected piece of a level set: a polyline on the mesh with its level value and the
//! surface normal at each vertex.
use super::CurveError;
use crate::mesh::Vec3;

/// A level polyline. It runs along `∇F × n`, so that the side vector `u = n × t` of its Darboux
/// frame points along `+∇F`: the orientation the signed angle of Eq. 3 and 8 relies on.
#[derive(Clone, Debug, PartialEq)]
pub struct LevelCurve {
    /// The field value of the level set.
    pub level: f64,
    /// The polyline's vertices (a closed curve does not repeat its first vertex).
    pub points: Vec<Vec3>,
    /// Unit surface normal per vertex, interpolated linearly from the mesh's smooth (second-order)
    /// vertex normals, [`crate::mesh::TriMesh::smooth_normals`].
    pub normals: Vec<Vec3>,
    /// Whether the polyline closes on itself (a level set that never meets the boundary).
    pub closed: bool,
    /// Interior vertices that are singular for the field (their own level curve does not cross
    /// exactly two star edges, see [`crate::field::find_level_crossing`]) and whose star this
    /// curve passes through: near them the level set may branch or turn sharply.
    pub singular_vertices: Vec<u32>,
}

/// Most points of the polylines one resampling produces, all curves together
/// ([`resample_all`]) or one curve ([`LevelCurve::resampled`]): 4,000,000 (about 200 MB of
/// points and normals).
pub const MAX_CURVE_POINTS: usize = 4_000_000;

/// Every curve resampled at `spacing` (see [`LevelCurve::resampled`]), after checking that
/// together they get at most [`MAX_CURVE_POINTS`] points ([`CurveError::TooManyPoints`] with the
/// total, before anything is allocated); [`CurveError::InvalidSpacing`] for a spacing that is
/// not finite and positive.
pub fn resample_all(curves: &[LevelCurve], spacing: f64) -> Result<Vec<LevelCurve>, CurveError> {
    if !(spacing.is_finite() && spacing > 0.0) {
        return Err(CurveError::InvalidSpacing { spacing });
    }
    let total: f64 = curves.iter().map(|c| (c.length() / spacing).round().max(3.0) + 1.0).sum();
    if !total.is_finite() || total >= MAX_CURVE_POINTS as f64 {
        return Err(CurveError::TooManyPoints { spacing, points: total });
    }
    curves.iter().map(|c| c.resampled(spacing)).collect()
}

impl LevelCurve {
    /// Number of segments (`points.len()` for a closed curve).
    pub fn segment_count(&self) -> usize {
        match (self.closed, self.points.len()) {
            (_, 0) => 0,
            (true, n) => n,
            (false, n) => n - 1,
        }
    }

    /// The `k`-th segment's end points and normals (needs as many normals as points).
    fn segment(&self, k: usize) -> (Vec3, Vec3, Vec3, Vec3) {
        let next = (k + 1) % self.points.len();
        (self.points[k], self.points[next], self.normals[k], self.normals[next])
    }

    /// Total length (including the closing segment of a closed curve).
    pub fn length(&self) -> f64 {
        let n = self.points.len();
        (0..self.segment_count()).map(|k| (self.points[(k + 1) % n] - self.points[k]).norm()).sum()
    }

    /// The curve resampled at equal arc-length steps as close to `spacing` as the length allows:
    /// an open curve keeps its end points and gets `max(1, round(L/spacing))` segments, a closed
    /// one `max(3, round(L/spacing))`. New points lie on the old polyline (hence on the mesh);
    /// normals are interpolated linearly and normalised. At most [`super::MAX_CURVE_POINTS`]
    /// points ([`CurveError::TooManyPoints`], checked before allocating).
    pub fn resampled(&self, spacing: f64) -> Result<LevelCurve, CurveError> {
        if !(spacing.is_finite() && spacing > 0.0) {
            return Err(CurveError::InvalidSpacing { spacing });
        }
        if self.normals.len() != self.points.len() {
            return Err(CurveError::NormalCount { points: self.points.len(), normals: self.normals.len() });
        }
        let length = self.length();
        if self.points.len() < 2 || length.is_nan() || length <= 0.0 {
            return Ok(self.clone());
        }
        let minimum = if self.closed { 3 } else { 1 };
        let steps = (length / spacing).round();
        if !steps.is_finite() || steps >= super::MAX_CURVE_POINTS as f64 {
            return Err(CurveError::TooManyPoints { spacing, points: steps });
        }
        let segments = (steps as usize).max(minimum);
        let samples = if self.closed { segments } else { segments + 1 };
        let mut points = Vec::with_capacity(samples);
        let mut normals = Vec::with_capacity(samples);
        // Walk the old segments once; `start` is the arc length at the start of segment `k`.
        let (mut k, mut start) = (0, 0.0);
        for j in 0..samples {
            let target = length * j as f64 / segments as f64;
            loop {
                let (a, b, _, _) = self.segment(k);
                if start + (b - a).norm() >= target || k + 1 == self.segment_count() {
                    break;
                }
                start += (b - a).norm();
                k += 1;
            }
            let (a, b, na, nb) = self.segment(k);
            let piece = (b - a).norm();
            let t = if piece > 0.0 { ((target - start) / piece).clamp(0.0, 1.0) } else { 0.0 };
            points.push(a + (b - a) * t);
            normals.push((na + (nb - na) * t).try_normalize(0.0).unwrap_or(na));
        }
        Ok(LevelCurve { level: self.level, points, normals, closed: self.closed, singular_vertices: self.singular_vertices.clone() })
    }
}
