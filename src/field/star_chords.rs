//! The chords of the level polyline `p → v0 → q` through a vertex star, with their
//! derivatives with respect to the field values of the star (paper Fig. 7, Eq. 9–10, 13).
//!
//! The crossing point `p = a + t (b − a)`, `t = (F0 − Fa)/(Fb − Fa)`, moves along its edge
//! when the field changes:
//! `∂t/∂F0 = 1/(Fb − Fa)`, `∂t/∂Fa = −(1 − t)/(Fb − Fa)`, `∂t/∂Fb = −t/(Fb − Fa)`.
//! Field columns are local to the star: column 0 is the centre `v0`, column `1 + k`
//! its `k`-th ring neighbour.

use super::crossing::{find_level_crossing, EdgeCrossing, LevelCrossing};
use crate::mesh::{TriMesh, Vec3};

/// Most field columns a chord depends on: the centre and the two ends of both crossed edges.
const MAX_PARTIALS: usize = 6;

/// A vector-valued function of the star's field values: its value and sparse partials
/// `∂w/∂F_col` (a column may repeat; partials are meant to be accumulated).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FieldVector {
    pub value: Vec3,
    partials: [(usize, Vec3); MAX_PARTIALS],
    count: usize,
}

impl FieldVector {
    fn constant(value: Vec3) -> Self {
        FieldVector { value, partials: [(0, Vec3::zeros()); MAX_PARTIALS], count: 0 }
    }

    fn partials(&self) -> &[(usize, Vec3)] {
        &self.partials[..self.count]
    }

    /// `self − other`; the partial lists are concatenated (at most six entries in all uses here).
    fn minus(&self, other: &FieldVector) -> FieldVector {
        let mut out = FieldVector::constant(self.value - other.value);
        for &(col, d) in self.partials() {
            out.push(col, d);
        }
        for &(col, d) in other.partials() {
            out.push(col, -d);
        }
        out
    }

    fn push(&mut self, col: usize, d: Vec3) {
        // Invariant: callers combine at most two crossing points (3 partials each).
        self.partials[self.count] = (col, d);
        self.count += 1;
    }

    /// Accumulates `scale · ∂(c · ŵ)/∂F` into `row` (indexed by field column), where
    /// `ŵ = w/‖w‖` and `c` is held fixed: `∂(c·ŵ) = (c − (c·ŵ)ŵ) · ∂w / ‖w‖`.
    pub fn add_normalized_dot_partials(&self, c: &Vec3, scale: f64, row: &mut [f64]) {
        let norm = self.value.norm();
        let unit = self.value / norm;
        let projected = (c - unit * c.dot(&unit)) * (scale / norm);
        for &(col, d) in self.partials() {
            row[col] += projected.dot(&d);
        }
    }

    /// The unit vector `w/‖w‖`.
    pub fn unit(&self) -> Vec3 {
        self.value / self.value.norm()
    }
}

/// The three chords at a regular vertex: `e_p = v0 − p`, `e_q = v0 − q`, and the tangent `q − p`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StarChords {
    pub to_p: FieldVector,
    pub to_q: FieldVector,
    pub tangent: FieldVector,
}

/// Shortest chord, relative to the star's mean edge, below which a crossing is too close to
/// `v0` (or `p` to `q`) for a meaningful direction; such a vertex is treated as singular.
const DEGENERATE_CHORD: f64 = 1e-9;

impl StarChords {
    /// The chords of vertex `v`; `None` at boundary and singular vertices (Fig. 7) and where a
    /// chord degenerates.
    pub fn at_vertex(mesh: &TriMesh, field: &[f64], v: usize) -> Option<Self> {
        StarChords::new(mesh, field, v, &find_level_crossing(mesh, field, v)?)
    }

    /// Builds the chords of vertex `v` for a known crossing; `None` when a chord degenerates.
    pub fn new(mesh: &TriMesh, field: &[f64], v: usize, crossing: &LevelCrossing) -> Option<Self> {
        let v0 = FieldVector::constant(mesh.positions()[v]);
        let ring_len = mesh.star(v).neighbours.len();
        let p = crossing_point(mesh, field, ring_len, &crossing.p);
        let q = crossing_point(mesh, field, ring_len, &crossing.q);
        let chords = StarChords { to_p: v0.minus(&p), to_q: v0.minus(&q), tangent: q.minus(&p) };
        let scale = mesh.mean_edge_length() * DEGENERATE_CHORD;
        let shortest = chords.to_p.value.norm().min(chords.to_q.value.norm()).min(chords.tangent.value.norm());
        (shortest > scale).then_some(chords)
    }
}

fn crossing_point(mesh: &TriMesh, field: &[f64], ring_len: usize, c: &EdgeCrossing) -> FieldVector {
    let pa = mesh.positions()[c.a as usize];
    let pb = mesh.positions()[c.b as usize];
    let edge = pb - pa;
    let denominator = field[c.b as usize] - field[c.a as usize];
    let mut point = FieldVector::constant(pa + edge * c.t);
    let col_a = 1 + c.slot;
    let col_b = 1 + (c.slot + 1) % ring_len;
    point.push(0, edge / denominator);
    point.push(col_a, edge * (-(1.0 - c.t) / denominator));
    point.push(col_b, edge * (-c.t / denominator));
    point
}

/// Zeroes a block's residuals and Jacobian (singular vertices keep zero rows) and returns the
/// chords of vertex `v`, if it is regular.
pub(crate) fn clear_rows_at_vertex(
    mesh: &TriMesh,
    field: &[f64],
    v: usize,
    residuals: &mut [f64],
    jacobian: &mut Option<&mut [f64]>,
) -> Option<StarChords> {
    residuals.fill(0.0);
    if let Some(j) = jacobian.as_deref_mut() {
        j.fill(0.0);
    }
    StarChords::at_vertex(mesh, field, v)
}
