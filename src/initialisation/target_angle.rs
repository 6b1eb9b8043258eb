//! The target angle of the interactive design (Sec. 3.2.2, Fig. 14 c): the mean angle between
//! the level-set binormals and the surface normals where the strokes run.

use super::error::InitialisationError;
use super::strokes::StrokeSample;
use crate::field::level_frame;
use crate::mesh::TriMesh;

/// Mean signed angle θ (degrees, the convention of `LevelFrame::signed_angle_degrees`) of the
/// level sets of `field` at the strokes: for every sample in the middle half of its stroke
/// (25 %–75 % of its samples), the vertex of its triangle nearest to it (largest barycentric
/// coordinate); each vertex counted once, boundary and singular vertices and straight level
/// polylines skipped (reference notes §5.4, without the farthest-vertex slip noted there).
pub fn estimate_target_angle(mesh: &TriMesh, field: &[f64], samples: &[Vec<StrokeSample>]) -> Result<f64, InitialisationError> {
    let mut vertices = Vec::new();
    for stroke in samples {
        let last = stroke.len().saturating_sub(1) as f64;
        for (i, s) in stroke.iter().enumerate() {
            if !(0.25 * last..=0.75 * last).contains(&(i as f64)) {
                continue;
            }
            let Some(corners) = mesh.faces().get(s.face as usize) else { continue };
            let nearest = (0..3).fold(0, |best, k| if s.barycentric[k] > s.barycentric[best] { k } else { best });
            vertices.push(corners[nearest] as usize);
        }
    }
    vertices.sort_unstable();
    vertices.dedup();
    let angles: Vec<f64> = vertices
        .iter()
        .filter(|&&v| v < mesh.vertex_count() && field.len() == mesh.vertex_count())
        .filter_map(|&v| level_frame(mesh, field, v)?.signed_angle_degrees())
        .collect();
    if angles.is_empty() {
        return Err(InitialisationError::NoMeasurableAngle);
    }
    Ok(angles.iter().sum::<f64>() / angles.len() as f64)
}
