//! A 3-web as a mesh (paper Sec. 4.2, reference notes §8.2): levels of `F` and `H` at one even
//! pace `p`, so that with `F + G + H = 0` (Eq. 18) the diagonal `i + j = k` of their net is the
//! level `−(c_F + c_H) − k p` of `G`. The web's vertices are the crossings of the first two
//! families' levels, found exactly inside triangles (as [`super::quad_net_at`]); its faces are
//! triangles, each quad of the net split along its `G` diagonal.
//!
//! A **Kagome** pattern (Fig. 1) shifts the third family by half a pace: its levels are the
//! diagonals `i + j = k + ½`, which cross the first two families' curves halfway between their
//! crossings. No three curves then meet at a point; the vertices are the crossings of every pair,
//! and the faces are the pattern's triangles and hexagons.
//!
//! Both are read off one net of `F` and `H` at half the pace: crossing `(a, b)` of that fine net
//! is crossing `(a/2, b/2)` in levels of the web.

use super::quad_net::quad_net_at;
use crate::curves::{field_range, CurveError};
use crate::mesh::{TriMesh, Vec3};
use std::collections::BTreeMap;

/// The levels of a 3-web's three families.
#[derive(Clone, Debug, PartialEq)]
pub struct WebLevels {
    /// Increasing levels of `F`, `H` and `G` (families 0, 1 and 2).
    pub levels: [Vec<f64>; 3],
    /// The common spacing of every family's levels.
    pub pace: f64,
    /// Whether the third family is shifted by half a pace (a Kagome pattern).
    pub kagome: bool,
    /// `F`'s and `H`'s first level: `levels[0][i] = first[0] + i · pace`.
    first: [f64; 2],
}

/// One vertex of a web: where two or three of its families' curves cross.
#[derive(Clone, Debug, PartialEq)]
pub struct WebVertex {
    /// For each family, the index of its level through this vertex (into
    /// [`WebLevels::levels`]), `None` if none of its curves passes here.
    pub levels: [Option<usize>; 3],
    pub position: Vec3,
    /// The triangle of the surface mesh it lies in.
    pub face: usize,
}

/// The extracted web.
#[derive(Clone, Debug, PartialEq)]
pub struct Web {
    pub levels: WebLevels,
    /// Vertices ordered by their levels of `F`, then of `H` (half-levels for a Kagome pattern).
    pub vertices: Vec<WebVertex>,
    /// Triangles (a 3-web) or triangles and hexagons (Kagome), oriented as the net's quads
    /// `(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)`; a face is kept where all its vertices exist.
    pub faces: Vec<Vec<u32>>,
    /// Per family: its polylines as `(level index, vertex indices)`, maximal runs of existing
    /// consecutive vertices along one level, ≥ 2 vertices each.
    pub polylines: [Vec<(usize, Vec<u32>)>; 3],
}

/// Relative tolerance below which a field's range counts as a whole number of paces
/// ([`web_levels`]).
const PACE_ROUNDING: f64 = 1e-9;

/// The even-pace levels of a 3-web of the fields `f`, `h` (the first two families) and `g` (the
/// third, ≈ `−f − h`), with about `counts[0]` levels of `f` and `counts[1]` of `h`: the pace is
/// the smaller of `range / (count + 1)`, each field's levels spread over its range at that pace,
/// centred (reference notes §8.2), and the third family's levels those diagonals `i + j = k`
/// (Kagome: `k + ½`) that lie strictly inside `g`'s range.
///
/// Errors: a field of the wrong length, with non-finite or out-of-range values, or constant
/// ([`field_range`]); `counts` 0 ([`CurveError::NoLevels`]) or above the level limit.
pub fn web_levels(mesh: &TriMesh, f: &[f64], h: &[f64], g: &[f64], counts: [usize; 2], kagome: bool) -> Result<WebLevels, CurveError> {
    let ranges = [field_range(mesh, f)?, field_range(mesh, h)?];
    let (g_low, g_high) = field_range(mesh, g)?;
    if counts.contains(&0) {
        return Err(CurveError::NoLevels);
    }
    if let Some(&count) = counts.iter().find(|&&c| c > crate::curves::MAX_LEVELS) {
        return Err(CurveError::TooManyLevels { count });
    }
    let pace = (0..2).map(|k| (ranges[k].1 - ranges[k].0) / (counts[k] + 1) as f64).fold(f64::INFINITY, f64::min);
    let mut first = [0.0; 2];
    let mut levels: [Vec<f64>; 3] = Default::default();
    for k in 0..2 {
        let (low, high) = ranges[k];
        // The levels strictly inside the range at this pace, centred in it. The family that set
        // the pace spans exactly `counts[k] + 1` paces, which the division may return a last bit
        // above: a quotient within `PACE_ROUNDING` of a whole number counts as that number, so that
        // a field's last bits never add a row of levels.
        let paces = (high - low) / pace;
        let count = (((paces - PACE_ROUNDING * paces).ceil()) as usize).saturating_sub(1).clamp(1, crate::curves::MAX_LEVELS);
        first[k] = low + 0.5 * ((high - low) - (count - 1) as f64 * pace);
        levels[k] = (0..count).map(|i| first[k] + i as f64 * pace).collect();
    }
    let shift = if kagome { 0.5 } else { 0.0 };
    let sums = levels[0].len() + levels[1].len() - 1;
    // G = −F − H: the diagonal of sum k + shift is G's level −(first F + first H) − (k + shift) p;
    // increasing levels come from decreasing sums.
    levels[2] = (0..sums)
        .rev()
        .map(|k| -(first[0] + first[1]) - (k as f64 + shift) * pace)
        .filter(|&level| level > g_low && level < g_high)
        .collect();
    Ok(WebLevels { levels, pace, kagome, first })
}

impl WebLevels {
    /// The index into `levels[2]` of the third family's level on the fine diagonal `a + b = sum`
    /// (fine indices count half-levels of `F` and `H`), if it is one of the web's levels.
    fn third_level(&self, sum: usize) -> Option<usize> {
        // The fine sum 2 (k + shift) of diagonal k.
        let value = -(self.first[0] + self.first[1]) - 0.5 * sum as f64 * self.pace;
        let tolerance = 1e-9 * self.pace;
        let at = self.levels[2].partition_point(|&l| l < value - tolerance);
        (at < self.levels[2].len() && (self.levels[2][at] - value).abs() <= tolerance).then_some(at)
    }
}

/// The web of `f` and `h` (the first two families; the third is read as `−f − h`) at `levels`
/// ([`web_levels`]). The fields are checked by the caller (as for [`web_levels`]).
pub fn extract_web(mesh: &TriMesh, f: &[f64], h: &[f64], levels: WebLevels) -> Web {
    // The net at half the pace: fine level 2i is level i, 2i + 1 lies halfway to level i + 1.
    let fine = |k: usize| -> Vec<f64> { (0..2 * levels.levels[k].len() - 1).map(|a| levels.first[k] + 0.5 * a as f64 * levels.pace).collect() };
    let net = quad_net_at(mesh, f, h, [fine(0), fine(1)]);
    let third = |a: usize, b: usize| -> Option<usize> {
        let on_diagonal = if levels.kagome { (a + b) % 2 == 1 } else { a % 2 == 0 && b % 2 == 0 };
        if on_diagonal { levels.third_level(a + b) } else { None }
    };
    let mut vertices = Vec::new();
    let mut index: BTreeMap<(usize, usize), u32> = BTreeMap::new();
    for v in &net.vertices {
        let (a, b) = (v.i, v.j);
        let family = |fine: usize| (fine % 2 == 0).then_some(fine / 2);
        let through = [family(a), family(b), third(a, b)];
        if through.iter().flatten().count() < 2 {
            continue;
        }
        index.insert((a, b), vertices.len() as u32);
        vertices.push(WebVertex { levels: through, position: v.position, face: v.face });
    }
    let at = |a: isize, b: isize| -> Option<u32> { (a >= 0 && b >= 0).then(|| index.get(&(a as usize, b as usize)).copied()).flatten() };
    let faces = if levels.kagome { kagome_faces(&vertices, &index, at) } else { web_triangles(&index, at) };
    let (fine_a, fine_b) = (2 * levels.levels[0].len() as isize - 1, 2 * levels.levels[1].len() as isize - 1);
    let step = if levels.kagome { 1 } else { 2 };
    let mut polylines: [Vec<(usize, Vec<u32>)>; 3] = Default::default();
    for i in 0..levels.levels[0].len() as isize {
        push_runs(&mut polylines[0], i as usize, (0..fine_b).step_by(step).map(|b| at(2 * i, b)));
    }
    for j in 0..levels.levels[1].len() as isize {
        push_runs(&mut polylines[1], j as usize, (0..fine_a).step_by(step).map(|a| at(a, 2 * j)));
    }
    for sum in 0..(fine_a + fine_b - 1) {
        let Some(level) = levels.third_level(sum as usize) else { continue };
        let first = (sum - (fine_b - 1)).max(0);
        // Along the diagonal, the vertices lie where the third family passes (every fine step on
        // a Kagome diagonal, every other one on a 3-web's even diagonal).
        let points = (first..=sum.min(fine_a - 1)).filter(|a| third(*a as usize, (sum - a) as usize).is_some()).map(|a| at(a, sum - a));
        push_runs(&mut polylines[2], level, points);
    }
    Web { levels, vertices, faces, polylines }
}

/// A 3-web's triangles: each net quad `(i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j)` split
/// along its diagonal `(i, j + 1)–(i + 1, j)` (a level of `G`), each half kept where its three
/// vertices exist.
fn web_triangles(index: &BTreeMap<(usize, usize), u32>, at: impl Fn(isize, isize) -> Option<u32>) -> Vec<Vec<u32>> {
    let mut faces = Vec::new();
    for &(a, b) in index.keys() {
        let (a, b) = (a as isize, b as isize);
        for corners in [[(a, b), (a, b + 2), (a + 2, b)], [(a, b + 2), (a + 2, b + 2), (a + 2, b)]] {
            if let Some(face) = corners.iter().map(|&(x, y)| at(x, y)).collect::<Option<Vec<u32>>>() {
                faces.push(face);
            }
        }
    }
    faces
}

/// A Kagome pattern's faces: around each crossing of `F` and `H` (fine `(a, b)`, both even) a
/// triangle on each side, cut off by the third family's curves at `a + b ± 1`, and in each net
/// quad the hexagon between them.
fn kagome_faces(vertices: &[WebVertex], index: &BTreeMap<(usize, usize), u32>, at: impl Fn(isize, isize) -> Option<u32>) -> Vec<Vec<u32>> {
    let mut faces = Vec::new();
    for (&(a, b), &v) in index {
        if vertices[v as usize].levels[2].is_some() {
            continue;
        }
        let (a, b) = (a as isize, b as isize);
        let shapes: [&[(isize, isize)]; 3] = [
            &[(0, 0), (0, 1), (1, 0)],
            &[(0, 0), (0, -1), (-1, 0)],
            &[(0, 1), (0, 2), (1, 2), (2, 1), (2, 0), (1, 0)],
        ];
        for shape in shapes {
            if let Some(face) = shape.iter().map(|&(x, y)| at(a + x, b + y)).collect::<Option<Vec<u32>>>() {
                faces.push(face);
            }
        }
    }
    faces
}

/// Appends to `out` the maximal runs (≥ 2 vertices) of consecutive existing vertices of `points`,
/// each tagged with `level`.
fn push_runs(out: &mut Vec<(usize, Vec<u32>)>, level: usize, points: impl Iterator<Item = Option<u32>>) {
    let mut runs = Vec::new();
    super::quad_net::push_runs(&mut runs, points);
    out.extend(runs.into_iter().map(|run| (level, run)));
}
