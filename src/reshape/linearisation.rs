//! What the surface optimisation (Sec. 3.3) freezes for one iteration and recomputes on the
//! moved mesh after every step: the mesh's normals, areas and fairness operator, the lengths of
//! the chords of each curve vertex ([`super::curve_star`]), and the closest
//! point `v*` of every vertex on the original surface with its normal `n*` (Eq. 14).

use super::curve_star::CurveStar;
use crate::field::hessian_energy::HessianEnergy;
use crate::mesh::{FaceBvh, TriMesh, Vec3};
use rayon::prelude::*;

/// The original surface `S` of Eq. 14 with its closest-point hierarchy.
pub(crate) struct Original {
    pub mesh: TriMesh,
    bvh: FaceBvh,
}

/// The closest point `v*` of a point on the original surface and the normal `n*` there
/// (interpolated from the original vertex normals).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Anchor {
    pub point: Vec3,
    pub normal: Vec3,
    pub distance: f64,
}

impl Original {
    pub fn new(mesh: TriMesh) -> Original {
        Original { bvh: FaceBvh::new(&mesh), mesh }
    }

    /// The closest point of `query` on the original surface. The queries are the finite
    /// vertices of a valid mesh, which always have one.
    pub fn anchor(&self, query: &Vec3) -> Anchor {
        let closest = self.bvh.closest(&self.mesh, query);
        let Some(closest) = closest else {
            return Anchor { point: *query, normal: Vec3::zeros(), distance: 0.0 };
        };
        let corners = self.mesh.faces()[closest.face];
        let (mut point, mut normal) = (Vec3::zeros(), Vec3::zeros());
        for (&c, w) in corners.iter().zip(closest.weights) {
            point += self.mesh.positions()[c as usize] * w;
            normal += self.mesh.vertex_normals()[c as usize] * w;
        }
        let normal = normal.try_normalize(0.0).unwrap_or(self.mesh.face_normals()[closest.face]);
        Anchor { point, normal, distance: closest.distance }
    }

    /// [`Self::anchor`] of every point (in parallel, deterministic).
    pub fn anchors(&self, points: &[Vec3]) -> Vec<Anchor> {
        points.par_iter().map(|p| self.anchor(p)).collect()
    }
}

/// Lengths of the chords of one curve vertex, frozen for an iteration.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ChordLengths {
    /// `‖v0 − p‖`, `‖v0 − q‖` (for `E^S_c`), `‖v0 − p⁺‖`, `‖v0 − q⁺‖`, `‖q⁺ − p⁺‖` (for `E_angle`).
    pub to_p: f64,
    pub to_q: f64,
    pub to_far_p: f64,
    pub to_far_q: f64,
    pub tangent: f64,
}

/// The frozen quantities of one iteration, at the current positions.
pub(crate) struct Linearisation {
    pub mesh: TriMesh,
    pub hessian: HessianEnergy,
    /// Surface normal per vertex: the normal of its local quadric, the normal the outside
    /// measure ([`crate::quality`]) judges the curves against.
    pub normals: Vec<Vec3>,
    /// Per curve vertex: its smooth normal minus the unit vector area of its one-ring
    /// ([`ring_area_vector`], normalised). The angle rows use that unit vector at the moving
    /// positions plus this offset: the smooth normal at the positions of this iteration, changing
    /// to first order as the ring normal does.
    pub normal_offsets: Vec<Vec3>,
    pub chords: Vec<ChordLengths>,
    pub anchors: Vec<Anchor>,
}

/// Chords shorter than this (in mean edge lengths) are taken at this length: keeps the frozen
/// normalisations finite.
const MIN_CHORD: f64 = 1e-9;

impl Linearisation {
    pub fn new(mesh: TriMesh, curves: &[CurveStar], original: &Original) -> Linearisation {
        let positions = mesh.positions();
        let chords = curves
            .iter()
            .map(|c| {
                let v0 = positions[c.vertex as usize];
                let [p, q, far_p, far_q] = [c.p, c.q, c.far_p, c.far_q].map(|e| e.point(positions));
                let length = |d: Vec3| d.norm().max(MIN_CHORD);
                ChordLengths { to_p: length(v0 - p), to_q: length(v0 - q), to_far_p: length(v0 - far_p), to_far_q: length(v0 - far_q), tangent: length(far_q - far_p) }
            })
            .collect();
        let anchors = original.anchors(positions);
        let normals = mesh.smooth_normals().to_vec();
        let normal_offsets = curves
            .iter()
            .map(|c| {
                let v0 = c.vertex as usize;
                let ring = mesh.star(v0).neighbours.iter().map(|&w| positions[w as usize]);
                normals[v0] - ring_area_vector(ring).try_normalize(0.0).unwrap_or_else(Vec3::zeros)
            })
            .collect();
        Linearisation { hessian: HessianEnergy::new(&mesh), normals, normal_offsets, chords, anchors, mesh }
    }
}

/// The vector area `m = ½ Σ_k x_k × x_{k+1}` of a closed one-ring polygon (its neighbours in
/// counter-clockwise order); `m / ‖m‖` is the ring normal, independent of the centre vertex.
pub(crate) fn ring_area_vector(ring: impl Iterator<Item = Vec3> + Clone) -> Vec3 {
    let next = ring.clone().cycle().skip(1);
    ring.zip(next).fold(Vec3::zeros(), |m, (a, b)| m + a.cross(&b)) * 0.5
}
