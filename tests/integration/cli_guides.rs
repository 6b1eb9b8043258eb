//! The three ways into a field from the command line (paper Sec. 3.2.1–3.2.2): `lamella trace`
//! writes guide P-curves that `field --guides-file` starts from, `design --guides N` traces and
//! starts in one go, and `design --strokes` fits sketched strokes and estimates θ from them.

use crate::cli_support;

use cli_support::{assert_ok, lamella, read_json, small_roof, stderr, Scratch};
use lamella::mesh::{TriMesh, Vec3};
use serde_json::Value;

/// Positions of each guide in a guides.json.
fn guide_positions(guides: &Value) -> Vec<Vec<Vec3>> {
    let guides = guides["guides"].as_array().expect("guides");
    guides
        .iter()
        .map(|g| {
            let points = g["points"].as_array().expect("points");
            points
                .iter()
                .map(|p| {
                    let x: Vec<f64> = p["position"].as_array().expect("position").iter().map(|v| v.as_f64().expect("number")).collect();
                    Vec3::new(x[0], x[1], x[2])
                })
                .collect()
        })
        .collect()
}

/// The unit normal at a point on the edge `[a, b]`: the interpolated vertex normals.
fn edge_normal(mesh: &TriMesh, point: &Value) -> Vec3 {
    let edge: Vec<usize> = point["edge"].as_array().expect("edge").iter().map(|v| v.as_u64().expect("index") as usize).collect();
    let t = point["t"].as_f64().expect("t");
    let n = mesh.vertex_normals();
    n[edge[0]].lerp(&n[edge[1]], t).normalize()
}

#[test]
fn traced_guides_are_pseudo_geodesics_on_the_mesh_and_start_a_field() {
    let dir = Scratch::new("trace");
    let obj = small_roof(&dir, 400);
    let m = obj.to_str().expect("utf-8");
    let mesh = TriMesh::read_obj(&obj).expect("valid");
    let trace = ["trace", "--mesh", m, "--theta", "60", "--guides", "3", "--guide-side", "0", "--guide-angle", "60", "--out", "g", "-q"];
    assert_ok(&lamella(&dir.0, &trace));
    let guides = read_json(&dir.path("g/guides.json"));
    let report = read_json(&dir.path("g/report.json"));
    assert_eq!(report["crossings"].as_array().map(Vec::len), Some(0));
    let records = guides["guides"].as_array().expect("guides");
    assert_eq!(records.len(), 3);
    let mut measured = 0;
    for (i, record) in records.iter().enumerate() {
        assert_eq!(record["stop"], "boundary", "guide {i} runs from boundary to boundary");
        let points = record["points"].as_array().expect("points");
        // Every point lies on its edge of the mesh.
        for p in points {
            let edge: Vec<usize> = p["edge"].as_array().expect("edge").iter().map(|v| v.as_u64().expect("index") as usize).collect();
            let t = p["t"].as_f64().expect("t");
            let on_edge = mesh.positions()[edge[0]].lerp(&mesh.positions()[edge[1]], t);
            let x: Vec<f64> = p["position"].as_array().expect("xyz").iter().map(|v| v.as_f64().expect("number")).collect();
            assert!((on_edge - Vec3::new(x[0], x[1], x[2])).norm() < 1e-9);
        }
        // The discrete binormal of each bend keeps 60° to the surface normal (Sec. 3.1); bends
        // too slight to define a binormal are skipped.
        let x = &guide_positions(&guides)[i];
        for k in 1..x.len() - 1 {
            let b = (x[k] - x[k - 1]).cross(&(x[k + 1] - x[k]));
            let turn = b.norm() / ((x[k] - x[k - 1]).norm() * (x[k + 1] - x[k]).norm());
            if turn < 1e-3 {
                continue;
            }
            let angle = b.normalize().dot(&edge_normal(&mesh, &points[k])).clamp(-1.0, 1.0).acos().to_degrees();
            let angle = angle.min(180.0 - angle);
            assert!((angle - 60.0).abs() < 1.5, "guide {i} point {k}: binormal at {angle}° to the normal");
            measured += 1;
        }
    }
    assert!(measured > 50, "only {measured} bends measured");

    // The field started from the file takes θ from it and reaches the family.
    assert_ok(&lamella(&dir.0, &["field", "--mesh", m, "--guides-file", "g/guides.json", "--out", "f", "-q"]));
    let field = read_json(&dir.path("f/report.json"));
    assert_eq!(field["parameters"]["theta_degrees"].as_f64(), Some(60.0));
    assert_eq!(field["parameters"]["start"]["kind"], "guides file");
    assert_eq!(field["field"]["converged"], true);
    assert_eq!(field["field"]["singular_vertices"].as_u64(), Some(0));
    let history = field["field"]["history"].as_array().expect("history");
    assert!(history.last().expect("rows")["e_angle"].as_f64().expect("e_angle") <= 1e-5);
    assert!(field["field"]["angle_error_max_degrees"].as_f64().expect("max") < 0.5);
}

#[test]
fn design_traces_its_own_guides_or_follows_strokes() {
    let dir = Scratch::new("start");
    let obj = small_roof(&dir, 400);
    let m = obj.to_str().expect("utf-8");
    // Guides from this side of the coarse roof lead to a family with straight stretches (about a
    // fifth of the level curves), where no developable strip keeps 60°: the design writes its
    // outputs and says so, exit 3, in one line naming the strips and the worst point.
    let design = ["design", "--mesh", m, "--guides", "3", "--guide-side", "0", "--guide-angle", "60", "--strips", "6", "--out", "d", "-q"];
    let output = lamella(&dir.0, &design);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    let message = stderr(&output);
    assert_eq!(message.lines().count(), 1, "{message}");
    assert!(message.starts_with("lamella: no acceptable family: strip"), "{message}");
    assert!(message.contains("worst: strip") && message.contains("try"), "{message}");
    let report = read_json(&dir.path("d/report.json"));
    assert_eq!(report["parameters"]["start"]["kind"], "traced guides");
    assert!(report["parameters"]["start"]["gradient_target"].is_null(), "the target is the solver's, not a start key");
    assert_eq!(report["strips"]["acceptable"], false);
    let worst = report["strips"]["verdict"]["worst"]["error_degrees"].as_f64().expect("worst error");
    assert!(worst > 2.0, "the verdict's worst quad is {worst}° off");
    assert!(dir.path("d/strips.obj").is_file() && dir.path("d/unrolled.svg").is_file(), "the outputs are written");

    // Strokes drawn along P-curves of 60° (the traced guides' points): θ is estimated from them.
    assert_ok(&lamella(&dir.0, &["trace", "--mesh", m, "--guides", "3", "--guide-side", "0", "--guide-angle", "60", "--out", "g", "-q"]));
    let strokes: Vec<Vec<[f64; 3]>> =
        guide_positions(&read_json(&dir.path("g/guides.json"))).iter().map(|g| g.iter().map(|p| [p.x, p.y, p.z]).collect()).collect();
    std::fs::write(dir.path("strokes.json"), serde_json::json!({ "strokes": strokes }).to_string()).expect("write strokes");
    assert_ok(&lamella(&dir.0, &["field", "--mesh", m, "--strokes", "strokes.json", "--out", "s", "-q"]));
    let report = read_json(&dir.path("s/report.json"));
    let estimate = report["parameters"]["start"]["estimated_theta_degrees"].as_f64().expect("estimate");
    // The estimate averages level-set angles at the vertices nearest the strokes; on this coarse
    // roof (mean edge ≈ 1.6 m) that is within 2.5° of the strokes' own angle.
    assert!((estimate - 60.0).abs() < 2.5, "estimated θ = {estimate}°");
    assert_eq!(report["parameters"]["theta_degrees"].as_f64(), Some(estimate), "the estimate is the target");
    assert!(report["field"]["angle_error_max_degrees"].as_f64().expect("max") < 1.0);
}

/// Runs `args` and checks exit code 2 with a message containing `expected`.
fn assert_bad_input(dir: &Scratch, args: &[&str], expected: &str) {
    let output = lamella(&dir.0, args);
    assert_eq!(output.status.code(), Some(2), "{args:?}: {}", stderr(&output));
    assert!(stderr(&output).contains(expected), "{args:?}: `{expected}` not in {}", stderr(&output));
}

#[test]
fn bad_guide_and_stroke_input_is_named() {
    let dir = Scratch::new("bad-start");
    let obj = small_roof(&dir, 200);
    let m = obj.to_str().expect("utf-8");
    assert_bad_input(&dir, &["trace", "--mesh", m, "--guides", "0"], "--guides = 0");
    assert_bad_input(&dir, &["design", "--mesh", m, "--guides", "3", "--guide-angle", "180"], "--guide-angle = 180");
    assert_bad_input(&dir, &["design", "--mesh", m, "--guides", "3", "--guide-side", "9"], "--guide-side 9");
    assert_bad_input(&dir, &["design", "--mesh", m, "--guides", "3", "--guide-side", "left"], "not a side number");
    assert_bad_input(&dir, &["design", "--mesh", m, "--guides", "3", "--strokes", "s.json"], "cannot be used with");
    assert_bad_input(&dir, &["design", "--mesh", m, "--guides", "1"], "guide");
    std::fs::write(dir.path("broken.json"), "{\"strokes\": [[[0, 0]]]}").expect("write");
    assert_bad_input(&dir, &["design", "--mesh", m, "--strokes", "broken.json"], "not a strokes file");
    // Two strokes 100 m above the 40 m × 24 m roof.
    std::fs::write(dir.path("far.json"), "{\"strokes\": [[[0, 0, 100], [1, 0, 100]], [[0, 5, 100], [1, 5, 100]]]}").expect("write");
    assert_bad_input(&dir, &["design", "--mesh", m, "--strokes", "far.json"], "stroke 0");
    // Guides traced on another mesh.
    let other_dir = Scratch::new("bad-start-other");
    let other = small_roof(&other_dir, 400);
    assert_ok(&lamella(&dir.0, &["trace", "--mesh", other.to_str().expect("utf-8"), "--out", "other", "-q"]));
    assert_bad_input(&dir, &["field", "--mesh", m, "--guides-file", "other/guides.json"], "guide");
}
