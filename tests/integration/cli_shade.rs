//! `lamella shade` (paper Sec. 6): a south-facing vertical facade shaded against the noon sun of
//! late June; the report's blocked fraction checked against the files it comes from, and the
//! exit code 3 when the strips are too narrow to block the sun.

use crate::cli_support;

use cli_support::{assert_bad_input, lamella, parse_xml, read_json, stderr, Scratch};
use lamella::mesh::{TriMesh, Vec3};
use lamella::surfaces::{planar_disk, PlanarPatch};

/// A disk of radius 5 m in the plane y = 0, facing south (−y), written as facade.obj.
fn facade(dir: &Scratch) -> TriMesh {
    let disk = planar_disk(&PlanarPatch { radius: 5.0, target_vertices: 300, irregularity: 0.3, seed: 11 }).unwrap();
    let positions = disk.positions.iter().map(|p| Vec3::new(p.x, 0.0, p.y)).collect();
    let mesh = TriMesh::from_vertices_and_faces(positions, disk.faces).unwrap();
    mesh.write_obj(std::fs::File::create(dir.path("facade.obj")).expect("create")).expect("write");
    mesh
}

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
    let mesh = facade(&dir);
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
}

#[test]
fn shade_exits_3_when_the_strips_are_too_narrow_to_block() {
    let dir = Scratch::new("shade-narrow");
    facade(&dir);
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
    facade(&dir);
    assert_bad_input(&dir.0, &noon(&[("--dates", "13-01..13-02")], &[]), &["month 13"]);
    assert_bad_input(&dir.0, &noon(&[("--latitude", "95")], &[]), &["latitude"]);
    assert_bad_input(&dir.0, &noon(&[("--north", "0,0,1")], &[]), &["north"]);
    assert_bad_input(&dir.0, &noon(&[("--hours", "5..19")], &[]), &["delta"]);
    std::fs::write(dir.path("mask.csv"), "1\n0\n").expect("write");
    assert_bad_input(&dir.0, &noon(&[], &["--mask", "mask.csv"]), &["mask.csv", "2 values"]);
}
