//! Normals, areas, mixed Voronoi areas, gradient operators, scaling and serialisation checked
//! against analytic values.

use crate::mesh_support;

use lamella::mesh::{TriMesh, Vec3};
use mesh_support::{grid, mapped, mesh, sphere_cap, Lcg};

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(x, y, z)
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

/// The 6 × 5 grid, jittered in-plane (creating obtuse triangles), then rotated into a tilted plane.
fn tilted_jittered_grid() -> (TriMesh, Vec3) {
    let mut rng = Lcg(11);
    let (p, f) = grid(6, 5, 1.0);
    let p: Vec<Vec3> = p.iter().map(|q| q + v(0.35 * (rng.unit() - 0.5), 0.35 * (rng.unit() - 0.5), 0.0)).collect();
    let rotation = nalgebra::Rotation3::from_euler_angles(0.3, -0.7, 1.1);
    let normal = rotation * v(0.0, 0.0, 1.0);
    (mesh(mapped((p, f), |q| rotation * q + v(1.0, -2.0, 0.5))), normal)
}

#[test]
fn face_normal_and_area_of_a_triangle() {
    let p = vec![v(1.0, 1.0, 1.0), v(3.0, 1.0, 1.0), v(1.0, 4.0, 1.0)];
    let m = TriMesh::from_vertices_and_faces(p.clone(), vec![[0, 1, 2]]).unwrap();
    assert_eq!(m.face_areas()[0], 3.0);
    assert!((m.face_normals()[0] - v(0.0, 0.0, 1.0)).norm() < 1e-15);
    let flipped = TriMesh::from_vertices_and_faces(p, vec![[0, 2, 1]]).unwrap();
    assert!((flipped.face_normals()[0] - v(0.0, 0.0, -1.0)).norm() < 1e-15);
    // A triangle in the plane x + y + z = 1.
    let m = TriMesh::from_vertices_and_faces(vec![v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0), v(0.0, 0.0, 1.0)], vec![[0, 1, 2]])
        .unwrap();
    assert!(close(m.face_areas()[0], 3f64.sqrt() / 2.0, 1e-15));
    assert!((m.face_normals()[0] - v(1.0, 1.0, 1.0) / 3f64.sqrt()).norm() < 1e-15);
}

#[test]
fn vertex_normals_on_a_plane_are_exact() {
    let (m, normal) = tilted_jittered_grid();
    for n in m.vertex_normals().iter().chain(m.face_normals()) {
        assert!((n - normal).norm() < 1e-14, "{n} vs {normal}");
    }
}

/// Largest angle between an interior vertex normal and the radial direction on a sphere cap.
fn worst_radial_deviation(n: usize) -> f64 {
    let m = mesh(sphere_cap(n, 2.0));
    let mut worst: f64 = 0.0;
    for (i, (p, normal)) in m.positions().iter().zip(m.vertex_normals()).enumerate() {
        assert!(close(normal.norm(), 1.0, 1e-14));
        if !m.is_boundary_vertex(i) {
            worst = worst.max(normal.angle(&p.normalize()));
        }
    }
    worst
}

#[test]
fn vertex_normals_on_a_sphere_converge_to_radial() {
    let (coarse, fine) = (worst_radial_deviation(16), worst_radial_deviation(32));
    eprintln!("sphere cap: max interior vertex-normal angle to radial {coarse:.3e} (16x16), {fine:.3e} (32x32)");
    assert!(coarse < 2e-3, "{coarse}");
    assert!(fine < coarse / 3.0, "second-order convergence expected: {coarse} -> {fine}");
}

#[test]
fn mixed_voronoi_areas_of_single_triangles() {
    let area_parts = |p: Vec<Vec3>| {
        let m = TriMesh::from_vertices_and_faces(p, vec![[0, 1, 2]]).unwrap();
        let a = m.face_areas()[0];
        (m.vertex_areas().iter().map(|x| x / a).collect::<Vec<_>>(), a)
    };
    // Equilateral: the circumcentre is the centroid, each corner gets a third.
    let (parts, _) = area_parts(vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.5, 3f64.sqrt() / 2.0, 0.0)]);
    assert!(parts.iter().all(|x| close(*x, 1.0 / 3.0, 1e-14)), "{parts:?}");
    // Right angle at corner 0: circumcentre on the hypotenuse, parts 1/2, 1/4, 1/4.
    let (parts, _) = area_parts(vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)]);
    assert!(close(parts[0], 0.5, 1e-14) && close(parts[1], 0.25, 1e-14) && close(parts[2], 0.25, 1e-14));
    // Obtuse at corner 2: area/2 there, area/4 at the others.
    let (parts, _) = area_parts(vec![v(0.0, 0.0, 0.0), v(4.0, 0.0, 0.0), v(1.0, 0.5, 0.0)]);
    assert_eq!(parts, vec![0.25, 0.25, 0.5]);
    // Acute scalene: Voronoi part of corner 0 = area of the quadrilateral (p0, mid01, circumcentre, mid02).
    let p = [v(0.0, 0.0, 0.0), v(3.0, 0.0, 0.0), v(1.0, 2.0, 0.0)];
    let (parts, a) = area_parts(p.to_vec());
    let circumcentre = v(1.5, 0.5, 0.0); // equidistant: |c|² = |c − p1|² = |c − p2|²
    assert!(close((circumcentre - p[1]).norm(), circumcentre.norm(), 1e-15));
    assert!(close((circumcentre - p[2]).norm(), circumcentre.norm(), 1e-15));
    let quad = |m1: Vec3, m2: Vec3| 0.5 * (m1.cross(&circumcentre).z + circumcentre.cross(&m2).z);
    assert!(close(parts[0] * a, quad((p[0] + p[1]) / 2.0, (p[0] + p[2]) / 2.0), 1e-14));
}

#[test]
fn vertex_areas_sum_to_total_area() {
    for m in [tilted_jittered_grid().0, mesh(sphere_cap(9, 1.5))] {
        let total: f64 = m.face_areas().iter().sum();
        let sum: f64 = m.vertex_areas().iter().sum();
        assert!(close(sum, total, 1e-13), "{sum} vs {total}");
        let mean = m.normalized_vertex_areas().iter().sum::<f64>() / m.vertex_count() as f64;
        assert!(close(mean, 1.0, 1e-14));
        for (a, w) in m.vertex_areas().iter().zip(m.normalized_vertex_areas()) {
            assert!(close(*w, a * m.vertex_count() as f64 / total, 1e-13));
        }
    }
}

#[test]
fn interior_vertex_of_a_regular_grid_gets_the_cell_area() {
    let h = 0.3;
    let m = mesh(grid(5, 4, h));
    for vtx in (0..m.vertex_count()).filter(|&i| !m.is_boundary_vertex(i)) {
        assert!(close(m.vertex_areas()[vtx], h * h, 1e-14));
    }
}

#[test]
fn gradient_of_a_linear_function_is_its_tangential_part() {
    let a = v(0.7, -1.3, 2.1);
    let (planar, _) = tilted_jittered_grid();
    for m in [planar, mesh(sphere_cap(6, 1.0))] {
        for f in 0..m.face_count() {
            let g = m.face_gradients(f);
            let n = m.face_normals()[f];
            let grad: Vec3 = (0..3).map(|i| g[i] * a.dot(&m.positions()[m.faces()[f][i] as usize])).sum();
            let expected = a - n * a.dot(&n);
            assert!((grad - expected).norm() < 1e-12, "face {f}: {grad} vs {expected}");
            assert!((g[0] + g[1] + g[2]).norm() < 1e-12);
            // Hat function i is 1 at corner i and 0 at the others.
            let p = |k: usize| m.positions()[m.faces()[f][k] as usize];
            for (i, gi) in g.iter().enumerate() {
                assert!(gi.dot(&(p((i + 1) % 3) - p((i + 2) % 3))).abs() < 1e-12);
                assert!(close(gi.dot(&(p(i) - p((i + 1) % 3))), 1.0, 1e-12));
            }
        }
    }
}

#[test]
fn mean_edge_length_and_bounding_box_of_a_grid() {
    let (nx, ny, h) = (4, 3, 0.5);
    let m = mesh(grid(nx, ny, h));
    let straight = (nx * (ny + 1) + ny * (nx + 1)) as f64;
    let diagonal = (nx * ny) as f64;
    let expected = h * (straight + diagonal * 2f64.sqrt()) / (straight + diagonal);
    assert_eq!(m.edges().len(), (straight + diagonal) as usize);
    assert!(close(m.mean_edge_length(), expected, 1e-15));
    assert_eq!(m.bounding_box(), (v(0.0, 0.0, 0.0), v(2.0, 1.5, 0.0)));
}

#[test]
fn unit_scaled_copy() {
    let m = mesh(sphere_cap(7, 3.0));
    let (u, factor) = m.unit_scaled();
    assert!(close(factor, 1.0 / m.mean_edge_length(), 1e-15));
    assert!((u.mean_edge_length() - 1.0).abs() < 1e-12);
    for (p, q) in m.positions().iter().zip(u.positions()) {
        assert_eq!(p * factor, *q);
    }
    for (a, b) in m.face_normals().iter().zip(u.face_normals()).chain(m.vertex_normals().iter().zip(u.vertex_normals())) {
        assert!((a - b).norm() < 1e-14);
    }
    for (a, b) in m.face_areas().iter().zip(u.face_areas()).chain(m.vertex_areas().iter().zip(u.vertex_areas())) {
        assert!(close(*b, a * factor * factor, 1e-13));
    }
    for f in 0..m.face_count() {
        for i in 0..3 {
            assert!((m.face_gradients(f)[i] / factor - u.face_gradients(f)[i]).norm() < 1e-12 * u.face_gradients(f)[i].norm());
        }
    }
    assert_eq!(m.normalized_vertex_areas().len(), u.normalized_vertex_areas().len());
    assert_eq!((m.edges(), m.boundary_loops(), m.faces()), (u.edges(), u.boundary_loops(), u.faces()));
    let (lo, hi) = m.bounding_box();
    assert_eq!(u.bounding_box(), (lo * factor, hi * factor));
    let doubled = m.scaled(2.0);
    assert!(close(doubled.mean_edge_length(), 2.0 * m.mean_edge_length(), 1e-15));
}

#[test]
fn serde_round_trip_is_identical() {
    let (m, _) = tilted_jittered_grid();
    for mesh in [m.clone(), m.unit_scaled().0] {
        let bytes = bincode::serialize(&mesh).unwrap();
        let back: TriMesh = bincode::deserialize(&bytes).unwrap();
        assert_eq!(back, mesh);
        for (a, b) in mesh.positions().iter().zip(back.positions()) {
            assert!(a.iter().zip(b.iter()).all(|(x, y)| x.to_bits() == y.to_bits()));
        }
    }
    // Invalid data is rejected on deserialisation.
    let bad = bincode::serialize(&(vec![[0.0f64; 3]; 3], vec![[0u32, 1, 2]])).unwrap();
    assert!(bincode::deserialize::<TriMesh>(&bad).is_err());
}

#[test]
fn construction_is_deterministic_and_thread_safe() {
    fn assert_traits<T: Clone + Send + Sync + std::fmt::Debug + serde::Serialize + serde::de::DeserializeOwned>() {}
    assert_traits::<TriMesh>();
    let (m, _) = tilted_jittered_grid();
    let again = std::thread::spawn(|| tilted_jittered_grid().0).join().unwrap();
    assert_eq!(m, again);
}
