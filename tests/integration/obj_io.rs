//! OBJ reading and writing: statement forms, fan triangulation, line-numbered errors, and a
//! bit-exact write → parse round trip.

use crate::mesh_support;

use lamella::mesh::{MeshError, TriMesh, Vec3};
use mesh_support::{grid, mapped, mesh, Lcg};

fn obj_line_error(text: &str) -> (usize, MeshError) {
    match TriMesh::parse_obj(text) {
        Err(MeshError::ObjLine { line, error }) => (line, *error),
        other => panic!("expected an ObjLine error, got {other:?}"),
    }
}

fn parse_error_line(text: &str) -> usize {
    match TriMesh::parse_obj(text) {
        Err(MeshError::ObjParse { line, .. }) => line,
        other => panic!("expected an ObjParse error, got {other:?}"),
    }
}

const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

#[test]
fn index_forms_and_ignored_statements() {
    let text = "# a comment\r\nmtllib a.mtl\no square\ng part\ns 1\nusemtl red\n\
                v 0 0 0 1.0\nv 1 0 0 0.5 0.5 0.5\nv 1 1 0\nv 0 1 0\n\n\
                vt 0 0\nvn 0 0 1\n   \t\n\
                f 1/1 2/2/1 3//1\n\
                f -4 -2 4/1/1 # trailing comment\nl 1 2\n";
    let m = TriMesh::parse_obj(text).unwrap();
    assert_eq!(m.faces(), &[[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.positions()[1], Vec3::new(1.0, 0.0, 0.0));
}

#[test]
fn polygons_are_fan_triangulated_in_order() {
    let text = "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n";
    let m = TriMesh::parse_obj(text).unwrap();
    assert_eq!(m.faces(), &[[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
    let quad = TriMesh::parse_obj(&format!("{SQUARE}f 1 2 3 4\n")).unwrap();
    assert_eq!(quad.faces(), &[[0, 1, 2], [0, 2, 3]]);
}

#[test]
fn write_then_parse_is_bit_identical() {
    let mut rng = Lcg(3);
    let awkward = [0.1 + 0.2, 1.0 / 3.0, std::f64::consts::PI, 1e-300, -0.0, 123_456_789.123_456_79, 5e-324];
    // Heights at most 0.12 on cells of 0.7 (a height of 123 would be a spike whose faces fold
    // back onto each other, which validation refuses); 1e-300 becomes a subnormal.
    let soup = mapped(grid(5, 4, 0.7), |p| {
        Vec3::new(p.x + 0.1 * rng.unit(), p.y * (1.0 + 1e-9), awkward[(rng.next_u64() % 7) as usize] * 1e-9)
    });
    let m = mesh(soup);
    let mut bytes = Vec::new();
    m.write_obj(&mut bytes).unwrap();
    let back = TriMesh::parse_obj(std::str::from_utf8(&bytes).unwrap()).unwrap();
    assert_eq!(back.faces(), m.faces());
    for (a, b) in m.positions().iter().zip(back.positions()) {
        assert!(a.iter().zip(b.iter()).all(|(x, y)| x.to_bits() == y.to_bits()), "{a} vs {b}");
    }
    assert_eq!(back, m);
}

#[test]
fn read_obj_from_a_file_and_missing_file() {
    let dir = std::env::temp_dir().join(format!("lamella-obj-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("square.obj");
    std::fs::write(&path, format!("{SQUARE}f 1 2 3\nf 1 3 4\n")).unwrap();
    let m = TriMesh::read_obj(&path).unwrap();
    assert_eq!((m.vertex_count(), m.face_count()), (4, 2));
    let missing = dir.join("missing.obj");
    match TriMesh::read_obj(&missing) {
        Err(MeshError::Io { path, kind, .. }) => {
            assert_eq!(path, missing);
            assert_eq!(kind, std::io::ErrorKind::NotFound);
        }
        other => panic!("expected Io error, got {other:?}"),
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn mesh_errors_name_the_obj_line() {
    // Out-of-range face index on line 6 (after a comment line).
    let (line, e) = obj_line_error(&format!("# header\n{SQUARE}f 1 2 7\n"));
    assert_eq!((line, e), (6, MeshError::IndexOutOfRange { face: 0, corner: 2, index: 6, vertex_count: 4 }));
    // A 32-bit index far beyond the vertex list.
    let (line, e) = obj_line_error(&format!("{SQUARE}f 1 2 3\nf 1 3 4000000000\n"));
    assert_eq!((line, e), (6, MeshError::IndexOutOfRange { face: 1, corner: 2, index: 3_999_999_999, vertex_count: 4 }));
    // Non-finite coordinate on the second v line.
    let (line, e) = obj_line_error("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    assert_eq!((line, e), (2, MeshError::NonFiniteCoordinate { vertex: 1, axis: 0 }));
    // Isolated vertex: the line of its v statement.
    let (line, e) = obj_line_error(&format!("{SQUARE}f 1 2 3\n"));
    assert_eq!((line, e), (4, MeshError::IsolatedVertex { vertex: 3 }));
    // Zero-area triangle from the second fan triangle of a polygon on line 5.
    let (line, e) = obj_line_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 2 0\nf 1 2 3 4\n");
    assert_eq!((line, e), (5, MeshError::ZeroAreaFace { face: 1 }));
    // Repeated index, inconsistent orientation (named at the second face's line).
    let (line, e) = obj_line_error(&format!("{SQUARE}f 1 2 2\n"));
    assert_eq!((line, e), (5, MeshError::RepeatedIndex { face: 0, index: 1 }));
    let (line, e) = obj_line_error(&format!("{SQUARE}f 1 2 3\n\nf 1 3 4\nf 1 2 4\n"));
    assert_eq!(line, 8);
    assert!(matches!(e, MeshError::InconsistentOrientation { face_b: 2, .. }));
    // Errors that name no line come back unwrapped.
    let closed = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
    assert_eq!(TriMesh::parse_obj(closed).unwrap_err(), MeshError::NotDisk { euler_characteristic: 2, boundary_loops: 0 });
    assert_eq!(TriMesh::parse_obj("").unwrap_err(), MeshError::NoVertices);
    assert_eq!(TriMesh::parse_obj("# only a comment\n").unwrap_err(), MeshError::NoVertices);
}

#[test]
fn malformed_lines_name_the_obj_line() {
    assert_eq!(parse_error_line(&format!("{SQUARE}f 0 1 2\n")), 5);
    assert_eq!(parse_error_line(&format!("{SQUARE}f 1 2\n")), 5);
    assert_eq!(parse_error_line("v 1 2\n"), 1);
    assert_eq!(parse_error_line("v 0 0 0\nv 1 x 0\n"), 2);
    assert_eq!(parse_error_line(&format!("{SQUARE}f -5 1 2\n")), 5);
    assert_eq!(parse_error_line(&format!("{SQUARE}f 99999999999 1 2\n")), 5);
    assert_eq!(parse_error_line(&format!("{SQUARE}f 1/2/3/ a 2\n")), 5);
    assert_eq!(parse_error_line("\n\nhello world\n"), 3);
}

#[test]
fn garbage_text_never_panics() {
    let mut rng = Lcg(5);
    let tokens = ["v", "f", "vt", "1", "-1", "0", "2/3", "//", "/", "nan", "1e999", "#", "\n", "\r\n", " ", "é", "-0", "4294967296", "99"];
    for _ in 0..400 {
        let n = (rng.next_u64() % 40) as usize;
        let text: String = (0..n).map(|_| tokens[(rng.next_u64() % tokens.len() as u64) as usize]).collect::<Vec<_>>().join(" ");
        let _ = TriMesh::parse_obj(&text);
    }
}

#[test]
fn diagnose_obj_lists_every_problem_with_its_line() {
    // Line 5 repeats an index, line 6 refers to a vertex that does not exist; both are reported.
    let text = format!("{SQUARE}f 1 1 2\nf 1 2 9\n");
    let problems = TriMesh::diagnose_obj(&text).expect("well-formed lines");
    let lines: Vec<usize> = problems
        .iter()
        .filter_map(|p| match p {
            MeshError::ObjLine { line, .. } => Some(*line),
            _ => None,
        })
        .collect();
    assert!(lines.contains(&5) && lines.contains(&6), "{problems:?}");
    assert!(TriMesh::diagnose_obj(&format!("{SQUARE}f 1 2 3\nf 1 3 4\n")).expect("valid").is_empty());
    assert!(matches!(TriMesh::diagnose_obj("v 1 2\n"), Err(MeshError::ObjParse { line: 1, .. })));
}
