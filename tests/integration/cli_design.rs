//! The default run (`lamella` without arguments, the README's first command): its report.json
//! meets the paper's quality bounds, its SVGs are well-formed, its cut sheet has one labelled,
//! non-overlapping outline per strip; an existing output directory needs --force.

use crate::cli_support;

use cli_support::{assert_ok, lamella, parse_svg, polygon_points, read_json, small_roof, stderr, Element, Scratch};
use std::path::Path;

/// Axis-aligned bounding box of points: (min, max).
fn bounding_box(points: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    points.iter().fold(([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]), |(lo, hi), p| {
        ([lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])])
    })
}

/// Checks the cut sheet: one polygon and one label per strip, no two outlines' boxes overlapping,
/// and each label's length and width matching the outline (mm).
fn check_cut_sheet(path: &Path, strip_names: &[String], lengths_m: &[f64]) {
    let root = parse_svg(path);
    assert!(root.attribute("width").is_some_and(|w| w.ends_with("mm")), "sheet in millimetres");
    let mut polygons: Vec<&Element> = Vec::new();
    root.descendants("polygon", &mut polygons);
    let mut labels: Vec<&Element> = Vec::new();
    root.descendants("text", &mut labels);
    assert_eq!(polygons.len(), strip_names.len(), "one outline per strip");
    assert_eq!(labels.len(), strip_names.len(), "one label per strip");
    let boxes: Vec<_> = polygons.iter().map(|p| bounding_box(&polygon_points(p))).collect();
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            let apart = a.1[0] <= b.0[0] || b.1[0] <= a.0[0] || a.1[1] <= b.0[1] || b.1[1] <= a.0[1];
            assert!(apart, "outlines overlap: {a:?} {b:?}");
        }
    }
    for ((name, length), (polygon, label)) in strip_names.iter().zip(lengths_m).zip(polygons.iter().zip(&labels)) {
        assert_eq!(polygon.attribute("id"), Some(name.as_str()));
        assert!(label.text.starts_with(name.as_str()) && label.text.contains("width") && label.text.ends_with("mm"), "label {:?}", label.text);
        // "length N mm": the strip's length from report.json, in millimetres.
        let words: Vec<&str> = label.text.split_whitespace().collect();
        let at = words.iter().position(|w| *w == "length").expect("length in label");
        let mm: f64 = words[at + 1].parse().expect("length number");
        assert!((mm - 1000.0 * length).abs() <= 0.5, "{name}: label {mm} mm, report {length} m");
        // The outline spans at least the centre line's length (the strip is straight when flat).
        let (low, high) = bounding_box(&polygon_points(polygon));
        assert!(high[0] - low[0] >= mm - 1.0, "{name}: outline {} mm long", high[0] - low[0]);
    }
}

#[test]
fn default_run_meets_the_quality_bounds_and_writes_well_formed_files() {
    let dir = Scratch::new("default");
    let output = lamella(&dir.0, &[]);
    assert_ok(&output);
    let out = dir.path("lamella-out");
    for name in ["field.csv", "curves.obj", "strips.obj", "rulings.obj", "report.json", "unrolled.svg", "convergence.svg", "preview.svg", "session.bin", "view.html"] {
        assert!(out.join(name).is_file(), "missing {name}");
    }
    let report = read_json(&out.join("report.json"));
    let strips = report["strips"]["strips"].as_array().expect("strips array");
    assert!(strips.len() >= 20, "20 levels give at least 20 strips, got {}", strips.len());
    for s in strips {
        let diff = s["max_diff_theta_degrees"].as_f64().expect("diff θ");
        let straight = s["e_straight"].as_f64().expect("e_straight");
        assert!(diff <= 2.0, "{}: max diff θ {diff}°", s["name"]);
        let plane = s["max_quad_angle_error_degrees"].as_f64().expect("strip plane error");
        assert!(plane <= 2.0, "{}: strip plane {plane}° off", s["name"]);
        assert!(straight <= 1e-3, "{}: e_straight {straight}", s["name"]);
        assert!(s["length_m"].as_f64().expect("length") > 0.0);
    }
    assert_eq!(report["strips"]["overall"]["strip_count"].as_u64(), Some(strips.len() as u64));
    assert_eq!(report["strips"]["acceptable"], true, "{}", report["strips"]["verdict_message"]);
    assert_eq!(report["parameters"]["start"]["kind"], "search");
    // The built-in roof (2,970 vertices) is searched on a coarsening of about half its vertices.
    let proxy = report["parameters"]["start"]["proxy_vertices"].as_u64().expect("proxy vertex count");
    assert!((1250..=1500).contains(&proxy), "{proxy}");
    // Per-iteration history: iterations 0, 1, …, n without gaps.
    let history = report["field"]["history"].as_array().expect("history");
    let iterations = report["field"]["iterations"].as_u64().expect("iterations");
    assert_eq!(history.len() as u64, iterations + 1);
    assert!(history.iter().enumerate().all(|(i, h)| h["iteration"].as_u64() == Some(i as u64)));
    assert!(report["timings_s"]["total"].as_f64().expect("timing") > 0.0);

    let names: Vec<String> = strips.iter().map(|s| s["name"].as_str().expect("name").to_string()).collect();
    let lengths: Vec<f64> = strips.iter().map(|s| s["length_m"].as_f64().expect("length")).collect();
    check_cut_sheet(&out.join("unrolled.svg"), &names, &lengths);
    let convergence = parse_svg(&out.join("convergence.svg"));
    let mut lines = Vec::new();
    convergence.descendants("polyline", &mut lines);
    assert_eq!(lines.len(), 5, "E_angle and the four other curves");
    let preview = parse_svg(&out.join("preview.svg"));
    let mut facets = Vec::new();
    preview.descendants("polygon", &mut facets);
    assert!(facets.len() > 3000, "surface triangles and strip quads");

    // The existing directory is refused without --force and left as it was.
    let before = std::fs::read(out.join("report.json")).expect("report");
    let refused = lamella(&dir.0, &["design", "--max-iterations", "1", "--strips", "1"]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(stderr(&refused).contains("already exists") && stderr(&refused).contains("--force"), "{}", stderr(&refused));
    assert_eq!(std::fs::read(out.join("report.json")).expect("report"), before);
    let forced = lamella(&dir.0, &["design", "--max-iterations", "3", "--strips", "2", "--width", "0.3", "--force", "--quiet"]);
    assert_ok(&forced);
    assert!(forced.stdout.is_empty(), "--quiet prints nothing");
    let replaced = read_json(&out.join("report.json"));
    assert_eq!(replaced["field"]["iterations"].as_u64(), Some(3));
    assert_eq!(replaced["strips"]["width_m"].as_f64(), Some(0.3));
    // No staging directories are left beside the output.
    let leftovers: Vec<_> = std::fs::read_dir(&dir.0).expect("dir").filter_map(Result::ok).filter(|e| e.file_name() != "lamella-out").collect();
    assert!(leftovers.is_empty(), "left behind: {leftovers:?}");
}

#[test]
fn a_surface_without_the_family_exits_three_with_the_verdict() {
    // A sphere cap and θ = 10°: the P-curves are small circles (spherical radius 2θ) that cannot
    // cover the cap (paper Sec. 3.3). The design writes its outputs and says so: exit 3.
    let dir = Scratch::new("no-family");
    let cap = lamella::surfaces::SphereCap { radius: 10.0, cap_angle: 35f64.to_radians(), target_vertices: 1200, irregularity: 0.25, seed: 2 };
    let mesh = lamella::surfaces::sphere_cap(&cap).expect("valid cap").into_mesh().expect("valid mesh");
    mesh.write_obj(std::fs::File::create(dir.path("cap.obj")).expect("create")).expect("write");
    let output = lamella(&dir.0, &["design", "--mesh", "cap.obj", "--theta", "10", "--strips", "8", "--out", "d"]);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    let last = stderr(&output).lines().last().unwrap_or_default().to_string();
    assert!(last.starts_with("lamella: no acceptable family: strip"), "{last}");
    assert!(last.contains("worst: strip") && last.contains("° off") && last.contains("try"), "{last}");
    // The remedy of Sec. 3.3, tried: a short reshape within 2 % of the diagonal, and its outcome.
    let report = read_json(&dir.path("d/report.json"));
    let trial = &report["reshape_trial"];
    let reshaped = trial["acceptable"].as_bool().expect("the trial's verdict");
    assert!(trial["deviation_percent"].as_f64().expect("deviation") <= 2.0 * (1.0 + 1e-9), "{trial}");
    if reshaped {
        assert!(last.contains("lamella reshape --session d/session.bin --theta 10 --tolerance"), "{last}");
    } else {
        assert!(last.contains("a trial reshape within 2 % of the surface's diagonal did not make the strips acceptable either"), "{last}");
    }
    assert_eq!(report["strips"]["acceptable"], false);
    assert!(report["strips"]["overall"]["max_quad_angle_error_degrees"].as_f64().expect("error") > 2.0);
    assert!(report["parameters"]["start"]["candidates"].as_array().is_some_and(|c| !c.is_empty()), "the search's candidates are listed");
    // A looser tolerance does not make it acceptable when quads flip or miss by more.
    let strict = lamella(&dir.0, &["design", "--mesh", "cap.obj", "--theta", "60", "--strips", "8", "--tolerance", "0.001", "--out", "t"]);
    assert_eq!(strict.status.code(), Some(3), "a 0.001° tolerance is missed: {}", stderr(&strict));
}

#[test]
fn where_every_start_is_nearly_straight_the_design_goes_on_and_says_so() {
    // A helicoid at θ = 60° (see design_default_start): every candidate's family is nearly
    // straight over most of the surface. The design continues from the best of them (before, it
    // stopped with exit 2 and no outputs), warns, marks the start in report.json, and the strips'
    // verdict gives the exit code.
    let dir = Scratch::new("fallback");
    let mesh = crate::design_default_start::helicoid(2000);
    mesh.write_obj(std::fs::File::create(dir.path("helicoid.obj")).expect("create")).expect("write");
    let output = lamella(&dir.0, &["design", "--mesh", "helicoid.obj", "--theta", "60", "--out", "d"]);
    let err = stderr(&output);
    assert!(matches!(output.status.code(), Some(0 | 3)), "{err}");
    assert!(err.contains("warning: every start leads to nearly straight level curves"), "{err}");
    let report = read_json(&dir.path("d/report.json"));
    let start = &report["parameters"]["start"];
    assert_eq!(start["fallback"], true, "{start}");
    let winner = start["winner"].as_u64().expect("a winner") as usize;
    let reason = start["candidates"][winner]["rejected"].as_str().expect("the winner's rejection");
    assert!(reason.contains("nearly straight"), "{reason}");
    // The exit code is the strips' verdict.
    let acceptable = report["strips"]["acceptable"].as_bool().expect("verdict");
    assert_eq!(output.status.code(), Some(if acceptable { 0 } else { 3 }), "{err}");
    assert!(dir.path("d/strips.obj").is_file() && dir.path("d/field.csv").is_file());
}

#[test]
fn family_names_and_their_angles_must_agree() {
    let dir = Scratch::new("family");
    for (args, needle) in [
        (vec!["design", "--family", "geodesic", "--theta", "60"], "--family geodesic means θ = 90°"),
        (vec!["design", "--family", "asymptotic", "--theta", "30"], "--family asymptotic means θ = 0°"),
        (vec!["design", "--family", "pseudo-geodesic", "--theta", "90"], "geodesic family"),
        (vec!["design", "--family", "spiral"], "is not asymptotic, geodesic or pseudo-geodesic"),
        (vec!["design", "--direction", "0,0,0"], "--direction = 0,0,0"),
        (vec!["design", "--direction", "1,2"], "is not three numbers"),
        (vec!["design", "--tolerance", "0"], "--tolerance = 0"),
    ] {
        let output = lamella(&dir.0, &args);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {}", stderr(&output));
        assert!(stderr(&output).contains(needle), "{args:?}: `{needle}` not in {}", stderr(&output));
    }
}

#[test]
fn a_large_mesh_is_searched_on_a_coarsening_and_designed_in_full() {
    // 6,000 vertices: the start search probes its candidates on a 1,500-vertex coarsening, then
    // the winner's field is carried to the full mesh and converged there.
    let dir = Scratch::new("proxy");
    small_roof(&dir, 6000);
    let output = lamella(&dir.0, &["design", "--mesh", "roof.obj", "--strips", "12", "--out", "d"]);
    assert_ok(&output);
    let line = stderr(&output).lines().find(|l| l.starts_with("start search")).unwrap_or_default().to_string();
    assert!(line.starts_with("start search on a ") && line.contains("-vertex coarsening"), "{line}");
    let report = read_json(&dir.path("d/report.json"));
    let proxy = report["parameters"]["start"]["proxy_vertices"].as_u64().expect("proxy vertex count");
    assert!((1250..=1500).contains(&proxy), "{proxy}");
    assert!(line.contains(&format!("on a {proxy}-vertex")), "{line}");
    let values = std::fs::read_to_string(dir.path("d/field.csv")).expect("field").lines().filter(|l| l.parse::<f64>().is_ok()).count();
    assert!(values > 5000, "the field covers the full mesh: {values} values");
    assert_eq!(report["strips"]["acceptable"], true, "{}", report["strips"]["verdict_message"]);
    assert_eq!(report["strips"]["overall"]["flipped_quads"].as_u64(), Some(0));
}
