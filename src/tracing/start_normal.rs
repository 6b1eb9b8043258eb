//! The surface normal at the boundary start point, from a least-squares quadratic fit.
//!
//! Vertex normals at the boundary average only the faces on the inner side, so they lean into
//! the surface by about `κ·h/3`; a start tangent taken perpendicular to such a normal leans out
//! of the tangent plane, and its first turn carries that lean into a persistent error of the
//! curve's direction (the turns of Eq. 4 telescope to the normal change along the curve plus
//! this start term). A quadratic height function fitted to the vertices around the start point
//! has a second-order accurate gradient even on a one-sided neighbourhood.

use nalgebra::{DMatrix, DVector};

use super::normal::point_normal;
use crate::mesh::{EdgePoint, TriMesh, Vec3};

/// Fewest vertices for the 6-coefficient fit.
const MIN_POINTS: usize = 10;
/// Smallest accepted singular value relative to the largest (a well-spread neighbourhood).
const CONDITION: f64 = 1e-6;
/// The fitted normal must stay within this angle (degrees) of the vertex-normal estimate.
const MAX_CORRECTION_DEGREES: f64 = 30.0;

/// The unit normal at `start` (a valid point on a boundary edge) from the height function
/// `z = c₀ + a·x + b·y + c·x² + d·xy + e·y²` fitted over the two-rings of its edge's end vertices,
/// in the frame of the interpolated vertex normal; that interpolated normal itself if the fit
/// is ill-posed.
pub(crate) fn start_normal(mesh: &TriMesh, start: &EdgePoint, position: &Vec3) -> Option<Vec3> {
    let rough = point_normal(mesh, start)?;
    Some(fitted_normal(mesh, start, position, &rough).unwrap_or(rough))
}

fn fitted_normal(mesh: &TriMesh, start: &EdgePoint, position: &Vec3, rough: &Vec3) -> Option<Vec3> {
    let vertices = two_ring(mesh, start.edge);
    if vertices.len() < MIN_POINTS {
        return None;
    }
    let e1 = rough.cross(&Vec3::x()).try_normalize(1e-6).or_else(|| rough.cross(&Vec3::y()).try_normalize(0.0))?;
    let e2 = rough.cross(&e1);
    let scale = mesh.mean_edge_length();
    let positions = mesh.positions();
    let mut design = DMatrix::zeros(vertices.len(), 6);
    let mut heights = DVector::zeros(vertices.len());
    for (row, &v) in vertices.iter().enumerate() {
        // Internal invariant: star vertices are mesh vertices.
        let d = (positions[v as usize] - position) / scale;
        let (x, y) = (d.dot(&e1), d.dot(&e2));
        for (column, value) in [1.0, x, y, x * x, x * y, y * y].into_iter().enumerate() {
            design[(row, column)] = value;
        }
        heights[row] = d.dot(rough);
    }
    let svd = design.svd(true, true);
    let well_posed = svd.singular_values.min() > CONDITION * svd.singular_values.max();
    if !well_posed {
        return None;
    }
    let coefficients = svd.solve(&heights, 0.0).ok()?;
    let normal = (rough - e1 * coefficients[1] - e2 * coefficients[2]).try_normalize(0.0)?;
    let within = normal.dot(rough) >= MAX_CORRECTION_DEGREES.to_radians().cos();
    (within && normal.iter().all(|c| c.is_finite())).then_some(normal)
}

/// The vertices within two edges of `edge`'s end vertices, sorted.
fn two_ring(mesh: &TriMesh, edge: [u32; 2]) -> Vec<u32> {
    let mut ring: Vec<u32> = edge.to_vec();
    for _ in 0..2 {
        let mut grown = ring.clone();
        for &v in &ring {
            grown.extend_from_slice(mesh.star(v as usize).neighbours);
        }
        grown.sort_unstable();
        grown.dedup();
        ring = grown;
    }
    ring
}
