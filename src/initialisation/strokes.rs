//! Sketched strokes on the surface (Sec. 3.2.2, "Interactive steering", Fig. 14): polylines of
//! 3D points near the surface, projected to the mesh and filtered so that every triangle holds at
//! most one stroke point.

use super::error::{positive_option, InitialisationError};
use super::surface_locator::SurfaceLocator;
use crate::mesh::{TriMesh, Vec3};

/// A stroke point on the mesh.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct StrokeSample {
    /// The triangle the point lies in.
    pub face: u32,
    /// Barycentric coordinates `(u, v, t)` with respect to the face's corners, in winding order.
    pub barycentric: [f64; 3],
    /// Index of the point in its input stroke.
    pub point: usize,
}

impl StrokeSample {
    /// `u F0 + v F1 + t F2`: the piecewise linear field at the sample (face and field must fit the mesh).
    pub(crate) fn value(&self, mesh: &TriMesh, field: &[f64]) -> f64 {
        let corners = mesh.faces()[self.face as usize];
        corners.iter().zip(self.barycentric).map(|(&c, w)| w * field[c as usize]).sum()
    }
}

/// Projects every stroke point to its closest point on `mesh` and filters the strokes: a run of
/// consecutive points in one triangle keeps its middle point, and a triangle the stroke visits
/// again later is skipped, so each triangle holds at most one point of the stroke.
///
/// `max_distance` (in mean edge lengths of `mesh`) bounds the distance of a point from the surface.
/// Fails on fewer than two strokes, a stroke with fewer than two points (as given or after the
/// filter), a non-finite point, a point too far from the surface, or two strokes passing through
/// one triangle (they cross).
pub fn project_strokes(mesh: &TriMesh, strokes: &[Vec<Vec3>], max_distance: f64) -> Result<Vec<Vec<StrokeSample>>, InitialisationError> {
    let max_distance = positive_option("max_distance", max_distance)?;
    if strokes.len() < 2 {
        return Err(InitialisationError::TooFewStrokes { count: strokes.len() });
    }
    for (stroke, points) in strokes.iter().enumerate() {
        if points.len() < 2 {
            return Err(InitialisationError::StrokeTooShort { stroke, points: points.len() });
        }
        if let Some(point) = points.iter().position(|p| !p.iter().all(|c| c.is_finite())) {
            return Err(InitialisationError::NonFiniteStrokePoint { stroke, point });
        }
    }
    let reach = max_distance * mesh.mean_edge_length();
    let locator = SurfaceLocator::new(mesh, reach);
    let mut owner: Vec<Option<usize>> = vec![None; mesh.face_count()];
    let mut projected = Vec::with_capacity(strokes.len());
    for (stroke, points) in strokes.iter().enumerate() {
        let mut raw = Vec::with_capacity(points.len());
        for (point, p) in points.iter().enumerate() {
            let hit = locator.closest(p).ok_or(InitialisationError::StrokePointOffSurface { stroke, point, max_distance: reach })?;
            raw.push(StrokeSample { face: hit.face, barycentric: hit.barycentric, point });
        }
        let samples = one_per_triangle(&raw);
        if samples.len() < 2 {
            return Err(InitialisationError::StrokeTooShort { stroke, points: samples.len() });
        }
        for s in &samples {
            match owner[s.face as usize] {
                Some(first) => return Err(InitialisationError::CrossingStrokes { first, second: stroke, face: s.face }),
                None => owner[s.face as usize] = Some(stroke),
            }
        }
        projected.push(samples);
    }
    Ok(projected)
}

/// The middle sample of every run of consecutive samples in one triangle, skipping triangles an
/// earlier run of the same stroke already used.
fn one_per_triangle(raw: &[StrokeSample]) -> Vec<StrokeSample> {
    let mut kept: Vec<StrokeSample> = Vec::new();
    let mut used = std::collections::HashSet::new();
    let mut start = 0;
    while start < raw.len() {
        let face = raw[start].face;
        let end = start + raw[start..].iter().take_while(|s| s.face == face).count();
        if used.insert(face) {
            kept.push(raw[(start + end - 1) / 2]);
        }
        start = end;
    }
    kept
}
