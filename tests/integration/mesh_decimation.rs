//! The coarse stand-in of a mesh (`lamella::mesh::coarsened`): a valid mesh of the same topology
//! and outline whose vertices are a subset of the input's, close to the input surface, the same
//! bits every time.

use crate::mesh_support;

use std::collections::HashSet;

use lamella::mesh::{
    coarsened, FaceBvh, TriMesh, Vec3, MAX_BOUNDARY_TURN_DEGREES, MAX_NORMAL_DEVIATION_DEGREES,
};
use lamella::surfaces::hall_roof;
use mesh_support::{grid_with, mapped, mesh};

/// Bit patterns of a position, for set membership.
fn key(p: &Vec3) -> [u64; 3] {
    [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]
}

/// V − E + F.
fn euler_characteristic(m: &TriMesh) -> i64 {
    m.vertex_count() as i64 - m.edges().len() as i64 + m.face_count() as i64
}

/// A 60 × 40 grid of 0.1 m cells on a saddle, with a 10 × 6-cell hole: two boundary loops.
fn saddle_with_hole() -> TriMesh {
    let soup = grid_with(60, 40, 0.1, |i, j| {
        !((25..35).contains(&i) && (17..23).contains(&j))
    });
    mesh(mapped(soup, |p| {
        Vec3::new(p.x, p.y, 0.15 * (p.x - 3.0) * (p.y - 2.0))
    }))
}

/// Checks what every coarsening must keep, for `fine` coarsened to `target` vertices.
fn check_coarsening(fine: &TriMesh, target: usize) -> TriMesh {
    let coarse = coarsened(fine, target).expect("a valid coarse mesh");
    assert!(
        coarse.vertex_count() <= target + target / 20,
        "{} vertices for a target of {target}",
        coarse.vertex_count()
    );
    assert!(coarse.vertex_count() < fine.vertex_count());
    assert_eq!(
        euler_characteristic(&coarse),
        euler_characteristic(fine),
        "topology changed"
    );
    assert_eq!(
        coarse.boundary_loops().len(),
        fine.boundary_loops().len(),
        "boundary loops changed"
    );

    let fine_positions: HashSet<[u64; 3]> = fine.positions().iter().map(key).collect();
    assert!(
        coarse
            .positions()
            .iter()
            .all(|p| fine_positions.contains(&key(p))),
        "a coarse vertex is not an input vertex"
    );

    // Boundary corners (turns beyond the collapse limit) stay.
    let coarse_positions: HashSet<[u64; 3]> = coarse.positions().iter().map(key).collect();
    for boundary in fine.boundary_loops() {
        let n = boundary.len();
        for k in 0..n {
            let [a, b, c] = [
                boundary[(k + n - 1) % n],
                boundary[k],
                boundary[(k + 1) % n],
            ]
            .map(|v| fine.positions()[v as usize]);
            let turn = (b - a).angle(&(c - b)).to_degrees();
            if turn > MAX_BOUNDARY_TURN_DEGREES + 1e-9 {
                assert!(
                    coarse_positions.contains(&key(&b)),
                    "boundary corner {b:?} (turn {turn:.1}°) removed"
                );
            }
        }
    }

    // The coarse surface stays near the fine one and keeps its orientation: every fine vertex
    // within a few coarse edge lengths' chordal gap, the normal there within the collapse limit.
    let bvh = FaceBvh::new(&coarse);
    let (low, high) = fine.bounding_box();
    let diagonal = (high - low).norm();
    let mut worst: f64 = 0.0;
    for (p, n) in fine.positions().iter().zip(fine.vertex_normals()) {
        let closest = bvh.closest(&coarse, p).expect("a closest face");
        worst = worst.max(closest.distance);
        let normal = coarse.face_normals()[closest.face];
        let angle = normal.angle(n).to_degrees();
        assert!(
            angle <= MAX_NORMAL_DEVIATION_DEGREES + 15.0,
            "coarse normal {angle:.1}° from the fine normal at {p:?}"
        );
    }
    assert!(
        worst <= 0.01 * diagonal,
        "fine vertex {worst:.4} m from the coarse surface (diagonal {diagonal:.2} m)"
    );

    // Same bits every time.
    let again = coarsened(fine, target).unwrap();
    assert_eq!(again.faces(), coarse.faces());
    assert!(again
        .positions()
        .iter()
        .zip(coarse.positions())
        .all(|(a, b)| key(a) == key(b)));
    coarse
}

#[test]
fn the_hall_roof_coarsens_to_the_target_with_its_outline() {
    let fine = hall_roof(10_000).into_mesh().unwrap();
    let coarse = check_coarsening(&fine, 3_000);
    // The edge lengths even out: the coarse mean edge is about √(10000/3000) times the fine one.
    let ratio = coarse.mean_edge_length() / fine.mean_edge_length();
    assert!(
        (1.4..2.4).contains(&ratio),
        "mean edge length ratio {ratio:.2}"
    );
}

#[test]
fn a_surface_with_a_hole_keeps_both_boundary_loops() {
    let fine = saddle_with_hole();
    assert_eq!(fine.boundary_loops().len(), 2);
    let coarse = check_coarsening(&fine, 600);
    // The hole's rectangle keeps its four corners and its size.
    let inner = coarse
        .boundary_loops()
        .iter()
        .min_by_key(|l| l.len())
        .unwrap();
    let xs: Vec<f64> = inner
        .iter()
        .map(|&v| coarse.positions()[v as usize].x)
        .collect();
    let width =
        xs.iter().cloned().fold(f64::MIN, f64::max) - xs.iter().cloned().fold(f64::MAX, f64::min);
    assert!((width - 1.0).abs() < 1e-9, "hole width {width}");
}
