//! Where the level curve through a vertex leaves its star (paper Fig. 7).
//!
//! For an interior vertex `v0` with value `F0`, the level curve `F = F0` crosses the
//! boundary of the vertex star in two points `p` and `q`. Walking the star's outer edges
//! counter-clockwise about the normal, an edge `a → b` whose values decrease (`Fa > Fb`)
//! carries `p`, one whose values increase carries `q`. The tangent `q − p` then points so
//! that the side vector `u = n × (q − p)` follows `+∇F`: this is the orientation of the
//! Darboux frame the signed angle of Eq. 3 relies on. Crossings use the half-open test
//! `min(Fa, Fb) ≤ F0 < max(Fa, Fb)`, which settles ties deterministically.
//! A vertex with any other number of crossings is *singular* and carries no angle term.

use crate::mesh::{TriMesh, Vec3};

/// One crossing of the level curve with an outer edge `a → b` of a vertex star.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeCrossing {
    /// Position of `a` in the star's neighbour list (the edge runs to the next neighbour).
    pub slot: usize,
    /// Vertex index of `a`.
    pub a: u32,
    /// Vertex index of `b`.
    pub b: u32,
    /// Crossing parameter `t = (F0 − Fa) / (Fb − Fa)` in `[0, 1)`; the point is `a + t (b − a)`.
    pub t: f64,
}

impl EdgeCrossing {
    /// The crossing point on the mesh.
    pub fn point(&self, mesh: &TriMesh) -> Vec3 {
        let pa = mesh.positions()[self.a as usize];
        let pb = mesh.positions()[self.b as usize];
        pa + (pb - pa) * self.t
    }
}

/// The two points where the level curve through a vertex leaves its star.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LevelCrossing {
    /// Crossing on the edge `v1 → v2` with `F1 > F2` (the curve enters here).
    pub p: EdgeCrossing,
    /// Crossing on the edge `v3 → v4` with `F4 > F3` (the curve leaves here).
    pub q: EdgeCrossing,
}

/// Finds `p` and `q` for vertex `v` (Fig. 7). Returns `None` for boundary vertices and for
/// singular vertices (the level curve does not cross exactly two star edges).
pub fn find_level_crossing(mesh: &TriMesh, field: &[f64], v: usize) -> Option<LevelCrossing> {
    let star = mesh.star(v);
    if !star.closed {
        return None;
    }
    let f0 = field[v];
    let ring = star.neighbours;
    let mut p = None;
    let mut q = None;
    for slot in 0..ring.len() {
        let a = ring[slot];
        let b = ring[(slot + 1) % ring.len()];
        let (fa, fb) = (field[a as usize], field[b as usize]);
        if fa == fb || f0 < fa.min(fb) || f0 >= fa.max(fb) {
            continue;
        }
        let crossing = EdgeCrossing { slot, a, b, t: (f0 - fa) / (fb - fa) };
        let target = if fa > fb { &mut p } else { &mut q };
        if target.replace(crossing).is_some() {
            return None;
        }
    }
    Some(LevelCrossing { p: p?, q: q? })
}
