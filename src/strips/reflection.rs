//! The one-parameter family of discrete rectifying developables of planar quads on a fixed
//! polyline (Sec. 3.4, Fig. 20): every inner ruling `d_i` lies in the outer bisecting plane
//! `R_i` (Eq. 16) and consecutive rulings are coplanar with their segment (Eq. 17), so choosing
//! one ruling fixes all others by successive reflection. [`fitted_rulings`] picks the member
//! whose rulings come nearest to given directions: with the common node candidates of a net
//! (Sec. 5.2.1), it tells how close to torsion-free nodes a strip can come without moving its
//! polyline.

use super::frenet::{principal_normals, unit_edges};
use crate::mesh::Vec3;
use nalgebra::Matrix3;

/// Samples of the free angle in `(0, π)` before the local refinement.
const SAMPLES: usize = 180;
/// Golden-section steps of the refinement (the bracket shrinks by 0.618 each).
const REFINEMENTS: usize = 60;

/// The family's rulings as linear maps of the ruling at the inner vertex `start`: the ruling at
/// vertex `i` is `M_i d_start` (up to length and sign), because crossing the plane of the quad on
/// `ê` through `d` with the bisecting plane of normal `n_p` is `(ê × d) × n_p = d (ê·n_p) − ê (d·n_p)`,
/// linear in `d`. Where the polyline is straight the quad's plane continues (identity), and the
/// two ends copy their neighbour (their quads stay planar). Each map is scaled to unit norm
/// (lengths are immaterial).
fn propagation(points: &[Vec3], start: usize) -> Vec<Matrix3<f64>> {
    let n = points.len();
    let edges = unit_edges(points);
    let normals = principal_normals(points);
    // The map from the ruling at one end of `edge` to the ruling at `to`.
    let step = |edge: &Vec3, to: usize| match normals[to] {
        Some(np) if to > 0 && to + 1 < n => Matrix3::identity() * edge.dot(&np) - edge * np.transpose(),
        _ => Matrix3::identity(),
    };
    let unit = |m: Matrix3<f64>| {
        let norm = m.norm();
        if norm > 0.0 { m / norm } else { m }
    };
    let mut maps = vec![Matrix3::identity(); n];
    for i in start..n - 1 {
        maps[i + 1] = unit(step(&edges[i], i + 1) * maps[i]);
    }
    for i in (1..=start).rev() {
        maps[i - 1] = unit(step(&edges[i - 1], i - 1) * maps[i]);
    }
    maps
}

/// Unit rulings `M_i d` of [`propagation`], each oriented along the one before it; `None` when one
/// vanishes (a ruling along its segment: the strip would be unbounded).
fn rulings_of(maps: &[Matrix3<f64>], d: &Vec3, start: usize) -> Option<Vec<Vec3>> {
    let mut rulings: Vec<Vec3> = maps.iter().map(|m| (m * d).try_normalize(1e-12)).collect::<Option<_>>()?;
    for i in start + 1..rulings.len() {
        if rulings[i].dot(&rulings[i - 1]) < 0.0 {
            rulings[i] = -rulings[i];
        }
    }
    for i in (0..start).rev() {
        if rulings[i].dot(&rulings[i + 1]) < 0.0 {
            rulings[i] = -rulings[i];
        }
    }
    Some(rulings)
}

/// The rulings of the member of the family whose ruling at the inner vertex `start` is `ruling`
/// (a direction in `R_start`), one per vertex: inner vertices by reflection (the plane of the
/// quad before a vertex cut with the vertex's `R_i`; where the polyline is straight the quad's
/// plane continues), the two ends copying their neighbour (their quads stay planar). `None` when
/// a ruling falls along its segment (the strip would be unbounded).
pub fn reflected_rulings(points: &[Vec3], start: usize, ruling: Vec3) -> Option<Vec<Vec3>> {
    if points.len() < 3 || start == 0 || start + 1 >= points.len() {
        return None;
    }
    rulings_of(&propagation(points, start), &ruling, start)
}

/// The member of the family whose rulings come nearest to `targets` (unit directions as lines,
/// `None` where there is none), in the least squares of `sin²` of their angles: the free angle
/// sampled at 1° then refined. `None` for fewer than three points, a polyline straight at
/// every inner vertex, no target, or no member without a ruling along its segment.
pub fn fitted_rulings(points: &[Vec3], targets: &[Option<Vec3>]) -> Option<Vec<Vec3>> {
    let normals = principal_normals(points);
    let start = (1..points.len().saturating_sub(1)).find(|&i| normals[i].is_some())?;
    if !targets.iter().any(Option::is_some) {
        return None;
    }
    let edges = unit_edges(points);
    let tangent = (edges[start - 1] + edges[start]).try_normalize(1e-12)?;
    let across = normals[start]?.cross(&tangent);
    let maps = propagation(points, start);
    // The member of angle φ has rulings d_i = cos φ A_i + sin φ B_i; its misfit at vertex i,
    // 1 − (d_i·t_i)²/‖d_i‖², needs only the dot products of A_i, B_i and t_i, taken once here
    // for the few hundred angles tried.
    let terms: Vec<MisfitTerms> = maps.iter().zip(targets).map(|(m, t)| MisfitTerms::new(&(m * tangent), &(m * across), t.as_ref())).collect();
    let misfit = |phis: [f64; 2]| misfits(&terms, phis.map(f64::sin_cos));
    // The samples in lanes of four (each lane sums its vertices in order, as one sample alone
    // would); the last lanes repeat the last sample.
    let step = std::f64::consts::PI / SAMPLES as f64;
    let angles = sample_angles();
    let mut best = (f64::NAN, f64::INFINITY);
    for lanes in angles.chunks(LANES) {
        let values: [f64; LANES] = misfits(&terms, std::array::from_fn(|l| lanes[l.min(lanes.len() - 1)].1));
        for (&(phi, _), value) in lanes.iter().zip(values) {
            if value < best.1 {
                best = (phi, value);
            }
        }
    }
    let (best, best_misfit) = best;
    if best.is_nan() {
        return None;
    }
    let (mut low, mut high) = (best - step, best + step);
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..REFINEMENTS {
        let (x, y) = (high - ratio * (high - low), low + ratio * (high - low));
        let [at_x, at_y] = misfit([x, y]);
        if at_x < at_y {
            high = y;
        } else {
            low = x;
        }
    }
    let refined = 0.5 * (low + high);
    let phi = if misfits(&terms, [refined.sin_cos()])[0] <= best_misfit { refined } else { best };
    rulings_of(&maps, &(tangent * phi.cos() + across * phi.sin()), start)
}

/// Samples evaluated side by side in [`fitted_rulings`]' scan.
const LANES: usize = 4;

/// The sampled angles `s π / SAMPLES` (s = 1 … SAMPLES − 1) with their sines and cosines,
/// computed once.
fn sample_angles() -> &'static [(f64, (f64, f64))] {
    static ANGLES: std::sync::OnceLock<Vec<(f64, (f64, f64))>> = std::sync::OnceLock::new();
    ANGLES.get_or_init(|| {
        let step = std::f64::consts::PI / SAMPLES as f64;
        (1..SAMPLES).map(|s| s as f64 * step).map(|phi| (phi, phi.sin_cos())).collect()
    })
}

/// The misfit of [`fitted_rulings`] of the members at the angles of `(sin, cos)` pairs, each
/// lane summed over the vertices in order: `Σ_i 1 − (d_i·t_i)²/‖d_i‖²` over the vertices with a
/// target, +∞ where some ruling vanishes.
fn misfits<const L: usize>(terms: &[MisfitTerms], angles: [(f64, f64); L]) -> [f64; L] {
    let mut totals = [0.0; L];
    let mut vanishing = [false; L];
    for term in terms {
        let floor = 1e-24 * (term.aa + term.bb);
        for l in 0..L {
            let (sin, cos) = angles[l];
            let length = cos * cos * term.aa + 2.0 * cos * sin * term.ab + sin * sin * term.bb;
            vanishing[l] |= length <= floor;
            if let Some([at, bt]) = term.target {
                totals[l] += 1.0 - (cos * at + sin * bt).powi(2) / length;
            }
        }
    }
    std::array::from_fn(|l| if vanishing[l] { f64::INFINITY } else { totals[l] })
}

/// The dot products the misfit of [`fitted_rulings`] needs at one vertex, from its rulings `a`
/// (member φ = 0) and `b` (φ = 90°) and its target `t`: `a·a`, `a·b`, `b·b` and `(a·t, b·t)`.
struct MisfitTerms {
    aa: f64,
    ab: f64,
    bb: f64,
    target: Option<[f64; 2]>,
}

impl MisfitTerms {
    fn new(a: &Vec3, b: &Vec3, target: Option<&Vec3>) -> MisfitTerms {
        MisfitTerms { aa: a.norm_squared(), ab: a.dot(b), bb: b.norm_squared(), target: target.map(|t| [a.dot(t), b.dot(t)]) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A helix: its rectifying developable is a cylinder with rulings along the axis.
    fn helix(points: usize) -> Vec<Vec3> {
        (0..points).map(|i| {
            let t = 0.3 * i as f64;
            Vec3::new(t.cos(), t.sin(), 0.4 * t)
        }).collect()
    }

    #[test]
    fn every_member_has_planar_quads_and_rulings_in_the_bisecting_planes() {
        let points = helix(12);
        let normals = principal_normals(&points);
        let guess = Vec3::new(0.2, -0.1, 1.0);
        let np = normals[3].unwrap();
        let rulings = reflected_rulings(&points, 3, guess - np * guess.dot(&np)).unwrap();
        let edges = unit_edges(&points);
        for (j, e) in edges.iter().enumerate() {
            assert!(rulings[j].dot(&rulings[j + 1].cross(e)).abs() < 1e-12, "quad {j}");
        }
        for i in 1..points.len() - 1 {
            assert!(rulings[i].dot(&normals[i].unwrap()).abs() < 1e-12, "vertex {i}");
        }
    }

    #[test]
    fn the_helix_strip_fitted_to_its_axis_has_axial_rulings() {
        let points = helix(20);
        let targets = vec![Some(Vec3::z()); points.len()];
        let rulings = fitted_rulings(&points, &targets).unwrap();
        // The discrete helix's bisecting planes all contain the axis.
        for d in &rulings {
            assert!(d.dot(&Vec3::z()).abs() > 1.0 - 1e-9, "{d:?}");
        }
    }
}
