//! Extraction of level sets of the piecewise-linear field (Sec. 3.4): every triangle the level
//! crosses contributes one segment between two of its edges; segments sharing an edge are chained
//! into polylines, open ones from boundary edge to boundary edge first, then closed loops.
//!
//! Vertices are classified by the half-open test `F ≥ level` (as in [`crate::field::find_level_crossing`]),
//! so a triangle is crossed on exactly zero or two edges and ties are settled deterministically;
//! a level through a vertex yields two coincident crossings, merged afterwards.

use super::levels::field_range;
use super::{CurveError, LevelCurve};
use crate::field::find_level_crossing;
use crate::mesh::{TriMesh, Vec3};

/// Crossings closer than this fraction of the mean edge length are merged (a level through a vertex).
const MERGE: f64 = 1e-9;
/// Marks an edge or face without a crossing.
const NONE: u32 = u32::MAX;

/// The level curves of `field` (one value per vertex) at each of `levels`, level by level, each
/// level's pieces in a deterministic order. Every level must lie in `[min F, max F]`; at most
/// [`super::MAX_LEVELS`] levels.
/// Pieces that collapse to a single point are dropped.
pub fn extract_level_curves(mesh: &TriMesh, field: &[f64], levels: &[f64]) -> Result<Vec<LevelCurve>, CurveError> {
    let (min, max) = field_range(mesh, field)?;
    if levels.is_empty() {
        return Err(CurveError::NoLevels);
    }
    if levels.len() > super::MAX_LEVELS {
        return Err(CurveError::TooManyLevels { count: levels.len() });
    }
    for (index, &level) in levels.iter().enumerate() {
        if !level.is_finite() {
            return Err(CurveError::NonFiniteLevel { index });
        }
        if level < min || level > max {
            return Err(CurveError::LevelOutOfRange { level, min, max });
        }
    }
    let singular: Vec<bool> = (0..mesh.vertex_count())
        .map(|v| !mesh.is_boundary_vertex(v) && find_level_crossing(mesh, field, v).is_none())
        .collect();
    let face_edges = face_edge_indices(mesh);
    let mut curves = Vec::new();
    for &level in levels {
        let slicer = LevelSlicer::new(mesh, field, level, &face_edges);
        curves.extend(slicer.chains().into_iter().filter_map(|chain| slicer.curve(&chain, &singular)));
    }
    Ok(curves)
}

/// Index (into `mesh.edges()`) of the edge opposite each corner's successor: edge `k` of face
/// `[a, b, c]` joins corners `k` and `k + 1`.
fn face_edge_indices(mesh: &TriMesh) -> Vec<[u32; 3]> {
    let edges = mesh.edges();
    let index = |a: u32, b: u32| {
        let key = [a.min(b), a.max(b)];
        // Every face edge is a mesh edge (validated mesh), and `edges` is sorted.
        edges.binary_search(&key).map_or(NONE, |i| i as u32)
    };
    mesh.faces().iter().map(|f| [index(f[0], f[1]), index(f[1], f[2]), index(f[2], f[0])]).collect()
}

/// A chain of crossed faces, with the crossed edges between and around them.
struct Chain {
    /// Crossed edges in order; `edges.len() == faces.len() + 1` for open chains.
    edges: Vec<u32>,
    faces: Vec<u32>,
    closed: bool,
}

/// The crossings of one level.
struct LevelSlicer<'a> {
    mesh: &'a TriMesh,
    field: &'a [f64],
    level: f64,
    /// The two crossed edges of each face (`[NONE, NONE]` if not crossed).
    face_crossings: Vec<[u32; 2]>,
    /// The (at most two) crossed faces on each edge.
    edge_faces: Vec<[u32; 2]>,
}

impl<'a> LevelSlicer<'a> {
    fn new(mesh: &'a TriMesh, field: &'a [f64], level: f64, face_edges: &[[u32; 3]]) -> Self {
        let above = |v: u32| field[v as usize] >= level;
        let mut face_crossings = vec![[NONE; 2]; mesh.face_count()];
        let mut edge_faces = vec![[NONE; 2]; mesh.edges().len()];
        for (f, face) in mesh.faces().iter().enumerate() {
            let mut crossed = Vec::with_capacity(2);
            for k in 0..3 {
                if above(face[k]) != above(face[(k + 1) % 3]) {
                    crossed.push(face_edges[f][k]);
                }
            }
            // A binary classification of three corners changes sign on zero or two edges.
            if let [e0, e1] = crossed[..] {
                face_crossings[f] = [e0, e1];
                for e in [e0, e1] {
                    let slot = &mut edge_faces[e as usize];
                    let free = if slot[0] == NONE { 0 } else { 1 };
                    slot[free] = f as u32;
                }
            }
        }
        LevelSlicer { mesh, field, level, face_crossings, edge_faces }
    }

    /// Open chains (starting at boundary edges, in edge order), then closed loops (in face order).
    fn chains(&self) -> Vec<Chain> {
        let mut visited = vec![false; self.face_crossings.len()];
        let mut chains = Vec::new();
        for (e, faces) in self.edge_faces.iter().enumerate() {
            if faces[0] != NONE && faces[1] == NONE && !visited[faces[0] as usize] {
                chains.push(self.walk(e as u32, faces[0], &mut visited));
            }
        }
        for f in 0..self.face_crossings.len() {
            if self.face_crossings[f][0] != NONE && !visited[f] {
                chains.push(self.walk(self.face_crossings[f][0], f as u32, &mut visited));
            }
        }
        chains
    }

    /// Walks from crossed edge `edge` into face `face` until the boundary or back to the start.
    fn walk(&self, edge: u32, face: u32, visited: &mut [bool]) -> Chain {
        let mut chain = Chain { edges: vec![edge], faces: Vec::new(), closed: false };
        let (mut edge, mut face) = (edge, face);
        loop {
            visited[face as usize] = true;
            chain.faces.push(face);
            let [a, b] = self.face_crossings[face as usize];
            edge = if a == edge { b } else { a };
            let [f0, f1] = self.edge_faces[edge as usize];
            let next = if f0 == face { f1 } else { f0 };
            if next != NONE && visited[next as usize] {
                chain.closed = edge == chain.edges[0];
                if !chain.closed {
                    chain.edges.push(edge);
                }
                return chain;
            }
            chain.edges.push(edge);
            if next == NONE {
                return chain;
            }
            face = next;
        }
    }

    /// Point and unit normal where the level crosses edge `e`.
    fn crossing(&self, e: u32) -> (Vec3, Vec3) {
        let [a, b] = self.mesh.edges()[e as usize];
        let (fa, fb) = (self.field[a as usize], self.field[b as usize]);
        // Crossed edges have values on both sides of the level, so fa != fb.
        let t = ((self.level - fa) / (fb - fa)).clamp(0.0, 1.0);
        let (pa, pb) = (self.mesh.positions()[a as usize], self.mesh.positions()[b as usize]);
        let (na, nb) = (self.mesh.smooth_normals()[a as usize], self.mesh.smooth_normals()[b as usize]);
        (pa + (pb - pa) * t, (na + (nb - na) * t).try_normalize(0.0).unwrap_or(na))
    }

    /// `∇F × n` of face `f`: the direction level curves run in.
    fn running_direction(&self, f: u32) -> Vec3 {
        let face = self.mesh.faces()[f as usize];
        let operators = self.mesh.face_gradients(f as usize);
        let gradient: Vec3 = (0..3).map(|k| operators[k] * self.field[face[k] as usize]).sum();
        gradient.cross(&self.mesh.face_normals()[f as usize])
    }

    /// The polyline of a chain, oriented along `∇F × n`, with coincident crossings merged.
    fn curve(&self, chain: &Chain, singular: &[bool]) -> Option<LevelCurve> {
        let crossings: Vec<(Vec3, Vec3)> = chain.edges.iter().map(|&e| self.crossing(e)).collect();
        let along: f64 = chain
            .faces
            .iter()
            .enumerate()
            .map(|(k, &f)| {
                let (a, b) = (crossings[k].0, crossings[(k + 1) % crossings.len()].0);
                (b - a).dot(&self.running_direction(f))
            })
            .sum();
        let tolerance = MERGE * self.mesh.mean_edge_length();
        let mut points: Vec<Vec3> = Vec::with_capacity(crossings.len());
        let mut normals: Vec<Vec3> = Vec::with_capacity(crossings.len());
        for (p, n) in crossings {
            if points.last().is_some_and(|q| (p - q).norm() <= tolerance) {
                continue;
            }
            points.push(p);
            normals.push(n);
        }
        if chain.closed && points.len() > 1 && (points[0] - points[points.len() - 1]).norm() <= tolerance {
            points.pop();
            normals.pop();
        }
        if points.len() < 2 {
            return None;
        }
        if along < 0.0 {
            points.reverse();
            normals.reverse();
        }
        let mut singular_vertices: Vec<u32> = chain
            .faces
            .iter()
            .flat_map(|&f| self.mesh.faces()[f as usize])
            .filter(|&v| singular[v as usize])
            .collect();
        singular_vertices.sort_unstable();
        singular_vertices.dedup();
        Some(LevelCurve { level: self.level, points, normals, closed: chain.closed, singular_vertices })
    }
}
