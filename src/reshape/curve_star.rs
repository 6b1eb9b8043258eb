//! The level curve through a vertex as the surface optimisation sees it (Sec. 3.3, Fig. 7):
//! with F fixed at the vertices, the star edges the curve crosses and the crossing parameters
//! depend on F alone, so `p = (1 − t₁) v₁ + t₁ v₂` and `q = (1 − t₂) v₃ + t₂ v₄` are re-found on
//! the moving mesh each iteration as these fixed combinations of its vertices.
//!
//! The angle rows are measured further out along the same curve: from `p` it enters the face
//! across `p`'s edge, leaves it on another edge, and so on, face by face, to the first crossing
//! `p⁺` about three edges from `v0` ([`ANGLE_CHORD_REACH`]), again a fixed combination (and
//! likewise `q⁺`). The binormal of the star chords alone, about one edge long, is met on the
//! cylinder of the tests by curves that miss θ by 10° and more at the scale of three edges
//! (straight polylines satisfy any angle there). The problem ([`super::problem`]) keeps rows on
//! the star chords too, so that the curve bends the same way at both scales. At the boundary
//! the walk stops at the last crossing before it (`p⁺ = p` if there is no face across `p`).

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
    /// `p⁺` and `q⁺`: the crossings of the curve about [`ANGLE_CHORD_REACH`] beyond `p` and `q`.
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
                let far = |e: Crossing| walk(mesh, &adjacency, field, v as u32, e);
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

/// How far from `v0` the crossings `p⁺`, `q⁺` of the angle rows lie, in mean edge lengths (the
/// optimisation's mesh has mean edge length 1): the scale at which the curves are judged
/// ([`crate::quality::DEFAULT_SPACING_EDGES`]). On the 60° → 45° cylinder of the tests the
/// curves then meet θ to 0.3° RMS at that scale; with the chords one face beyond the star
/// (about one edge), to 2.3°.
pub(crate) const ANGLE_CHORD_REACH: f64 = 3.0;

/// Most faces walked beyond the star to reach [`ANGLE_CHORD_REACH`].
const MAX_WALK_FACES: usize = 12;

/// Follows the level curve `F = F(v0)` outwards from the star crossing `start`, face by face,
/// to the first crossing at least [`ANGLE_CHORD_REACH`] from `v0` (at least one face beyond the
/// star; at most [`MAX_WALK_FACES`] faces), stopping early where the curve meets the boundary,
/// passes through a vertex or comes back to the star of `v0`.
fn walk(mesh: &TriMesh, adjacency: &EdgeFaces, field: &[f64], v0: u32, start: Crossing) -> Crossing {
    let positions = mesh.positions();
    let origin = positions[v0 as usize];
    let Some((first, second)) = adjacency.faces(start.a, start.b) else { return start };
    let star_face = [Some(first), second].into_iter().flatten().find(|&f| mesh.faces()[f as usize].contains(&v0));
    let Some(mut face) = star_face else { return start };
    let mut crossing = start;
    for _ in 0..MAX_WALK_FACES {
        let Some((next, next_face)) = beyond(mesh, adjacency, field, field[v0 as usize], crossing, face) else { break };
        if mesh.faces()[next_face as usize].contains(&v0) {
            break;
        }
        (crossing, face) = (next, next_face);
        if crossing.t == 0.0 || (crossing.point(positions) - origin).norm() >= ANGLE_CHORD_REACH {
            break;
        }
    }
    crossing
}

/// Where the level curve `F = f0` through `crossing`, entering the face across its edge from `face`,
/// leaves that face, and the face: on the edge from one end of `crossing`'s edge to the face's
/// third vertex whose values bracket the level (the half-open test of
/// [`crate::field::find_level_crossing`]). `None` at the boundary or if neither edge brackets it.
fn beyond(mesh: &TriMesh, adjacency: &EdgeFaces, field: &[f64], f0: f64, crossing: Crossing, face: u32) -> Option<(Crossing, u32)> {
    let next = adjacency.across(crossing.a, crossing.b, face)?;
    let c = *mesh.faces()[next as usize].iter().find(|&&w| w != crossing.a && w != crossing.b)?;
    [crossing.a, crossing.b].into_iter().find_map(|a| {
        let (fa, fc) = (field[a as usize], field[c as usize]);
        (fa != fc && f0 >= fa.min(fc) && f0 < fa.max(fc)).then(|| (Crossing { a, b: c, t: (f0 - fa) / (fc - fa) }, next))
    })
}
