//! Per-face gradient operators of the piecewise linear hat functions (the P1 gradient used for
//! ∇F throughout Sec. 3): ∇φ_i = (n_f × e_i) / (2 A_f), with e_i the edge opposite corner i
//! in winding order. For a field F with vertex values F_i, ∇F on face f = Σ_i F_i ∇φ_i.

use super::triangle::Triangle;
use super::Vec3;

/// Gradients of the three corner hat functions on every face (they sum to zero).
pub(crate) fn face_gradients(
    positions: &[Vec3],
    faces: &[[u32; 3]],
    face_normals: &[Vec3],
    face_areas: &[f64],
) -> Vec<[Vec3; 3]> {
    faces
        .iter()
        .zip(face_normals.iter().zip(face_areas))
        .map(|(face, (normal, &area))| {
            let triangle = Triangle::of(positions, face);
            let scale = 1.0 / (2.0 * area);
            [0, 1, 2].map(|i| normal.cross(&triangle.opposite_edge(i)) * scale)
        })
        .collect()
}
