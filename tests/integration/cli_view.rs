//! `lamella design` writes view.html, and `lamella view DIR` writes it again from the files of
//! the output directory: the same strips, figures and utilisation as report.json, the surface and
//! curves of the directory; bad directories are refused naming the file.

use crate::cli_support;

use cli_support::{assert_bad_input, assert_ok, lamella, read_json, small_roof, stdout, Scratch};
use serde_json::Value;
use std::path::Path;

/// The JSON of a viewer page's data block.
fn page_data(path: &Path) -> Value {
    let page = std::fs::read_to_string(path).expect("view.html");
    for forbidden in ["http://", "https://", "src="] {
        assert!(!page.contains(forbidden), "{} contains {forbidden}", path.display());
    }
    let open = "<script type=\"application/json\" id=\"lamella-data\">";
    let start = page.find(open).expect("data block") + open.len();
    let end = start + page[start..].find("</script>").expect("end of the data block");
    serde_json::from_str(&page[start..end]).expect("data is JSON")
}

/// Strip names and figures of a page, with the names and figures of report.json beside them.
fn check_against_report(data: &Value, report: &Value) {
    let strips = data["strips"].as_array().expect("strips");
    let reported = report["strips"]["strips"].as_array().expect("report strips");
    assert_eq!(strips.len(), reported.len());
    for (s, r) in strips.iter().zip(reported) {
        assert_eq!(s["name"], r["name"]);
        assert_eq!(s["rulings"], r["vertices"]);
        for (ours, theirs) in [("length", "length_m"), ("max_diff_theta_degrees", "max_diff_theta_degrees"), ("max_quad_angle_error_degrees", "max_quad_angle_error_degrees")] {
            let (a, b) = (s["metrics"][ours].as_f64().expect(ours), r[theirs].as_f64().expect(theirs));
            assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{}: {ours} {a} against {b}", r["name"]);
        }
    }
    let utilisation: Vec<f64> = strips.iter().map(|s| s["utilisation"].as_f64().expect("utilisation")).collect();
    let checked: Vec<f64> = report["fabrication"]["strips"].as_array().expect("fabrication").iter().map(|c| c["max_utilisation"].as_f64().expect("max")).collect();
    assert_eq!(utilisation.len(), checked.len());
    assert!(utilisation.iter().zip(&checked).all(|(a, b)| (a - b).abs() <= 1e-12 * b.abs().max(1.0)));
    assert_eq!(data["has_utilisation"], true);
}

#[test]
fn design_writes_the_viewer_and_view_writes_it_again_from_the_files() {
    let dir = Scratch::new("view");
    let roof = small_roof(&dir, 600);
    let roof = roof.to_str().expect("path");
    let design = lamella(&dir.0, &["design", "--mesh", roof, "--max-iterations", "40", "--strips", "6", "--thickness", "6mm", "--stock", "12m", "--out", "out", "--quiet"]);
    let code = design.status.code();
    assert!(code == Some(0) || code == Some(3), "exit {code:?}: {}", cli_support::stderr(&design));
    let out = dir.path("out");
    let view = out.join("view.html");
    let report = read_json(&out.join("report.json"));
    let written = page_data(&view);
    check_against_report(&written, &report);
    assert_eq!(written["families"], serde_json::json!([format!("θ = {}°", report["parameters"]["theta_degrees"].as_f64().expect("θ"))]));
    let vertices = std::fs::read_to_string(out.join("surface.obj")).expect("surface").lines().filter(|l| l.starts_with("v ")).count();
    assert_eq!(written["surface"]["vertices"].as_u64(), Some(vertices as u64));
    let curves = std::fs::read_to_string(out.join("curves.obj")).expect("curves").lines().filter(|l| l.starts_with("l ")).count();
    assert_eq!(written["curves"]["counts"].as_array().expect("curve counts").len(), curves);
    assert!(std::fs::read_to_string(out.join(".lamella-output")).expect("marker").lines().any(|l| l == "view.html"));

    // `view` prints the path of an existing page and leaves it alone.
    let before = std::fs::read(&view).expect("page");
    let shown = lamella(&dir.0, &["view", "out"]);
    assert_ok(&shown);
    assert_eq!(stdout(&shown).trim(), Path::new("out").join("view.html").display().to_string());
    assert_eq!(std::fs::read(&view).expect("page"), before);

    // Without one it writes the page from the directory's files: the same strips, figures,
    // utilisation, surface and curves; the geometry within the quantisation of the same box.
    std::fs::remove_file(&view).expect("remove");
    assert_ok(&lamella(&dir.0, &["view", "out"]));
    let again = page_data(&view);
    check_against_report(&again, &report);
    for key in ["box", "curves", "surface"] {
        assert_eq!(again[key], written[key], "{key}");
    }
    let marker = std::fs::read_to_string(out.join(".lamella-output")).expect("marker");
    assert_eq!(marker.lines().filter(|l| *l == "view.html").count(), 1, "{marker}");
    // The directory is still a Lamella output that --force replaces.
    let forced = lamella(&dir.0, &["design", "--mesh", roof, "--max-iterations", "1", "--strips", "1", "--out", "out", "--force", "--quiet"]);
    assert!(matches!(forced.status.code(), Some(0) | Some(3)), "{}", cli_support::stderr(&forced));
}

#[test]
fn view_refuses_what_is_not_an_output_directory() {
    let dir = Scratch::new("view-bad");
    assert_bad_input(&dir.0, &["view", "missing"], &["missing is not a directory"]);
    std::fs::create_dir(dir.path("empty")).expect("mkdir");
    assert_bad_input(&dir.0, &["view", "empty"], &["has no strips.obj"]);

    std::fs::create_dir(dir.path("broken")).expect("mkdir");
    std::fs::write(dir.path("broken/strips.obj"), "g strip_0\nv 0 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\n").expect("write");
    assert_bad_input(&dir.0, &["view", "broken"], &["report.json"]);
    std::fs::write(dir.path("broken/report.json"), "{\"parameters\": {\"theta_degrees\": 60}}").expect("write");
    std::fs::write(dir.path("broken/curves.obj"), "v 0 0 0\nl 1 2\n").expect("write");
    assert_bad_input(&dir.0, &["view", "broken"], &["curves.obj: line 2", "not a vertex"]);
    std::fs::write(dir.path("broken/strips.obj"), "g strip_0\nv 0 0 0\nv 0 1 0\nv 1 0 nan\nv 1 1 0\n").expect("write");
    assert_bad_input(&dir.0, &["view", "broken"], &["strips.obj: line 4", "non-finite"]);
    assert!(!dir.path("broken/view.html").exists());

    // A minimal directory (strips and report only) gets its page, figures it lacks shown as n/a.
    std::fs::write(dir.path("broken/strips.obj"), "g strip_0\nv 0 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\n").expect("write");
    std::fs::write(dir.path("broken/curves.obj"), "v 0 0 0\nv 1 0 0\nl 1 2\n").expect("write");
    assert_ok(&lamella(&dir.0, &["view", "broken"]));
    let data = page_data(&dir.path("broken/view.html"));
    assert_eq!(data["strips"][0]["name"], "strip_0");
    assert!(data["strips"][0]["metrics"]["length"].is_null());
    assert!(data["surface"].is_null());
}
