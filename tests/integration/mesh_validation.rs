//! Every validation error of the mesh constructors, the check order, `diagnose`, and no panics.

use crate::mesh_support;

use lamella::mesh::{diagnose, MeshError, TriMesh, Vec3};
use mesh_support::{grid, grid_with, mesh, tube, Lcg, Soup};

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(x, y, z)
}

fn first_error((positions, faces): Soup) -> MeshError {
    let all = diagnose(&positions, &faces);
    match TriMesh::from_vertices_and_faces(positions, faces) {
        Ok(_) => panic!("mesh was accepted"),
        Err(e) => {
            assert_eq!(all.first(), Some(&e), "constructor reports diagnose's first error");
            e
        }
    }
}

fn unit_triangle() -> Vec<Vec3> {
    vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)]
}

#[test]
fn empty_meshes() {
    assert_eq!(first_error((vec![], vec![])), MeshError::NoVertices);
    assert_eq!(diagnose(&[], &[]), vec![MeshError::NoVertices, MeshError::NoFaces]);
    assert_eq!(first_error((unit_triangle(), vec![])), MeshError::NoFaces);
    assert_eq!(TriMesh::from_arrays(&[], &[]).unwrap_err(), MeshError::NoVertices);
}

#[test]
fn array_lengths() {
    let e = TriMesh::from_arrays(&[0.0; 4], &[0, 1, 2]).unwrap_err();
    assert_eq!(e, MeshError::ArrayLength { array: "positions", len: 4 });
    let e = TriMesh::from_arrays(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0], &[0, 1, 2, 0]).unwrap_err();
    assert_eq!(e, MeshError::ArrayLength { array: "triangles", len: 4 });
    let ok = TriMesh::from_arrays(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0], &[0, 1, 2]).unwrap();
    assert_eq!((ok.vertex_count(), ok.face_count()), (3, 1));
}

#[test]
fn non_finite_coordinates() {
    let mut p = unit_triangle();
    p[1].z = f64::NAN;
    assert_eq!(first_error((p.clone(), vec![[0, 1, 2]])), MeshError::NonFiniteCoordinate { vertex: 1, axis: 2 });
    p[2].x = f64::NEG_INFINITY;
    let all = diagnose(&p, &[[0, 1, 2]]);
    assert!(all.contains(&MeshError::NonFiniteCoordinate { vertex: 2, axis: 0 }));
}

#[test]
fn index_out_of_range() {
    let e = first_error((unit_triangle(), vec![[0, 1, 7]]));
    assert_eq!(e, MeshError::IndexOutOfRange { face: 0, corner: 2, index: 7, vertex_count: 3 });
    let e = first_error((unit_triangle(), vec![[0, 1, 2], [u32::MAX, 0, 1]]));
    assert_eq!(e, MeshError::IndexOutOfRange { face: 1, corner: 0, index: u32::MAX as u64, vertex_count: 3 });
}

#[test]
fn repeated_index() {
    let mut p = unit_triangle();
    p.push(v(1.0, 1.0, 0.0));
    let e = first_error((p, vec![[0, 1, 2], [1, 3, 1]]));
    assert_eq!(e, MeshError::RepeatedIndex { face: 1, index: 1 });
}

#[test]
fn zero_area_faces() {
    // Collinear corners.
    let p = vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(2.0, 0.0, 0.0)];
    assert_eq!(first_error((p, vec![[0, 1, 2]])), MeshError::ZeroAreaFace { face: 0 });
    // Zero-length edge (coincident vertices).
    let p = vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(1.0, 0.0, 0.0)];
    assert_eq!(first_error((p, vec![[0, 1, 2]])), MeshError::ZeroAreaFace { face: 0 });
    // Relative test: height 1e-13 on base 1 is degenerate, height 1e-6 is not, at any scale.
    for scale in [1e-100, 1.0, 1e100] {
        let thin = |h: f64| vec![v(0.0, 0.0, 0.0), v(scale, 0.0, 0.0), v(0.5 * scale, h * scale, 0.0)];
        assert_eq!(first_error((thin(1e-13), vec![[0, 1, 2]])), MeshError::ZeroAreaFace { face: 0 });
        let r = TriMesh::from_vertices_and_faces(thin(1e-6), vec![[0, 1, 2]]);
        assert!(r.is_ok(), "scale {scale}: {r:?}");
    }
}

#[test]
fn isolated_vertex() {
    let mut p = unit_triangle();
    p.push(v(5.0, 5.0, 5.0));
    assert_eq!(first_error((p, vec![[0, 1, 2]])), MeshError::IsolatedVertex { vertex: 3 });
}

#[test]
fn three_faces_on_one_edge() {
    let p = vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.5, 1.0, 0.0), v(0.5, -1.0, 0.0), v(0.5, 0.0, 1.0)];
    let e = first_error((p, vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]]));
    assert_eq!(e, MeshError::NonManifoldEdge { a: 0, b: 1, face_count: 3, face: 2 });
}

#[test]
fn bow_tie_vertex() {
    let p = vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(-1.0, 0.0, 0.0), v(-1.0, -1.0, 0.0)];
    let e = first_error((p, vec![[0, 1, 2], [0, 3, 4]]));
    assert_eq!(e, MeshError::NonManifoldVertex { vertex: 0, fans: 2 });
}

#[test]
fn opposite_winding() {
    let p = vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.5, 1.0, 0.0), v(0.5, -1.0, 0.0)];
    let e = first_error((p, vec![[0, 1, 2], [0, 1, 3]]));
    assert_eq!(e, MeshError::InconsistentOrientation { face_a: 0, face_b: 1, from: 0, to: 1 });
}

#[test]
fn mobius_strip_is_not_orientable() {
    let n = 12;
    let mut positions = Vec::new();
    for i in 0..n {
        let phi = std::f64::consts::TAU * i as f64 / n as f64;
        let radial = v(phi.cos(), phi.sin(), 0.0);
        let width = radial * (phi / 2.0).cos() + v(0.0, 0.0, (phi / 2.0).sin());
        positions.push(radial * 2.0 - width * 0.3); // bottom, index 2i
        positions.push(radial * 2.0 + width * 0.3); // top, index 2i + 1
    }
    let bottom = |i: usize| (2 * i) as u32;
    let top = |i: usize| (2 * i + 1) as u32;
    let mut faces = Vec::new();
    for i in 0..n {
        // After a full turn the half twist swaps the sides.
        let (b1, t1) = if i + 1 == n { (top(0), bottom(0)) } else { (bottom(i + 1), top(i + 1)) };
        faces.push([bottom(i), b1, t1]);
        faces.push([bottom(i), t1, top(i)]);
    }
    let all = diagnose(&positions, &faces);
    assert!(!all.is_empty() && all.iter().all(|e| matches!(e, MeshError::InconsistentOrientation { .. })));
    assert!(matches!(first_error((positions, faces)), MeshError::InconsistentOrientation { .. }));
}

#[test]
fn two_disjoint_triangles() {
    let mut p = unit_triangle();
    p.extend(unit_triangle().iter().map(|q| q + v(3.0, 0.0, 0.0)));
    let e = first_error((p, vec![[3, 4, 5], [0, 1, 2]]));
    assert_eq!(e, MeshError::MultipleComponents { count: 2, vertex: 3 });
}

#[test]
fn closed_surfaces_are_not_disks() {
    let tetra = vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0), v(0.0, 0.0, 1.0)];
    let faces = vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
    assert_eq!(first_error((tetra, faces)), MeshError::NotDisk { euler_characteristic: 2, boundary_loops: 0 });

    let cube: Vec<Vec3> = (0..8).map(|i| v((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64)).collect();
    let quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let faces: Vec<[u32; 3]> = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
    assert_eq!(first_error((cube, faces)), MeshError::NotDisk { euler_characteristic: 2, boundary_loops: 0 });

    // A torus: the tube with its ends glued (χ = 0, no boundary).
    let (n, m) = (8, 6);
    let id = |i: usize, j: usize| ((j % m) * n + i % n) as u32;
    let positions: Vec<Vec3> = (0..m)
        .flat_map(|j| {
            (0..n).map(move |i| {
                let (a, b) = (std::f64::consts::TAU * i as f64 / n as f64, std::f64::consts::TAU * j as f64 / m as f64);
                v((2.0 + a.cos()) * b.cos(), (2.0 + a.cos()) * b.sin(), a.sin())
            })
        })
        .collect();
    let faces: Vec<[u32; 3]> = (0..m)
        .flat_map(|j| (0..n).flat_map(move |i| [[id(i, j), id(i + 1, j), id(i + 1, j + 1)], [id(i, j), id(i + 1, j + 1), id(i, j + 1)]]))
        .collect();
    assert_eq!(first_error((positions, faces)), MeshError::NotDisk { euler_characteristic: 0, boundary_loops: 0 });

    // Capping one end of an open tube (χ = 0, 2 loops) gives a disk (χ = 1, 1 loop): accepted.
    let (mut positions, mut faces) = tube(8, 2);
    positions.push(v(0.0, 0.0, 0.0));
    faces.extend((0..8u32).map(|i| [24, (i + 1) % 8, i]));
    assert!(TriMesh::from_vertices_and_faces(positions, faces).is_ok(), "capped tube is a disk");
}

#[test]
fn disks_with_holes_are_accepted() {
    let annulus = mesh(grid_with(6, 5, 1.0, |i, j| !(2..4).contains(&i) || !(2..3).contains(&j)));
    assert_eq!(annulus.boundary_loops().len(), 2);
    let two_holes = mesh(grid_with(9, 5, 1.0, |i, j| !((i == 2 || i == 6) && j == 2)));
    assert_eq!(two_holes.boundary_loops().len(), 3);
    let cylinder = mesh(tube(10, 3));
    assert_eq!(cylinder.boundary_loops().len(), 2);
    let v = cylinder.vertex_count() as i64;
    assert_eq!(v - cylinder.edges().len() as i64 + cylinder.face_count() as i64, 0);
}

#[test]
fn geometry_beyond_f64_range() {
    let p: Vec<Vec3> = unit_triangle().iter().map(|q| q * 1e300).collect();
    assert_eq!(first_error((p, vec![[0, 1, 2]])), MeshError::GeometryOutOfRange { face: 0 });
    let m = mesh(grid(2, 2, 1.0));
    assert!(matches!(m.try_scaled(1e-200), Err(MeshError::GeometryOutOfRange { .. })));
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(m.try_scaled(bad), Err(MeshError::InvalidScaleFactor { .. })));
        assert_eq!(m.scaled(bad), m);
    }
}

#[test]
fn check_order_and_full_diagnosis() {
    // NaN coordinate, out-of-range index, repeated index, zero-area face, isolated vertex, bow tie.
    let mut p = vec![
        v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(1.0, 1.0, 0.0), v(-1.0, 0.0, 0.0), v(-1.0, -1.0, 0.0),
        v(f64::NAN, 0.0, 0.0), v(9.0, 9.0, 9.0), v(2.0, 0.0, 0.0),
    ];
    p.push(v(3.0, 0.0, 0.0));
    let faces = vec![[0, 1, 2], [0, 3, 4], [0, 1, 99], [1, 2, 2], [5, 0, 1], [0, 7, 8], [7, 8, 1]];
    let all = diagnose(&p, &faces);
    let expected = [
        MeshError::NonFiniteCoordinate { vertex: 5, axis: 0 },
        MeshError::IndexOutOfRange { face: 2, corner: 2, index: 99, vertex_count: 9 },
        MeshError::RepeatedIndex { face: 3, index: 2 },
        MeshError::ZeroAreaFace { face: 5 },
        MeshError::IsolatedVertex { vertex: 6 },
    ];
    for e in &expected {
        assert!(all.contains(e), "missing {e:?} in {all:?}");
    }
    let position = |pred: &dyn Fn(&MeshError) -> bool| all.iter().position(pred).unwrap();
    assert!(position(&|e| matches!(e, MeshError::IsolatedVertex { .. }))
        < position(&|e| matches!(e, MeshError::NonManifoldVertex { vertex: 0, .. })));
    assert_eq!(all[0], expected[0]);
    assert_eq!(TriMesh::from_vertices_and_faces(p, faces).unwrap_err(), expected[0]);
    assert!(diagnose(&grid(3, 3, 1.0).0, &grid(3, 3, 1.0).1).is_empty());
}

#[test]
fn errors_display_their_elements() {
    let e = MeshError::NonManifoldEdge { a: 3, b: 8, face_count: 3, face: 5 };
    let text = e.to_string();
    assert!(text.contains("(3, 8)") && text.contains("3 faces"));
    let e = MeshError::NotDisk { euler_characteristic: 2, boundary_loops: 0 };
    assert!(e.to_string().contains("Euler characteristic 2"));
    let wrapped = MeshError::ObjLine { line: 12, error: Box::new(MeshError::IsolatedVertex { vertex: 4 }) };
    assert!(wrapped.to_string().contains("line 12") && wrapped.to_string().contains("vertex 4"));
    assert!(std::error::Error::source(&wrapped).is_some());
}

#[test]
fn random_input_never_panics() {
    let mut rng = Lcg(7);
    let specials = [f64::NAN, f64::INFINITY, -0.0, 1e308, 1e-308, 0.0, 1.0];
    for round in 0..300 {
        let nv = (rng.next_u64() % 8) as usize;
        let nf = (rng.next_u64() % 8) as usize;
        let positions: Vec<f64> = (0..3 * nv + (round % 4 == 0) as usize)
            .map(|_| if rng.unit() < 0.1 { specials[(rng.next_u64() % 7) as usize] } else { rng.unit() })
            .collect();
        let triangles: Vec<u32> = (0..3 * nf)
            .map(|_| if rng.unit() < 0.05 { u32::MAX } else { (rng.next_u64() % (nv as u64 + 1)) as u32 })
            .collect();
        let _ = TriMesh::from_arrays(&positions, &triangles);
        let p: Vec<Vec3> = positions.chunks_exact(3).map(Vec3::from_column_slice).collect();
        let f: Vec<[u32; 3]> = triangles.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
        let _ = diagnose(&p, &f);
    }
}
