//! Mixed Voronoi vertex areas (Meyer, Desbrun, Schröder, Barr 2003), the vertex weights of the
//! angle energies (paper Sec. 3.2.2, "A normalised to mean 1").

use super::triangle::Triangle;
use super::Vec3;

/// Mixed Voronoi area of every vertex. Per face: if no angle is obtuse, each corner gets its
/// circumcentric Voronoi part (|e_ij|² cot γ_k + |e_ik|² cot γ_j) / 8; otherwise the obtuse
/// corner gets area/2 and the other two area/4. The areas sum to the total surface area.
pub(crate) fn mixed_voronoi_areas(positions: &[Vec3], faces: &[[u32; 3]], face_areas: &[f64]) -> Vec<f64> {
    let mut areas = vec![0.0; positions.len()];
    for (face, &area) in faces.iter().zip(face_areas) {
        let triangle = Triangle::of(positions, face);
        let obtuse = (0..3).find(|&c| triangle.is_obtuse_at(c));
        for c in 0..3 {
            let part = match obtuse {
                Some(o) if o == c => area / 2.0,
                Some(_) => area / 4.0,
                None => {
                    // Edge c→c+1 is opposite corner c+2, edge c→c+2 opposite corner c+1.
                    let (j, k) = ((c + 1) % 3, (c + 2) % 3);
                    (triangle.opposite_edge(k).norm_squared() * triangle.corner_cot(k)
                        + triangle.opposite_edge(j).norm_squared() * triangle.corner_cot(j))
                        / 8.0
                }
            };
            areas[face[c] as usize] += part;
        }
    }
    areas
}

/// Areas divided by their mean, so that they average to 1.
pub(crate) fn normalized(areas: &[f64]) -> Vec<f64> {
    let mean = areas.iter().sum::<f64>() / areas.len() as f64;
    areas.iter().map(|a| a / mean).collect()
}
