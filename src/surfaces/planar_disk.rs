//! An irregular triangulation of a planar disk, the flat reference case: affine functions on it
//! must have zero fairness energy (Eq. 6), boundary vertices included.

use super::random::SplitMix64;
use super::{irregularity, positive, GeneratedSurface, SurfaceError};
use crate::mesh::Vec3;
use std::f64::consts::{PI, TAU};

/// Parameters of [`planar_disk`].
#[derive(Debug, Clone, PartialEq)]
pub struct PlanarPatch {
    /// Disk radius > 0.
    pub radius: f64,
    /// Approximate number of vertices (rounded to whole rings).
    pub target_vertices: usize,
    /// Jitter of the points as a fraction of the ring spacing, in `[0, MAX_IRREGULARITY]`.
    pub irregularity: f64,
    pub seed: u64,
}

/// The disk `x² + y² ≤ radius²` in the plane `z = 0`, centred at the origin.
///
/// Vertices: the centre plus `m` concentric rings, ring `k` with `6k` points at radius `k·h`
/// (`h = radius / m`), each ring rotated by a random angle. Points of the inner rings are
/// displaced radially and along the ring by up to `±irregularity / 2 · h`; points of the outer
/// ring only along the boundary circle, so it stays exact. Consecutive rings are zipped together
/// by advancing along whichever ring has the next smaller polar angle. `m` is chosen so that
/// `1 + 3m(m + 1)` is closest to `target_vertices`. Faces are counter-clockwise seen from `+z`
/// (normals `+z`).
pub fn planar_disk(patch: &PlanarPatch) -> Result<GeneratedSurface, SurfaceError> {
    let radius = positive("radius", patch.radius)?;
    let irregularity = irregularity(patch.irregularity)?;
    let rings = ring_count(patch.target_vertices);
    let spacing = radius / rings as f64;
    let mut rng = SplitMix64::new(patch.seed);

    let mut positions = vec![Vec3::zeros()];
    // Polar angles of the points of the previous ring, in counter-clockwise order.
    let mut previous_ring: Vec<(u32, f64)> = vec![(0, 0.0)];
    let mut faces = Vec::with_capacity(6 * rings * rings);
    for k in 1..=rings {
        let count = 6 * k;
        let ring_radius = k as f64 * spacing;
        let rotation = rng.next_f64() * TAU / count as f64;
        let mut ring = Vec::with_capacity(count);
        for j in 0..count {
            let along = rng.symmetric(0.5 * irregularity * spacing);
            let r = if k < rings { ring_radius + rng.symmetric(0.5 * irregularity * spacing) } else { ring_radius };
            let angle = rotation + TAU * j as f64 / count as f64 + along / ring_radius;
            ring.push((positions.len() as u32, angle));
            positions.push(Vec3::new(r * angle.cos(), r * angle.sin(), 0.0));
        }
        zip_rings(&previous_ring, &ring, &mut faces);
        previous_ring = ring;
    }
    Ok(GeneratedSurface { positions, faces })
}

/// The number of rings `m ≥ 1` with `1 + 3m(m + 1)` closest to `target_vertices`.
fn ring_count(target_vertices: usize) -> usize {
    let vertices = |m: usize| 1 + 3 * m * (m + 1);
    let mut m = 1;
    while vertices(m + 1) <= target_vertices {
        m += 1;
    }
    if vertices(m + 1) - target_vertices < target_vertices.saturating_sub(vertices(m)) {
        m + 1
    } else {
        m
    }
}

/// Triangulates the annulus between two rings of `(vertex, polar angle)` points listed
/// counter-clockwise with strictly increasing angles spanning less than one turn. The inner ring
/// may be the single centre vertex (then the result is a fan).
fn zip_rings(inner: &[(u32, f64)], outer: &[(u32, f64)], faces: &mut Vec<[u32; 3]>) {
    let (Some(&(_, reference)), false) = (inner.first(), outer.is_empty()) else {
        return;
    };
    // Start the outer ring at the point angularly closest to the first inner point.
    let outer_start = (0..outer.len())
        .min_by(|&a, &b| signed_angle(outer[a].1 - reference).abs().total_cmp(&signed_angle(outer[b].1 - reference).abs()))
        .unwrap_or(0);
    // Angles unwrapped counter-clockwise from each ring's start; step `len` is the start again.
    let inner_angle = |n: usize| ccw_offset(inner[n % inner.len()].1, reference, n == inner.len());
    let outer_angle = |n: usize| {
        let start = outer[outer_start].1;
        let offset = ccw_offset(outer[(outer_start + n) % outer.len()].1, start, n == outer.len());
        signed_angle(start - reference) + offset
    };
    let inner_vertex = |n: usize| inner[n % inner.len()].0;
    let outer_vertex = |n: usize| outer[(outer_start + n) % outer.len()].0;
    // A single centre vertex never advances.
    let inner_steps = if inner.len() == 1 { 0 } else { inner.len() };
    let (mut i, mut o) = (0, 0);
    while i < inner_steps || o < outer.len() {
        let advance_inner = o == outer.len() || (i < inner_steps && inner_angle(i + 1) < outer_angle(o + 1));
        if advance_inner {
            faces.push([inner_vertex(i), outer_vertex(o), inner_vertex(i + 1)]);
            i += 1;
        } else {
            faces.push([inner_vertex(i), outer_vertex(o), outer_vertex(o + 1)]);
            o += 1;
        }
    }
}

/// The counter-clockwise angle from `from` to `angle` in `[0, 2π)`, or `2π` for a full turn.
fn ccw_offset(angle: f64, from: f64, full_turn: bool) -> f64 {
    if full_turn {
        TAU
    } else {
        (angle - from).rem_euclid(TAU)
    }
}

/// `angle` wrapped to `[−π, π)`.
fn signed_angle(angle: f64) -> f64 {
    (angle + PI).rem_euclid(TAU) - PI
}
