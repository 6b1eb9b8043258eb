//! Ordered one-ring stars of the vertices (the vertex star of Fig. 7), stored in flat
//! CSR-style arrays.

/// One-ring of a vertex, counter-clockwise about the normal (i.e. following the face winding):
/// face `faces[k]` has corners (v, neighbours[k], neighbours[(k+1) % neighbours.len()]) in
/// winding order. Interior vertex: closed, `faces.len() == neighbours.len()`. Boundary vertex:
/// open, starts at the boundary neighbour whose edge has its face on the CCW side,
/// `faces.len() == neighbours.len() - 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VertexStar<'a> {
    pub neighbours: &'a [u32],
    pub faces: &'a [u32],
    pub closed: bool,
}

/// All stars: the neighbours of vertex v are `neighbours[neighbour_start[v]..neighbour_start[v+1]]`,
/// its faces `faces[face_start[v]..face_start[v+1]]`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Stars {
    neighbour_start: Vec<usize>,
    neighbours: Vec<u32>,
    face_start: Vec<usize>,
    faces: Vec<u32>,
}

/// A face seen from one of its corners v: (v, next, prev) in winding order.
#[derive(Clone, Copy)]
struct Wedge {
    next: u32,
    prev: u32,
    face: u32,
}

impl Stars {
    /// Builds the stars of a validated (manifold, consistently oriented) mesh.
    /// `boundary_next[v]` is the target of the boundary halfedge leaving v, if any.
    pub(crate) fn new(vertex_count: usize, faces: &[[u32; 3]], boundary_next: &[Option<u32>]) -> Stars {
        // Wedges grouped by vertex (CSR), each group sorted by `next` for binary search.
        let mut wedge_start = vec![0usize; vertex_count + 1];
        for face in faces {
            for &v in face {
                wedge_start[v as usize + 1] += 1;
            }
        }
        for v in 0..vertex_count {
            wedge_start[v + 1] += wedge_start[v];
        }
        let mut fill = wedge_start.clone();
        let mut wedges = vec![Wedge { next: 0, prev: 0, face: 0 }; 3 * faces.len()];
        for (f, face) in faces.iter().enumerate() {
            for c in 0..3 {
                let v = face[c] as usize;
                wedges[fill[v]] = Wedge { next: face[(c + 1) % 3], prev: face[(c + 2) % 3], face: f as u32 };
                fill[v] += 1;
            }
        }
        let mut stars = Stars {
            neighbour_start: Vec::with_capacity(vertex_count + 1),
            neighbours: Vec::with_capacity(3 * faces.len() + vertex_count),
            face_start: Vec::with_capacity(vertex_count + 1),
            faces: Vec::with_capacity(3 * faces.len()),
        };
        stars.neighbour_start.push(0);
        stars.face_start.push(0);
        for v in 0..vertex_count {
            let group = &mut wedges[wedge_start[v]..wedge_start[v + 1]];
            group.sort_unstable_by_key(|w| w.next);
            stars.push_star(group, boundary_next[v]);
        }
        stars
    }

    /// Walks one fan: from wedge (v, a, b) to the wedge (v, b, c) until it closes or ends.
    fn push_star(&mut self, group: &[Wedge], boundary_next: Option<u32>) {
        let find = |next: u32| group.binary_search_by_key(&next, |w| w.next).ok();
        // Internal invariant: on a validated mesh the boundary neighbour starts a wedge, and
        // every vertex has at least one wedge (no isolated vertices).
        let start = match boundary_next {
            Some(n) => find(n).expect("boundary halfedge belongs to a face"),
            None => 0,
        };
        let mut k = start;
        for _ in 0..group.len() {
            let wedge = group[k];
            self.neighbours.push(wedge.next);
            self.faces.push(wedge.face);
            match find(wedge.prev) {
                Some(next) if next != start => k = next,
                Some(_) => break,
                None => {
                    self.neighbours.push(wedge.prev);
                    break;
                }
            }
        }
        self.neighbour_start.push(self.neighbours.len());
        self.face_start.push(self.faces.len());
    }

    /// The star of vertex `v` (`v` < vertex count).
    pub(crate) fn get(&self, v: usize) -> VertexStar<'_> {
        let neighbours = &self.neighbours[self.neighbour_start[v]..self.neighbour_start[v + 1]];
        let faces = &self.faces[self.face_start[v]..self.face_start[v + 1]];
        VertexStar { neighbours, faces, closed: neighbours.len() == faces.len() }
    }
}
