//! The irregular triangulation shared by the parametric test surfaces: a jittered grid of roughly
//! square cells in a rectangular, roughly arc-length parameter domain, each cell split along a
//! random diagonal.

use super::random::SplitMix64;
use super::GeneratedSurface;
use crate::mesh::Vec3;

/// Below this smallest angle (radians, 20°) a randomly chosen diagonal is replaced by the other
/// one when that one gives a larger smallest angle.
const ACCEPTABLE_MIN_ANGLE: f64 = 0.349_065_850_398_865_9;

/// A rectangle `[0, width] × [0, height]` of a parameter domain whose parameters are (close to)
/// arc length on the surface, so that square parameter cells give well-shaped triangles.
pub(crate) struct ParameterRectangle {
    pub width: f64,
    pub height: f64,
}

/// Triangulates `domain` with about `target_vertices` vertices and maps every grid point through
/// `surface_point`.
///
/// Grid points are jittered: every coordinate that is not on the boundary is displaced by up to
/// `±irregularity / 2` cell sizes, so boundary points slide only along their boundary side and the
/// four corners stay fixed (`irregularity < 1` keeps neighbouring points ordered). Each cell is split
/// along a random diagonal unless that split has an angle below 20° and the other diagonal does
/// better, judged on the mapped (3D) triangles. Faces are counter-clockwise in the parameter
/// domain, so the face normals point along `∂p/∂u × ∂p/∂v`.
pub(crate) fn jittered_grid(
    domain: &ParameterRectangle,
    target_vertices: usize,
    irregularity: f64,
    rng: &mut SplitMix64,
    surface_point: impl Fn(f64, f64) -> Vec3,
) -> GeneratedSurface {
    let (columns, rows) = grid_size(domain, target_vertices);
    let cell_u = domain.width / columns as f64;
    let cell_v = domain.height / rows as f64;
    let mut positions = Vec::with_capacity((columns + 1) * (rows + 1));
    for j in 0..=rows {
        for i in 0..=columns {
            let mut u = i as f64 * cell_u;
            let mut v = j as f64 * cell_v;
            if i > 0 && i < columns {
                u += rng.symmetric(0.5 * irregularity * cell_u);
            }
            if j > 0 && j < rows {
                v += rng.symmetric(0.5 * irregularity * cell_v);
            }
            positions.push(surface_point(u, v));
        }
    }
    let index = |i: usize, j: usize| (j * (columns + 1) + i) as u32;
    let mut faces = Vec::with_capacity(2 * columns * rows);
    for j in 0..rows {
        for i in 0..columns {
            // Counter-clockwise cell corners in the parameter domain.
            let (a, b, c, d) = (index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
            let along_ac = [[a, b, c], [a, c, d]];
            let along_bd = [[a, b, d], [b, c, d]];
            let quality = |split: &[[u32; 3]; 2]| {
                split
                    .iter()
                    .map(|t| min_angle(&positions, t))
                    .fold(f64::INFINITY, f64::min)
            };
            let (chosen, other) = if rng.next_bool() { (along_ac, along_bd) } else { (along_bd, along_ac) };
            let split = if quality(&chosen) < ACCEPTABLE_MIN_ANGLE && quality(&other) > quality(&chosen) {
                other
            } else {
                chosen
            };
            faces.extend_from_slice(&split);
        }
    }
    GeneratedSurface { positions, faces }
}

/// Numbers of cells `(columns, rows)`, at least one each, such that `(columns + 1)(rows + 1)` is
/// close to `target_vertices` and the cells are close to square.
fn grid_size(domain: &ParameterRectangle, target_vertices: usize) -> (usize, usize) {
    let target = target_vertices.max(4) as f64;
    let aspect = domain.width / domain.height;
    let points_u = (target * aspect).sqrt().round().max(2.0);
    let points_v = (target / points_u).round().max(2.0);
    (points_u as usize - 1, points_v as usize - 1)
}

/// The smallest interior angle (radians) of triangle `t`.
pub(crate) fn min_angle(positions: &[Vec3], t: &[u32; 3]) -> f64 {
    // Internal invariant: grid triangles index only the grid points generated with them.
    let p = t.map(|k| positions[k as usize]);
    (0..3)
        .map(|k| {
            let e1 = p[(k + 1) % 3] - p[k];
            let e2 = p[(k + 2) % 3] - p[k];
            e1.cross(&e2).norm().atan2(e1.dot(&e2))
        })
        .fold(f64::INFINITY, f64::min)
}
