//! Where the next point is searched (Fig. 13): the edges of the triangle across the current
//! edge and, near a vertex, the edges opposite that vertex in its whole one-ring.

use crate::mesh::{EdgeFaces, EdgePoint, TriMesh};

/// An edge `[a, b]` (`a < b`) on which the next point may lie, with the face whose interior the
/// segment to it crosses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CandidateEdge {
    pub edge: [u32; 2],
    pub face: u32,
}

/// The candidate edges around `point` (canonical, on a mesh edge), excluding the face the
/// curve arrived through (`None` at the start point):
/// * the other two edges of each face of the current edge except `arrived`, i.e. the triangle
///   across the edge (the start point's boundary face);
/// * if `point` is within `vertex_ratio` of an end vertex `v`, also the edge opposite `v` in
///   every face of its one-ring except `arrived` (the widened search of the authors' code, so
///   a curve passing close to a vertex does not stall in its thin wedges).
///
/// Each edge appears once, with the first face that reached it, in a deterministic order.
pub(crate) fn candidate_edges(
    mesh: &TriMesh,
    adjacency: &EdgeFaces,
    point: &EdgePoint,
    arrived: Option<u32>,
    vertex_ratio: f64,
) -> Vec<CandidateEdge> {
    let [a, b] = point.edge;
    let mut candidates: Vec<CandidateEdge> = Vec::new();
    let mut push = |edge: [u32; 2], face: u32| {
        let edge = [edge[0].min(edge[1]), edge[0].max(edge[1])];
        if edge != point.edge && !candidates.iter().any(|c| c.edge == edge) {
            candidates.push(CandidateEdge { edge, face });
        }
    };
    let faces = mesh.faces();
    if let Some((first, second)) = adjacency.faces(a, b) {
        for f in [Some(first), second].into_iter().flatten().filter(|&f| Some(f) != arrived) {
            // Internal invariant: adjacency faces index the mesh's faces.
            let corners = faces[f as usize];
            for c in 0..3 {
                push([corners[c], corners[(c + 1) % 3]], f);
            }
        }
    }
    let near = if point.t <= vertex_ratio {
        Some(a)
    } else if point.t >= 1.0 - vertex_ratio {
        Some(b)
    } else {
        None
    };
    if let Some(v) = near {
        // Internal invariant: `v` is a validated vertex index.
        for &f in mesh.star(v as usize).faces.iter().filter(|&&f| Some(f) != arrived) {
            let corners = faces[f as usize];
            // The corner order within the face is irrelevant: take the two corners that are not v.
            let others: Vec<u32> = corners.iter().copied().filter(|&c| c != v).collect();
            if let [x, y] = others[..] {
                push([x, y], f);
            }
        }
    }
    candidates
}
