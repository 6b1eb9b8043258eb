//! Edges, ordered vertex stars, boundary edges and boundary loops.

use crate::mesh_support;

use std::collections::BTreeSet;

use lamella::mesh::{TriMesh, Vec3};
use mesh_support::{grid, grid_with, mesh, tube};

/// Whether (a, b, c) is a cyclic rotation of `face`, i.e. the same face with the same winding.
fn same_winding(face: [u32; 3], a: u32, b: u32, c: u32) -> bool {
    (0..3).any(|r| [face[r], face[(r + 1) % 3], face[(r + 2) % 3]] == [a, b, c])
}

/// Checks the documented star invariants of every vertex against the face list.
fn check_stars(m: &TriMesh) {
    let boundary: BTreeSet<[u32; 2]> = m.boundary_edges().iter().map(|e| [e.from.min(e.to), e.from.max(e.to)]).collect();
    for v in 0..m.vertex_count() {
        let s = m.star(v);
        let n = s.neighbours;
        assert_eq!(s.closed, !m.is_boundary_vertex(v));
        assert_eq!(s.faces.len(), if s.closed { n.len() } else { n.len() - 1 });
        for (k, &f) in s.faces.iter().enumerate() {
            let face = m.faces()[f as usize];
            assert!(same_winding(face, v as u32, n[k], n[(k + 1) % n.len()]), "vertex {v} face {f}");
        }
        let incident: BTreeSet<u32> =
            (0..m.face_count() as u32).filter(|&f| m.faces()[f as usize].contains(&(v as u32))).collect();
        assert_eq!(s.faces.iter().copied().collect::<BTreeSet<_>>(), incident);
        assert_eq!(s.faces.len(), incident.len());
        let adjacent: BTreeSet<u32> = m
            .edges()
            .iter()
            .filter(|e| e.contains(&(v as u32)))
            .map(|e| if e[0] == v as u32 { e[1] } else { e[0] })
            .collect();
        assert_eq!(n.iter().copied().collect::<BTreeSet<_>>(), adjacent);
        assert_eq!(n.len(), adjacent.len());
        if !s.closed {
            let key = |a: u32, b: u32| [a.min(b), a.max(b)];
            assert!(boundary.contains(&key(v as u32, n[0])) && boundary.contains(&key(v as u32, n[n.len() - 1])));
        }
    }
}

#[test]
fn hand_built_fan() {
    // Hexagon around vertex 0, faces listed starting from the middle of the ring.
    let mut positions = vec![Vec3::zeros()];
    positions.extend((0..6).map(|k| {
        let a = std::f64::consts::TAU * k as f64 / 6.0;
        Vec3::new(a.cos(), a.sin(), 0.0)
    }));
    let ring = |k: u32| 1 + k % 6;
    let faces: Vec<[u32; 3]> = (0..6).map(|k| [0, ring(k + 3), ring(k + 4)]).collect();
    let closed = mesh((positions.clone(), faces.clone()));
    let s = closed.star(0);
    assert!(s.closed);
    assert_eq!(s.neighbours, &[1, 2, 3, 4, 5, 6]);
    assert_eq!(s.faces, &[3, 4, 5, 0, 1, 2]);
    check_stars(&closed);

    // Remove the face (0, 3, 4): the star opens and starts at 4, whose edge has its face on the CCW side.
    let open_faces: Vec<[u32; 3]> = faces.iter().copied().filter(|f| *f != [0, 3, 4]).collect();
    let open = mesh((positions, open_faces.clone()));
    let s = open.star(0);
    assert!(!s.closed);
    assert_eq!(s.neighbours, &[4, 5, 6, 1, 2, 3]);
    let expected: Vec<u32> = [[0, 4, 5], [0, 5, 6], [0, 6, 1], [0, 1, 2], [0, 2, 3]]
        .iter()
        .map(|f| open_faces.iter().position(|g| g == f).unwrap() as u32)
        .collect();
    assert_eq!(s.faces, expected.as_slice());
    check_stars(&open);
}

#[test]
fn grid_stars_turn_counter_clockwise() {
    let m = mesh(grid(5, 4, 1.0));
    check_stars(&m);
    for v in 0..m.vertex_count() {
        let s = m.star(v);
        let p = |i: u32| m.positions()[i as usize] - m.positions()[v];
        let turns = s.neighbours.len() - usize::from(!s.closed);
        for k in 0..turns {
            let (a, b) = (p(s.neighbours[k]), p(s.neighbours[(k + 1) % s.neighbours.len()]));
            assert!(a.cross(&b).z > 0.0, "vertex {v}: neighbours must turn counter-clockwise about +z");
        }
        if s.closed {
            assert_eq!(s.neighbours.len(), 6);
        }
    }
    // Corner (0, 0) has faces only on its CCW side: star (1, 0)-(1, 1)-(0, 1), open.
    let s = m.star(0);
    assert_eq!((s.neighbours, s.closed), (&[1, 7, 6][..], false));
}

#[test]
fn edges_are_sorted_unique_pairs() {
    let m = mesh(grid_with(4, 4, 1.0, |i, j| (i, j) != (1, 2)));
    let e = m.edges();
    assert!(e.iter().all(|[a, b]| a < b));
    assert!(e.windows(2).all(|w| w[0] < w[1]));
    let from_faces: BTreeSet<[u32; 2]> = m
        .faces()
        .iter()
        .flat_map(|f| (0..3).map(move |i| [f[i].min(f[(i + 1) % 3]), f[i].max(f[(i + 1) % 3])]))
        .collect();
    assert_eq!(e.to_vec(), from_faces.into_iter().collect::<Vec<_>>());
}

/// Signed area of a closed planar polygon in the xy-plane (positive when counter-clockwise).
fn signed_area(m: &TriMesh, loop_: &[u32]) -> f64 {
    let p = |i: usize| m.positions()[loop_[i % loop_.len()] as usize];
    (0..loop_.len()).map(|i| p(i).x * p(i + 1).y - p(i + 1).x * p(i).y).sum::<f64>() / 2.0
}

#[test]
fn grid_with_a_hole_has_two_loops() {
    // 7 × 5 cells with a 3 × 2 hole.
    let m = mesh(grid_with(7, 5, 1.0, |i, j| !((2..5).contains(&i) && (1..3).contains(&j))));
    let loops = m.boundary_loops();
    assert_eq!(loops.len(), 2);
    assert_eq!(loops[0].len(), 2 * (7 + 5));
    assert_eq!(loops[1].len(), 2 * (3 + 2));
    // Interior on the left: the outer loop runs counter-clockwise, the hole clockwise.
    assert_eq!(signed_area(&m, &loops[0]), 35.0);
    assert_eq!(signed_area(&m, &loops[1]), -6.0);
    // Consecutive loop vertices are exactly the boundary edges, oriented as in their faces.
    let directed: BTreeSet<(u32, u32)> = m.boundary_edges().iter().map(|e| (e.from, e.to)).collect();
    let from_loops: BTreeSet<(u32, u32)> =
        loops.iter().flat_map(|l| (0..l.len()).map(move |i| (l[i], l[(i + 1) % l.len()]))).collect();
    assert_eq!(directed, from_loops);
    assert_eq!(m.boundary_edges().len(), 34);
    for e in m.boundary_edges() {
        assert!(same_winding(m.faces()[e.face as usize], e.from, e.to, m.faces()[e.face as usize].iter().copied().find(|&x| x != e.from && x != e.to).unwrap()));
    }
    let on_loops: BTreeSet<u32> = loops.iter().flatten().copied().collect();
    for v in 0..m.vertex_count() {
        assert_eq!(m.is_boundary_vertex(v), on_loops.contains(&(v as u32)));
    }
    check_stars(&m);
}

#[test]
fn open_tube_is_an_annulus() {
    let m = mesh(tube(12, 4));
    let loops = m.boundary_loops();
    assert_eq!(loops.len(), 2);
    assert!(loops.iter().all(|l| l.len() == 12));
    // Equal lengths: ordered by start vertex; the bottom ring (z = 0) runs with increasing angle.
    assert_eq!(loops[0], (0..12).collect::<Vec<u32>>());
    assert!(loops[1].iter().all(|&v| m.positions()[v as usize].z == 2.0));
    check_stars(&m);
}
