//! Where a failed optimisation went wrong: the vertices carrying the largest residuals, named in
//! the error so that a user can look at the mesh there.

use super::problem::FieldProblem;
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
