//! A bounding-volume hierarchy over the faces of a mesh: closest-point queries in logarithmic
//! rather than linear time (the strips project every centre point onto the surface in every
//! round).

use super::{closest_barycentric, TriMesh, Vec3};

/// Faces per leaf at most.
const LEAF_FACES: usize = 4;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Aabb {
    low: Vec3,
    high: Vec3,
}

impl Aabb {
    fn empty() -> Aabb {
        Aabb { low: Vec3::repeat(f64::INFINITY), high: Vec3::repeat(f64::NEG_INFINITY) }
    }

    fn grow(&mut self, p: &Vec3) {
        self.low = self.low.inf(p);
        self.high = self.high.sup(p);
    }

    fn merge(&mut self, other: &Aabb) {
        self.grow(&other.low);
        self.grow(&other.high);
    }

    /// Squared distance from `p` to the box (0 inside).
    fn distance_squared(&self, p: &Vec3) -> f64 {
        let d = (self.low - p).sup(&Vec3::zeros()).sup(&(p - self.high));
        d.norm_squared()
    }
}

/// A node: an inner node's children are `first` and `second`; a leaf's faces are
/// `order[first..second]`.
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    first: usize,
    second: usize,
    leaf: bool,
}

/// The closest point of a mesh to a query: face, barycentric weights and distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosestFace {
    pub face: usize,
    pub weights: [f64; 3],
    pub distance: f64,
}

/// The hierarchy over one mesh's faces (built once; queries do not change it).
#[derive(Clone, Debug)]
pub struct FaceBvh {
    nodes: Vec<Node>,
    /// Faces in leaf order.
    order: Vec<usize>,
}

impl FaceBvh {
    /// Builds the hierarchy by recursive median splits along the longest axis of the face
    /// centroids' box (deterministic: ties by face index).
    pub fn new(mesh: &TriMesh) -> FaceBvh {
        let corners: Vec<[Vec3; 3]> = mesh.faces().iter().map(|f| f.map(|v| mesh.positions()[v as usize])).collect();
        FaceBvh::over_triangles(&corners)
    }

    /// The hierarchy over a triangle soup (`corners[f]` the corners of triangle `f`), for
    /// [`Self::ray_hits`] on geometry that is not one valid mesh (e.g. the strips of a pattern).
    pub fn over_triangles(corners: &[[Vec3; 3]]) -> FaceBvh {
        let boxes: Vec<Aabb> = corners
            .iter()
            .map(|f| {
                let mut b = Aabb::empty();
                f.iter().for_each(|p| b.grow(p));
                b
            })
            .collect();
        let centroids: Vec<Vec3> = boxes.iter().map(|b| (b.low + b.high) * 0.5).collect();
        let mut bvh = FaceBvh { nodes: Vec::new(), order: (0..boxes.len()).collect() };
        if !boxes.is_empty() {
            bvh.build(&boxes, &centroids, 0, boxes.len());
        }
        bvh
    }

    /// Builds the node over `order[start..end]` and returns its index.
    fn build(&mut self, boxes: &[Aabb], centroids: &[Vec3], start: usize, end: usize) -> usize {
        let mut bounds = Aabb::empty();
        let mut spread = Aabb::empty();
        for &f in &self.order[start..end] {
            bounds.merge(&boxes[f]);
            spread.grow(&centroids[f]);
        }
        let index = self.nodes.len();
        self.nodes.push(Node { bounds, first: start, second: end, leaf: true });
        if end - start <= LEAF_FACES {
            return index;
        }
        let axis = (spread.high - spread.low).iamax();
        let middle = start + (end - start) / 2;
        self.order[start..end].sort_by(|&a, &b| centroids[a][axis].total_cmp(&centroids[b][axis]).then(a.cmp(&b)));
        let first = self.build(boxes, centroids, start, middle);
        let second = self.build(boxes, centroids, middle, end);
        self.nodes[index] = Node { bounds, first, second, leaf: false };
        index
    }

    /// The closest point of `mesh` (the mesh the hierarchy was built on) to `query`; among faces
    /// at the same distance the lowest index. `None` for a non-finite query or an empty mesh.
    pub fn closest(&self, mesh: &TriMesh, query: &Vec3) -> Option<ClosestFace> {
        if self.nodes.is_empty() || !query.iter().all(|x| x.is_finite()) {
            return None;
        }
        let mut best: Option<ClosestFace> = None;
        let mut stack = vec![0usize];
        while let Some(n) = stack.pop() {
            let node = self.nodes[n];
            let bound = node.bounds.distance_squared(query);
            if best.is_some_and(|b| bound > b.distance * b.distance) {
                continue;
            }
            if node.leaf {
                for &f in &self.order[node.first..node.second] {
                    let corners = mesh.faces()[f].map(|v| mesh.positions()[v as usize]);
                    let weights = closest_barycentric(query, &corners);
                    let point = corners[0] * weights[0] + corners[1] * weights[1] + corners[2] * weights[2];
                    let distance = (query - point).norm();
                    if best.is_none_or(|b| distance < b.distance || (distance == b.distance && f < b.face)) {
                        best = Some(ClosestFace { face: f, weights, distance });
                    }
                }
                continue;
            }
            // Visit the nearer child first (pushed last).
            let (a, b) = (node.first, node.second);
            let (da, db) = (self.nodes[a].bounds.distance_squared(query), self.nodes[b].bounds.distance_squared(query));
            if da <= db {
                stack.push(b);
                stack.push(a);
            } else {
                stack.push(a);
                stack.push(b);
            }
        }
        best
    }

    /// Whether the ray `origin + s · direction`, `s > 0`, meets one of the triangles `corners`
    /// (those the hierarchy was built over, [`Self::over_triangles`]). Exact Möller–Trumbore
    /// tests; a ray through an edge or corner counts as a hit. `false` for a non-finite ray or a
    /// zero direction.
    pub fn ray_hits(&self, corners: &[[Vec3; 3]], origin: &Vec3, direction: &Vec3) -> bool {
        let finite = |v: &Vec3| v.iter().all(|x| x.is_finite());
        if self.nodes.is_empty() || !finite(origin) || !finite(direction) || direction.norm_squared() == 0.0 {
            return false;
        }
        let inverse = direction.map(|d| 1.0 / d);
        let mut stack = vec![0usize];
        while let Some(n) = stack.pop() {
            let node = self.nodes[n];
            if !node.bounds.meets_ray(origin, &inverse) {
                continue;
            }
            if !node.leaf {
                stack.push(node.second);
                stack.push(node.first);
                continue;
            }
            if self.order[node.first..node.second].iter().any(|&f| ray_meets_triangle(origin, direction, &corners[f])) {
                return true;
            }
        }
        false
    }
}

/// Möller–Trumbore: whether `origin + s · direction`, `s > 0`, meets the closed triangle.
fn ray_meets_triangle(origin: &Vec3, direction: &Vec3, [a, b, c]: &[Vec3; 3]) -> bool {
    let (e1, e2) = (b - a, c - a);
    let p = direction.cross(&e2);
    let det = e1.dot(&p);
    if det == 0.0 || !det.is_finite() {
        return false;
    }
    let s = origin - a;
    let u = s.dot(&p) / det;
    if !(0.0..=1.0).contains(&u) {
        return false;
    }
    let q = s.cross(&e1);
    let v = direction.dot(&q) / det;
    if v < 0.0 || u + v > 1.0 {
        return false;
    }
    e2.dot(&q) / det > 0.0
}

impl Aabb {
    /// Slab test: whether the ray `origin + s · d`, `s ≥ 0`, meets the box (`inverse` = 1/d
    /// componentwise, infinite for zero components).
    fn meets_ray(&self, origin: &Vec3, inverse: &Vec3) -> bool {
        let (mut near, mut far) = (0.0f64, f64::INFINITY);
        for k in 0..3 {
            let (t0, t1) = ((self.low[k] - origin[k]) * inverse[k], (self.high[k] - origin[k]) * inverse[k]);
            // 0 · ∞ (a ray in the slab's plane) is NaN: the slab does not limit the ray then.
            let (lo, hi) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
            if !lo.is_nan() {
                near = near.max(lo);
            }
            if !hi.is_nan() {
                far = far.min(hi);
            }
        }
        near <= far
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surfaces::{hall_roof, SplitMix64};

    #[test]
    fn the_hierarchy_finds_the_same_closest_point_as_a_scan_of_every_face() {
        let mesh = hall_roof(800).into_mesh().unwrap();
        let bvh = FaceBvh::new(&mesh);
        let mut rng = SplitMix64::new(3);
        for _ in 0..300 {
            let q = Vec3::new(rng.symmetric(25.0), rng.symmetric(15.0), rng.symmetric(10.0));
            let scan = (0..mesh.face_count())
                .map(|f| {
                    let corners = mesh.faces()[f].map(|v| mesh.positions()[v as usize]);
                    let w = closest_barycentric(&q, &corners);
                    ((q - (corners[0] * w[0] + corners[1] * w[1] + corners[2] * w[2])).norm(), f)
                })
                .fold((f64::INFINITY, 0), |best, c| if c.0 < best.0 { c } else { best });
            let found = bvh.closest(&mesh, &q).unwrap();
            assert_eq!(found.distance, scan.0);
            assert_eq!(found.face, scan.1);
        }
        assert!(bvh.closest(&mesh, &Vec3::new(f64::NAN, 0.0, 0.0)).is_none());
    }

    #[test]
    fn a_ray_hits_what_a_scan_of_every_triangle_hits() {
        let mesh = hall_roof(800).into_mesh().unwrap();
        let corners: Vec<[Vec3; 3]> = mesh.faces().iter().map(|f| f.map(|v| mesh.positions()[v as usize])).collect();
        let bvh = FaceBvh::over_triangles(&corners);
        let mut rng = SplitMix64::new(5);
        let mut hits = 0;
        for _ in 0..400 {
            let origin = Vec3::new(rng.symmetric(25.0), rng.symmetric(15.0), rng.symmetric(10.0));
            let direction = Vec3::new(rng.symmetric(1.0), rng.symmetric(1.0), rng.symmetric(1.0));
            let scan = corners.iter().any(|c| ray_meets_triangle(&origin, &direction, c));
            assert_eq!(bvh.ray_hits(&corners, &origin, &direction), scan);
            hits += scan as usize;
        }
        assert!(hits > 40 && hits < 360, "{hits} of 400 rays hit: the test should see both outcomes");
        // A ray straight down through the roof's top and a ray pointing away from it.
        let top = mesh.positions().iter().fold(Vec3::repeat(f64::NEG_INFINITY), |a, p| if p.z > a.z { *p } else { a });
        assert!(bvh.ray_hits(&corners, &(top + Vec3::new(0.01, 0.01, 5.0)), &-Vec3::z()));
        assert!(!bvh.ray_hits(&corners, &(top + Vec3::new(0.0, 0.0, 5.0)), &Vec3::z()));
    }
}
