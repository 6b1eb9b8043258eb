//! `lamella surface`: the built-in surfaces as OBJ. The Brauner surface of Fig. 32 is checked
//! against its closed form (x = cos²u − 2v, y = sin u cos u − u, z = 2μ e^{−v} cos u), and its
//! asymptotic.obj against what the u-lines are: curves rising at atan(μ e^{−v}) whose principal
//! normals are horizontal (so orthogonal to the surface normal: asymptotic).

use crate::cli_support;

use cli_support::{assert_bad_input, lamella, read_json, stderr, Scratch};
use lamella::mesh::{TriMesh, Vec3};

/// The polylines of an OBJ file of `v` and `l` elements.
fn polylines(text: &str) -> Vec<Vec<Vec3>> {
    let mut vertices = Vec::new();
    let mut lines = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let c: Vec<f64> = words.map(|w| w.parse().expect("coordinate")).collect();
                vertices.push(Vec3::new(c[0], c[1], c[2]));
            }
            Some("l") => lines.push(words.map(|w| vertices[w.parse::<usize>().expect("index") - 1]).collect()),
            _ => {}
        }
    }
    lines
}

/// u of a point of the paper's Brauner surface from y = sin u cos u − u (decreasing on (0, π)).
fn parameter_u(y: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, std::f64::consts::PI);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if mid.sin() * mid.cos() - mid > y {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn the_brauner_surface_and_its_asymptotic_u_lines_match_the_closed_form() {
    let dir = Scratch::new("surface-brauner");
    let mu = 0.8;
    let output = lamella(&dir.path(""), &["surface", "brauner", "--vertices", "1500", "--mu", "0.8", "--lines", "5", "--out", "out"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let mesh = TriMesh::parse_obj(&std::fs::read_to_string(dir.path("out/surface.obj")).expect("surface.obj")).expect("a valid mesh");
    assert!((1200..1800).contains(&mesh.vertex_count()), "{} vertices", mesh.vertex_count());
    for p in mesh.positions() {
        let u = parameter_u(p.y);
        let v = (u.cos().powi(2) - p.x) / 2.0;
        assert!((p.z - 2.0 * mu * (-v).exp() * u.cos()).abs() < 1e-9, "{p:?} is off the surface");
        assert!((0.6 - 1e-9..=std::f64::consts::PI - 0.6 + 1e-9).contains(&u) && (-0.5 - 1e-9..=0.5 + 1e-9).contains(&v), "{p:?}: u {u}, v {v}");
    }
    let report = read_json(&dir.path("out/report.json"));
    assert_eq!(report["vertices"], mesh.vertex_count());
    let lines = polylines(&std::fs::read_to_string(dir.path("out/asymptotic.obj")).expect("asymptotic.obj"));
    let slopes = report["asymptotic_u_lines"].as_array().expect("u-lines");
    assert_eq!((lines.len(), slopes.len()), (5, 5));
    for (line, entry) in lines.iter().zip(slopes) {
        let v = entry["v"].as_f64().expect("v");
        let slope = (mu * (-v).exp()).atan().to_degrees();
        assert!((entry["slope_degrees"].as_f64().expect("slope") - slope).abs() < 1e-9);
        for w in line.windows(3) {
            // The chord rises at the slope (a chord of 1/200 of the line, to 0.01°).
            let d = w[2] - w[0];
            let rise = d.z.atan2(d.x.hypot(d.y)).to_degrees().abs();
            assert!((rise - slope).abs() < 0.01, "v = {v}: rises at {rise}°, not {slope}°");
            // The principal normal (the second difference without its part along the chord) is
            // horizontal.
            let t = d.normalize();
            let bend = w[2] - 2.0 * w[1] + w[0];
            let normal = bend - t * bend.dot(&t);
            assert!(normal.z.abs() < 1e-3 * normal.norm(), "v = {v}: principal normal {normal:?} leaves the horizontal");
        }
    }
}

#[test]
fn bad_surface_flags_are_refused_by_name() {
    let dir = Scratch::new("surface-bad");
    let cwd = dir.path("");
    assert_bad_input(&cwd, &["surface", "brauner", "--mu", "-1", "--out", "a"], &["mu"]);
    assert_bad_input(&cwd, &["surface", "brauner", "--lines", "1", "--out", "b"], &["--lines"]);
    assert_bad_input(&cwd, &["surface", "hall-roof", "--mu", "2", "--out", "c"], &["--mu", "hall-roof"]);
    assert_bad_input(&cwd, &["surface", "hall-roof", "--vertices", "50", "--out", "d"], &["--vertices"]);
    let output = lamella(&cwd, &["surface", "sphere", "--out", "e"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("hall-roof"), "{}", stderr(&output));
    for name in ["a", "b", "c", "d", "e"] {
        assert!(!dir.path(name).exists(), "{name} written after bad input");
    }
}
