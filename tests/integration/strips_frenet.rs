//! The discrete Frenet frame (Eq. 1), the version-1 rectifying developable (Fig. 19), the unrolling
//! and the preferred strip on a discrete circular helix, whose rectifying developable is known:
//! the helix is a geodesic of its cylinder, so the rulings are the cylinder's generators.

use lamella::curves::LevelCurve;
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::{
    discrete_binormals, initial_rulings, principal_normals, rectifying_strips, straightness, unroll, version_one_rulings, StripParams,
};
use lamella::surfaces::{cylinder_patch, CylinderPatch};

const RADIUS: f64 = 4.0;
/// Rise per radian.
const PITCH: f64 = 1.5;

fn helix(count: usize, step: f64) -> Vec<Vec3> {
    (0..count)
        .map(|k| {
            let t = 0.2 + step * k as f64;
            Vec3::new(RADIUS * t.cos(), RADIUS * t.sin(), PITCH * t)
        })
        .collect()
}

#[test]
fn discrete_frame_of_a_helix() {
    let points = helix(20, 0.15);
    let normals = principal_normals(&points);
    let binormals = discrete_binormals(&points);
    assert!(normals[0].is_none() && normals[19].is_none() && binormals[0].is_none());
    // The edges of the discrete helix (step Δ) have a horizontal part of length a = 2R sin(Δ/2)
    // turning by Δ and a vertical part pΔ, so ê_{i−1} × ê_i has b·z = a cos(Δ/2) / √(a² cos²(Δ/2) + p²Δ²).
    let (step, a) = (0.15f64, 2.0 * RADIUS * (0.075f64).sin());
    let expected = a * (step / 2.0).cos() / ((a * (step / 2.0).cos()).powi(2) + (PITCH * step).powi(2)).sqrt();
    for i in 1..19 {
        let n = normals[i].expect("curved");
        let axis_to_point = Vec3::new(points[i].x, points[i].y, 0.0).normalize();
        assert!((n + axis_to_point).norm() < 1e-12, "principal normal {i} is not −radial");
        let b = binormals[i].expect("curved");
        assert!((b.z - expected).abs() < 1e-12 && (b.norm() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn version_one_rulings_of_a_helix_are_the_generators() {
    let points = helix(20, 0.15);
    let reference = vec![Vec3::z(); points.len()];
    let lines = version_one_rulings(&points, &reference);
    assert!(lines[0].is_none() && lines[1].is_none() && lines[19].is_none());
    for (i, line) in lines.iter().enumerate().take(19).skip(2) {
        assert!((line.expect("defined") - Vec3::z()).norm() < 1e-12, "L_{i} not vertical");
    }
    for (i, d) in initial_rulings(&points, &reference).iter().enumerate() {
        assert!((d - Vec3::z()).norm() < 1e-9, "initial ruling {i}: {d:?}");
    }
    // Unrolling the cylinder strip along its generators gives the straight developed helix.
    let offsets: Vec<Vec3> = points.iter().map(|_| Vec3::z() * 0.5).collect();
    let flat = unroll(&points, &offsets);
    let chord = 2.0 * RADIUS * (0.075f64).sin();
    let length = 19.0 * (chord * chord + (PITCH * 0.15).powi(2)).sqrt();
    assert!((flat.length - length).abs() < 1e-12 * length);
    assert!(straightness(&flat.centre, flat.length) < 1e-12);
}

#[test]
fn unrolling_measures_the_bend_of_a_planar_arc() {
    // A circular arc in the plane with rulings towards its centre: the strip is flat, so its
    // unrolling is the arc itself, turning by the arc angle at every vertex.
    let points: Vec<Vec3> = (0..11).map(|k| Vec3::new((0.1 * k as f64).cos(), (0.1 * k as f64).sin(), 0.0) * 10.0).collect();
    let offsets: Vec<Vec3> = points.iter().map(|p| -p.normalize()).collect();
    let flat = unroll(&points, &offsets);
    let chord_angle: f64 = 0.1;
    let expected_turn = chord_angle; // exterior angle at every inner vertex
    let first = [flat.centre[1][0] - flat.centre[0][0], flat.centre[1][1] - flat.centre[0][1]];
    let second = [flat.centre[2][0] - flat.centre[1][0], flat.centre[2][1] - flat.centre[1][1]];
    let turn = (first[0] * second[1] - first[1] * second[0]).atan2(first[0] * second[0] + first[1] * second[1]);
    assert!((turn.abs() - expected_turn).abs() < 1e-12, "turn {turn}");
    assert!(straightness(&flat.centre, flat.length) > 1e-2);
}

#[test]
fn preferred_strip_of_a_cylinder_geodesic() {
    // θ = 90°: geodesics; the strip is tangent to the cylinder along the helix.
    let patch = CylinderPatch { radius: RADIUS, span: 2.0, height: 5.0, target_vertices: 1500, irregularity: 0.2, seed: 4 };
    let mesh: TriMesh = cylinder_patch(&patch).expect("valid").into_mesh().expect("valid");
    let points = helix(12, 0.12);
    let normals = points.iter().map(|p| Vec3::new(p.x, p.y, 0.0).normalize()).collect();
    let curve = LevelCurve { level: 0.0, points: points.clone(), normals, closed: false, singular_vertices: Vec::new() };
    let pattern = rectifying_strips(&mesh, &[curve], &StripParams::new(90.0, 0.4)).expect("valid parameters");
    let strip = &pattern.strips[0];
    assert!(strip.warnings.is_empty(), "{:?}", strip.warnings);
    assert!(pattern.metrics.max_planar <= 1e-6 && pattern.metrics.max_e_straight <= 1e-3);
    assert!(pattern.metrics.max_diff_theta_degrees <= 1.5, "{}", pattern.metrics.max_diff_theta_degrees);
    for (i, d) in strip.rulings.iter().enumerate() {
        // Generators of the cylinder, up to the mesh's faceting.
        assert!(d.z.abs() > 0.99, "ruling {i}: {d:?}");
    }
}
