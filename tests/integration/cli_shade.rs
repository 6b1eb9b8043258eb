//! `lamella shade` (paper Sec. 6): a south-facing vertical facade shaded against the noon sun of
//! late June; the report's blocked fraction checked against the files it comes from, the strips'
//! planes measured in strips.obj against each curve's θ, and the exit code 3 when the strips are
//! too narrow to block the sun or miss their curves' θ by more than `--tolerance`.

use crate::cli_support;

use cli_support::{assert_bad_input, lamella, parse_xml, read_json, stderr, Scratch};
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{planar_disk, PlanarPatch};

/// A disk of radius 5 m over the plane y = 0, facing south (−y), written as facade.obj:
/// the plane itself for `twist` 0, else the hyperbolic paraboloid y = twist · x · z.
fn facade(dir: &Scratch, twist: f64) -> TriMesh {
    let disk = planar_disk(&PlanarPatch { radius: 5.0, target_vertices: 300, irregularity: 0.3, seed: 11 }).unwrap();
    let positions = disk.positions.iter().map(|p| Vec3::new(p.x, twist * p.x * p.y, p.y)).collect();
    let mesh = TriMesh::from_vertices_and_faces(positions, disk.faces).unwrap();
    mesh.write_obj(std::fs::File::create(dir.path("facade.obj")).expect("create")).expect("write");
    mesh
}

/// The earth axis at latitude 47.4° with north +y and up +z: (0, cos 47.4°, sin 47.4°).
const EARTH_AXIS: &str = "0,0.676876,0.736097";

/// The noon site's arguments with some flags' values replaced and `extra` appended.
fn noon<'a>(replace: &[(&str, &'a str)], extra: &[&'a str]) -> Vec<&'a str> {
    let base = [("--mesh", "facade.obj"), ("--latitude", "47.4"), ("--north", "0,1,0"), ("--dates", "06-14..06-28"), ("--hours", "11.5..12.5")];
    let mut args = vec!["shade", "--quiet"];
    for (flag, value) in base {
        args.push(flag);
        args.push(replace.iter().find(|(f, _)| *f == flag).map_or(value, |(_, v)| *v));
    }
    args.extend_from_slice(extra);
    args
}

#[test]
fn shade_blocks_the_noon_sun_on_a_facade_and_says_so_in_its_files() {
    let dir = Scratch::new("shade");
    let mesh = facade(&dir, 0.0);
    let args = noon(&[], &["--strips", "10", "--out", "d"]);
    let output = lamella(&dir.0, &args);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let report = read_json(&dir.path("d/report.json"));
    let block = report["sun_path"]["blocked_fraction"]["block_region"].as_f64().expect("block fraction");
    assert!(block >= 0.8, "blocked fraction {block}");
    assert!(report["sun_path"]["blocked_fraction"]["pass_region"].is_null());
    // The region's fraction is the per-vertex fractions' hours pooled: every vertex sees the
    // same suns on a plane, so it is their mean.
    let per_vertex: Vec<f64> = report["sun_path"]["per_vertex"].as_array().expect("array").iter().filter_map(|v| v.as_f64()).collect();
    assert_eq!(per_vertex.len(), mesh.vertex_count());
    let mean = per_vertex.iter().sum::<f64>() / per_vertex.len() as f64;
    assert!((mean - block).abs() < 1e-9, "mean {mean} vs pooled {block}");
    // Light region of the site: δ within ±7.5° plus the equation of time (solar hours: none), γ near 23.4°.
    let delta = &report["light_region"]["block"]["delta_degrees"];
    assert!((delta[0].as_f64().unwrap() + 7.5).abs() < 1e-6 && (delta[1].as_f64().unwrap() - 7.5).abs() < 1e-6, "{delta}");
    for file in ["curves.obj", "strips.obj", "rulings.obj", "field.csv", "unrolled.svg"] {
        assert!(dir.path(&format!("d/{file}")).exists(), "{file}");
    }
    let shading = parse_xml(&std::fs::read_to_string(dir.path("d/shading.svg")).expect("shading.svg"));
    let mut polygons = Vec::new();
    shading.descendants("polygon", &mut polygons);
    assert_eq!(polygons.len(), mesh.face_count());
    let sunpath = parse_xml(&std::fs::read_to_string(dir.path("d/sunpath.svg")).expect("sunpath.svg"));
    let mut circles = Vec::new();
    sunpath.descendants("circle", &mut circles);
    let suns = report["sun_path"]["block_suns"].as_u64().expect("suns") as usize;
    assert_eq!(circles.len(), suns + 3, "one dot per sun and three elevation circles");
    assert_eq!(suns, 15 * 2, "15 days × the hours 11.5 and 12.5");
    // The default start: the constant-slope family (Fig. 34–35) of the voted slope, which on a
    // vertical south facade near noon is 0 (horizontal tangents orthogonal to the sun) up to
    // half a 5° bin.
    assert_eq!(report["start"]["kind"], "constant slope about the earth axis", "{}", report["start"]);
    let slope = report["start"]["slope_degrees"].as_f64().expect("slope");
    assert!(slope.abs() <= 2.5, "slope {slope}");
    assert_eq!(report["constant_slope_vote"]["used"], true);
    // The strips' verdict: every quad within the default 2° of its curve's θ, measured from
    // strips.obj on the facade's exact normal.
    assert_eq!(report["strips"]["verdict"]["acceptable"], true, "{}", report["strips"]["verdict"]);
    let worst = worst_quad_off_theta(&dir.path("d/strips.obj"), &report, 0.0);
    assert!(worst <= 2.0, "worst quad {worst}° off its curve's θ");
}

/// Largest angle, over the quads of strips.obj, between the quad's plane and its curve's θ in
/// the report, measured against the exact normal of the facade of `twist` (−twist·z, 1,
/// −twist·x) at the middle of the quad's first ruling: the quad's direction across the strip
/// (the ruling made orthogonal to the centre line) is the binormal `b`, and the unsigned angle
/// between the lines `b` and the normal is compared with min(θ, 180° − θ).
fn worst_quad_off_theta(strips_obj: &std::path::Path, report: &serde_json::Value, twist: f64) -> f64 {
    let thetas = report["strips"]["theta_degrees"].as_array().expect("theta per curve");
    let text = std::fs::read_to_string(strips_obj).expect("strips.obj");
    let (mut vertices, mut curve, mut worst, mut quads) = (Vec::new(), None, 0.0f64, 0);
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["#", "curve", k, ..] => curve = Some(k.parse::<usize>().expect("curve index")),
            ["v", x, y, z] => vertices.push(Vec3::new(x.parse().unwrap(), y.parse().unwrap(), z.parse().unwrap())),
            ["f", a, b, _, d] => {
                let at = |w: &str| vertices[w.parse::<usize>().unwrap() - 1];
                let (l0, l1, r0) = (at(a), at(b), at(d));
                let t = (l1 - l0).normalize();
                let ruling = r0 - l0;
                let binormal = (ruling - t * ruling.dot(&t)).normalize();
                let middle = l0 + ruling * 0.5;
                let normal = Vec3::new(-twist * middle.z, 1.0, -twist * middle.x).normalize();
                let measured = binormal.dot(&normal).abs().clamp(0.0, 1.0).acos().to_degrees();
                let theta = thetas[curve.expect("a curve before the faces")].as_f64().expect("θ of a stripped curve");
                worst = worst.max((measured - theta.min(180.0 - theta)).abs());
                quads += 1;
            }
            _ => {}
        }
    }
    assert!(quads > 0, "no quad in strips.obj");
    worst
}

#[test]
fn shade_exits_3_when_the_strips_miss_their_curves_theta_though_the_sun_is_blocked() {
    // Twisted, the facade's level curves from the paper's planar start (height along the earth
    // axis) are no P-curves of one angle. The strips hold their quads near θ (within a few tenths
    // of a degree by the verdict's measure, about 2° against the exact normal), so a tolerance of
    // 0.1° fails them, while the noon sun is still blocked: the exit must come from the strips.
    let dir = Scratch::new("shade-twisted");
    facade(&dir, 0.08);
    let strict = ["--strips", "10", "--start-direction", EARTH_AXIS, "--min-blocked", "0.7", "--tolerance", "0.1"];
    let args = noon(&[], &[&strict[..], &["--out", "d"]].concat());
    let output = lamella(&dir.0, &args);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    let message = stderr(&output);
    assert_eq!(message.trim_end().lines().count(), 1, "{message}");
    assert!(message.contains("by more than 0.1°") && message.contains("worst: strip") && message.contains("quad"), "{message}");
    assert!(!message.contains("block region"), "the sun-path check passes: {message}");
    let report = read_json(&dir.path("d/report.json"));
    // The sun-path check alone passes: the exit comes from the strips.
    let block = report["sun_path"]["blocked_fraction"]["block_region"].as_f64().expect("block fraction");
    assert!(block >= 0.7, "blocked fraction {block}");
    let verdict = &report["strips"]["verdict"];
    assert_eq!(verdict["acceptable"], false, "{verdict}");
    assert_eq!(report["verdict"]["acceptable"], false);
    // The measured planes do miss θ by more than the tolerance somewhere.
    let worst = worst_quad_off_theta(&dir.path("d/strips.obj"), &report, 0.08);
    assert!(worst > 0.1, "worst quad {worst}°");
    // A tolerance above the worst quad lets every strip meet its θ (deterministic run); the
    // flipped quads the verdict also counts still fail it.
    let reported = verdict["worst"]["error_degrees"].as_f64().expect("worst error");
    let loose = format!("{}", reported.ceil() + 1.0);
    let output = lamella(&dir.0, &noon(&[], &["--strips", "10", "--start-direction", EARTH_AXIS, "--min-blocked", "0.7", "--tolerance", &loose, "--out", "e"]));
    let loose_verdict = &read_json(&dir.path("e/report.json"))["strips"]["verdict"];
    assert_eq!(loose_verdict["strips_missing_theta"].as_array().map(Vec::len), Some(0), "{loose_verdict}");
    let flipped = loose_verdict["strips_with_flipped_quads"].as_array().map_or(0, Vec::len);
    assert_eq!(output.status.code(), Some(if flipped > 0 { 3 } else { 0 }), "{}", stderr(&output));
    for file in ["curves.obj", "strips.obj", "field.csv", "unrolled.svg", "shading.svg", "sunpath.svg"] {
        assert!(dir.path(&format!("d/{file}")).exists(), "{file}");
    }
}

#[test]
fn shade_exits_3_when_the_strips_are_too_narrow_to_block() {
    let dir = Scratch::new("shade-narrow");
    facade(&dir, 0.0);
    let args = noon(&[], &["--strips", "10", "--width", "0.05", "--out", "d"]);
    let output = lamella(&dir.0, &args);
    assert_eq!(output.status.code(), Some(3), "{}", stderr(&output));
    assert!(stderr(&output).contains("block region"), "{}", stderr(&output));
    let report = read_json(&dir.path("d/report.json"));
    let block = report["sun_path"]["blocked_fraction"]["block_region"].as_f64().expect("block fraction");
    assert!(block < 0.8 && report["verdict"]["acceptable"] == false, "{block}");
}

#[test]
fn shade_refuses_bad_sites_and_masks() {
    let dir = Scratch::new("shade-bad");
    facade(&dir, 0.0);
    assert_bad_input(&dir.0, &noon(&[("--dates", "13-01..13-02")], &[]), &["month 13"]);
    assert_bad_input(&dir.0, &noon(&[("--latitude", "95")], &[]), &["latitude"]);
    assert_bad_input(&dir.0, &noon(&[("--north", "0,0,1")], &[]), &["north"]);
    assert_bad_input(&dir.0, &noon(&[("--hours", "5..19")], &[]), &["delta"]);
    assert_bad_input(&dir.0, &noon(&[], &["--tolerance", "0"]), &["tolerance"]);
    std::fs::write(dir.path("mask.csv"), "1\n0\n").expect("write");
    assert_bad_input(&dir.0, &noon(&[], &["--mask", "mask.csv"]), &["mask.csv", "2 values"]);
}
