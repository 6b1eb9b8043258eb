//! `lamella net`: the files of a two-family net, their geometry read back from outside, the
//! family syntax and its errors.

use crate::cli_support;

use cli_support::{assert_bad_input, lamella, read_json, stderr, Scratch};
use lamella::surfaces::{hyperbolic_paraboloid, HyperbolicParaboloid};
use std::path::PathBuf;

/// A hyperbolic paraboloid z = xy/5 over [−5, 5]² as OBJ.
fn hypar_obj(dir: &Scratch) -> PathBuf {
    let surface = HyperbolicParaboloid { c: 5.0, half_width: 5.0, target_vertices: 900, irregularity: 0.4, seed: 5 };
    let mesh = hyperbolic_paraboloid(&surface).expect("surface").into_mesh().expect("mesh");
    let path = dir.path("hypar.obj");
    mesh.write_obj(std::fs::File::create(&path).expect("create")).expect("write");
    path
}

/// Vertex positions, faces and polylines (as 0-based index lists) of an OBJ text.
type ObjElements = (Vec<[f64; 3]>, Vec<Vec<usize>>, Vec<Vec<usize>>);

/// `v` lines, `f` lines (as index lists) and `l` lines of an OBJ text.
fn obj_elements(text: &str) -> ObjElements {
    let (mut v, mut f, mut l) = (Vec::new(), Vec::new(), Vec::new());
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let p: Vec<f64> = words.map(|w| w.parse().expect("number")).collect();
                v.push([p[0], p[1], p[2]]);
            }
            Some("f") => f.push(words.map(|w| w.parse::<usize>().expect("index") - 1).collect()),
            Some("l") => l.push(words.map(|w| w.parse::<usize>().expect("index") - 1).collect()),
            _ => {}
        }
    }
    (v, f, l)
}

#[test]
fn the_asymptotic_net_of_a_hyperbolic_paraboloid_is_written_with_its_nodes() {
    let dir = Scratch::new("net-aa");
    let mesh = hypar_obj(&dir);
    let output = lamella(&dir.0, &["net", "--mesh", mesh.to_str().expect("path"), "--families", "A,A", "--lines", "6", "--out", "out", "--quiet"]);
    let code = output.status.code();
    assert!(code == Some(0) || code == Some(3), "exit {code:?}: {}", stderr(&output));
    let out = dir.path("out");
    for name in ["curves_0.obj", "curves_1.obj", "strips_0.obj", "strips_1.obj", "net.obj", "nodes.csv", "unrolled.svg", "preview.svg", "view.html", "report.json"] {
        assert!(out.join(name).is_file(), "{name} missing");
    }
    // The net's vertices lie on z = xy/5 and its quads are flat parallelograms of the rulings:
    // each quad edge runs along x or along y.
    let (vertices, quads, lines) = obj_elements(&std::fs::read_to_string(out.join("net.obj")).expect("net.obj"));
    assert!(quads.len() >= 16, "{} quads", quads.len());
    for p in &vertices {
        assert!((p[2] - p[0] * p[1] / 5.0).abs() < 0.05, "{p:?} is off the surface");
    }
    for quad in &quads {
        for k in 0..4 {
            let (a, b) = (vertices[quad[k]], vertices[quad[(k + 1) % 4]]);
            let (dx, dy) = ((b[0] - a[0]).abs(), (b[1] - a[1]).abs());
            assert!(dx.min(dy) <= 0.02 * dx.max(dy), "a quad edge runs diagonally: {a:?} → {b:?}");
        }
    }
    assert!(!lines.is_empty(), "no rows or columns");
    // nodes.csv: one row per crossing of two strips, on the surface.
    let nodes = std::fs::read_to_string(out.join("nodes.csv")).expect("nodes.csv");
    let mut rows = nodes.lines();
    assert_eq!(
        rows.next(),
        Some(
            "strip_0,strip_1,arc_length_0,arc_length_1,x,y,z,axis_x,axis_y,axis_z,ruling_angle_degrees,\
             conical_curvature_0,darboux_angle_degrees_0,binormal_offset_0,singular_point_near_0,\
             conical_curvature_1,darboux_angle_degrees_1,binormal_offset_1,singular_point_near_1"
        )
    );
    let mut count = 0;
    for row in rows {
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells.len(), 19, "{row}");
        assert!(cells[0].starts_with("f0_strip_") && cells[1].starts_with("f1_strip_"), "{row}");
        // Sec. 5.1 per strip: k, atan |k| in degrees and Prop. 2's offset, empty where the strip is
        // straight there (the rulings of z = xy/5 are), and whether the ruling's singular point is near.
        for k in 0..2 {
            let d = &cells[11 + 4 * k..15 + 4 * k];
            if let Ok(conical) = d[0].parse::<f64>() {
                let darboux: f64 = d[1].parse().expect("angle with k");
                assert!((darboux - conical.abs().atan().to_degrees()).abs() < 1e-9 && d[2].parse::<f64>().expect("offset") >= 0.0, "{row}");
            } else {
                assert!(d[0].is_empty() && d[1].is_empty() && d[2].is_empty(), "{row}");
            }
            assert!(d[3] == "0" || d[3] == "1", "{row}");
        }
        let numbers: Vec<f64> = cells[2..11].iter().map(|c| c.parse().expect("number")).collect();
        assert!(numbers[0] >= 0.0 && numbers[1] >= 0.0, "{row}");
        assert!((numbers[4] - numbers[2] * numbers[3] / 5.0).abs() < 0.05, "{row}");
        let axis = (numbers[5] * numbers[5] + numbers[6] * numbers[6] + numbers[7] * numbers[7]).sqrt();
        assert!((axis - 1.0).abs() < 1e-6 && (0.0..=90.0).contains(&numbers[8]), "{row}");
        count += 1;
    }
    assert!(count >= 9, "{count} nodes");
    let report = read_json(&out.join("report.json"));
    assert_eq!(report["nodes"]["count"].as_u64(), Some(count));
    assert!(report["intersection"]["mean_degrees"].as_f64().expect("mean") > 60.0, "{report}");
    let svg = std::fs::read_to_string(out.join("unrolled.svg")).expect("svg");
    assert_eq!(svg.matches("<circle class=\"node\"").count(), 2 * count as usize, "one mark per node on each strip");
}

#[test]
fn family_names_and_angles_are_checked() {
    let dir = Scratch::new("net-bad");
    assert_bad_input(&dir.0, &["net", "--families", "P60", "--out", "o"], &["--families", "two families"]);
    assert_bad_input(&dir.0, &["net", "--families", "A,A,G,G", "--out", "o"], &["--families", "a 3-web three"]);
    assert_bad_input(&dir.0, &["net", "--families", "P60,X", "--out", "o"], &["--families", "'X'"]);
    assert_bad_input(&dir.0, &["net", "--families", "P200,G", "--out", "o"], &["--families", "P200"]);
    assert_bad_input(&dir.0, &["net", "--families", "A,A", "--min-angle", "95", "--out", "o"], &["min_intersection_degrees"]);
}

#[test]
fn a_resumed_net_ends_where_an_uninterrupted_one_does() {
    let dir = Scratch::new("net-resume");
    let mesh = hypar_obj(&dir);
    let mesh = mesh.to_str().expect("path");
    let run = |args: &[&str]| {
        let output = lamella(&dir.0, &[args, &["--lines", "6", "--quiet"][..]].concat());
        assert!(matches!(output.status.code(), Some(0 | 3)), "{}", stderr(&output));
    };
    run(&["net", "--mesh", mesh, "--families", "A,A", "--max-iterations", "9", "--out", "whole"]);
    run(&["net", "--mesh", mesh, "--families", "A,A", "--max-iterations", "4", "--out", "first"]);
    run(&["net", "--resume", "first/net.bin", "--max-iterations", "9", "--out", "rest"]);
    let read = |path: &str| std::fs::read(dir.path(path)).expect(path);
    assert_eq!(read_json(&dir.path("first/report.json"))["iterations"].as_u64(), Some(4));
    assert_eq!(read_json(&dir.path("rest/report.json"))["iterations"], read_json(&dir.path("whole/report.json"))["iterations"]);
    for file in ["curves_0.obj", "curves_1.obj", "net.obj"] {
        assert_eq!(read(&format!("rest/{file}")), read(&format!("whole/{file}")), "{file} differs");
    }
    assert_bad_input(&dir.0, &["net", "--resume", "hypar.obj", "--out", "x"], &["hypar.obj", "not a usable net session"]);
    let clash = lamella(&dir.0, &["net", "--resume", "first/net.bin", "--families", "G,G", "--out", "y"]);
    assert_eq!(clash.status.code(), Some(2), "{}", stderr(&clash));
}

#[test]
fn a_net_crossing_below_the_minimum_angle_exits_3_and_says_where() {
    // The rulings of z = xy/5 over [−5, 5]² cross at 60° in the corners and at 90° in the middle:
    // a minimum of 85° cannot be held by an A,A net, so the verdict must say so.
    let dir = Scratch::new("net-min-angle");
    let mesh = hypar_obj(&dir);
    let output = lamella(&dir.0, &["net", "--mesh", mesh.to_str().expect("path"), "--families", "A,A", "--min-angle", "85", "--lines", "6", "--out", "out", "--quiet"]);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    let report = read_json(&dir.path("out").join("report.json"));
    let min = report["intersection"]["min_degrees"].as_f64().expect("min_degrees");
    let families_missed = stderr(&output).contains("family A:");
    assert!(min < 84.0 || families_missed, "exit 3 with the families crossing at {min}° and no family missed");
    if min < 84.0 {
        assert!(stderr(&output).contains(&format!("the first two families cross at {min:.1}°")), "{}", stderr(&output));
    }
}

#[test]
fn a_net_with_a_material_writes_workshop_files_for_both_families_with_the_nodes() {
    let dir = Scratch::new("net-fabrication");
    let mesh = hypar_obj(&dir);
    let args = ["net", "--mesh", mesh.to_str().expect("path"), "--families", "A,A", "--lines", "6", "--width", "0.12", "--material", "plywood", "--thickness", "4mm", "--stock", "4m", "--out", "out", "--quiet"];
    let output = lamella(&dir.0, &args);
    let code = output.status.code();
    assert!(code == Some(0) || code == Some(3), "exit {code:?}: {}", stderr(&output));
    let out = dir.path("out");
    for name in ["cut.dxf", "cut.svg", "bom.csv", "utilisation.svg"] {
        assert!(out.join(name).is_file(), "{name} missing");
    }
    // Nodes per strip, from nodes.csv: (strip name, arc length along it).
    let nodes_csv = std::fs::read_to_string(out.join("nodes.csv")).expect("nodes.csv");
    let mut nodes: Vec<(String, f64)> = Vec::new();
    for line in nodes_csv.lines().skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        nodes.push((cells[0].to_string(), cells[2].parse().expect("arc length")));
        nodes.push((cells[1].to_string(), cells[3].parse().expect("arc length")));
    }
    assert!(nodes.len() >= 2 * 16, "{} node ends", nodes.len());
    // The bill of materials covers both families, each with its own θ (asymptotic: 0°), and the
    // pieces of a strip chain along it with 0.3 m overlaps that hold no node.
    let bom = std::fs::read_to_string(out.join("bom.csv")).expect("bom.csv");
    let rows: Vec<Vec<String>> = bom.lines().skip(1).map(|l| l.split(',').map(str::to_string).collect()).collect();
    for k in 0..2 {
        assert!(rows.iter().any(|r| r[1].starts_with(&format!("f{k}_strip_"))), "no piece of family {k}");
    }
    assert!(rows.iter().all(|r| r[2] == "asymptotic" && r[3].parse::<f64>() == Ok(0.0)), "{bom}");
    let overlap = 0.3;
    let mut spliced = 0;
    let mut start = 0.0;
    for (i, row) in rows.iter().enumerate() {
        let length: f64 = row[4].parse().expect("length");
        assert!(length <= 4.0 + 1e-9, "{} is {length} m long", row[0]);
        let end = start + length;
        let continues = rows.get(i + 1).is_some_and(|next| next[1] == row[1]);
        if continues {
            spliced += 1;
            let inside: Vec<f64> = nodes.iter().filter(|(s, a)| *s == row[1] && *a >= end - overlap && *a <= end).map(|n| n.1).collect();
            assert!(inside.is_empty(), "the splice of {} over [{:.3}, {end:.3}] m holds nodes at {inside:?}", row[0], end - overlap);
            start = end - overlap;
        } else {
            start = 0.0;
        }
    }
    assert!(spliced >= 4, "only {spliced} splices: the strips should outgrow 4 m boards");
    // Every node is marked on both of its strips: a circle on the MARKS layer each (or two where
    // it falls in a splice's overlap).
    let dxf = std::fs::read_to_string(out.join("cut.dxf")).expect("cut.dxf");
    let lines: Vec<&str> = dxf.lines().map(str::trim).collect();
    let circles = lines.windows(4).filter(|w| w[0] == "0" && w[1] == "CIRCLE" && w[2] == "8" && w[3] == "MARKS").count();
    assert!(circles >= nodes.len(), "{circles} node marks for {} node ends", nodes.len());
    let report = read_json(&out.join("report.json"));
    assert_eq!(report["fabrication"]["pieces"].as_array().map(Vec::len), Some(rows.len()));
}

/// The OBJ's `l` polylines under each `o` name.
fn obj_groups(text: &str) -> std::collections::BTreeMap<String, Vec<Vec<usize>>> {
    let mut groups = std::collections::BTreeMap::new();
    let mut name = String::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("o") => name = words.next().unwrap_or("").to_string(),
            Some("l") => groups.entry(name.clone()).or_insert_with(Vec::new).push(words.map(|w| w.parse::<usize>().expect("index") - 1).collect()),
            _ => {}
        }
    }
    groups
}

#[test]
fn an_aag_web_is_written_as_triangles_with_its_three_families_and_a_kagome_pattern_as_triangles_and_hexagons() {
    let dir = Scratch::new("net-aag");
    let mesh = hypar_obj(&dir);
    let mesh = mesh.to_str().expect("path");
    for (out, kagome) in [("web", false), ("kagome", true)] {
        let mut args = vec!["net", "--mesh", mesh, "--families", "A,A,G", "--lines", "6", "--out", out, "--quiet"];
        if kagome {
            args.push("--kagome");
        }
        let output = lamella(&dir.0, &args);
        let code = output.status.code();
        assert!(code == Some(0) || code == Some(3), "exit {code:?}: {}", stderr(&output));
        let out = dir.path(out);
        for name in ["curves_2.obj", "strips_2.obj", "net.obj", "nodes.csv", "unrolled.svg", "report.json"] {
            assert!(out.join(name).is_file(), "{name} missing");
        }
        let text = std::fs::read_to_string(out.join("net.obj")).expect("net.obj");
        let (vertices, faces, _) = obj_elements(&text);
        for p in &vertices {
            assert!((p[2] - p[0] * p[1] / 5.0).abs() < 0.05, "{p:?} is off the surface");
        }
        let groups = obj_groups(&text);
        assert!(["rows", "columns", "diagonals"].iter().all(|g| groups.get(*g).is_some_and(|lines| !lines.is_empty())), "{:?}", groups.keys());
        // Each vertex lies on the polylines of two families (Kagome) or two or three (a 3-web).
        let mut families_at = vec![0usize; vertices.len()];
        for lines in groups.values() {
            let mut on = vec![false; vertices.len()];
            lines.iter().flatten().for_each(|&v| on[v] = true);
            on.iter().enumerate().filter(|(_, o)| **o).for_each(|(v, _)| families_at[v] += 1);
        }
        let report = read_json(&out.join("report.json"));
        let web = &report["web"];
        assert_eq!(web["kagome"].as_bool(), Some(kagome), "{report}");
        assert!(web["residual_max"].as_f64().expect("residual") <= 1e-6, "{report}");
        if kagome {
            assert!(families_at.iter().all(|&n| n == 2), "a Kagome vertex on {:?} families", families_at.iter().find(|&&n| n != 2));
            assert!(faces.iter().all(|f| f.len() == 3 || f.len() == 6) && faces.iter().any(|f| f.len() == 6), "faces of {:?} sides", faces.iter().map(Vec::len).collect::<std::collections::BTreeSet<_>>());
        } else {
            assert!(families_at.iter().all(|&n| n == 2 || n == 3) && families_at.iter().filter(|&&n| n == 3).count() >= 10);
            assert!(faces.len() >= 20 && faces.iter().all(|f| f.len() == 3), "{} faces", faces.len());
            // The diagonals of a 3-web pass through vertices where rows and columns cross.
            assert!(groups["diagonals"].iter().flatten().all(|&v| families_at[v] >= 2));
        }
        assert_eq!(report["web"]["hexagons"].as_u64(), Some(faces.iter().filter(|f| f.len() == 6).count() as u64));
        // nodes.csv names strips of every pair of families.
        let nodes = std::fs::read_to_string(out.join("nodes.csv")).expect("nodes.csv");
        let pairs: std::collections::BTreeSet<(String, String)> = nodes
            .lines()
            .skip(1)
            .map(|row| {
                let cells: Vec<&str> = row.split(',').collect();
                (cells[0][..2].to_string(), cells[1][..2].to_string())
            })
            .collect();
        assert!(pairs.contains(&("f0".into(), "f2".into())) && pairs.contains(&("f1".into(), "f2".into())), "{pairs:?}");
        assert_eq!(pairs.contains(&("f0".into(), "f1".into())), true, "{pairs:?}");
    }
    assert_bad_input(&dir.0, &["net", "--mesh", mesh, "--families", "A,A", "--kagome", "--out", "o"], &["--kagome", "three"]);
    // optimise reads the web back (rows, columns, diagonals) and makes its diagonals geodesic.
    assert_bad_input(&dir.0, &["optimise", "--net", "web/net.obj", "--types", "A,A", "--reference", mesh, "--out", "o"], &["2 families for a net of 3"]);
    let output = lamella(&dir.0, &["optimise", "--net", "web/net.obj", "--types", "A,A,G", "--reference", mesh, "--out", "opt", "--quiet"]);
    assert!(matches!(output.status.code(), Some(0 | 3)), "{}", stderr(&output));
    let text = std::fs::read_to_string(dir.path("opt/net.obj")).expect("net.obj");
    let (vertices, faces, _) = obj_elements(&text);
    assert!(obj_groups(&text).contains_key("diagonals") && !faces.is_empty() && faces.iter().all(|f| f.len() == 3), "{} faces", faces.len());
    // The diagonals' discrete binormals against the exact normal of z = xy/5: geodesic to 1°.
    let normal = |p: [f64; 3]| {
        let n = [-p[1] / 5.0, -p[0] / 5.0, 1.0];
        let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        n.map(|c| c / length)
    };
    let mut worst: f64 = 0.0;
    for line in &obj_groups(&text)["diagonals"] {
        for w in line.windows(3) {
            let [a, b, c] = [w[0], w[1], w[2]].map(|v| vertices[v]);
            let (e, f) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - b[0], c[1] - b[1], c[2] - b[2]]);
            let binormal = [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]];
            let length = (binormal.iter().map(|x| x * x).sum::<f64>()).sqrt();
            let n = normal(b);
            let cosine = (binormal[0] * n[0] + binormal[1] * n[1] + binormal[2] * n[2]) / length;
            worst = worst.max(cosine.abs().min(1.0).asin().to_degrees());
        }
    }
    assert!(worst <= 1.0, "a diagonal's binormal is {worst:.2}° off 90° to the exact normal");
    let report = read_json(&dir.path("opt/report.json"));
    assert_eq!(report["families"].as_array().map(Vec::len), Some(3), "{report}");
}

/// `--start-field` per family replaces the default start: on z = xy/5 the heights x and y, whose
/// level sets are the two families of rulings, give the AA net of the rulings themselves.
#[test]
fn a_net_starts_from_the_fields_given_per_family() {
    let dir = Scratch::new("net-start-fields");
    let mesh_path = hypar_obj(&dir);
    let (vertices, _, _) = obj_elements(&std::fs::read_to_string(&mesh_path).expect("hypar.obj"));
    for (name, axis) in [("x.csv", 0), ("y.csv", 1)] {
        let values: String = vertices.iter().map(|p| format!("{}\n", p[axis])).collect();
        std::fs::write(dir.path(name), values).expect("write");
    }
    let mesh = mesh_path.to_str().expect("path");
    let output = lamella(&dir.0, &["net", "--mesh", mesh, "--families", "A,A", "--start-field", "x.csv", "--start-field", "y.csv", "--lines", "6", "--out", "out", "--quiet"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let report = read_json(&dir.path("out/report.json"));
    assert!(report.get("start").is_none(), "no default start was searched: {}", report["start"]);
    // Rows run along x = const (the first field's levels), columns along y = const: every edge
    // of a quad keeps x or y to a few millimetres.
    let (net, quads, _) = obj_elements(&std::fs::read_to_string(dir.path("out/net.obj")).expect("net.obj"));
    assert!(quads.len() >= 16, "{} quads", quads.len());
    for quad in &quads {
        for k in 0..4 {
            let (a, b) = (net[quad[k]], net[quad[(k + 1) % 4]]);
            assert!((a[0] - b[0]).abs() < 0.01 || (a[1] - b[1]).abs() < 0.01, "edge {a:?} → {b:?} runs along neither ruling");
        }
    }
    assert_bad_input(&dir.0, &["net", "--mesh", mesh, "--families", "A,A", "--start-field", "x.csv", "--out", "o"], &["--start-field", "one per family", "got 1"]);
    std::fs::write(dir.path("short.csv"), "1\n2\n").expect("write");
    assert_bad_input(&dir.0, &["net", "--mesh", mesh, "--families", "A,A", "--start-field", "x.csv", "--start-field", "short.csv", "--out", "o"], &["short.csv", "2 values"]);
}

#[test]
fn where_every_start_pair_is_nearly_straight_the_net_goes_on_and_says_so() {
    // The helicoid of design_default_start at θ = 60°: before, `net` stopped with exit 2 ("no
    // candidate start"); it now continues from the best pair, warns, marks report.json's start,
    // and writes the net, whose verdict gives the exit code.
    let dir = Scratch::new("net-fallback");
    let mesh = crate::design_default_start::helicoid(1500);
    mesh.write_obj(std::fs::File::create(dir.path("helicoid.obj")).expect("create")).expect("write");
    let output = lamella(&dir.0, &["net", "--mesh", "helicoid.obj", "--families", "P60,P60", "--out", "n"]);
    let err = stderr(&output);
    assert!(matches!(output.status.code(), Some(0 | 3)), "{err}");
    assert!(err.contains("warning: every start pair has a nearly straight family"), "{err}");
    let report = read_json(&dir.path("n/report.json"));
    let start = &report["start"];
    assert_eq!(start["fallback"], true, "{start}");
    let winner = start["winner"].as_u64().expect("a winner") as usize;
    assert!(start["candidates"][winner]["rejected"].as_str().is_some_and(|r| r.contains("nearly straight")), "{start}");
    for file in ["net.obj", "nodes.csv", "curves_0.obj", "strips_1.obj"] {
        assert!(dir.path(&format!("n/{file}")).is_file(), "{file} missing");
    }
}
