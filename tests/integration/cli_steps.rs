//! Each subcommand on a small generated mesh, chained through the files they read and write:
//! `info`, `field` (and `field --resume`, which continues exactly where it stopped), `strips`,
//! `unroll`, `metrics`, and `--config`.

use crate::cli_support;

use cli_support::{assert_ok, lamella, lamella_threads, parse_svg, polygon_points, read_json, small_roof, stdout, Scratch};
use lamella::mesh::TriMesh;
use std::path::Path;

fn text(path: &Path) -> String {
    std::fs::read_to_string(path).expect("read")
}

#[test]
fn info_reports_the_generated_roof() {
    let dir = Scratch::new("info");
    let obj = small_roof(&dir, 400);
    let mesh = TriMesh::read_obj(&obj).expect("valid");
    let output = lamella(&dir.0, &["info", obj.to_str().expect("utf-8")]);
    assert_ok(&output);
    let report = stdout(&output);
    let value = |key: &str| -> String {
        let line = report.lines().find(|l| l.trim_start().starts_with(key)).unwrap_or_else(|| panic!("no `{key}` in {report}"));
        line.split_once(':').expect("key: value").1.trim().to_string()
    };
    assert_eq!(value("vertices"), mesh.vertex_count().to_string());
    assert_eq!(value("faces"), mesh.face_count().to_string());
    // The roof is one disk: V − E + F = 1 with one boundary loop.
    let edges: i64 = value("edges").parse().expect("edges");
    assert_eq!(mesh.vertex_count() as i64 - edges + mesh.face_count() as i64, 1);
    assert!(value("boundary loops").starts_with("1 "));
    assert!(value("disk").starts_with("yes"));
    assert!(value("bounding box").contains("40.0000 × 24.0000"), "the roof is 40 m × 24 m in plan");
    assert_eq!(value("problems"), "none");
}

#[test]
fn field_resume_continues_where_it_stopped() {
    let dir = Scratch::new("resume");
    let obj = small_roof(&dir, 400);
    let m = obj.to_str().expect("utf-8");
    // An explicit start, whose warm-up schedule takes more than 9 iterations.
    let start = ["--direction", "1,0,0"];
    assert_ok(&lamella(&dir.0, &[&["field", "--mesh", m, "--max-iterations", "4", "--out", "part", "-q"][..], &start].concat()));
    assert_ok(&lamella(&dir.0, &["field", "--resume", "part/session.bin", "--max-iterations", "9", "--out", "resumed", "-q"]));
    assert_ok(&lamella(&dir.0, &[&["field", "--mesh", m, "--max-iterations", "9", "--out", "whole", "-q"][..], &start].concat()));
    let part = read_json(&dir.path("part/report.json"));
    let resumed = read_json(&dir.path("resumed/report.json"));
    let whole = read_json(&dir.path("whole/report.json"));
    assert_eq!(part["field"]["iterations"].as_u64(), Some(4));
    assert_eq!(resumed["field"]["iterations"].as_u64(), Some(9), "the iteration count continues");
    // The resumed history extends the saved one: iterations 0..=9 without a gap, equal to the
    // uninterrupted run's.
    assert_eq!(resumed["field"]["history"], whole["field"]["history"]);
    assert_eq!(text(&dir.path("resumed/field.csv")), text(&dir.path("whole/field.csv")), "same field bits");
    assert_eq!(std::fs::read(dir.path("resumed/session.bin")).expect("session"), std::fs::read(dir.path("whole/session.bin")).expect("session"));
    assert!(text(&dir.path("part/field.csv")) != text(&dir.path("whole/field.csv")), "4 iterations are not 9");
}

#[test]
fn strips_unroll_and_metrics_chain_through_their_files() {
    let dir = Scratch::new("steps");
    let obj = small_roof(&dir, 400);
    let m = obj.to_str().expect("utf-8");
    assert_ok(&lamella(&dir.0, &["field", "--mesh", m, "--out", "f", "-q"]));
    let field = read_json(&dir.path("f/report.json"));
    assert_eq!(field["field"]["converged"].as_bool(), Some(true));
    let field_values = text(&dir.path("f/field.csv")).lines().filter(|l| !l.starts_with('#')).count();
    assert_eq!(field_values, TriMesh::read_obj(&obj).expect("valid").vertex_count());
    assert!(parse_svg(&dir.path("f/convergence.svg")).name == "svg");

    assert_ok(&lamella(&dir.0, &["strips", "--mesh", m, "--field", "f/field.csv", "--strips", "3", "--width", "0.4", "--out", "s", "-q"]));
    for name in ["curves.obj", "strips.obj", "rulings.obj", "preview.svg", "report.json"] {
        assert!(dir.path("s").join(name).is_file(), "missing {name}");
    }
    let report = read_json(&dir.path("s/report.json"));
    let strips = report["strips"]["strips"].as_array().expect("strips");
    assert!(strips.len() >= 3, "3 levels across the hall give at least 3 strips");
    let strips_obj = text(&dir.path("s/strips.obj"));
    assert_eq!(strips_obj.lines().filter(|l| l.starts_with("g strip_")).count(), strips.len());
    // diagnostics.csv: the Sec. 5.1 quantities at every vertex of every strip's central polyline.
    let diagnostics = text(&dir.path("s/diagnostics.csv"));
    let rows: Vec<&str> = diagnostics.lines().filter(|l| !l.starts_with('#')).skip(1).collect();
    let vertices: u64 = strips.iter().map(|s| s["vertices"].as_u64().expect("vertices")).sum();
    assert_eq!(rows.len() as u64, vertices);
    assert!(rows.iter().all(|r| r.split(',').count() == 13 && !r.contains("NaN") && !r.contains("inf")), "{diagnostics}");
    assert!(rows.iter().filter(|r| !r.split(',').nth(7).unwrap_or("").is_empty()).count() > rows.len() / 2, "k mostly undefined");
    // curves.obj holds one `l` polyline per level curve.
    assert_eq!(text(&dir.path("s/curves.obj")).lines().filter(|l| l.starts_with("l ")).count(), report["strips"]["curves"].as_u64().expect("curves") as usize);

    assert_ok(&lamella(&dir.0, &["unroll", "--strips", "s/strips.obj", "--out", "u", "-q"]));
    let sheet = parse_svg(&dir.path("u/unrolled.svg"));
    let mut outlines = Vec::new();
    sheet.descendants("polygon", &mut outlines);
    assert_eq!(outlines.len(), strips.len());
    for (outline, s) in outlines.iter().zip(strips) {
        // The flat strip's straight boundaries are `width` apart: its outline, turned with its
        // chord horizontal, is 400 mm tall (the unrolled centre line is straight, e_straight ≈ 0).
        let points = polygon_points(outline);
        let (low, high) = points.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| (l.min(p[1]), h.max(p[1])));
        assert!((high - low - 400.0).abs() < 1.0, "{}: outline {} mm tall", s["name"], high - low);
    }

    let metrics = lamella(&dir.0, &["metrics", "--mesh", m, "--strips", "s/strips.obj", "--json"]);
    assert_ok(&metrics);
    let measured: serde_json::Value = serde_json::from_str(&stdout(&metrics)).expect("metrics JSON");
    let measured = measured["strips"].as_array().expect("strips");
    assert_eq!(measured.len(), strips.len());
    // Re-measured from the stored boundaries: the same Table 4 numbers as at build time.
    for (again, built) in measured.iter().zip(strips) {
        let close = |a: &serde_json::Value, b: &serde_json::Value, tolerance: f64| {
            let (a, b) = (a.as_f64().expect("number"), b.as_f64().expect("number"));
            assert!((a - b).abs() <= tolerance, "{}: {a} vs {b}", built["name"]);
        };
        close(&again["metrics"]["length"], &built["length_m"], 1e-9);
        close(&again["metrics"]["max_diff_theta_degrees"], &built["max_diff_theta_degrees"], 1e-6);
        close(&again["metrics"]["e_straight"], &built["e_straight"], 1e-9);
        close(&again["metrics"]["appro_percent"], &built["appro_percent"], 1e-9);
    }
    let table = lamella(&dir.0, &["metrics", "--mesh", m, "--strips", "s/strips.obj"]);
    assert_ok(&table);
    assert!(stdout(&table).lines().any(|l| l.starts_with("overall")));
}

#[test]
fn config_file_sets_parameters_and_flags_win() {
    let dir = Scratch::new("config");
    let obj = small_roof(&dir, 300);
    std::fs::write(dir.path("design.toml"), format!("mesh = {:?}\ntheta = 70\nmax_iterations = 2\nstrips = 2\nwidth = 0.25\n", obj.to_str().expect("utf-8"))).expect("write");
    assert_ok(&lamella(&dir.0, &["design", "--config", "design.toml", "--strips", "1", "--out", "c", "-q"]));
    let report = read_json(&dir.path("c/report.json"));
    assert_eq!(report["parameters"]["theta_degrees"].as_f64(), Some(70.0));
    assert_eq!(report["parameters"]["strips"].as_u64(), Some(1), "the flag wins over the file");
    assert_eq!(report["field"]["iterations"].as_u64(), Some(2));
    assert_eq!(report["strips"]["width_m"].as_f64(), Some(0.25));
}

#[test]
fn help_explains_every_subcommand() {
    let dir = Scratch::new("help");
    for command in [&["--help"][..], &["design", "--help"], &["info", "--help"], &["field", "--help"], &["strips", "--help"], &["unroll", "--help"], &["metrics", "--help"], &["reshape", "--help"]] {
        let output = lamella(&dir.0, command);
        assert_ok(&output);
        let help = stdout(&output);
        assert!(help.contains("Usage:"), "{command:?}");
        if command.len() == 2 && command[0] != "info" {
            assert!(help.contains("default"), "{command:?} names its defaults:\n{help}");
        }
    }
    let design = stdout(&lamella(&dir.0, &["design", "--help"]));
    for flag in ["--mesh", "--theta", "--max-iterations", "--strips", "--width", "--out", "--force", "--config", "--quiet", "--verbose"] {
        assert!(design.contains(flag), "design --help lacks {flag}");
    }
    assert!(design.contains("degrees") && design.contains("metres"), "units in design --help");
}

#[test]
fn outputs_do_not_depend_on_the_thread_count() {
    let dir = Scratch::new("threads");
    let obj = small_roof(&dir, 300);
    let m = obj.to_str().expect("utf-8");
    for (threads, out) in [(1, "one"), (2, "two")] {
        let args = ["design", "--mesh", m, "--strips", "3", "--max-iterations", "12", "--out", out, "-q"];
        assert_ok(&lamella_threads(&dir.0, threads, &args));
    }
    for name in ["field.csv", "session.bin", "energies.csv", "curves.obj", "strips.obj", "rulings.obj", "unrolled.svg", "convergence.svg", "preview.svg"] {
        let one = std::fs::read(dir.path("one").join(name)).expect("one");
        let two = std::fs::read(dir.path("two").join(name)).expect("two");
        assert!(one == two, "{name} differs between 1 and 2 threads");
    }
}

#[test]
fn progress_is_plain_lines_off_a_terminal_every_iteration_verbose_and_silent_quiet() {
    let dir = Scratch::new("progress");
    let obj = small_roof(&dir, 200);
    let m = obj.to_str().expect("utf-8");
    let plain = lamella(&dir.0, &["field", "--mesh", m, "--max-iterations", "10", "--out", "plain"]);
    assert_ok(&plain);
    let log = cli_support::stderr(&plain);
    assert!(!log.contains('\r'), "no progress bar when stderr is not a terminal");
    assert_eq!(log.lines().filter(|l| l.starts_with("iteration")).count(), 1, "one line per 10 iterations:\n{log}");
    assert!(stdout(&plain).contains("after 10 iterations"), "summary on stdout");
    let verbose = lamella(&dir.0, &["field", "--mesh", m, "--max-iterations", "10", "--out", "verbose", "--verbose"]);
    assert_ok(&verbose);
    let log = cli_support::stderr(&verbose);
    assert_eq!(log.lines().filter(|l| l.starts_with("iteration") && l.contains("E_grad")).count(), 10, "{log}");
    let quiet = lamella(&dir.0, &["field", "--mesh", m, "--max-iterations", "10", "--out", "quiet", "--quiet"]);
    assert_ok(&quiet);
    assert!(quiet.stdout.is_empty() && quiet.stderr.is_empty());
}
