//! `lamella reshape` (paper Sec. 3.3): a cylinder's 60° field on a surface moved towards 45°,
//! its output files checked against each other and against the tolerance.

use crate::cli_support;
use crate::field_support;

use cli_support::{assert_bad_input, lamella, parse_xml, read_json, stderr, Scratch};
use field_support::{cylinder, perturbed_height};
use lamella::field::{FieldParams, FieldSolver};
use lamella::mesh::TriMesh;

/// Writes the cylinder (600 vertices), its optimised 60° field and the session into `dir`.
fn cylinder_files(dir: &Scratch) -> TriMesh {
    let mesh = cylinder(600, 5);
    let mut solver = FieldSolver::new(&mesh, &perturbed_height(&mesh), FieldParams::pseudo_geodesic(60.0)).expect("valid input");
    solver.step(300).expect("solver runs");
    mesh.write_obj(std::fs::File::create(dir.path("cyl.obj")).expect("create")).expect("write");
    let field: String = solver.field().iter().map(|f| format!("{f}\n")).collect();
    std::fs::write(dir.path("field.csv"), field).expect("write field");
    std::fs::write(dir.path("session.bin"), solver.to_bytes()).expect("write session");
    mesh
}

/// The `deviation` column of deviation.csv.
fn deviation_column(path: &std::path::Path) -> Vec<f64> {
    let text = std::fs::read_to_string(path).expect("deviation.csv");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("vertex,x,y,z,dx,dy,dz,deviation"));
    lines.map(|l| l.rsplit(',').next().expect("column").parse().expect("number")).collect()
}

#[test]
fn reshape_writes_a_moved_surface_within_the_tolerance() {
    let dir = Scratch::new("reshape");
    let mesh = cylinder_files(&dir);
    let output = lamella(&dir.0, &["reshape", "--mesh", "cyl.obj", "--field", "field.csv", "--theta", "45", "--tolerance", "5%", "--strips", "8", "--out", "d"]);
    let report = read_json(&dir.path("d/report.json"));
    let acceptable = report["strips"]["acceptable"].as_bool().expect("verdict");
    // Exit 3 exactly when the strips on the moved surface miss θ (as `design`).
    assert_eq!(output.status.code(), Some(if acceptable { 0 } else { 3 }), "{}", stderr(&output));
    let moved = TriMesh::read_obj(&dir.path("d/surface.obj")).expect("surface.obj is a mesh");
    assert_eq!((moved.vertex_count(), moved.faces()), (mesh.vertex_count(), mesh.faces()));
    let deviations = deviation_column(&dir.path("d/deviation.csv"));
    assert_eq!(deviations.len(), mesh.vertex_count());
    let max = deviations.iter().copied().fold(0.0, f64::max);
    let (low, high) = mesh.bounding_box();
    let tolerance = report["deviation"]["tolerance_m"].as_f64().expect("tolerance");
    assert!((tolerance - 0.05 * (high - low).norm()).abs() <= 1e-9 * tolerance, "tolerance {tolerance}");
    assert!(max > 0.0 && max <= tolerance, "max deviation {max}, tolerance {tolerance}");
    assert_eq!(report["deviation"]["max_m"].as_f64(), Some(max));
    // The moved vertices lie where deviation.csv says they were moved to.
    let text = std::fs::read_to_string(dir.path("d/deviation.csv")).expect("csv");
    for (line, p) in text.lines().skip(1).zip(moved.positions()) {
        let columns: Vec<f64> = line.split(',').skip(1).take(3).map(|c| c.parse().expect("number")).collect();
        assert!((columns[0] - p.x).abs() + (columns[1] - p.y).abs() + (columns[2] - p.z).abs() <= 1e-9, "{line}");
    }
    let svg = parse_xml(&std::fs::read_to_string(dir.path("d/preview.svg")).expect("svg"));
    let mut polygons = Vec::new();
    svg.descendants("polygon", &mut polygons);
    assert!(polygons.len() >= mesh.face_count(), "{} polygons", polygons.len());
    for name in ["curves.obj", "strips.obj", "rulings.obj"] {
        assert!(dir.path(&format!("d/{name}")).is_file(), "{name} missing");
    }
}

#[test]
fn reshape_reads_a_session() {
    let dir = Scratch::new("reshape-session");
    let mesh = cylinder_files(&dir);
    let output = lamella(&dir.0, &["reshape", "--session", "session.bin", "--theta", "45", "--tolerance", "0.2", "--max-iterations", "20", "--strips", "6", "--out", "s", "--quiet"]);
    assert!(matches!(output.status.code(), Some(0 | 3)), "{}", stderr(&output));
    let report = read_json(&dir.path("s/report.json"));
    assert_eq!(report["deviation"]["tolerance_m"].as_f64(), Some(0.2));
    assert!(report["iterations"].as_u64().expect("iterations") <= 20);
    assert_eq!(deviation_column(&dir.path("s/deviation.csv")).len(), mesh.vertex_count());
}

#[test]
fn a_resumed_reshape_ends_where_an_uninterrupted_one_does() {
    let dir = Scratch::new("reshape-resume");
    cylinder_files(&dir);
    let common = ["--strips", "6", "--quiet"];
    let run = |args: &[&str]| {
        let output = lamella(&dir.0, &[args, &common[..]].concat());
        assert!(matches!(output.status.code(), Some(0 | 3)), "{}", stderr(&output));
    };
    run(&["reshape", "--session", "session.bin", "--theta", "45", "--tolerance", "0.2", "--max-iterations", "12", "--out", "whole"]);
    run(&["reshape", "--session", "session.bin", "--theta", "45", "--tolerance", "0.2", "--max-iterations", "5", "--out", "first"]);
    run(&["reshape", "--resume", "first/reshape.bin", "--max-iterations", "12", "--out", "rest"]);
    let read = |path: &str| std::fs::read(dir.path(path)).expect(path);
    assert_eq!(read_json(&dir.path("first/report.json"))["iterations"].as_u64(), Some(5));
    assert_eq!(read_json(&dir.path("rest/report.json"))["iterations"], read_json(&dir.path("whole/report.json"))["iterations"]);
    assert_eq!(read("rest/surface.obj"), read("whole/surface.obj"), "the same surface, bit for bit");
    assert_eq!(read("rest/deviation.csv"), read("whole/deviation.csv"));
    // A field session is not a surface session; --theta comes from the saved one.
    assert_bad_input(&dir.0, &["reshape", "--resume", "session.bin", "--out", "x"], &["session.bin", "not a usable surface session"]);
    let clash = lamella(&dir.0, &["reshape", "--resume", "first/reshape.bin", "--theta", "30", "--out", "y"]);
    assert_eq!(clash.status.code(), Some(2), "{}", stderr(&clash));
}

#[test]
fn reshape_rejects_bad_input() {
    let dir = Scratch::new("reshape-bad");
    cylinder_files(&dir);
    let base = ["reshape", "--mesh", "cyl.obj", "--field", "field.csv", "--out", "x"];
    let with = |extra: &[&'static str]| -> Vec<&str> { base.iter().copied().chain(extra.iter().copied()).collect() };
    assert_bad_input(&dir.0, &with(&["--theta", "45", "--tolerance", "lots"]), &["--tolerance", "lots"]);
    assert_bad_input(&dir.0, &with(&["--theta", "45", "--tolerance", "-3%"]), &["tolerance"]);
    assert_bad_input(&dir.0, &with(&["--theta", "180"]), &["--theta", "180"]);
    assert_bad_input(&dir.0, &with(&["--theta", "45", "--max-iterations", "0"]), &["--max-iterations"]);
    std::fs::write(dir.path("short.csv"), "1\n2\n3\n").expect("write");
    assert_bad_input(&dir.0, &["reshape", "--mesh", "cyl.obj", "--field", "short.csv", "--theta", "45", "--out", "y"], &["short.csv"]);
    assert!(!dir.path("x").exists() && !dir.path("y").exists(), "no output for bad input");
}

#[test]
fn design_names_a_reshape_tolerance_that_makes_its_strips_acceptable() {
    // z = xy/5 at θ = 30°: the default design's strips miss θ (exit 3). The verdict's message
    // names the tolerance of the tightest acceptable reshape trial; reshaping with it makes the strips
    // acceptable, within 1 % of the diagonal, the deviation measured here against every face.
    use lamella::surfaces::{hyperbolic_paraboloid, HyperbolicParaboloid};
    let dir = Scratch::new("reshape-advice");
    let surface = HyperbolicParaboloid { c: 5.0, half_width: 5.0, target_vertices: 2000, irregularity: 0.5, seed: 8 };
    let mesh = hyperbolic_paraboloid(&surface).expect("valid surface").into_mesh().expect("valid mesh");
    mesh.write_obj(std::fs::File::create(dir.path("hypar.obj")).expect("create")).expect("write");
    let output = lamella(&dir.0, &["design", "--mesh", "hypar.obj", "--theta", "30", "--out", "d", "--quiet"]);
    let message = stderr(&output);
    assert_eq!(output.status.code(), Some(3), "{message}");
    let trial = &read_json(&dir.path("d/report.json"))["reshape_trial"];
    assert_eq!(trial["acceptable"], true, "{trial}");
    let command = message.split("lamella reshape ").nth(1).expect("the message names a reshape");
    let words: Vec<&str> = command.split_whitespace().collect();
    assert_eq!(&words[..4], &["--session", "d/session.bin", "--theta", "30"], "{message}");
    assert_eq!(words[4], "--tolerance", "{message}");
    let percent: f64 = words[5].trim_end_matches('%').parse().expect("a percentage");
    assert!(percent <= 1.0, "the trial needed {percent} % of the diagonal");
    // The tolerance named is the one the accepted trial ran with, and it held there.
    assert_eq!(trial["allowed_percent"].as_f64(), Some(percent), "{trial}");
    assert!(trial["deviation_percent"].as_f64().expect("deviation") <= percent * (1.0 + 1e-9), "{trial}");

    let output = lamella(&dir.0, &["reshape", "--session", "d/session.bin", "--theta", "30", "--tolerance", words[5], "--out", "r", "--quiet"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(read_json(&dir.path("r/report.json"))["strips"]["acceptable"], true);
    let moved = TriMesh::read_obj(&dir.path("r/surface.obj")).expect("surface.obj is a mesh");
    let (low, high) = mesh.bounding_box();
    let worst = crate::reshape_cylinder::brute_force_distances(moved.positions(), &mesh).into_iter().fold(0.0, f64::max);
    assert!(worst > 0.0 && worst <= percent / 100.0 * (high - low).norm() * (1.0 + 1e-9), "moved {worst} m, {percent} % of the diagonal");
}

#[test]
fn an_asymptotic_design_that_misses_names_no_reshape() {
    // `reshape` takes 0° < θ < 180°: for θ = 0 (the asymptotic family) the verdict must not name
    // it, nor run a trial. The tolerance of 0.01° makes the strips miss.
    use lamella::surfaces::{hyperbolic_paraboloid, HyperbolicParaboloid};
    let dir = Scratch::new("reshape-asymptotic");
    let surface = HyperbolicParaboloid { c: 5.0, half_width: 5.0, target_vertices: 600, irregularity: 0.4, seed: 5 };
    let mesh = hyperbolic_paraboloid(&surface).expect("valid surface").into_mesh().expect("valid mesh");
    mesh.write_obj(std::fs::File::create(dir.path("hypar.obj")).expect("create")).expect("write");
    let output = lamella(&dir.0, &["design", "--mesh", "hypar.obj", "--theta", "0", "--tolerance", "0.01", "--strips", "6", "--out", "d", "--quiet"]);
    let message = stderr(&output);
    assert_eq!(output.status.code(), Some(3), "{message}");
    assert!(message.contains("no acceptable family") && !message.contains("reshape"), "{message}");
    assert!(read_json(&dir.path("d/report.json")).get("reshape_trial").is_none());
}

#[test]
fn alternating_field_and_surface_steps_meet_theta_within_the_tolerance() {
    use lamella::curves::{extract_level_curves, uniform_levels};
    use lamella::field::Family;
    use lamella::quality::{family_angles, DEFAULT_SPACING_EDGES};
    let dir = Scratch::new("reshape-alternate");
    let mesh = cylinder_files(&dir);
    let args = ["reshape", "--session", "session.bin", "--theta", "45", "--alternate", "4", "--max-iterations", "40", "--tolerance", "1%", "--strips", "8", "--out", "a"];
    let output = lamella(&dir.0, &args);
    // The 45° family exists on the cylinder: the field steps reach it, the strips are acceptable.
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let report = read_json(&dir.path("a/report.json"));
    let rounds = report["alternating"]["rounds"].as_u64().expect("rounds");
    assert!((1..=4).contains(&rounds), "{rounds} rounds");
    if rounds < 4 {
        assert_eq!(report["alternating"]["converged"].as_bool(), Some(true), "stopped early only on convergence");
    }
    assert!(!dir.path("a/reshape.bin").exists(), "an alternation writes no surface session");
    // The new field, read back, on the moved surface: its level curves judged from outside.
    let moved = TriMesh::read_obj(&dir.path("a/surface.obj")).expect("surface.obj is a mesh");
    let field: Vec<f64> = std::fs::read_to_string(dir.path("a/field.csv")).expect("field.csv").lines().filter(|l| !l.starts_with('#')).map(|l| l.parse().expect("number")).collect();
    assert_eq!(field.len(), mesh.vertex_count());
    let levels = uniform_levels(&moved, &field, 10).expect("valid field");
    let curves = extract_level_curves(&moved, &field, &levels).expect("levels in range");
    let (low, high) = moved.bounding_box();
    let angles = family_angles(&curves, Family::PseudoGeodesic { theta_degrees: 45.0 }, DEFAULT_SPACING_EDGES * moved.mean_edge_length(), (high - low).norm()).expect("curves");
    assert!(angles.measured > 40 && angles.rms_error_degrees < 1.0 && angles.max_error_degrees < 3.0, "{angles:?}");
    // Within 1 % of the diagonal, by every face of the original.
    let worst = crate::reshape_cylinder::brute_force_distances(moved.positions(), &mesh).into_iter().fold(0.0, f64::max);
    let (low, high) = mesh.bounding_box();
    assert!(worst > 0.0 && worst <= 0.01 * (high - low).norm() * (1.0 + 1e-9), "moved {worst}");
    assert_eq!(deviation_column(&dir.path("a/deviation.csv")).len(), mesh.vertex_count());
    // Bad rounds and a session to resume are refused.
    let mut zero = args;
    zero[6] = "0";
    assert_bad_input(&dir.0, &zero, &["--alternate", "0"]);
    let clash = lamella(&dir.0, &["reshape", "--resume", "x.bin", "--alternate", "3", "--out", "y"]);
    assert_eq!(clash.status.code(), Some(2), "{}", stderr(&clash));
}
