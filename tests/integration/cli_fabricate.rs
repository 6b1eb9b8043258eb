//! `lamella fabricate` and `design --thickness`: the workshop files (cut.dxf, cut.svg, bom.csv,
//! utilisation.svg, report.json), strips over 100 % flagged with exit 0 and a warning, bad input
//! refused with exit 2 naming the option, and the same files from `design` as from `fabricate`
//! on its strips.obj.

use crate::cli_support;
use crate::fabrication_support;

use cli_support::{assert_bad_input, assert_ok, lamella, parse_xml, read_json, small_roof, stderr, Scratch};
use dxf::entities::EntityType;
use fabrication_support::helix_pattern;
use std::fmt::Write as _;

/// Writes the helix strips as strips.obj (`g strip_<i>`, vertices left and right alternating).
fn helix_strips_obj(dir: &Scratch) -> std::path::PathBuf {
    let mut text = String::new();
    for strip in helix_pattern() {
        let _ = writeln!(text, "g {}", strip.name);
        for (c, d) in strip.centre.iter().zip(&strip.offsets) {
            let (l, r) = (c + d, c - d);
            let _ = writeln!(text, "v {} {} {}\nv {} {} {}", l.x, l.y, l.z, r.x, r.y, r.z);
        }
    }
    let path = dir.path("strips.obj");
    std::fs::write(&path, text).expect("write strips.obj");
    path
}

fn read(dir: &Scratch, name: &str) -> String {
    std::fs::read_to_string(dir.path(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn fabricate_writes_the_workshop_files() {
    let dir = Scratch::new("fabricate");
    helix_strips_obj(&dir);
    let output = lamella(&dir.0, &["fabricate", "--strips", "strips.obj", "--material", "timber", "--thickness", "6mm", "--stock", "4.8m", "--out", "f"]);
    assert_ok(&output);
    assert!(stderr(&output).is_empty(), "no warning: {}", stderr(&output));
    let report = read_json(&dir.path("f/report.json"));
    let fabrication = &report["fabrication"];
    let pieces = fabrication["pieces"].as_array().expect("pieces");
    assert_eq!(fabrication["strips"].as_array().map(Vec::len), Some(4));
    assert_eq!(fabrication["material"]["youngs_modulus_gpa"].as_f64(), Some(11.0));
    assert_eq!(fabrication["thickness_m"].as_f64(), Some(0.006));
    assert!(fabrication["overstressed"].as_array().is_some_and(Vec::is_empty));
    let yield_ = fabrication["material_yield"].as_f64().expect("yield");
    assert!(yield_ > 0.0 && yield_ <= 1.0);
    // bom.csv and the report list the same pieces; every piece fits a 4.8 m board.
    let bom = read(&dir, "f/bom.csv");
    let rows: Vec<&str> = bom.lines().skip(1).collect();
    assert_eq!(rows.len(), pieces.len());
    for (row, piece) in rows.iter().zip(pieces) {
        let fields: Vec<&str> = row.split(',').collect();
        assert_eq!(Some(fields[0]), piece["id"].as_str());
        assert!(piece["length_m"].as_f64().expect("length") <= 4.8);
        assert_eq!(fields[2], "", "no θ given: family unknown");
    }
    let splices = pieces.iter().filter(|p| p["splice_partners"].as_array().is_some_and(|s| !s.is_empty())).count();
    assert!(splices >= 2, "the long strips were split");
    // cut.dxf reads back; the SVGs are well-formed XML.
    let drawing = dxf::Drawing::load_file(dir.path("f/cut.dxf")).expect("DXF parses");
    let outlines = drawing.entities().filter(|e| e.common.layer == "OUTLINE" && matches!(e.specific, EntityType::Polyline(_))).count();
    assert_eq!(outlines, pieces.len());
    for name in ["f/cut.svg", "f/utilisation.svg"] {
        let root = parse_xml(&read(&dir, name));
        assert_eq!(root.name, "svg", "{name}");
    }
    let preview = parse_xml(&read(&dir, "f/utilisation.svg"));
    let mut quads = Vec::new();
    preview.descendants("polygon", &mut quads);
    let expected: usize = helix_pattern().iter().map(|s| s.centre.len() - 1).sum();
    assert_eq!(quads.len(), expected, "one coloured quad per strip quad");
}

#[test]
fn strips_over_the_allowable_stress_are_flagged_and_the_run_succeeds() {
    let dir = Scratch::new("overstressed");
    helix_strips_obj(&dir);
    let output = lamella(&dir.0, &["fabricate", "--strips", "strips.obj", "--material", "steel", "--thickness", "20mm", "--out", "f"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let warning = stderr(&output);
    assert_eq!(warning.lines().count(), 1, "{warning}");
    assert!(warning.contains("warning") && warning.contains("over 100 %") && warning.contains("strip_3"), "{warning}");
    let report = read_json(&dir.path("f/report.json"));
    let over: Vec<&str> = report["fabrication"]["overstressed"].as_array().expect("list").iter().filter_map(|v| v.as_str()).collect();
    assert!(over.contains(&"strip_3"), "{over:?}");
    let worst = &report["fabrication"]["strips"][3];
    assert!(worst["max_utilisation"].as_f64().expect("utilisation") > 1.0 && worst["overstressed"] == true);
    // The cut sheet labels the overstressed pieces with their utilisation, in red.
    let svg = read(&dir, "f/cut.svg");
    assert!(svg.lines().any(|l| l.contains("class=\"label\"") && l.contains("fill=\"#d00\"") && l.contains("strip_3-1 (")), "flagged label");
    // Custom values: a soft material is never over.
    let soft = lamella(
        &dir.0,
        &["fabricate", "--strips", "strips.obj", "--material", "custom", "--youngs-modulus", "1GPa", "--shear-modulus", "0.1GPa", "--allowable-stress", "1GPa", "--thickness", "20mm", "--out", "g", "-q"],
    );
    assert_ok(&soft);
    let report = read_json(&dir.path("g/report.json"));
    assert_eq!(report["fabrication"]["material"]["name"].as_str(), Some("custom"));
    assert!(report["fabrication"]["overstressed"].as_array().is_some_and(Vec::is_empty));
}

#[test]
fn bad_fabrication_input_names_the_option() {
    let dir = Scratch::new("fabricate-bad");
    helix_strips_obj(&dir);
    let base = ["fabricate", "--strips", "strips.obj", "--out", "f"];
    let cases: [(&[&str], &str); 9] = [
        (&["--material", "cheese", "--thickness", "6mm"], "--material"),
        (&["--thickness", "-6mm"], "--thickness"),
        (&["--thickness", "6 inches"], "--thickness"),
        (&["--thickness", "6mm", "--stock", "0.5m"], "--stock"),
        (&["--thickness", "6mm", "--stock", "4.8m", "--overlap", "3m"], "--stock"),
        (&["--thickness", "6mm", "--stock", "four"], "--stock"),
        (&["--thickness", "6mm", "--stock-width", "0.05m"], "strip_0-1"),
        (&["--material", "custom", "--thickness", "6mm"], "--youngs-modulus"),
        (&["--material", "timber"], "--thickness"),
    ];
    for (extra, needle) in cases {
        let args: Vec<&str> = base.iter().chain(extra).copied().collect();
        assert_bad_input(&dir.0, &args, &[needle]);
    }
    assert!(!dir.path("f").exists(), "nothing written on bad input");
    // A bad flag of design is refused before the field is optimised.
    assert_bad_input(&dir.0, &["design", "--thickness", "0mm", "--out", "d"], &["--thickness"]);
}

#[test]
fn design_writes_the_same_workshop_files_as_fabricate_on_its_strips() {
    let dir = Scratch::new("design-fabricate");
    let obj = small_roof(&dir, 300);
    let m = obj.to_str().expect("utf-8");
    let design = lamella(&dir.0, &["design", "--mesh", m, "--strips", "3", "--width", "0.3", "--max-iterations", "12", "--thickness", "6mm", "--stock", "3m", "--out", "d", "-q"]);
    // Few iterations may leave the family unacceptable (exit 3); the outputs are written either way.
    assert!(matches!(design.status.code(), Some(0 | 3)), "{}", stderr(&design));
    let report = read_json(&dir.path("d/report.json"));
    let theta = report["parameters"]["theta_degrees"].as_f64().expect("θ").to_string();
    assert_ok(&lamella(&dir.0, &["fabricate", "--strips", "d/strips.obj", "--thickness", "6mm", "--stock", "3m", "--theta", &theta, "--out", "f", "-q"]));
    for name in ["cut.dxf", "cut.svg", "bom.csv"] {
        assert!(read(&dir, &format!("d/{name}")) == read(&dir, &format!("f/{name}")), "{name} differs between design and fabricate");
    }
    // Strip ids agree between the 3D strips, the flat pieces and the bill of materials.
    let groups: Vec<String> = read(&dir, "d/strips.obj").lines().filter_map(|l| l.strip_prefix("g ").map(str::to_string)).collect();
    let pieces = report["fabrication"]["pieces"].as_array().expect("pieces");
    assert!(!pieces.is_empty());
    for piece in pieces {
        let strip = piece["strip"].as_str().expect("strip");
        assert!(groups.iter().any(|g| g == strip), "{strip} not in strips.obj");
        assert!(piece["id"].as_str().expect("id").starts_with(&format!("{strip}-")));
        assert_eq!(piece["family"].as_str(), Some("pseudo-geodesic"));
    }
    assert!(dir.path("d/utilisation.svg").exists());
}
