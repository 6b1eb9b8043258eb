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

/// How a crossing point `a + t (b − a)` depends on the star's field values: columns 0 (the
/// centre), `col_a` and `col_b` (the ends of its edge).
#[derive(Clone, Copy, Debug)]
struct PointPartials {
    edge: Vec3,
    /// `Fb − Fa`.
    denominator: f64,
    t: f64,
    col_a: usize,
    col_b: usize,
}

impl PointPartials {
    /// `(column, ∂point/∂F_column)` for the centre and both edge ends.
    fn partials(&self) -> [(usize, Vec3); 3] {
        [
            (0, self.edge / self.denominator),
            (self.col_a, self.edge * (-(1.0 - self.t) / self.denominator)),
            (self.col_b, self.edge * (-self.t / self.denominator)),
        ]
    }
}

/// A crossing point of the level curve with its dependence on the field.
#[derive(Clone, Copy, Debug)]
struct CrossingPoint {
    position: Vec3,
    partials: PointPartials,
}

/// A chord `from − to` between two points of the star as a function of the star's field values:
/// its value and, derived on demand, its partials `∂w/∂F_col` (the end `to` is always a crossing
/// point; `from` is a crossing point too or the fixed centre vertex).
#[derive(Clone, Copy, Debug)]
pub(crate) struct FieldVector {
    pub value: Vec3,
    from: Option<PointPartials>,
    to: PointPartials,
}

impl FieldVector {
    /// `from − to` for the fixed point `from` (the centre vertex) and a crossing point `to`.
    fn from_fixed(from: Vec3, to: &CrossingPoint) -> Self {
        FieldVector { value: from - to.position, from: None, to: to.partials }
    }

    /// `from − to` for two crossing points.
    fn between(from: &CrossingPoint, to: &CrossingPoint) -> Self {
        FieldVector { value: from.position - to.position, from: Some(from.partials), to: to.partials }
    }

    /// Accumulates `scale · ∂(c · ŵ)/∂F` into `row` (indexed by field column), where
    /// `ŵ = w/‖w‖` and `c` is held fixed: `∂(c·ŵ) = (c − (c·ŵ)ŵ) · ∂w / ‖w‖`. A column may
    /// receive several contributions (those of `from`, then those of `to`).
    pub fn add_normalized_dot_partials(&self, c: &Vec3, scale: f64, row: &mut [f64]) {
        let norm = self.value.norm();
        let unit = self.value / norm;
        let projected = (c - unit * c.dot(&unit)) * (scale / norm);
        for (col, d) in self.from.iter().flat_map(PointPartials::partials) {
            row[col] += projected.dot(&d);
        }
        for (col, d) in self.to.partials() {
            row[col] += projected.dot(&-d);
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
        let v0 = mesh.positions()[v];
        let ring_len = mesh.star(v).neighbours.len();
        let p = crossing_point(mesh, field, ring_len, &crossing.p);
        let q = crossing_point(mesh, field, ring_len, &crossing.q);
        let chords = StarChords {
            to_p: FieldVector::from_fixed(v0, &p),
            to_q: FieldVector::from_fixed(v0, &q),
            tangent: FieldVector::between(&q, &p),
        };
        let scale = mesh.mean_edge_length() * DEGENERATE_CHORD;
        let shortest = chords.to_p.value.norm().min(chords.to_q.value.norm()).min(chords.tangent.value.norm());
        (shortest > scale).then_some(chords)
    }
}

fn crossing_point(mesh: &TriMesh, field: &[f64], ring_len: usize, c: &EdgeCrossing) -> CrossingPoint {
    let pa = mesh.positions()[c.a as usize];
    let pb = mesh.positions()[c.b as usize];
    let edge = pb - pa;
    let partials = PointPartials {
        edge,
        denominator: field[c.b as usize] - field[c.a as usize],
        t: c.t,
        col_a: 1 + c.slot,
        col_b: 1 + (c.slot + 1) % ring_len,
    };
    CrossingPoint { position: pa + edge * c.t, partials }
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
