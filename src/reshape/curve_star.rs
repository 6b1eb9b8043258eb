//! The level curve through a vertex as the surface optimisation sees it (Sec. 3.3, Fig. 7):
//! with F fixed at the vertices, the star edges the curve crosses and the crossing parameters
//! depend on F alone, so `p = (1 − t₁) v₁ + t₁ v₂` and `q = (1 − t₂) v₃ + t₂ v₄` are re-found on
//! the moving mesh each iteration as these fixed combinations of its vertices.
//!
//! The angle rows are measured one face further out: where the curve leaves the star at `p`
//! it enters the face across `p`'s edge and leaves it at `p⁺`, again a fixed combination (and
//! likewise `q⁺`). The binormal of the star chords alone, about one edge long, is met on the
//! cylinder of the tests by curves that miss θ by 10° and more at the scale of three edges
//! (straight polylines satisfy any angle there); the chords to `p⁺` and `q⁺` span about two
//! edges on each side. At the boundary (no face across) `p⁺ = p`.

use crate::field::find_level_crossing;
use crate::mesh::{EdgeFaces, TriMesh, Vec3};

/// A crossing point `a + t (b − a)` of the level curve with a star edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Crossing {
    pub a: u32,
    pub b: u32,
    pub t: f64,
}

impl Crossing {
    pub fn point(&self, positions: &[Vec3]) -> Vec3 {
        let (pa, pb) = (positions[self.a as usize], positions[self.b as usize]);
        pa + (pb - pa) * self.t
    }
}

/// A linear combination `Σ c_i x_{w_i}` of vertex positions: (vertex, coefficient) terms.
pub(crate) type Combination = [(u32, f64); 4];

/// A regular interior vertex `v0` of the field with the crossings `p` and `q` of its level curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CurveStar {
    pub vertex: u32,
    pub p: Crossing,
    pub q: Crossing,
    /// `p⁺` and `q⁺`: where the curve leaves the faces across `p`'s and `q`'s edges.
    pub far_p: Crossing,
    pub far_q: Crossing,
}

impl CurveStar {
    /// The curve vertices of `field` on `mesh` (the interior vertices whose level curve crosses
    /// exactly two star edges), in increasing order.
    pub fn all(mesh: &TriMesh, field: &[f64]) -> Vec<CurveStar> {
        let adjacency = EdgeFaces::new(mesh);
        (0..mesh.vertex_count())
            .filter_map(|v| {
                let crossing = find_level_crossing(mesh, field, v)?;
                let c = |e: crate::field::EdgeCrossing| Crossing { a: e.a, b: e.b, t: e.t };
                let (p, q) = (c(crossing.p), c(crossing.q));
                let far = |e: Crossing| beyond(mesh, &adjacency, field, v as u32, e).unwrap_or(e);
                Some(CurveStar { vertex: v as u32, p, q, far_p: far(p), far_q: far(q) })
            })
            .collect()
    }

    /// The distinct vertices the star's rows depend on: `v0`, then the crossing edges' ends.
    pub fn vertices(&self) -> Vec<u32> {
        let mut vertices = vec![self.vertex];
        let (p, q, far_p, far_q) = (self.p, self.q, self.far_p, self.far_q);
        for w in [p.a, p.b, q.a, q.b, far_p.a, far_p.b, far_q.a, far_q.b] {
            if !vertices.contains(&w) {
                vertices.push(w);
            }
        }
        vertices
    }

    /// `v0 − p` for the crossing `p` (`p`, `q`, `p⁺` or `q⁺`).
    pub fn from(&self, p: &Crossing) -> Combination {
        [(self.vertex, 1.0), (p.a, p.t - 1.0), (p.b, -p.t), (self.vertex, 0.0)]
    }

    /// `q⁺ − p⁺`, along the curve.
    pub fn tangent(&self) -> Combination {
        let (p, q) = (self.far_p, self.far_q);
        [(q.a, 1.0 - q.t), (q.b, q.t), (p.a, p.t - 1.0), (p.b, -p.t)]
    }
}

/// The value of `combination` at the positions `x` (xyz per vertex).
pub(crate) fn combine(combination: &Combination, x: &[f64]) -> Vec3 {
    combination.iter().fold(Vec3::zeros(), |sum, &(w, c)| {
        let i = 3 * w as usize;
        sum + Vec3::new(x[i], x[i + 1], x[i + 2]) * c
    })
}

/// Where the level curve `F = F(v0)`, entering the face across the star edge of `crossing`
/// (the face without `v0`), leaves it: on the edge from one end of `crossing`'s edge to the
/// face's third vertex whose values bracket `F(v0)` (the half-open test of
/// [`crate::field::find_level_crossing`]). `None` at the boundary or if neither edge brackets it.
fn beyond(mesh: &TriMesh, adjacency: &EdgeFaces, field: &[f64], v0: u32, crossing: Crossing) -> Option<Crossing> {
    let (first, second) = adjacency.faces(crossing.a, crossing.b)?;
    let face = [Some(first), second].into_iter().flatten().find(|&f| !mesh.faces()[f as usize].contains(&v0))?;
    let c = *mesh.faces()[face as usize].iter().find(|&&w| w != crossing.a && w != crossing.b)?;
    let f0 = field[v0 as usize];
    [crossing.a, crossing.b].into_iter().find_map(|a| {
        let (fa, fc) = (field[a as usize], field[c as usize]);
        (fa != fc && f0 >= fa.min(fc) && f0 < fa.max(fc)).then(|| Crossing { a, b: c, t: (f0 - fa) / (fc - fa) })
    })
}
