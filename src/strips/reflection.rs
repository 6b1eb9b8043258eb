//! The one-parameter family of discrete rectifying developables of planar quads on a fixed
//! polyline (Sec. 3.4, Fig. 20): every inner ruling `d_i` lies in the outer bisecting plane
//! `R_i` (Eq. 16) and consecutive rulings are coplanar with their segment (Eq. 17), so choosing
//! one ruling fixes all others by successive reflection. [`fitted_rulings`] picks the member
//! whose rulings come nearest to given directions: with the common node candidates of a net
//! (Sec. 5.2.1), it tells how close to torsion-free nodes a strip can come without moving its
//! polyline.

use super::frenet::{principal_normals, unit_edges};
use crate::mesh::Vec3;

/// Samples of the free angle in `(0, π)` before the local refinement.
const SAMPLES: usize = 240;
/// Golden-section steps of the refinement (the bracket shrinks by 0.618 each).
const REFINEMENTS: usize = 40;

/// The rulings of the member of the family whose ruling at the inner vertex `start` is `ruling`
/// (a direction in `R_start`), one per vertex: inner vertices by reflection (the plane of the
/// quad before a vertex cut with the vertex's `R_i`; where the polyline is straight the quad's
/// plane continues), the two ends copying their neighbour (their quads stay planar). `None` when
/// a ruling falls along its segment (the strip would be unbounded).
pub fn reflected_rulings(points: &[Vec3], start: usize, ruling: Vec3) -> Option<Vec<Vec3>> {
    let n = points.len();
    if n < 3 || start == 0 || start + 1 >= n {
        return None;
    }
    let edges = unit_edges(points);
    let normals = principal_normals(points);
    let mut rulings = vec![Vec3::zeros(); n];
    rulings[start] = ruling.try_normalize(0.0)?;
    // Crosses the plane of the quad on `edge` (through `from`) with the bisecting plane at `to`.
    let next = |from: &Vec3, edge: &Vec3, to: usize| -> Option<Vec3> {
        let quad = edge.cross(from).try_normalize(1e-12)?;
        let d = match normals[to] {
            Some(np) if to > 0 && to + 1 < n => quad.cross(&np).try_normalize(1e-12)?,
            _ => *from,
        };
        Some(if d.dot(from) < 0.0 { -d } else { d })
    };
    for i in start..n - 1 {
        rulings[i + 1] = next(&rulings[i], &edges[i], i + 1)?;
    }
    for i in (1..=start).rev() {
        rulings[i - 1] = next(&rulings[i], &edges[i - 1], i - 1)?;
    }
    Some(rulings)
}

/// The member of the family whose rulings come nearest to `targets` (unit directions as lines,
/// `None` where there is none), in the least squares of `sin²` of their angles: the free angle
/// sampled at 0.75° then refined. `None` for fewer than three points, a polyline straight at
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
    let member = |phi: f64| reflected_rulings(points, start, tangent * phi.cos() + across * phi.sin());
    let misfit = |phi: f64| -> f64 {
        member(phi).map_or(f64::INFINITY, |rulings| {
            rulings.iter().zip(targets).filter_map(|(d, t)| t.map(|t| 1.0 - d.dot(&t).powi(2))).sum()
        })
    };
    let step = std::f64::consts::PI / SAMPLES as f64;
    let (best, _) = (1..SAMPLES).map(|s| (s as f64 * step, misfit(s as f64 * step))).fold((f64::NAN, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
    if best.is_nan() {
        return None;
    }
    let (mut low, mut high) = (best - step, best + step);
    let ratio = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..REFINEMENTS {
        let (a, b) = (high - ratio * (high - low), low + ratio * (high - low));
        if misfit(a) < misfit(b) {
            high = b;
        } else {
            low = a;
        }
    }
    let refined = 0.5 * (low + high);
    if misfit(refined) <= misfit(best) { member(refined) } else { member(best) }
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
