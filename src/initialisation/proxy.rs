//! The start search's stand-in for a mesh: the same surface coarsened to about 1,500 vertices
//! ([`crate::mesh::coarsened`]), and the way back, a field carried from the stand-in to the mesh.
//!
//! Which start leads to the asked family is a property of the surface, not of its resolution;
//! short solves, however, converge more slowly as a mesh grows (a probe that settles on 3,000
//! vertices is still far from its family on 10,000), and each of their iterations costs more. Probing on a stand-in keeps the search's
//! cost and its judgement the same for any input; the winner's field is then carried over and
//! the solve on the mesh itself starts next to its family.

use crate::mesh::{coarsened, FaceBvh, TriMesh};

/// The stand-in for `mesh` with about `target_vertices` vertices; `None` when `mesh` is small
/// enough to be searched itself (at most 1.5 × `target_vertices`, or `target_vertices` = 0) or
/// when no valid coarsening exists (then the search runs on `mesh`).
pub(crate) fn search_proxy(mesh: &TriMesh, target_vertices: usize) -> Option<TriMesh> {
    if target_vertices == 0 || 2 * mesh.vertex_count() <= 3 * target_vertices {
        return None;
    }
    coarsened(mesh, target_vertices).ok()
}

/// `field` (one value per vertex of `proxy`) at every vertex of `mesh`: linear on the face of
/// `proxy` closest to the vertex. Every vertex of `proxy` is a vertex of `mesh`, so the values
/// there are carried unchanged.
pub(crate) fn carried_to(proxy: &TriMesh, field: &[f64], mesh: &TriMesh) -> Vec<f64> {
    let faces = FaceBvh::new(proxy);
    mesh.positions()
        .iter()
        .map(|p| {
            // Invariant: a valid mesh has faces, so a closest face exists.
            let closest = faces.closest(proxy, p).expect("a valid mesh has faces");
            let face = proxy.faces()[closest.face];
            (0..3).map(|k| closest.weights[k] * field[face[k] as usize]).sum()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surfaces::hall_roof;

    #[test]
    fn small_meshes_are_searched_themselves() {
        let mesh = hall_roof(3_000).into_mesh().unwrap();
        assert!(search_proxy(&mesh, 3_000).is_none());
        assert!(search_proxy(&mesh, 0).is_none());
    }

    #[test]
    fn a_linear_field_is_carried_exactly_up_to_the_chordal_gap() {
        let mesh = hall_roof(10_000).into_mesh().unwrap();
        let proxy = search_proxy(&mesh, 3_000).expect("a stand-in");
        let height = |p: &crate::mesh::Vec3| 0.3 * p.x - 0.2 * p.y + 0.1 * p.z;
        let on_proxy: Vec<f64> = proxy.positions().iter().map(height).collect();
        let carried = carried_to(&proxy, &on_proxy, &mesh);
        // The roof's chords over 0.7 m edges sag by millimetres; the closest point moves by as much.
        let worst = mesh.positions().iter().zip(&carried).map(|(p, f)| (height(p) - f).abs()).fold(0.0, f64::max);
        assert!(worst < 0.01, "carried field off by {worst}");
    }
}
