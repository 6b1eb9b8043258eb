//! The net as a quad mesh (reference notes §8.2): vertex `(i, j)` is the crossing of level `i` of
//! `F` with level `j` of `G`, found exactly inside a triangle (both fields are linear there, so
//! the crossing solves a 2 × 2 system in barycentric coordinates); rows (constant `i`) and
//! columns (constant `j`) are the polylines of consecutive crossings, and every 2 × 2 block of
//! crossings that all exist is a quad.

use crate::curves::{uniform_levels, CurveError};
use crate::mesh::{TriMesh, Vec3};
use std::collections::BTreeMap;

/// One crossing of a level of each field.
#[derive(Clone, Debug, PartialEq)]
pub struct NetVertex {
    /// Level index in the first and the second field.
    pub i: usize,
    pub j: usize,
    pub position: Vec3,
    /// The triangle it lies in.
    pub face: usize,
}

/// The extracted net.
#[derive(Clone, Debug, PartialEq)]
pub struct QuadNet {
    /// The level values of each field.
    pub levels: [Vec<f64>; 2],
    /// Crossings ordered by `(i, j)`.
    pub vertices: Vec<NetVertex>,
    /// Quads `(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)` as vertex indices.
    pub quads: Vec<[u32; 4]>,
    /// Rows: runs of crossings along one level of the first field (increasing `j`), ≥ 2 vertices.
    pub rows: Vec<Vec<u32>>,
    /// Columns: the same along one level of the second field (increasing `i`).
    pub columns: Vec<Vec<u32>>,
}

/// Barycentric tolerance of a crossing on a triangle's edge or corner.
const BARYCENTRIC_TOLERANCE: f64 = 1e-12;

/// The net of `count[k]` equally spaced levels of each field (as [`uniform_levels`]).
/// Errors as [`uniform_levels`] for a field of the wrong length, with non-finite values, or constant.
pub fn extract_quad_net(mesh: &TriMesh, f: &[f64], g: &[f64], counts: [usize; 2]) -> Result<QuadNet, CurveError> {
    let levels = [uniform_levels(mesh, f, counts[0])?, uniform_levels(mesh, g, counts[1])?];
    Ok(quad_net_at(mesh, f, g, levels))
}

/// The net of the given (increasing) levels of each field; the fields are checked by the caller.
pub fn quad_net_at(mesh: &TriMesh, f: &[f64], g: &[f64], levels: [Vec<f64>; 2]) -> QuadNet {
    let mut crossings: BTreeMap<(usize, usize), NetVertex> = BTreeMap::new();
    for (face, corners) in mesh.faces().iter().enumerate() {
        let fv = corners.map(|c| f[c as usize]);
        let gv = corners.map(|c| g[c as usize]);
        let (fi, gj) = (levels_within(&levels[0], &fv), levels_within(&levels[1], &gv));
        if fi.is_empty() || gj.is_empty() {
            continue;
        }
        let det = (fv[1] - fv[0]) * (gv[2] - gv[0]) - (fv[2] - fv[0]) * (gv[1] - gv[0]);
        if det == 0.0 || !det.is_finite() {
            continue;
        }
        for i in fi.clone() {
            for j in gj.clone() {
                if crossings.contains_key(&(i, j)) {
                    continue;
                }
                let (a, b) = (levels[0][i] - fv[0], levels[1][j] - gv[0]);
                let l1 = (a * (gv[2] - gv[0]) - (fv[2] - fv[0]) * b) / det;
                let l2 = ((fv[1] - fv[0]) * b - a * (gv[1] - gv[0])) / det;
                let l0 = 1.0 - l1 - l2;
                if [l0, l1, l2].iter().all(|&l| l >= -BARYCENTRIC_TOLERANCE) {
                    let p = mesh.positions();
                    let position = p[corners[0] as usize] * l0 + p[corners[1] as usize] * l1 + p[corners[2] as usize] * l2;
                    crossings.insert((i, j), NetVertex { i, j, position, face });
                }
            }
        }
    }
    let index: BTreeMap<(usize, usize), u32> = crossings.keys().enumerate().map(|(k, &key)| (key, k as u32)).collect();
    let vertices: Vec<NetVertex> = crossings.into_values().collect();
    let at = |i: usize, j: usize| index.get(&(i, j)).copied();
    let mut quads = Vec::new();
    for v in &vertices {
        let (i, j) = (v.i, v.j);
        if let (Some(a), Some(b), Some(c), Some(d)) = (at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)) {
            quads.push([a, b, c, d]);
        }
    }
    let rows = runs(levels[0].len(), levels[1].len(), at);
    let columns = runs(levels[1].len(), levels[0].len(), |j, i| at(i, j));
    QuadNet { levels, vertices, quads, rows, columns }
}

/// The indices of `levels` (increasing) within the range of the three corner values.
fn levels_within(levels: &[f64], values: &[f64; 3]) -> std::ops::Range<usize> {
    let low = values.iter().copied().fold(f64::INFINITY, f64::min);
    let high = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    levels.partition_point(|&l| l < low)..levels.partition_point(|&l| l <= high)
}

/// Maximal runs of consecutive existing vertices `at(line, step)` along each line, ≥ 2 long.
fn runs(lines: usize, steps: usize, at: impl Fn(usize, usize) -> Option<u32>) -> Vec<Vec<u32>> {
    let mut out = Vec::new();
    for line in 0..lines {
        push_runs(&mut out, (0..steps).map(|step| at(line, step)));
    }
    out
}

/// Appends to `out` the maximal runs (≥ 2 vertices) of consecutive existing vertices of `points`.
pub(super) fn push_runs(out: &mut Vec<Vec<u32>>, points: impl Iterator<Item = Option<u32>>) {
    let mut run = Vec::new();
    for point in points.chain(std::iter::once(None)) {
        match point {
            Some(v) => run.push(v),
            None => {
                if run.len() >= 2 {
                    out.push(std::mem::take(&mut run));
                }
                run.clear();
            }
        }
    }
}
