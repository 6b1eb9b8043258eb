//! Procedural test surfaces: vertices on the analytic surfaces, vertex counts, validity as meshes,
//! disk topology, orientation, triangle quality and determinism.

use lamella::mesh::Vec3;
use lamella::surfaces::{
    cylinder_patch, hall_roof, hyperbolic_paraboloid, planar_disk, CylinderPatch, GeneratedSurface,
    HallRoofSection, HyperbolicParaboloid, PlanarPatch,
};
use std::collections::HashMap;
use std::f64::consts::PI;

fn paper_cylinder(target_vertices: usize, irregularity: f64, seed: u64) -> CylinderPatch {
    CylinderPatch { radius: 10.0, span: 150f64.to_radians(), height: 15.0, target_vertices, irregularity, seed }
}

fn paraboloid(target_vertices: usize, irregularity: f64, seed: u64) -> HyperbolicParaboloid {
    HyperbolicParaboloid { c: 8.0, half_width: 5.0, target_vertices, irregularity, seed }
}

fn disk(target_vertices: usize, irregularity: f64, seed: u64) -> PlanarPatch {
    PlanarPatch { radius: 3.0, target_vertices, irregularity, seed }
}

fn corners(s: &GeneratedSurface, f: &[u32; 3]) -> [Vec3; 3] {
    f.map(|k| s.positions[k as usize])
}

fn face_normal(s: &GeneratedSurface, f: &[u32; 3]) -> Vec3 {
    let [a, b, c] = corners(s, f);
    (b - a).cross(&(c - a)).normalize()
}

fn centroid(s: &GeneratedSurface, f: &[u32; 3]) -> Vec3 {
    let [a, b, c] = corners(s, f);
    (a + b + c) / 3.0
}

/// Interior angles of a triangle, by the law of cosines.
fn angles(p: [Vec3; 3]) -> [f64; 3] {
    [0, 1, 2].map(|k| {
        let a = (p[(k + 1) % 3] - p[k]).norm();
        let b = (p[(k + 2) % 3] - p[k]).norm();
        let c = (p[(k + 1) % 3] - p[(k + 2) % 3]).norm();
        ((a * a + b * b - c * c) / (2.0 * a * b)).clamp(-1.0, 1.0).acos()
    })
}

fn min_angle_degrees(s: &GeneratedSurface) -> f64 {
    s.faces
        .iter()
        .flat_map(|f| angles(corners(s, f)))
        .fold(f64::INFINITY, f64::min)
        .to_degrees()
}

/// Asserts a consistently oriented disk: every directed edge used once, V − E + F = 1, and the
/// boundary edges form one closed loop. Returns the boundary vertices.
fn assert_disk_topology(s: &GeneratedSurface) -> Vec<u32> {
    let mut directed = HashMap::new();
    for f in &s.faces {
        for k in 0..3 {
            assert!(directed.insert((f[k], f[(k + 1) % 3]), ()).is_none(), "edge used twice in the same direction");
        }
    }
    let boundary: HashMap<u32, u32> =
        directed.keys().filter(|(a, b)| !directed.contains_key(&(*b, *a))).map(|&(a, b)| (a, b)).collect();
    let undirected_edges = (directed.len() + boundary.len()) / 2;
    let euler = s.positions.len() as i64 - undirected_edges as i64 + s.faces.len() as i64;
    assert_eq!(euler, 1, "Euler characteristic of a disk");
    let start = *boundary.keys().next().expect("a disk has a boundary");
    let mut loop_vertices = vec![start];
    let mut v = boundary[&start];
    while v != start {
        loop_vertices.push(v);
        v = boundary[&v];
        assert!(loop_vertices.len() <= boundary.len());
    }
    assert_eq!(loop_vertices.len(), boundary.len(), "a single boundary loop");
    loop_vertices
}

fn assert_count(actual: usize, target: usize) {
    let relative = (actual as f64 - target as f64).abs() / target as f64;
    assert!(relative <= 0.15, "{actual} vertices for a target of {target}");
}

#[test]
fn cylinder_patch_lies_on_the_cylinder_with_outward_normals() {
    let patch = paper_cylinder(2000, 0.3, 11);
    let s = cylinder_patch(&patch).unwrap();
    assert_count(s.positions.len(), 2000);
    for p in &s.positions {
        assert!((p.x.hypot(p.y) - patch.radius).abs() < 1e-12);
        let phi = p.y.atan2(p.x);
        assert!(phi >= -1e-12 && phi <= patch.span + 1e-12);
        assert!(p.z >= 0.0 && p.z <= patch.height);
    }
    for f in &s.faces {
        let c = centroid(&s, f);
        let radial = Vec3::new(c.x, c.y, 0.0).normalize();
        assert!(face_normal(&s, f).dot(&radial) > 0.9, "normals point away from the axis");
    }
    let boundary = assert_disk_topology(&s);
    // The boundary loop runs along the four sides of the patch.
    for &v in &boundary {
        let p = s.positions[v as usize];
        let phi = p.y.atan2(p.x);
        let on_side = phi.abs() < 1e-12 || (phi - patch.span).abs() < 1e-12 || p.z == 0.0 || p.z == patch.height;
        assert!(on_side, "boundary vertex {p:?} is not on a side of the patch");
    }
    assert!(s.into_mesh().is_ok());
}

#[test]
fn hyperbolic_paraboloid_lies_on_the_graph_with_upward_normals() {
    let surface = paraboloid(1500, 0.3, 5);
    let s = hyperbolic_paraboloid(&surface).unwrap();
    assert_count(s.positions.len(), 1500);
    for p in &s.positions {
        assert!((p.z - p.x * p.y / surface.c).abs() < 1e-12);
        assert!(p.x.abs() <= surface.half_width + 1e-12 && p.y.abs() <= surface.half_width + 1e-12);
    }
    for f in &s.faces {
        assert!(face_normal(&s, f).z > 0.0);
    }
    // The four plan corners are vertices.
    for (x, y) in [(-5.0, -5.0), (5.0, -5.0), (5.0, 5.0), (-5.0, 5.0)] {
        assert!(s.positions.iter().any(|p| (p.x - x).abs() < 1e-12 && (p.y - y).abs() < 1e-12));
    }
    assert_disk_topology(&s);
    assert!(s.into_mesh().is_ok());
}

#[test]
fn planar_disk_is_flat_round_and_counter_clockwise() {
    let patch = disk(1200, 0.3, 3);
    let s = planar_disk(&patch).unwrap();
    assert_count(s.positions.len(), 1200);
    for p in &s.positions {
        assert_eq!(p.z, 0.0);
        assert!(p.x.hypot(p.y) <= patch.radius + 1e-12);
    }
    for f in &s.faces {
        assert!(face_normal(&s, f).z > 0.999);
    }
    let boundary = assert_disk_topology(&s);
    for &v in &boundary {
        let p = s.positions[v as usize];
        assert!((p.x.hypot(p.y) - patch.radius).abs() < 1e-12, "boundary vertices lie on the circle");
    }
    // The triangles tile the disk: their areas add up to the inscribed polygon's area.
    let area: f64 = s.faces.iter().map(|f| {
        let [a, b, c] = corners(&s, f);
        0.5 * (b - a).cross(&(c - a)).norm()
    }).sum();
    let mut angles: Vec<f64> = boundary.iter().map(|&v| s.positions[v as usize].y.atan2(s.positions[v as usize].x)).collect();
    angles.sort_by(f64::total_cmp);
    let polygon: f64 = (0..angles.len())
        .map(|k| {
            let next = if k + 1 == angles.len() { angles[0] + 2.0 * PI } else { angles[k + 1] };
            0.5 * patch.radius * patch.radius * (next - angles[k]).sin()
        })
        .sum();
    assert!((area - polygon).abs() < 1e-10 * polygon);
    assert!(s.into_mesh().is_ok());
}

#[test]
fn hall_roof_has_the_requested_sizes_arched_sections_and_upward_normals() {
    for target in [600, 3_000, 10_000, 50_000] {
        let start = std::time::Instant::now();
        let s = hall_roof(target);
        let elapsed = start.elapsed();
        eprintln!("hall_roof({target}): {} vertices, {} faces in {elapsed:?}", s.positions.len(), s.faces.len());
        assert_count(s.positions.len(), target);
        assert!(elapsed.as_secs_f64() < 1.0);
        for p in &s.positions {
            assert!(p.x.abs() <= 20.0 + 1e-12 && p.z >= -1e-12);
            // The cross-section at x is the circle through the eaves (±w, 0) and the crown (0, h).
            let section = HallRoofSection::at(p.x);
            let (w, h) = (section.half_span, section.rise);
            let radius = (w * w + h * h) / (2.0 * h);
            assert!((p.y.hypot(p.z - (h - radius)) - radius).abs() < 1e-12);
        }
        for f in &s.faces {
            let n = face_normal(&s, f);
            assert!(n.z > 0.0, "normals point up");
            let y = centroid(&s, f).y;
            if y.abs() > 1.0 {
                assert!(n.y * y > 0.0, "off the crown, normals point away from the hall's axis");
            }
        }
        assert!(min_angle_degrees(&s) > 10.0);
        assert_disk_topology(&s);
        assert!(s.into_mesh().is_ok());
    }
    // Plan extent: 40 m long, 21 m wide in the middle and 24 m at the ends; rise 8 m → 5 m.
    assert_eq!((HallRoofSection::at(0.0).half_span, HallRoofSection::at(0.0).rise), (10.5, 8.0));
    let end = HallRoofSection::at(20.0);
    assert!((end.half_span - 12.0).abs() < 1e-12 && (end.rise - 5.0).abs() < 1e-12);
}

/// Angle defect 2π − Σ angles at the interior vertex closest to `target`.
fn angle_defect_near(s: &GeneratedSurface, target: Vec3) -> f64 {
    let (v, _) = s
        .positions
        .iter()
        .enumerate()
        .map(|(i, p)| (i as u32, (p - target).norm()))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    let sum: f64 = s
        .faces
        .iter()
        .filter_map(|f| f.iter().position(|&k| k == v).map(|k| angles(corners(s, f))[k]))
        .sum();
    2.0 * PI - sum
}

#[test]
fn hall_roof_gaussian_curvature_changes_sign_along_the_crown() {
    let s = hall_roof(10_000);
    // Dome-like in the middle, saddle-like towards the gable ends.
    assert!(angle_defect_near(&s, Vec3::new(0.0, 0.0, 8.0)) > 0.0);
    for x in [-16.0, 16.0] {
        let h = HallRoofSection::at(x).rise;
        assert!(angle_defect_near(&s, Vec3::new(x, 0.0, h)) < 0.0);
    }
}

#[test]
fn triangles_stay_well_shaped_up_to_irregularity_0_3() {
    let mut worst: f64 = 180.0;
    for seed in 0..8 {
        for irregularity in [0.0, 0.15, 0.3] {
            let meshes = [
                cylinder_patch(&paper_cylinder(800, irregularity, seed)).unwrap(),
                hyperbolic_paraboloid(&paraboloid(800, irregularity, seed)).unwrap(),
                planar_disk(&disk(800, irregularity, seed)).unwrap(),
            ];
            for s in &meshes {
                worst = worst.min(min_angle_degrees(s));
            }
        }
    }
    eprintln!("smallest angle over all generated triangles: {worst:.2}°");
    assert!(worst > 10.0);
}

fn bits(s: &GeneratedSurface) -> Vec<u64> {
    s.positions.iter().flat_map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]).collect()
}

#[test]
fn generators_are_deterministic_in_their_seed() {
    let pairs = [
        (cylinder_patch(&paper_cylinder(500, 0.3, 1)), cylinder_patch(&paper_cylinder(500, 0.3, 1)), cylinder_patch(&paper_cylinder(500, 0.3, 2))),
        (hyperbolic_paraboloid(&paraboloid(500, 0.3, 1)), hyperbolic_paraboloid(&paraboloid(500, 0.3, 1)), hyperbolic_paraboloid(&paraboloid(500, 0.3, 2))),
        (planar_disk(&disk(500, 0.3, 1)), planar_disk(&disk(500, 0.3, 1)), planar_disk(&disk(500, 0.3, 2))),
    ];
    for (a, b, c) in pairs {
        let (a, b, c) = (a.unwrap(), b.unwrap(), c.unwrap());
        assert_eq!(bits(&a), bits(&b));
        assert_eq!(a.faces, b.faces);
        assert_ne!(bits(&a), bits(&c));
    }
    assert_eq!(bits(&hall_roof(3000)), bits(&hall_roof(3000)));
}

#[test]
fn invalid_parameters_are_rejected() {
    let mut c = paper_cylinder(500, 0.3, 1);
    c.span = 2.0 * PI;
    assert!(cylinder_patch(&c).is_err());
    c.span = 1.0;
    c.radius = f64::NAN;
    assert!(cylinder_patch(&c).is_err());
    let mut h = paraboloid(500, 0.3, 1);
    h.c = 0.0;
    assert!(hyperbolic_paraboloid(&h).is_err());
    h.c = 1.0;
    h.irregularity = 1.5;
    assert!(hyperbolic_paraboloid(&h).is_err());
    let mut d = disk(500, 0.3, 1);
    d.radius = -1.0;
    assert!(planar_disk(&d).is_err());
    // Tiny targets still give valid meshes.
    assert!(planar_disk(&disk(0, 0.3, 1)).unwrap().into_mesh().is_ok());
    assert!(hall_roof(0).into_mesh().is_ok());
}
