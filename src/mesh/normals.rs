//! Face normals and areas from the winding, and corner-angle-weighted vertex normals.

use super::triangle::Triangle;
use super::Vec3;

/// Unit face normals (right-hand rule on the winding) and face areas.
pub(crate) fn face_normals_and_areas(positions: &[Vec3], faces: &[[u32; 3]]) -> (Vec<Vec3>, Vec<f64>) {
    faces
        .iter()
        .map(|face| {
            let cross = Triangle::of(positions, face).cross();
            let norm = cross.norm();
            (cross / norm, 0.5 * norm)
        })
        .unzip()
}

/// Vertex normals: the sum of the incident face normals weighted by the corner angle at the
/// vertex, normalised. If that sum vanishes (faces folded flat onto each other), the normal of
/// the incident face with the largest corner angle is used instead.
pub(crate) fn vertex_normals(positions: &[Vec3], faces: &[[u32; 3]], face_normals: &[Vec3]) -> Vec<Vec3> {
    let mut sums = vec![Vec3::zeros(); positions.len()];
    let mut fallback: Vec<(f64, Vec3)> = vec![(-1.0, Vec3::zeros()); positions.len()];
    for (face, normal) in faces.iter().zip(face_normals) {
        let triangle = Triangle::of(positions, face);
        for (c, &v) in face.iter().enumerate() {
            let angle = triangle.corner_angle(c);
            let v = v as usize;
            sums[v] += normal * angle;
            if angle > fallback[v].0 {
                fallback[v] = (angle, *normal);
            }
        }
    }
    sums.iter()
        .zip(fallback)
        .map(|(sum, (_, largest))| {
            let norm = sum.norm();
            // A unit-normal sum this short is pure cancellation; its direction is noise.
            if norm > 1e-12 {
                sum / norm
            } else {
                largest
            }
        })
        .collect()
}
