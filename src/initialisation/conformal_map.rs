//! The conformal parameterisation `m: S → ℝ²` on which Sec. 3.2.2 sets up the initial linear
//! function: the least-squares conformal map (LSCM, Lévy et al. 2002) with a free boundary.
//!
//! On each face f, a map `(u, v)` is conformal when `∇v = n_f × ∇u` (the gradient of `v` is the
//! gradient of `u` turned by 90° in the face plane). LSCM minimises
//! `Σ_f A_f ‖∇v − n_f × ∇u‖²` over the piecewise linear `u, v`, written in a tangent frame
//! `(t1, t2)` of every face as two linear residuals per face. Two vertices of the outer (longest)
//! boundary loop are pinned, its first vertex at (0, 0) and the loop vertex farthest from it at
//! (1, 0), which removes the similarity freedom; holes stay free. The result is orientation
//! preserving with respect to the face normals: a flat mesh is reproduced up to a similarity, a
//! developable one up to a similarity of its development.

use super::linear_least_squares::LinearRows;
use super::smoothness_rows::face_frame;
use crate::mesh::TriMesh;

/// The LSCM image of every vertex of `mesh`, `None` if the system is singular (which a valid,
/// connected mesh does not produce).
pub(crate) fn least_squares_conformal_map(mesh: &TriMesh) -> Option<Vec<[f64; 2]>> {
    let n = mesh.vertex_count();
    // Internal invariant: a validated mesh has at least one boundary loop with three vertices.
    let outer = &mesh.boundary_loops()[0];
    let first = outer[0] as usize;
    let origin = mesh.positions()[first];
    let second = outer
        .iter()
        .map(|&v| v as usize)
        .max_by(|&a, &b| {
            let (da, db) = ((mesh.positions()[a] - origin).norm(), (mesh.positions()[b] - origin).norm());
            da.total_cmp(&db).then(b.cmp(&a))
        })
        .unwrap_or(first);
    // Variables: u of every free vertex, then v of every free vertex.
    let mut free_index = vec![usize::MAX; n];
    let mut free = 0;
    for (v, index) in free_index.iter_mut().enumerate() {
        if v != first && v != second {
            *index = free;
            free += 1;
        }
    }
    let pinned = |v: usize| -> Option<[f64; 2]> {
        if v == first {
            Some([0.0, 0.0])
        } else if v == second {
            Some([1.0, 0.0])
        } else {
            None
        }
    };
    let mut rows = LinearRows::new();
    for (f, face) in mesh.faces().iter().enumerate() {
        let normal = mesh.face_normals()[f];
        let gradients = mesh.face_gradients(f);
        let weight = mesh.face_areas()[f];
        for axis in face_frame(mesh, f) {
            // Σ_i v_i (axis · ∇φ_i) − u_i (axis · (n × ∇φ_i)) = 0; pinned values go to the target.
            let mut entries = Vec::with_capacity(6);
            let mut target = 0.0;
            for (corner, gradient) in face.iter().zip(gradients) {
                let (cu, cv) = (-axis.dot(&normal.cross(gradient)), axis.dot(gradient));
                let vertex = *corner as usize;
                match pinned(vertex) {
                    Some([pu, pv]) => target -= cu * pu + cv * pv,
                    None => {
                        entries.push((free_index[vertex], cu));
                        entries.push((free + free_index[vertex], cv));
                    }
                }
            }
            rows.push(entries, target, weight);
        }
    }
    let solution = rows.factorise(2 * free)?.solve(rows.targets())?;
    Some(
        (0..n)
            .map(|v| pinned(v).unwrap_or_else(|| [solution[free_index[v]], solution[free + free_index[v]]]))
            .collect(),
    )
}
