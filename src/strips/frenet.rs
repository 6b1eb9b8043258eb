//! The discrete Frenet frame of a polyline (Eq. 1) and the first version of a discrete
//! rectifying developable (Fig. 19): rulings `L_i = R_{i−1} ∩ R_i` of consecutive outer
//! bisecting (rectifying) planes `R_i : (x − c_i)·n_i^p = 0`.
use crate::mesh::Vec3;

/// Below this `‖ê_i − ê_{i−1}‖` (a turning angle of about 1e-9 rad) the polyline is straight at a
/// vertex: its principal normal and its rectifying plane are undefined.
const STRAIGHT: f64 = 1e-9;
/// Below this `‖n_{i−1}^p × n_i^p‖` two rectifying planes are too close to parallel for their
/// intersection line to be a reliable ruling.
const PARALLEL: f64 = 1e-6;

/// Unit edge vectors `ê_i = (c_{i+1} − c_i)/‖c_{i+1} − c_i‖` (zero for a zero-length edge).
pub fn unit_edges(points: &[Vec3]) -> Vec<Vec3> {
    points.windows(2).map(|w| (w[1] - w[0]).try_normalize(0.0).unwrap_or_else(Vec3::zeros)).collect()
}

/// Discrete principal normal `n_i^p = (ê_i − ê_{i−1})/‖ê_i − ê_{i−1}‖` at every vertex (Eq. 1);
/// `None` at the two ends and where the polyline is straight.
pub fn principal_normals(points: &[Vec3]) -> Vec<Option<Vec3>> {
    let edges = unit_edges(points);
    (0..points.len())
        .map(|i| {
            if i == 0 || i + 1 >= points.len() {
                return None;
            }
            (edges[i] - edges[i - 1]).try_normalize(STRAIGHT)
        })
        .collect()
}

/// Discrete binormal `b_i = t_i × n_i^p`, with `t_i` the unit outer bisector (Eq. 1), i.e. the
/// normalised `ê_{i−1} × ê_i`; `None` at the ends and where the polyline is straight.
pub fn discrete_binormals(points: &[Vec3]) -> Vec<Option<Vec3>> {
    let edges = unit_edges(points);
    let normals = principal_normals(points);
    (0..points.len())
        .map(|i| {
            normals[i]?;
            edges[i - 1].cross(&edges[i]).try_normalize(0.0)
        })
        .collect()
}

/// Version-1 rulings (Fig. 19): the unit direction of `L_i = R_{i−1} ∩ R_i` for every vertex pair
/// `(i − 1, i)`, stored at index `i` (index 0 and the ends' neighbours are `None`), oriented to make a
/// positive product with `reference[i]` (e.g. the binormals). `None` where a plane is undefined or
/// the two planes are nearly parallel.
pub fn version_one_rulings(points: &[Vec3], reference: &[Vec3]) -> Vec<Option<Vec3>> {
    let normals = principal_normals(points);
    (0..points.len())
        .map(|i| {
            let (a, b) = (normals.get(i.checked_sub(1)?).copied()??, normals[i]?);
            let line = a.cross(&b).try_normalize(PARALLEL)?;
            let side = reference.get(i).map_or(1.0, |r| line.dot(r));
            Some(if side < 0.0 { -line } else { line })
        })
        .collect()
}

/// Initial rulings of the preferred strip (Sec. 3.4): in the rectifying plane `R_i`, the average of
/// the unit directions of `L_i` and `L_{i+1}`; where only one exists, that one; where none exists,
/// the binormal `reference[i]` projected into `R_i` (or kept as it is where `R_i` is undefined).
/// The two ends, which have no rectifying plane, copy their neighbour's ruling (so the end quads
/// start planar). Unit vectors oriented along `reference`.
/// One ruling per point that has a reference vector (`min(points.len(), reference.len())`).
pub fn initial_rulings(points: &[Vec3], reference: &[Vec3]) -> Vec<Vec3> {
    let points = &points[..points.len().min(reference.len())];
    let lines = version_one_rulings(points, reference);
    let normals = principal_normals(points);
    let n = points.len();
    let mut rulings: Vec<Vec3> = (0..n)
        .map(|i| {
            let next = lines.get(i + 1).copied().flatten();
            let guess = match (lines[i], next) {
                (Some(a), Some(b)) => a + b,
                (Some(a), None) | (None, Some(a)) => a,
                (None, None) => reference[i],
            };
            let in_plane = normals[i].map_or(guess, |n| guess - n * guess.dot(&n));
            let unit = in_plane.try_normalize(PARALLEL).unwrap_or(reference[i]);
            if unit.dot(&reference[i]) < 0.0 { -unit } else { unit }
        })
        .collect();
    if n >= 3 {
        rulings[0] = rulings[1];
        rulings[n - 1] = rulings[n - 2];
    }
    rulings
}
