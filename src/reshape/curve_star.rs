//! The level curve through a vertex as the surface optimisation sees it (Sec. 3.3, Fig. 7):
//! with F fixed at the vertices, the star edges the curve crosses and the crossing parameters
//! depend on F alone, so `p = (1 − t₁) v₁ + t₁ v₂` and `q = (1 − t₂) v₃ + t₂ v₄` are re-found on
//! the moving mesh each iteration as these fixed combinations of its vertices.

use crate::field::find_level_crossing;
use crate::mesh::{TriMesh, Vec3};

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
}

impl CurveStar {
    /// The curve vertices of `field` on `mesh` (the interior vertices whose level curve crosses
    /// exactly two star edges), in increasing order.
    pub fn all(mesh: &TriMesh, field: &[f64]) -> Vec<CurveStar> {
        (0..mesh.vertex_count())
            .filter_map(|v| {
                let crossing = find_level_crossing(mesh, field, v)?;
                let c = |e: crate::field::EdgeCrossing| Crossing { a: e.a, b: e.b, t: e.t };
                Some(CurveStar { vertex: v as u32, p: c(crossing.p), q: c(crossing.q) })
            })
            .collect()
    }

    /// The distinct vertices the star's rows depend on: `v0`, then the crossing edges' ends.
    pub fn vertices(&self) -> Vec<u32> {
        let mut vertices = vec![self.vertex];
        for w in [self.p.a, self.p.b, self.q.a, self.q.b] {
            if !vertices.contains(&w) {
                vertices.push(w);
            }
        }
        vertices
    }

    /// `e_p = v0 − p`.
    pub fn to_p(&self) -> Combination {
        [(self.vertex, 1.0), (self.p.a, self.p.t - 1.0), (self.p.b, -self.p.t), (self.vertex, 0.0)]
    }

    /// `e_q = v0 − q`.
    pub fn to_q(&self) -> Combination {
        [(self.vertex, 1.0), (self.q.a, self.q.t - 1.0), (self.q.b, -self.q.t), (self.vertex, 0.0)]
    }

    /// `q − p`, along the curve.
    pub fn tangent(&self) -> Combination {
        [(self.q.a, 1.0 - self.q.t), (self.q.b, self.q.t), (self.p.a, self.p.t - 1.0), (self.p.b, -self.p.t)]
    }
}

/// The value of `combination` at the positions `x` (xyz per vertex).
pub(crate) fn combine(combination: &Combination, x: &[f64]) -> Vec3 {
    combination.iter().fold(Vec3::zeros(), |sum, &(w, c)| {
        let i = 3 * w as usize;
        sum + Vec3::new(x[i], x[i + 1], x[i + 2]) * c
    })
}
