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
