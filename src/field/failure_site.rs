//! Where a failed optimisation went wrong: the vertices carrying the largest residuals, named in
//! the error so that a user can look at the mesh there.

use super::problem::FieldProblem;
#[cfg(test)]
use super::FieldError;
use crate::solver::LeastSquaresProblem;

/// How many vertices a located failure names.
pub(crate) const NAMED_VERTICES: usize = 5;

/// The vertices with the largest residuals at `x`, largest first (at most [`NAMED_VERTICES`]):
/// each residual block's squared norm is charged to every field value it depends on; blocks
/// with non-finite residuals count as infinite. Ties go to the smaller vertex index.
pub(crate) fn largest_residual_vertices(problem: &FieldProblem, x: &[f64], vertex_count: usize) -> Vec<u32> {
    let mut score = vec![0.0f64; vertex_count];
    let mut residuals = Vec::new();
    for b in 0..problem.block_count() {
        residuals.clear();
        residuals.resize(problem.block_residual_count(b), 0.0);
        problem.evaluate_block(b, x, &mut residuals, None);
        let squared: f64 = residuals.iter().map(|r| r * r).sum();
        let squared = if squared.is_finite() { squared } else { f64::INFINITY };
        for &v in problem.block_variables(b).iter().filter(|&&v| (v as usize) < vertex_count) {
            score[v as usize] += squared;
        }
    }
    let mut order: Vec<u32> = (0..vertex_count as u32).collect();
    order.sort_by(|&a, &b| score[b as usize].total_cmp(&score[a as usize]).then(a.cmp(&b)));
    order.truncate(NAMED_VERTICES);
    order
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::{FieldParams, FieldSolver};
    use crate::surfaces::hall_roof;

    #[test]
    fn a_spike_in_the_field_is_named() {
        let mesh = hall_roof(200).into_mesh().expect("valid roof");
        let mut field: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
        let spike = (0..mesh.vertex_count()).find(|&v| !mesh.is_boundary_vertex(v) && v > mesh.vertex_count() / 2).expect("interior vertex");
        field[spike] += 30.0;
        let solver = FieldSolver::new(&mesh, &field, FieldParams::pseudo_geodesic(60.0)).expect("solver");
        let named = largest_residual_vertices(&solver.problem, &solver.x, mesh.vertex_count());
        assert_eq!(named.len(), NAMED_VERTICES);
        assert!(named.contains(&(spike as u32)), "{named:?} should name vertex {spike}");
        let message = FieldError::SolverFailedNear { error: crate::solver::SolverError::FactorizationFailed { trials: 10 }, vertices: named }.to_string();
        assert!(message.contains(&spike.to_string()) && message.contains("largest residuals"), "{message}");
    }
}
