//! `lamella::view`: the viewer page is self-contained, its embedded geometry decodes back to the
//! scene within the quantisation error, it is deterministic, bad scenes are refused naming the
//! element, and a 50k-vertex design stays well under 20 MB.

use lamella::mesh::Vec3;
use lamella::strips::{unroll, StripMetrics};
use lamella::surfaces::hall_roof;
use lamella::view::{dequantise, view_html, ViewError, ViewScene, ViewStrip, ViewSurface, QUANTISATION_STEPS, SELF_CHECK_ID};
use serde_json::Value;

/// A strip along the helix-like curve `x = t, y = a sin(t / 3), z = 2 + 0.1 t` for t in
/// `0..length`, with rulings tilted out of the xy plane, `rulings` of them.
fn strip(name: &str, family: usize, offset: f64, rulings: usize, length: f64) -> ViewStrip {
    let centre: Vec<Vec3> = (0..rulings)
        .map(|i| {
            let t = length * i as f64 / (rulings - 1) as f64;
            Vec3::new(t, offset + 0.5 * (t / 3.0).sin(), 2.0 + 0.1 * t)
        })
        .collect();
    let offsets: Vec<Vec3> = (0..rulings).map(|i| Vec3::new(0.02 * i as f64 / rulings as f64, 0.2, 0.12)).collect();
    let left: Vec<Vec3> = centre.iter().zip(&offsets).map(|(c, d)| c + d).collect();
    let right: Vec<Vec3> = centre.iter().zip(&offsets).map(|(c, d)| c - d).collect();
    let unrolling = unroll(&centre, &offsets);
    let metrics = StripMetrics { length: unrolling.length, max_diff_theta_degrees: 0.25 + offset, max_quad_angle_error_degrees: 0.5, ..StripMetrics::default() };
    ViewStrip { name: name.to_string(), family, left, right, unrolling, metrics, utilisation: Some(0.3 * (family + 1) as f64) }
}

/// A flat 4 × 3 grid surface under two strips of two families and one level curve.
fn scene() -> ViewScene {
    let positions: Vec<Vec3> = (0..12).map(|k| Vec3::new((k % 4) as f64 * 4.0, (k / 4) as f64 * 2.0 - 2.0, 1.5)).collect();
    let mut triangles = Vec::new();
    for j in 0..2u32 {
        for i in 0..3u32 {
            let v = 4 * j + i;
            triangles.push([v, v + 1, v + 5]);
            triangles.push([v, v + 5, v + 4]);
        }
    }
    ViewScene {
        title: "test scene".into(),
        surface: Some(ViewSurface { positions, triangles }),
        curves: vec![vec![Vec3::new(0.0, 0.0, 2.0), Vec3::new(6.0, 0.4, 2.6), Vec3::new(12.0, -0.2, 3.2)]],
        families: vec!["P60".into(), "G".into()],
        strips: vec![strip("f0_strip_0", 0, 0.0, 30, 12.0), strip("f1_strip_0", 1, 1.0, 12, 9.0)],
    }
}

/// The JSON of the page's data block.
fn data_of(page: &str) -> Value {
    let open = "<script type=\"application/json\" id=\"lamella-data\">";
    let start = page.find(open).expect("data block") + open.len();
    let end = start + page[start..].find("</script>").expect("end of the data block");
    serde_json::from_str(&page[start..end]).expect("data is JSON")
}

fn corners<const D: usize>(value: &Value) -> ([f64; D], [f64; D]) {
    let read = |key: &str| std::array::from_fn(|k| value[key][k].as_f64().expect("box coordinate"));
    (read("low"), read("high"))
}

#[test]
fn the_page_is_self_contained_and_carries_the_viewer() {
    let page = view_html(&scene()).expect("page");
    for forbidden in ["http://", "https://", "src=", "<link", "@import", "url(", "fetch(", "XMLHttpRequest"] {
        assert!(!page.contains(forbidden), "the page contains {forbidden}");
    }
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert!(page.contains("default-src 'none'"), "no content security policy forbidding loads");
    assert!(page.contains(&format!("id=\"{SELF_CHECK_ID}\"")));
    assert!(page.contains("getContext(\"webgl2\""), "no WebGL viewer script");
    assert!(page.contains("<title>test scene · Lamella</title>"));
    // Legend and figures name their units.
    for label in ["\"°\"", "\"m\"", "\"%\"", "max_diff_theta_degrees", "max_quad_angle_error_degrees", "appro_percent"] {
        assert!(page.contains(label), "the viewer lacks {label}");
    }
}

#[test]
fn the_embedded_geometry_decodes_back_to_the_scene() {
    let scene = scene();
    let data = data_of(&view_html(&scene).expect("page"));
    let strips = data["strips"].as_array().expect("strips");
    assert_eq!(strips.len(), 2);
    assert_eq!(strips[1]["name"], "f1_strip_0");
    assert_eq!(strips[1]["family"], 1);
    assert_eq!(strips[1]["rulings"], 12);
    // serde_json's reader may miss the last bit of a float.
    let length = strips[0]["metrics"]["length"].as_f64().expect("length");
    assert!((length / scene.strips[0].metrics.length - 1.0).abs() < 1e-12, "{length}");
    assert_eq!(strips[1]["utilisation"].as_f64(), Some(0.6));
    assert_eq!(data["families"], serde_json::json!(["P60", "G"]));
    assert_eq!(data["has_utilisation"], true);

    let (low, high) = corners::<3>(&data["box"]);
    let tolerance: Vec<f64> = (0..3).map(|k| (high[k] - low[k]) / QUANTISATION_STEPS / 2.0 + 1e-12).collect();
    let close = |p: &[f64; 3], q: &Vec3| (0..3).all(|k| (p[k] - q[k]).abs() <= tolerance[k]);
    // The box is the scene's: the surface's lowest z, the strips' highest.
    assert_eq!(low[2], 1.5);

    let ends = dequantise::<3>(data["strip_positions"].as_str().expect("positions"), low, high).expect("base64");
    let expected: Vec<Vec3> = scene.strips.iter().flat_map(|s| s.left.iter().zip(&s.right).flat_map(|(l, r)| [*l, *r])).collect();
    assert_eq!(ends.len(), expected.len());
    assert!(ends.iter().zip(&expected).all(|(p, q)| close(p, q)), "strip ends decode outside the quantisation error");

    let surface = scene.surface.as_ref().expect("surface");
    let positions = dequantise::<3>(data["surface"]["positions"].as_str().expect("surface"), low, high).expect("base64");
    assert_eq!(positions.len(), surface.positions.len());
    assert!(positions.iter().zip(&surface.positions).all(|(p, q)| close(p, q)));
    let bytes = base64_bytes(data["surface"]["triangles"].as_str().expect("triangles"));
    let triangles: Vec<u32> = bytes.chunks(4).map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]])).collect();
    assert_eq!(triangles, surface.triangles.iter().flatten().copied().collect::<Vec<_>>());

    assert_eq!(data["curves"]["counts"], serde_json::json!([3]));
    let curve = dequantise::<3>(data["curves"]["positions"].as_str().expect("curves"), low, high).expect("base64");
    assert!(curve.iter().zip(&scene.curves[0]).all(|(p, q)| close(p, q)));
}

/// Bytes of base64 text, decoded here independently of the crate.
fn base64_bytes(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    };
    let digits: Vec<u8> = text.bytes().filter(|&c| c != b'=').map(value).collect();
    let mut bytes = Vec::new();
    for group in digits.chunks(4) {
        let word = group.iter().enumerate().fold(0u32, |w, (k, &d)| w | (u32::from(d) << (18 - 6 * k)));
        bytes.extend_from_slice(&word.to_be_bytes()[1..group.len()]);
    }
    bytes
}

#[test]
fn the_flat_strips_keep_their_lengths_and_do_not_overlap() {
    let scene = scene();
    let data = data_of(&view_html(&scene).expect("page"));
    let (low, high) = corners::<2>(&data["flat"]);
    let flat = dequantise::<2>(data["flat"]["positions"].as_str().expect("flat"), low, high).expect("base64");
    let step = (0..2).map(|k| (high[k] - low[k]) / QUANTISATION_STEPS).fold(0.0, f64::max);
    let mut first = 0;
    let mut rows = Vec::new();
    for s in &scene.strips {
        let n = s.left.len();
        let centre: Vec<[f64; 2]> = (first..first + n).map(|i| [(flat[2 * i][0] + flat[2 * i + 1][0]) / 2.0, (flat[2 * i][1] + flat[2 * i + 1][1]) / 2.0]).collect();
        let length: f64 = centre.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum();
        assert!((length - s.unrolling.length).abs() <= 2.0 * n as f64 * step, "flat length {length} for {}", s.unrolling.length);
        // Each strip's chord runs along +x.
        assert!((centre[n - 1][1] - centre[0][1]).abs() <= 2.0 * step, "{:?} → {:?}", centre[0], centre[n - 1]);
        let ys = flat[2 * first..2 * (first + n)].iter().map(|p| p[1]);
        rows.push((ys.clone().fold(f64::INFINITY, f64::min), ys.fold(f64::NEG_INFINITY, f64::max)));
        first += n;
    }
    assert!(rows[1].1 < rows[0].0, "the second flat strip {:?} overlaps the first {:?}", rows[1], rows[0]);
}

#[test]
fn the_same_scene_gives_the_same_bytes() {
    let a = view_html(&scene()).expect("page");
    let b = view_html(&scene()).expect("page");
    assert_eq!(a, b);
    let mut other = scene();
    other.strips[0].left[3].z += 0.25;
    assert_ne!(view_html(&other).expect("page"), a);
}

#[test]
fn names_cannot_end_the_scripts_early() {
    let mut scene = scene();
    scene.title = "</script><script>alert(1)</script> & co".into();
    scene.strips[0].name = "</script><img src=x>".into();
    let page = view_html(&scene).expect("page");
    assert_eq!(page.matches("</script>").count(), 2, "only the data block and the viewer end a script");
    assert!(!page.contains("<img"));
    assert!(page.contains("&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt; &amp; co"));
    assert_eq!(data_of(&page)["strips"][0]["name"], "</script><img src=x>");
}

#[test]
fn bad_scenes_are_refused_naming_the_element() {
    let mut s = scene();
    s.strips[1].left[4].y = f64::NAN;
    let error = view_html(&s).expect_err("NaN");
    assert!(matches!(error, ViewError::InvalidStrip { strip: 1, .. }), "{error:?}");
    assert_eq!(error.to_string(), "strip 1 (`f1_strip_0`): ruling 4 has a non-finite end");

    let mut s = scene();
    s.strips[0].family = 2;
    assert_eq!(view_html(&s).expect_err("family").to_string(), "strip 0 (`f0_strip_0`): family 2 does not exist (2 families)");

    let mut s = scene();
    s.strips[0].right.pop();
    assert!(view_html(&s).expect_err("short").to_string().starts_with("strip 0 (`f0_strip_0`): 30 left boundary points, 29 right"));

    let mut s = scene();
    s.strips[1].utilisation = Some(f64::INFINITY);
    assert!(view_html(&s).expect_err("utilisation").to_string().contains("utilisation inf is not finite"));

    let mut s = scene();
    s.surface.as_mut().expect("surface").triangles[5][2] = 12;
    assert_eq!(view_html(&s).expect_err("triangle").to_string(), "surface: triangle 5 addresses a vertex beyond the 12 vertices");

    let mut s = scene();
    s.curves[0][1].x = f64::INFINITY;
    assert_eq!(view_html(&s).expect_err("curve").to_string(), "level curve 0: point 1 is not finite");
}

#[test]
fn a_50k_vertex_design_stays_under_20_megabytes() {
    let mesh = hall_roof(50_000).into_mesh().expect("hall roof");
    assert!(mesh.vertex_count() >= 45_000, "{} vertices", mesh.vertex_count());
    // As many strips as a fine design of it: 60 strips of 800 rulings each.
    let strips = (0..60).map(|k| strip(&format!("strip_{k}"), 0, k as f64 * 0.4, 800, 40.0)).collect();
    let curves = (0..60).map(|k| (0..800).map(|i| Vec3::new(i as f64 * 0.05, k as f64 * 0.4, 3.0)).collect()).collect();
    let scene = ViewScene { title: "50k".into(), surface: Some(ViewSurface::from_mesh(&mesh)), curves, families: vec!["P60".into()], strips };
    let page = view_html(&scene).expect("page");
    let megabytes = page.len() as f64 / 1e6;
    println!("50k-vertex page: {megabytes:.2} MB");
    assert!(megabytes < 20.0, "{megabytes:.2} MB");
    assert_eq!(data_of(&page)["surface"]["vertices"].as_u64(), Some(mesh.vertex_count() as u64));
}
