//! Combinatorial structure of a triangle list: undirected edges with their halfedges,
//! manifoldness, orientation, connected components, boundary halfedges and boundary loops,
//! and the disk test of the paper (Sec. 7: a topological disk, possibly with holes).

use super::error::MeshError;
use super::union_find::UnionFind;

/// One boundary edge with its single face, oriented as in that face (`from → to` is a
/// halfedge of `face`, so the face lies to the left when looking along the surface normal).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BoundaryEdge {
    pub from: u32,
    pub to: u32,
    pub face: u32,
}

/// A directed edge `from → to` of face `face`, where `from` is at corner `corner`.
#[derive(Clone, Copy, Debug)]
struct HalfEdge {
    key: (u32, u32),
    face: u32,
    corner: u8,
    from: u32,
    to: u32,
}

impl HalfEdge {
    /// Corner index, within this halfedge's face, of vertex `v` (one of its endpoints).
    fn corner_of(&self, v: u32) -> usize {
        if v == self.from {
            self.corner as usize
        } else {
            (self.corner as usize + 1) % 3
        }
    }
}

/// All halfedges of a face list, grouped by undirected edge.
pub(crate) struct EdgeTable {
    /// Sorted by (edge key, face, corner): each undirected edge is one contiguous run.
    halfedges: Vec<HalfEdge>,
    /// Start of each run in `halfedges`, plus a final sentinel.
    run_starts: Vec<usize>,
}

impl EdgeTable {
    /// Builds the table from `(face index, corners)` pairs; corners must be in range and distinct.
    pub(crate) fn new<'a>(faces: impl Iterator<Item = (usize, &'a [u32; 3])>) -> EdgeTable {
        let mut halfedges = Vec::new();
        for (f, corners) in faces {
            for c in 0..3 {
                let (from, to) = (corners[c], corners[(c + 1) % 3]);
                halfedges.push(HalfEdge {
                    key: (from.min(to), from.max(to)),
                    face: f as u32,
                    corner: c as u8,
                    from,
                    to,
                });
            }
        }
        halfedges.sort_unstable_by_key(|h| (h.key, h.face, h.corner));
        let mut run_starts: Vec<usize> = (0..halfedges.len())
            .filter(|&i| i == 0 || halfedges[i - 1].key != halfedges[i].key)
            .collect();
        run_starts.push(halfedges.len());
        EdgeTable { halfedges, run_starts }
    }

    fn runs(&self) -> impl Iterator<Item = &[HalfEdge]> {
        self.run_starts.windows(2).map(|w| &self.halfedges[w[0]..w[1]])
    }

    /// The edges with two faces: `([a, b], face_a, face_b)`, `a < b`, the faces in index order,
    /// in edge order.
    pub(crate) fn interior_edges(&self) -> impl Iterator<Item = ([u32; 2], usize, usize)> + '_ {
        self.runs().filter(|run| run.len() == 2).map(|run| ([run[0].key.0, run[0].key.1], run[0].face as usize, run[1].face as usize))
    }

    /// Undirected edges `[a, b]` with `a < b`, sorted.
    pub(crate) fn edges(&self) -> Vec<[u32; 2]> {
        self.runs().map(|run| [run[0].key.0, run[0].key.1]).collect()
    }

    pub(crate) fn edge_count(&self) -> usize {
        self.run_starts.len() - 1
    }

    /// Edges with a single face, in edge order, oriented as in their face.
    pub(crate) fn boundary_edges(&self) -> Vec<BoundaryEdge> {
        self.runs()
            .filter(|run| run.len() == 1)
            .map(|run| BoundaryEdge { from: run[0].from, to: run[0].to, face: run[0].face })
            .collect()
    }

    /// Edges shared by more than two faces.
    pub(crate) fn non_manifold_edges(&self) -> Vec<MeshError> {
        self.runs()
            .filter(|run| run.len() > 2)
            .map(|run| MeshError::NonManifoldEdge {
                a: run[0].key.0,
                b: run[0].key.1,
                face_count: run.len(),
                face: run[2].face as usize,
            })
            .collect()
    }

    /// Pairs of faces that traverse their shared (two-face) edge in the same direction.
    pub(crate) fn orientation_conflicts(&self) -> Vec<MeshError> {
        self.runs()
            .filter(|run| run.len() == 2 && run[0].from == run[1].from)
            .map(|run| MeshError::InconsistentOrientation {
                face_a: run[0].face as usize,
                face_b: run[1].face as usize,
                from: run[0].from,
                to: run[0].to,
            })
            .collect()
    }

    /// Vertices whose faces do not form a single fan. Corners `3f + c` of faces sharing an
    /// edge are joined at both edge endpoints; a vertex is manifold iff its corners form one set.
    pub(crate) fn non_manifold_vertices(&self, face_count: usize) -> Vec<MeshError> {
        let mut sets = UnionFind::new(3 * face_count);
        for run in self.runs() {
            let first = &run[0];
            for other in &run[1..] {
                for v in [first.from, first.to] {
                    sets.union(
                        3 * first.face as usize + first.corner_of(v),
                        3 * other.face as usize + other.corner_of(v),
                    );
                }
            }
        }
        // (vertex, corner set) for every corner present in the table.
        let mut pairs: Vec<(u32, usize)> = self
            .halfedges
            .iter()
            .map(|h| (h.from, sets.find(3 * h.face as usize + h.corner as usize)))
            .collect();
        pairs.sort_unstable();
        pairs.dedup();
        let mut errors = Vec::new();
        let mut i = 0;
        while i < pairs.len() {
            let vertex = pairs[i].0;
            let fans = pairs[i..].iter().take_while(|p| p.0 == vertex).count();
            if fans > 1 {
                errors.push(MeshError::NonManifoldVertex { vertex: vertex as usize, fans });
            }
            i += fans;
        }
        errors
    }
}

/// Connected components of the vertices used by `faces`, each named by its smallest vertex,
/// in increasing order.
pub(crate) fn component_representatives<'a>(
    vertex_count: usize,
    faces: impl Iterator<Item = &'a [u32; 3]>,
) -> Vec<usize> {
    let mut sets = UnionFind::new(vertex_count);
    let mut used = vec![false; vertex_count];
    for face in faces {
        for c in 0..3 {
            used[face[c] as usize] = true;
            sets.union(face[c] as usize, face[(c + 1) % 3] as usize);
        }
    }
    let mut seen_root = vec![false; vertex_count];
    let mut representatives = Vec::new();
    for v in (0..vertex_count).filter(|&v| used[v]) {
        let root = sets.find(v);
        if !seen_root[root] {
            seen_root[root] = true;
            representatives.push(v);
        }
    }
    representatives
}

/// Boundary loops traced along the boundary halfedges (interior on the left), each starting
/// at its smallest vertex, in order of that vertex. Requires a manifold, consistently oriented
/// mesh (each vertex then has at most one outgoing boundary halfedge).
pub(crate) fn trace_boundary_loops(vertex_count: usize, boundary: &[BoundaryEdge]) -> Vec<Vec<u32>> {
    let mut next: Vec<Option<u32>> = vec![None; vertex_count];
    for e in boundary {
        next[e.from as usize] = Some(e.to);
    }
    let mut visited = vec![false; vertex_count];
    let mut loops = Vec::new();
    for start in 0..vertex_count {
        if visited[start] || next[start].is_none() {
            continue;
        }
        let mut cycle = Vec::new();
        let mut v = start;
        // Bounded walk: a valid boundary closes after at most `boundary.len()` steps.
        while !visited[v] && cycle.len() <= boundary.len() {
            visited[v] = true;
            cycle.push(v as u32);
            match next[v] {
                Some(w) => v = w as usize,
                None => break,
            }
        }
        loops.push(cycle);
    }
    loops
}

/// The disk test of Sec. 7: at least one boundary loop and V − E + F = 2 − loops.
pub(crate) fn disk_check(
    vertex_count: usize,
    edge_count: usize,
    face_count: usize,
    loop_count: usize,
) -> Result<(), MeshError> {
    let chi = vertex_count as i64 - edge_count as i64 + face_count as i64;
    if loop_count >= 1 && chi == 2 - loop_count as i64 {
        Ok(())
    } else {
        Err(MeshError::NotDisk { euler_characteristic: chi, boundary_loops: loop_count })
    }
}
