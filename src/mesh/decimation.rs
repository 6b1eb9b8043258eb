//! A coarser mesh of the same surface: shortest-edge-first half-edge collapses.
//!
//! Used where a decision about a surface does not depend on its resolution, such as which start
//! leads the level sets to the asked family (`crate::initialisation::StartSearch`): made on a mesh
//! of a few thousand vertices it costs the same for any input. Every kept vertex keeps its
//! position, so the coarse mesh interpolates the fine one.
//!
//! A collapse of the halfedge u → v removes u, hands its faces to v and deletes the one or two
//! faces on the edge. It is made only when
//! - the *link condition* holds (the vertices adjacent to both u and v are exactly the apexes of
//!   the faces on the edge), so the mesh stays a manifold of the same topology;
//! - u is interior, or u and v are neighbours along the boundary and the boundary turns at u by
//!   at most [`MAX_BOUNDARY_TURN_DEGREES`] (boundary corners and the outline's shape stay);
//! - every face u hands to v has a shape quality `4√3·A / Σ l²` (1 for an equilateral triangle)
//!   of at least [`MIN_TRIANGLE_QUALITY`] and a normal within [`MAX_NORMAL_DEVIATION_DEGREES`]
//!   of the input's vertex normals at its corners (no fold-overs, no drift from the surface).
//!
//! Edges are visited shortest first (ties by vertex indices), so the result is deterministic
//! and its edge lengths even out; of an edge's two halfedges the one leaving the better worst
//! face is collapsed.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::{MeshError, TriMesh, Vec3};

/// Largest turn of the boundary (degrees) at a boundary vertex that may be removed.
pub const MAX_BOUNDARY_TURN_DEGREES: f64 = 10.0;
/// Smallest shape quality `4√3·A / Σ l²` of a face made by a collapse.
pub const MIN_TRIANGLE_QUALITY: f64 = 0.3;
/// Largest angle (degrees) between a face made by a collapse and the input's vertex normals at
/// its corners.
pub const MAX_NORMAL_DEVIATION_DEGREES: f64 = 25.0;

/// `mesh` coarsened to at most `target_vertices` vertices where the rules above allow (fewer
/// collapses otherwise); a copy of `mesh` when it has no more vertices than that.
/// Errors: the coarse mesh fails [`TriMesh`] validation (not expected; reported, not hidden).
pub fn coarsened(mesh: &TriMesh, target_vertices: usize) -> Result<TriMesh, MeshError> {
    let mut state = Collapses::new(mesh);
    let mut queue = BinaryHeap::new();
    for &[a, b] in mesh.edges() {
        queue.push(state.entry(a, b));
    }
    let mut remaining = mesh.vertex_count();
    while remaining > target_vertices {
        let Some(Reverse((_, a, b))) = queue.pop() else {
            break;
        };
        let best =
            [(a, b), (b, a)].into_iter().filter_map(|(u, v)| state.collapse_quality(u, v).map(|q| (q, u, v))).max_by(|x, y| x.0.total_cmp(&y.0));
        if let Some((_, u, v)) = best {
            for [p, q] in state.collapse(u, v) {
                queue.push(state.entry(p, q));
            }
            remaining -= 1;
        }
    }
    state.into_mesh()
}

/// Ordering key of an edge: its length (the bits of a non-negative f64 order like its value),
/// then its vertices.
type EdgeKey = Reverse<(u64, u32, u32)>;

/// The mesh while it is being coarsened.
struct Collapses<'a> {
    positions: &'a [Vec3],
    normals: &'a [Vec3],
    faces: Vec<[u32; 3]>,
    face_alive: Vec<bool>,
    /// Alive faces around each vertex.
    vertex_faces: Vec<Vec<u32>>,
    removed: Vec<bool>,
    /// For boundary vertices, the previous and next vertex along their boundary loop.
    boundary_neighbours: Vec<Option<[u32; 2]>>,
    min_normal_cosine: f64,
}

impl<'a> Collapses<'a> {
    fn new(mesh: &'a TriMesh) -> Collapses<'a> {
        let faces = mesh.faces().to_vec();
        let mut vertex_faces = vec![Vec::new(); mesh.vertex_count()];
        for (f, face) in faces.iter().enumerate() {
            for &v in face {
                vertex_faces[v as usize].push(f as u32);
            }
        }
        let mut boundary_neighbours = vec![None; mesh.vertex_count()];
        for boundary_loop in mesh.boundary_loops() {
            let n = boundary_loop.len();
            for (i, &v) in boundary_loop.iter().enumerate() {
                boundary_neighbours[v as usize] = Some([boundary_loop[(i + n - 1) % n], boundary_loop[(i + 1) % n]]);
            }
        }
        Collapses {
            positions: mesh.positions(),
            normals: mesh.vertex_normals(),
            face_alive: vec![true; faces.len()],
            faces,
            vertex_faces,
            removed: vec![false; mesh.vertex_count()],
            boundary_neighbours,
            min_normal_cosine: MAX_NORMAL_DEVIATION_DEGREES.to_radians().cos(),
        }
    }

    fn entry(&self, a: u32, b: u32) -> EdgeKey {
        let length = (self.positions[a as usize] - self.positions[b as usize]).norm();
        Reverse((length.to_bits(), a.min(b), a.max(b)))
    }

    /// Vertices adjacent to `v` (sorted, without repeats).
    fn neighbours(&self, v: u32) -> Vec<u32> {
        let mut around: Vec<u32> = self.vertex_faces[v as usize].iter().flat_map(|&f| self.faces[f as usize]).filter(|&w| w != v).collect();
        around.sort_unstable();
        around.dedup();
        around
    }

    /// The worst shape quality of the faces the collapse u → v would make, or `None` when the
    /// collapse is not allowed (see the module documentation).
    fn collapse_quality(&self, u: u32, v: u32) -> Option<f64> {
        if self.removed[u as usize] || self.removed[v as usize] {
            return None;
        }
        let on_edge: Vec<u32> = self.vertex_faces[u as usize].iter().copied().filter(|&f| self.faces[f as usize].contains(&v)).collect();
        if on_edge.is_empty() {
            return None;
        }
        if let Some([previous, next]) = self.boundary_neighbours[u as usize] {
            if v != previous && v != next {
                return None;
            }
            let (p, q, r) = (self.positions[previous as usize], self.positions[u as usize], self.positions[next as usize]);
            if turn_degrees(q - p, r - q) > MAX_BOUNDARY_TURN_DEGREES {
                return None;
            }
        }
        let mut apexes: Vec<u32> = on_edge.iter().flat_map(|&f| self.faces[f as usize]).filter(|&w| w != u && w != v).collect();
        apexes.sort_unstable();
        let (around_u, around_v) = (self.neighbours(u), self.neighbours(v));
        let common: Vec<u32> = around_u.iter().copied().filter(|w| around_v.binary_search(w).is_ok()).collect();
        if common != apexes {
            return None;
        }
        let mut worst = f64::INFINITY;
        for &f in &self.vertex_faces[u as usize] {
            let face = self.faces[f as usize];
            if face.contains(&v) {
                continue;
            }
            let moved = face.map(|w| if w == u { v } else { w });
            let [a, b, c] = moved.map(|w| self.positions[w as usize]);
            let cross = (b - a).cross(&(c - a));
            let area = 0.5 * cross.norm();
            let squares = (b - a).norm_squared() + (c - b).norm_squared() + (a - c).norm_squared();
            let quality = 4.0 * 3f64.sqrt() * area / squares;
            // A degenerate face (zero squares: NaN quality) is refused with the thin ones.
            if quality.is_nan() || quality < MIN_TRIANGLE_QUALITY {
                return None;
            }
            let normal = cross / (2.0 * area);
            if moved.iter().any(|&w| normal.dot(&self.normals[w as usize]) < self.min_normal_cosine) {
                return None;
            }
            worst = worst.min(quality);
        }
        Some(worst)
    }

    /// Collapses u → v (allowed, see [`Self::collapse_quality`]); returns the edges whose
    /// collapse may have become possible or changed: those of the faces now around v.
    fn collapse(&mut self, u: u32, v: u32) -> Vec<[u32; 2]> {
        let faces_of_u = std::mem::take(&mut self.vertex_faces[u as usize]);
        for f in faces_of_u {
            let face = &mut self.faces[f as usize];
            if face.contains(&v) {
                self.face_alive[f as usize] = false;
                for w in *face {
                    if w != u {
                        self.vertex_faces[w as usize].retain(|&g| g != f);
                    }
                }
            } else {
                for w in face.iter_mut() {
                    if *w == u {
                        *w = v;
                    }
                }
                self.vertex_faces[v as usize].push(f);
            }
        }
        self.vertex_faces[v as usize].sort_unstable();
        self.removed[u as usize] = true;
        if let Some([previous, next]) = self.boundary_neighbours[u as usize].take() {
            // The boundary now runs other → v (or v → other) where it ran through u.
            let other = if v == next { previous } else { next };
            self.replace_boundary_neighbour(v, u, other);
            self.replace_boundary_neighbour(other, u, v);
        }
        self.vertex_faces[v as usize]
            .iter()
            .flat_map(|&f| {
                let [a, b, c] = self.faces[f as usize];
                [[a, b], [b, c], [c, a]]
            })
            .collect()
    }

    fn replace_boundary_neighbour(&mut self, vertex: u32, from: u32, to: u32) {
        if let Some(pair) = &mut self.boundary_neighbours[vertex as usize] {
            for w in pair.iter_mut().filter(|w| **w == from) {
                *w = to;
            }
        }
    }

    fn into_mesh(self) -> Result<TriMesh, MeshError> {
        let mut index = vec![u32::MAX; self.positions.len()];
        let mut positions = Vec::new();
        for (v, p) in self.positions.iter().enumerate() {
            if !self.removed[v] {
                index[v] = positions.len() as u32;
                positions.push(*p);
            }
        }
        let faces = self.faces.iter().zip(&self.face_alive).filter(|(_, &alive)| alive).map(|(face, _)| face.map(|w| index[w as usize])).collect();
        TriMesh::from_vertices_and_faces(positions, faces)
    }
}

/// Turn angle (degrees) between consecutive boundary edge vectors.
fn turn_degrees(incoming: Vec3, outgoing: Vec3) -> f64 {
    incoming.angle(&outgoing).to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surfaces::hall_roof;

    #[test]
    fn a_mesh_at_or_below_the_target_is_unchanged() {
        let mesh = hall_roof(600).into_mesh().unwrap();
        let coarse = coarsened(&mesh, 10_000).unwrap();
        assert_eq!(coarse.positions(), mesh.positions());
        assert_eq!(coarse.faces(), mesh.faces());
    }
}
