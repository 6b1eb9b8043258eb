//! Rows shared by the initialisation solves: the fairness energy `E_fair` (Eq. 6) and the
//! piecewise linear gradient `∇F` of a field on a face, and a tangent frame of a face.

use super::linear_least_squares::LinearRows;
use crate::field::hessian_energy::HessianEnergy;
use crate::mesh::{TriMesh, Vec3};

/// Appends the rows of `weight · E_fair` (Eq. 6, the Hessian energy of `crate::field::hessian_energy`)
/// over the vertex values of `mesh`.
pub(crate) fn push_fairness_rows(rows: &mut LinearRows, mesh: &TriMesh, weight: f64) {
    let energy = HessianEnergy::new(mesh);
    for v in 0..mesh.vertex_count() {
        let variables = energy.vertex_variables(v);
        for coefficients in energy.vertex_operator(v).chunks_exact(variables.len()) {
            rows.push(variables.iter().zip(coefficients).map(|(&j, &c)| (j as usize, c)), 0.0, weight);
        }
    }
}

/// `∇F` on face `f` (`field` has one value per vertex).
pub(crate) fn face_gradient(mesh: &TriMesh, field: &[f64], f: usize) -> Vec3 {
    let corners = mesh.faces()[f];
    mesh.face_gradients(f).iter().zip(corners).map(|(g, c)| g * field[c as usize]).sum()
}

/// Area-weighted mean of `‖∇F‖` over the faces `f` with `include(f)`; `None` if none is included.
pub(crate) fn mean_gradient_norm(mesh: &TriMesh, field: &[f64], include: impl Fn(usize) -> bool) -> Option<f64> {
    let (mut weighted, mut area) = (0.0, 0.0);
    for f in (0..mesh.face_count()).filter(|&f| include(f)) {
        weighted += face_gradient(mesh, field, f).norm() * mesh.face_areas()[f];
        area += mesh.face_areas()[f];
    }
    (area > 0.0).then(|| weighted / area)
}

/// An orthonormal frame of the plane of face `f`.
pub(crate) fn face_frame(mesh: &TriMesh, f: usize) -> [Vec3; 2] {
    let face = mesh.faces()[f];
    let normal = mesh.face_normals()[f];
    let t1 = (mesh.positions()[face[1] as usize] - mesh.positions()[face[0] as usize]).normalize();
    [t1, normal.cross(&t1)]
}
