//! Bad input gives one clear line on stderr and exit code 2 (malformed or unreadable OBJ with
//! its line, an invalid mesh with every problem, parameters out of range, an unwritable or
//! existing output directory, a corrupt session, a bad config), and no output directory.

use crate::cli_support;

use cli_support::{assert_bad_input, lamella, small_roof, stderr, stdout, Scratch};

/// Two triangles with one wrongly oriented, a face repeating a vertex and an unused vertex.
const INVALID_MESH: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 5 5 5\nf 1 2 3\nf 2 3 4\nf 1 1 2\n";

#[test]
fn malformed_and_unreadable_obj() {
    let dir = Scratch::new("obj");
    std::fs::write(dir.path("bad.obj"), "# a comment\nv 0 0 0\nv 1 0 zero\nf 1 2 3\n").expect("write");
    assert_bad_input(&dir.0, &["design", "--mesh", "bad.obj", "--out", "o"], &["bad.obj", "line 3"]);
    assert_bad_input(&dir.0, &["info", "bad.obj"], &["line 3"]);
    assert_bad_input(&dir.0, &["design", "--mesh", "missing.obj", "--out", "o"], &["cannot read missing.obj"]);
    assert!(!dir.path("o").exists(), "no output directory after a failure");
}

#[test]
fn invalid_mesh_lists_every_problem() {
    let dir = Scratch::new("invalid");
    std::fs::write(dir.path("invalid.obj"), INVALID_MESH).expect("write");
    // Problems: face 2 (line 8) repeats vertex 0; vertex 4 (line 5) is unused; faces 0 and 1
    // traverse their shared edge 1–2 in the same direction (line 7).
    let needles = ["invalid mesh", "line 8", "more than once", "line 5", "used by no face", "orientation"];
    assert_bad_input(&dir.0, &["design", "--mesh", "invalid.obj", "--out", "o"], &needles);
    let info = lamella(&dir.0, &["info", "invalid.obj"]);
    assert_eq!(info.status.code(), Some(2));
    let report = stdout(&info);
    assert_eq!(report.lines().filter(|l| l.trim_start().starts_with("problem:")).count(), 3, "{report}");
}

#[test]
fn parameters_out_of_range() {
    let dir = Scratch::new("range");
    for (flag, value) in [("--theta", "200"), ("--theta", "-1"), ("--strips", "0"), ("--width", "0"), ("--width", "-0.3"), ("--max-iterations", "0"), ("--theta", "NaN")] {
        let name = flag.trim_start_matches('-');
        assert_bad_input(&dir.0, &["design", flag, value, "--out", "o"], &[name, "out of range"]);
    }
    // Not a number at all: clap's usage error, also exit code 2 (several lines of usage help).
    let output = lamella(&dir.0, &["design", "--theta", "sixty"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("--theta"));
    assert!(!dir.path("o").exists());
}

#[test]
fn unwritable_or_existing_output_directory() {
    let dir = Scratch::new("out");
    let obj = small_roof(&dir, 200);
    let m = obj.to_str().expect("utf-8");
    std::fs::write(dir.path("plain-file"), "not a directory").expect("write");
    assert_bad_input(&dir.0, &["design", "--mesh", m, "--out", "plain-file/out", "--max-iterations", "1"], &["cannot write output directory", "plain-file/out"]);
    std::fs::create_dir(dir.path("taken")).expect("mkdir");
    std::fs::write(dir.path("taken/keep.txt"), "mine").expect("write");
    assert_bad_input(&dir.0, &["field", "--mesh", m, "--out", "taken"], &["taken", "already exists", "--force"]);
    assert_eq!(std::fs::read_to_string(dir.path("taken/keep.txt")).expect("kept"), "mine");
}

#[test]
fn corrupt_session_field_csv_and_config() {
    let dir = Scratch::new("files");
    let obj = small_roof(&dir, 200);
    let m = obj.to_str().expect("utf-8");
    std::fs::write(dir.path("session.bin"), b"LMLF garbage").expect("write");
    assert_bad_input(&dir.0, &["field", "--resume", "session.bin", "--out", "o"], &["session.bin", "not a usable field session"]);
    std::fs::write(dir.path("field.csv"), "# field\n1\n2\n").expect("write");
    assert_bad_input(&dir.0, &["strips", "--mesh", m, "--field", "field.csv", "--out", "o"], &["field.csv", "2 values"]);
    std::fs::write(dir.path("field.csv"), "# field\n1\nabc\n").expect("write");
    assert_bad_input(&dir.0, &["strips", "--mesh", m, "--field", "field.csv", "--out", "o"], &["field.csv", "line 3"]);
    std::fs::write(dir.path("design.toml"), "theta = 60\ncolour = \"red\"\n").expect("write");
    assert_bad_input(&dir.0, &["design", "--config", "design.toml", "--out", "o"], &["design.toml", "line 2", "colour"]);
    std::fs::write(dir.path("design.toml"), "theta = 400\n").expect("write");
    assert_bad_input(&dir.0, &["design", "--config", "design.toml", "--out", "o"], &["theta", "out of range"]);
    std::fs::write(dir.path("strips.obj"), "v 0 0 0\n").expect("write");
    assert_bad_input(&dir.0, &["unroll", "--strips", "strips.obj", "--out", "o"], &["strips.obj", "line 1"]);
    assert!(!dir.path("o").exists());
}
