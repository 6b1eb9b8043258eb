//! Node and strip diagnostics of Sec. 5.1 per vertex of a strip's central polyline: how far the
//! binormals (the usual node axes) are from the rulings of the rectifying developable, and where
//! the developable's singular points lie.
//!
//! From the discrete curvature `κ` and torsion `τ`:
//! * the conical curvature `k = τ/κ` and the angle `atan |k|` between the binormal `b` and the
//!   Darboux vector `d = τ t + κ b`, the ruling of the rectifying developable `D`;
//! * by Prop. 2 (Eq. 20), a point at distance `v` from the curve on the binormal lies about
//!   `|κ| k² v² / 2` from `D`, evaluated at half the strip width;
//! * the singular point `c + v_r d` of the ruling, `v_r = −1/(κ k′)` (`k′ = dk/ds`), lies at the
//!   distance `|v_r| ‖d‖` from the curve along the ruling; it should stay well outside the strip.
//!
//! `κ` is that of the circle through three consecutive vertices; `τ` the rotation of the
//! discrete binormal (Eq. 1) about the edge between two vertices per edge length (signed, the
//! Frenet `b′ = −τ n`), averaged over the two edges of a vertex; `k′` a central difference of `k`
//! over arc length. The strip's own discrete binormal and ruling give the measured angle.

use super::frenet::{discrete_binormals, unit_edges};
use crate::mesh::Vec3;

/// Below this curvature (1/length) a vertex counts as straight: `k` and the quantities built on
/// it are undefined there.
const STRAIGHT_CURVATURE: f64 = 1e-9;

/// The singular point of a ruling counts as near the strip within this many strip widths of its
/// boundary (or inside it).
pub const SINGULAR_POINT_CLEARANCE_WIDTHS: f64 = 1.0;

/// The Sec. 5.1 quantities at one vertex of a strip's central polyline; `None` where undefined
/// (end vertices, straight pieces, a torsion or `k′` that cannot be differenced).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct VertexDiagnostics {
    /// Curvature `κ ≥ 0`.
    pub curvature: Option<f64>,
    /// Torsion `τ` (signed).
    pub torsion: Option<f64>,
    /// Conical curvature `k = τ/κ`.
    pub conical_curvature: Option<f64>,
    /// Angle `atan |k|` in degrees between binormal and Darboux vector (the ruling of `D`).
    pub darboux_angle_degrees: Option<f64>,
    /// Angle in degrees between the strip's binormal and its ruling at the vertex (the discrete
    /// counterpart of the previous one, measured on the strip).
    pub binormal_ruling_degrees: Option<f64>,
    /// `|κ| k² v² / 2` at `v` = half the strip width: the distance from `D` of the binormal
    /// point at the strip's edge (Prop. 2).
    pub binormal_offset: Option<f64>,
    /// `|v_r| ‖d‖`, the distance along the ruling from the curve to the ruling's singular point;
    /// `None` where `k′ = 0` (it is at infinity).
    pub singular_point_distance: Option<f64>,
    /// The singular point lies inside the strip or within
    /// [`SINGULAR_POINT_CLEARANCE_WIDTHS`] strip widths of its boundary.
    pub singular_point_near: bool,
}

/// The diagnostics of every vertex of the central polyline `centre` of a strip of `width`, whose
/// binormals and rulings (one per vertex, as [`super::RectifyingStrip`] holds them) give the
/// measured angle and the strip's extent along each ruling.
pub fn strip_diagnostics(centre: &[Vec3], binormals: &[Vec3], rulings: &[Vec3], width: f64) -> Vec<VertexDiagnostics> {
    let n = centre.len();
    let edges = unit_edges(centre);
    let lengths: Vec<f64> = centre.windows(2).map(|w| (w[1] - w[0]).norm()).collect();
    let frenet = discrete_binormals(centre);
    let curvature: Vec<Option<f64>> = (0..n).map(|i| circle_curvature(centre, i)).collect();
    // Torsion per edge i (between vertices i and i + 1).
    let edge_torsion: Vec<Option<f64>> = (0..n.saturating_sub(1))
        .map(|i| {
            let (a, b) = (frenet[i]?, frenet[i + 1]?);
            let angle = a.cross(&b).dot(&edges[i]).atan2(a.dot(&b));
            (lengths[i] > 0.0).then(|| angle / lengths[i])
        })
        .collect();
    let torsion: Vec<Option<f64>> = (0..n)
        .map(|i| {
            let before = i.checked_sub(1).and_then(|e| edge_torsion[e]);
            let after = edge_torsion.get(i).copied().flatten();
            match (before, after) {
                (Some(a), Some(b)) => Some(0.5 * (a + b)),
                (one, other) => one.or(other),
            }
        })
        .collect();
    let conical: Vec<Option<f64>> = (0..n)
        .map(|i| {
            let kappa = curvature[i].filter(|&k| k > STRAIGHT_CURVATURE)?;
            Some(torsion[i]? / kappa)
        })
        .collect();
    let half_width = 0.5 * width;
    (0..n)
        .map(|i| {
            let mut d = VertexDiagnostics { curvature: curvature[i], torsion: torsion[i], conical_curvature: conical[i], ..VertexDiagnostics::default() };
            if let (Some(b), Some(r)) = (binormals.get(i), rulings.get(i)) {
                d.binormal_ruling_degrees = b.try_normalize(0.0).zip(r.try_normalize(0.0)).map(|(b, r)| b.dot(&r).clamp(-1.0, 1.0).acos().to_degrees());
            }
            let (Some(kappa), Some(k)) = (curvature[i], conical[i]) else { return d };
            d.darboux_angle_degrees = Some(k.abs().atan().to_degrees());
            d.binormal_offset = Some(kappa * k * k * half_width * half_width / 2.0);
            if let Some(derivative) = conical_derivative(centre, &conical, i).filter(|k_s| *k_s != 0.0) {
                let tau = torsion[i].unwrap_or(0.0);
                let distance = (tau * tau + kappa * kappa).sqrt() / (kappa * derivative).abs();
                d.singular_point_distance = distance.is_finite().then_some(distance);
                // The strip reaches `width / (2 sin α)` along the ruling, α its angle with the curve.
                let extent = ruling_extent(&edges, rulings, i, half_width);
                d.singular_point_near = d.singular_point_distance.is_some_and(|s| s <= extent + SINGULAR_POINT_CLEARANCE_WIDTHS * width);
            }
            d
        })
        .collect()
}

/// Curvature of the circle through vertices `i − 1, i, i + 1` (`4 · area / product of sides`).
fn circle_curvature(points: &[Vec3], i: usize) -> Option<f64> {
    let (a, b, c) = (points[i.checked_sub(1)?], points[i], *points.get(i + 1)?);
    let sides = (b - a).norm() * (c - b).norm() * (c - a).norm();
    (sides > 0.0).then(|| 2.0 * (b - a).cross(&(c - b)).norm() / sides)
}

/// `dk/ds` at vertex `i` by a central difference over the neighbours' arc length (one-sided
/// where a neighbour has no `k`).
fn conical_derivative(points: &[Vec3], conical: &[Option<f64>], i: usize) -> Option<f64> {
    let k = |j: usize| conical.get(j).copied().flatten();
    let (before, after) = (i.checked_sub(1).filter(|&j| k(j).is_some()), Some(i + 1).filter(|&j| k(j).is_some()));
    let (from, to) = match (before, after) {
        (Some(a), Some(b)) => (a, b),
        (Some(a), None) => (a, i),
        (None, Some(b)) => (i, b),
        (None, None) => return None,
    };
    let arc: f64 = points[from..=to].windows(2).map(|w| (w[1] - w[0]).norm()).sum();
    let change = k(to)? - k(from)?;
    (arc > 0.0).then(|| change / arc)
}

/// How far the strip reaches along the ruling at vertex `i`: `half_width / sin α`, `α` the angle
/// between the ruling and the polyline's tangent (the bisector of its edges).
fn ruling_extent(edges: &[Vec3], rulings: &[Vec3], i: usize, half_width: f64) -> f64 {
    let tangent = match (i.checked_sub(1).and_then(|e| edges.get(e)), edges.get(i)) {
        (Some(a), Some(b)) => a + b,
        (Some(a), None) | (None, Some(a)) => *a,
        (None, None) => return half_width,
    };
    let (Some(t), Some(r)) = (tangent.try_normalize(0.0), rulings.get(i).and_then(|r| r.try_normalize(0.0))) else { return half_width };
    let sine = t.cross(&r).norm();
    if sine > 1e-6 {
        half_width / sine
    } else {
        half_width
    }
}
