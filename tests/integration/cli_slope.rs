//! `lamella field --family slope`: a constant-slope field (Sec. 5.2.3, Eq. 22) on the vault,
//! judged from outside on the level curves of the written field.csv against the vault's exact
//! normal; exit 3 when the curves miss the slope by more than 0.5° where it is reachable.

use crate::cli_support;

use cli_support::{assert_bad_input, lamella, read_json, stderr, Scratch};
use lamella::curves::{extract_level_curves, uniform_levels};
use lamella::field::slope_reachable;
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{vault, Vault};

const SURFACE: Vault = Vault { half_length: 5.0, half_width: 4.0, rise: 3.0, target_vertices: 4000, irregularity: 0.25, seed: 7 };

fn write_vault(dir: &Scratch, target_vertices: usize) -> (TriMesh, String) {
    let mesh = vault(&Vault { target_vertices, ..SURFACE }).expect("valid vault").into_mesh().expect("valid mesh");
    let path = dir.path("vault.obj");
    mesh.write_obj(std::fs::File::create(&path).expect("create obj")).expect("write obj");
    (mesh, path.display().to_string())
}

/// Largest slope error (degrees) of the 20 level curves of `dir/out/field.csv` (the levels the
/// command measures), chords every three edges, where the vault's exact normal reaches the slope.
fn outside_error(mesh: &TriMesh, dir: &Scratch, axis: &Vec3, slope: f64) -> f64 {
    let text = std::fs::read_to_string(dir.path("out/field.csv")).expect("field.csv");
    let field: Vec<f64> = text.lines().filter(|l| !l.starts_with('#')).map(|l| l.trim().parse().expect("number")).collect();
    let (a, b, h) = (SURFACE.half_length, SURFACE.half_width, SURFACE.rise);
    let normal = |p: &Vec3| Vec3::new(2.0 * h * p.x / (a * a) * (1.0 - (p.y / b).powi(2)), 2.0 * h * p.y / (b * b) * (1.0 - (p.x / a).powi(2)), 1.0).normalize();
    let curves = extract_level_curves(mesh, &field, &uniform_levels(mesh, &field, 20).expect("levels")).expect("curves");
    let mut worst: f64 = 0.0;
    for curve in &curves {
        for w in curve.resampled(3.0 * mesh.mean_edge_length()).expect("spacing").points.windows(3) {
            if slope_reachable(&normal(&w[1]), axis, slope) {
                worst = worst.max(((w[2] - w[0]).normalize().dot(axis).abs().asin().to_degrees() - slope).abs());
            }
        }
    }
    worst
}

fn run_slope(dir: &Scratch, path: &str, axis: &str) -> std::process::Output {
    lamella(&dir.0, &["field", "--mesh", path, "--family", "slope", "--axis", axis, "--slope", "30", "--out", "out", "-q"])
}

#[test]
fn a_slope_field_on_the_vault_is_accepted_and_meets_the_slope() {
    let dir = Scratch::new("slope-ok");
    let (mesh, path) = write_vault(&dir, 4000);
    // About the x axis every tangent plane of the vault is steep enough.
    let output = run_slope(&dir, &path, "1,0,0");
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    for file in ["field.csv", "session.bin", "energies.csv", "convergence.svg", "isophote.obj", "report.json"] {
        assert!(dir.path("out").join(file).is_file(), "{file} missing");
    }
    let report = read_json(&dir.path("out/report.json"));
    assert_eq!(report["field"]["acceptable"], true, "{report}");
    let error = outside_error(&mesh, &dir, &Vec3::x(), 30.0);
    assert!(error <= 0.5, "slope error up to {error}° from outside");
}

#[test]
fn the_verdict_beyond_an_isophote_agrees_with_the_outside_measure() {
    let dir = Scratch::new("slope-isophote");
    let (mesh, path) = write_vault(&dir, 4000);
    // Tilted 53° towards +x: the flank x > 0 is too flat for 30°; its boundary is reported.
    let output = run_slope(&dir, &path, "0.8,0,0.6");
    let report = read_json(&dir.path("out/report.json"));
    assert!(report["field"]["level_curves"]["unreachable"].as_u64().unwrap() > 0, "nothing beyond the isophote");
    assert!(std::fs::read_to_string(dir.path("out/isophote.obj")).expect("isophote").contains("\nl "), "no isophote polyline");
    let error = outside_error(&mesh, &dir, &Vec3::new(0.8, 0.0, 0.6), 30.0);
    // Measured: 0.61° near a corner (README): exit 3.
    assert_eq!(output.status.code(), Some(if error <= 0.5 { 0 } else { 3 }), "outside error {error}°: {}", stderr(&output));
}

#[test]
fn a_coarse_vault_misses_the_slope_and_exits_3() {
    let dir = Scratch::new("slope-coarse");
    let (mesh, path) = write_vault(&dir, 1200);
    let output = run_slope(&dir, &path, "0.8,0,0.6");
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    assert!(stderr(&output).contains("no acceptable family"), "{}", stderr(&output));
    assert!(outside_error(&mesh, &dir, &Vec3::new(0.8, 0.0, 0.6), 30.0) > 0.5, "exit 3 although the curves meet the slope");
}

#[test]
fn slope_flags_are_checked() {
    let dir = Scratch::new("slope-bad");
    let (_, path) = write_vault(&dir, 300);
    assert_bad_input(&dir.0, &["field", "--mesh", &path, "--family", "slope", "--theta", "60"], &["--slope"]);
    assert_bad_input(&dir.0, &["field", "--mesh", &path, "--family", "slope", "--axis", "0,0"], &["--axis"]);
    assert_bad_input(&dir.0, &["field", "--mesh", &path, "--family", "slope", "--axis", "0,0,0"], &["axis"]);
    assert_bad_input(&dir.0, &["field", "--mesh", &path, "--family", "slope", "--slope", "95"], &["slope"]);
    assert_bad_input(&dir.0, &["design", "--mesh", &path, "--family", "slope"], &["slope", "lamella field"]);
}
