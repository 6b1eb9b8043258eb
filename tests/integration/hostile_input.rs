//! Regression tests of the hostile-input audit (issue 13): each finding, through the library,
//! the command line and the C ABI as the audit reached it.

use crate::cli_support;
use crate::mesh_support;

use cli_support::{assert_bad_input, lamella, small_roof, stderr, stdout, Scratch};
use lamella::curves::{uniform_levels, CurveError};
use lamella::ffi::*;
use lamella::field::{FieldError, FieldParams, FieldSolver, FIELD_VALUE_LIMIT};
use lamella::mesh::{MeshError, TriMesh};
use lamella::surfaces::hall_roof;
use mesh_support::{folded, obj_text, sliver_grid};
use std::ffi::CStr;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::Instant;

fn last_error() -> String {
    // SAFETY: never NULL, valid until the next call on this thread.
    unsafe { CStr::from_ptr(lml_last_error_message()) }.to_string_lossy().into_owned()
}

fn roof_mesh() -> TriMesh {
    hall_roof(60).into_mesh().expect("valid roof")
}

fn axis_field(mesh: &TriMesh) -> Vec<f64> {
    mesh.positions().iter().map(|p| p.x).collect()
}

// 1. --force replaces only a previous Lamella output.

#[test]
fn force_refuses_a_directory_lamella_did_not_write() {
    let dir = Scratch::new("force-foreign");
    let mesh = small_roof(&dir, 60);
    let precious = dir.path("precious");
    std::fs::create_dir(&precious).expect("mkdir");
    std::fs::write(precious.join("thesis.tex"), "years of work").expect("write");
    // `out` from a design.toml, as in the audit.
    let config = dir.path("design.toml");
    std::fs::write(&config, format!("out = {:?}\n", precious.display().to_string())).expect("write");
    let m = mesh.to_str().expect("utf-8");
    let c = config.to_str().expect("utf-8");
    assert_bad_input(&dir.0, &["trace", "--mesh", m, "--guides", "2", "--config", c, "--force"], &["precious", "not a previous Lamella output", "marker"]);
    assert_eq!(std::fs::read_to_string(precious.join("thesis.tex")).expect("kept"), "years of work");
    // A plain file named by --out is not replaced either.
    std::fs::write(dir.path("notes.txt"), "keep").expect("write");
    assert_bad_input(&dir.0, &["trace", "--mesh", m, "--guides", "2", "--out", "notes.txt", "--force"], &["notes.txt", "not a directory"]);
    assert_eq!(std::fs::read_to_string(dir.path("notes.txt")).expect("kept"), "keep");
}

#[test]
fn force_replaces_a_previous_output_but_not_one_with_foreign_files() {
    let dir = Scratch::new("force-own");
    let mesh = small_roof(&dir, 60);
    let m = mesh.to_str().expect("utf-8");
    let args = ["trace", "--mesh", m, "--guides", "2", "--out", "g", "--force", "--quiet"];
    let first = lamella(&dir.0, &args);
    assert_eq!(first.status.code(), Some(0), "{}", stderr(&first));
    let marker = std::fs::read_to_string(dir.path("g/.lamella-output")).expect("marker");
    assert!(marker.lines().any(|l| l == "guides.json"), "{marker}");
    let again = lamella(&dir.0, &args);
    assert_eq!(again.status.code(), Some(0), "a previous output is replaced: {}", stderr(&again));
    std::fs::write(dir.path("g/mine.txt"), "added by hand").expect("write");
    assert_bad_input(&dir.0, &args, &["g", "mine.txt", "did not write"]);
    assert!(dir.path("g/mine.txt").exists() && dir.path("g/guides.json").exists(), "nothing removed");
}

// 2. Caller-controlled sizes of the C ABI are bounded before allocating.

struct Session {
    mesh: *mut LmlMesh,
    field: *mut LmlField,
}

impl Session {
    /// A mesh handle of `mesh` and a θ = 60° session on it started from `field`, or the status
    /// and message of `lml_field_new` (the mesh handle is then already freed).
    fn start(mesh: &TriMesh, field: &[f64]) -> Result<Session, (LmlStatus, String)> {
        let xyz: Vec<f64> = mesh.positions().iter().flat_map(|p| [p.x, p.y, p.z]).collect();
        let triangles: Vec<u32> = mesh.faces().iter().flatten().copied().collect();
        // SAFETY: arrays of the stated lengths, outputs are locals; a handle is freed once.
        unsafe {
            let mut handle = std::ptr::null_mut();
            assert_eq!(lml_mesh_new(xyz.as_ptr(), mesh.vertex_count(), triangles.as_ptr(), mesh.face_count(), &mut handle), LmlStatus::Ok);
            let mut params = std::mem::zeroed();
            assert_eq!(lml_field_params_default(LML_FAMILY_PSEUDO_GEODESIC, 60.0, &mut params), LmlStatus::Ok);
            let mut session = std::ptr::null_mut();
            match lml_field_new(handle, field.as_ptr(), field.len(), &params, &mut session) {
                LmlStatus::Ok => Ok(Session { mesh: handle, field: session }),
                status => {
                    let message = last_error();
                    lml_mesh_free(handle);
                    Err((status, message))
                }
            }
        }
    }

    fn new() -> Session {
        let mesh = roof_mesh();
        Session::start(&mesh, &axis_field(&mesh)).expect("a session on the roof")
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        // SAFETY: live handles from `new`, freed once.
        unsafe {
            lml_field_free(self.field);
            lml_mesh_free(self.mesh);
        }
    }
}

#[test]
fn caller_sizes_of_the_c_abi_fail_with_a_status_instead_of_aborting() {
    let session = Session::new();
    // SAFETY (all blocks): live handles, outputs are locals, `levels` holds the stated count.
    unsafe {
        let mut curves = std::ptr::NonNull::<LmlCurves>::dangling().as_ptr();
        assert_eq!(lml_curves_new_uniform(session.field, 1 << 40, 0.0, &mut curves), LmlStatus::InvalidArgument);
        assert!(curves.is_null());
        assert!(last_error().contains("at most 10000"), "{}", last_error());

        let mut values = vec![0.0; 200];
        let mut needed = 0;
        assert_eq!(lml_field_values(session.field, values.as_mut_ptr(), values.len(), &mut needed), LmlStatus::Ok);
        let middle = [0.5 * (values[..needed].iter().copied().fold(f64::INFINITY, f64::min) + values[..needed].iter().copied().fold(f64::NEG_INFINITY, f64::max))];
        assert_eq!(lml_curves_new(session.field, middle.as_ptr(), 1, 1e-9, &mut curves), LmlStatus::InvalidArgument);
        assert!(last_error().contains("points"), "{}", last_error());
        let many = vec![middle[0]; LML_MAX_LEVELS + 1];
        assert_eq!(lml_curves_new(session.field, many.as_ptr(), many.len(), 0.0, &mut curves), LmlStatus::InvalidArgument);
        assert!(last_error().contains("10001 levels"), "{}", last_error());

        let mut starts = [std::mem::zeroed::<LmlEdgePoint>(); 4];
        assert_eq!(lml_boundary_starts(session.mesh, 0, 30.0, 0, u32::MAX, starts.as_mut_ptr(), 4, &mut needed), LmlStatus::InvalidArgument);
        assert!(last_error().contains("at most 10000"), "{}", last_error());

        let mut options = std::mem::zeroed::<LmlTraceOptions>();
        assert_eq!(lml_trace_options_default(&mut options), LmlStatus::Ok);
        options.max_points = u64::MAX;
        let mut guides = std::ptr::null_mut();
        assert_eq!(lml_boundary_starts(session.mesh, 0, 30.0, 0, 2, starts.as_mut_ptr(), 4, &mut needed), LmlStatus::Ok);
        let status = lml_guides_trace(session.mesh, starts.as_ptr(), 2, 60.0, 90.0, &options, &mut guides);
        assert_eq!(status, LmlStatus::InvalidArgument, "{}", last_error());
        assert!(last_error().contains("max_points"), "{}", last_error());

        // Strips with iteration counts of UINT32_MAX: refused at once, naming the count.
        assert_eq!(lml_curves_new_uniform(session.field, 2, 0.0, &mut curves), LmlStatus::Ok);
        let mut params = std::mem::zeroed::<LmlStripParams>();
        assert_eq!(lml_strip_params_default(60.0, 0.3, &mut params), LmlStatus::Ok);
        let mut strips = std::ptr::null_mut();
        for field in 0..4 {
            let mut bad = params;
            let (name, slot) = match field {
                0 => ("binormal_rounds", &mut bad.binormal_rounds),
                1 => ("iterations_per_round", &mut bad.iterations_per_round),
                2 => ("final_iterations", &mut bad.final_iterations),
                _ => ("polish_iterations", &mut bad.polish_iterations),
            };
            *slot = u32::MAX;
            let started = Instant::now();
            assert_eq!(lml_strips_new(curves, &bad, &mut strips), LmlStatus::InvalidArgument);
            assert!(started.elapsed().as_secs_f64() < 1.0, "refused before any work");
            assert!(last_error().contains(name), "{}", last_error());
        }
        let mut at_limit = params;
        at_limit.binormal_rounds = LML_MAX_STRIP_ROUNDS;
        at_limit.iterations_per_round = 0;
        at_limit.final_iterations = LML_MAX_STRIP_ITERATIONS;
        at_limit.polish_iterations = 1;
        // Built (a few iterations need not give an acceptable family, which is not a refusal).
        let status = lml_strips_new(curves, &at_limit, &mut strips);
        assert!(matches!(status, LmlStatus::Ok | LmlStatus::NoAcceptableFamily), "{status:?}: {}", last_error());
        assert!(!strips.is_null());
        lml_strips_free(strips);
        lml_curves_free(curves);
    }
}

// 3. Restored sessions are validated: a subnormal scale is corrupt data.

/// Byte offset of the saved field scale: magic and version, then the unit mesh (positions as a
/// length-prefixed list of 3 doubles, faces as a length-prefixed list of 3 `u32`), then the scales.
fn field_scale_offset(mesh: &TriMesh) -> usize {
    8 + 8 + 24 * mesh.vertex_count() + 8 + 12 * mesh.face_count()
}

fn session_with_field_scale(scale: f64) -> Vec<u8> {
    let mesh = roof_mesh();
    let solver = FieldSolver::new(&mesh, &axis_field(&mesh), FieldParams::pseudo_geodesic(60.0)).expect("solver");
    let mut bytes = solver.to_bytes();
    let at = field_scale_offset(&mesh);
    let saved = f64::from_le_bytes(bytes[at..at + 8].try_into().expect("8 bytes"));
    assert!(saved > 0.0 && saved.is_normal(), "the offset points at the field scale ({saved})");
    bytes[at..at + 8].copy_from_slice(&scale.to_le_bytes());
    bytes
}

#[test]
fn a_session_with_a_subnormal_field_scale_is_corrupt_data() {
    let bytes = session_with_field_scale(1e-320);
    match FieldSolver::from_bytes(&bytes) {
        Err(FieldError::CorruptData { message }) => assert!(message.contains("field scale"), "{message}"),
        Err(other) => panic!("expected corrupt data, got {other}"),
        Ok(_) => panic!("a subnormal field scale was accepted"),
    }
    // A normal but tiny scale un-scales the field beyond the value limit.
    let tiny = session_with_field_scale(1e-300);
    let error = FieldSolver::from_bytes(&tiny).err().expect("refused");
    assert!(error.to_string().contains("un-scales"), "{error}");
    // The C ABI says CORRUPT_DATA.
    let mut out = std::ptr::NonNull::<LmlField>::dangling().as_ptr();
    // SAFETY: `bytes` holds `len` bytes; `out` is a local.
    assert_eq!(unsafe { lml_field_load(bytes.as_ptr(), bytes.len(), &mut out) }, LmlStatus::CorruptData);
    assert!(out.is_null());
    // The command line exits with 2 instead of printing "converged".
    let dir = Scratch::new("subnormal");
    std::fs::write(dir.path("session.bin"), &bytes).expect("write");
    assert_bad_input(&dir.0, &["field", "--resume", "session.bin", "--out", "f"], &["session.bin", "field scale"]);
    assert!(!dir.path("f").exists());
}

// 4. A failed stdout write is an error, a closed pipe ends quietly.

fn info_with_stdout(dir: &Path, stdout: Stdio) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lamella")).args(["info", "roof.obj"]).current_dir(dir).stdout(stdout).stderr(Stdio::piped()).output().expect("run")
}

#[test]
fn a_full_stdout_is_one_error_line_and_a_closed_pipe_ends_quietly() {
    let dir = Scratch::new("stdout");
    small_roof(&dir, 60);
    if Path::new("/dev/full").exists() {
        let full = std::fs::OpenOptions::new().write(true).open("/dev/full").expect("open /dev/full");
        let output = info_with_stdout(&dir.0, Stdio::from(full));
        let message = stderr(&output);
        assert_eq!(output.status.code(), Some(1), "{message}");
        assert_eq!(message.trim_end().lines().count(), 1, "{message}");
        assert!(message.contains("cannot write to standard output") && !message.contains("panicked"), "{message}");
    }
    // The reader has gone before anything is written: every write meets a closed pipe.
    let mut child = Command::new(env!("CARGO_BIN_EXE_lamella"))
        .args(["info", "roof.obj"])
        .current_dir(&dir.0)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    drop(child.stdout.take());
    let output = child.wait_with_output().expect("wait");
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert!(output.stderr.is_empty(), "quiet: {}", stderr(&output));
}

// 5. Error messages are bounded.

#[test]
fn long_tokens_and_long_problem_lists_are_cut() {
    let dir = Scratch::new("bounded");
    let token = "9".repeat(1 << 20);
    std::fs::write(dir.path("token.obj"), format!("v 0 0 {token}x\n")).expect("write");
    let message = assert_bad_input(&dir.0, &["info", "token.obj"], &["line 1", "invalid coordinate", "…"]);
    assert!(message.len() < 400, "{} bytes", message.len());
    std::fs::write(dir.path("field.csv"), format!("{token}x\n")).expect("write");
    small_roof(&dir, 60);
    let message = assert_bad_input(&dir.0, &["strips", "--mesh", "roof.obj", "--field", "field.csv", "--out", "s", "--quiet"], &["line 1", "…"]);
    assert!(message.len() < 400, "{} bytes", message.len());
    std::fs::write(dir.path("strokes.json"), format!("{{\"{token}\": 1}}")).expect("write");
    let message = assert_bad_input(&dir.0, &["design", "--mesh", "roof.obj", "--strokes", "strokes.json", "--out", "d", "--quiet"], &["strokes.json", "…"]);
    assert!(message.len() < 600, "{} bytes", message.len());

    // 400,000 unused vertices and one triangle: 400,000 problems.
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    obj.push_str(&"v 5 5 5\n".repeat(400_000));
    std::fs::write(dir.path("many.obj"), obj).expect("write");
    let message = assert_bad_input(&dir.0, &["design", "--mesh", "many.obj", "--out", "d"], &["400000 problem(s)", "and 399,990 more"]);
    assert!(message.len() < 2000, "{} bytes", message.len());
    let info = lamella(&dir.0, &["info", "many.obj"]);
    assert_eq!(info.status.code(), Some(2));
    let report = stdout(&info);
    assert!(report.lines().count() < 110, "{} lines", report.lines().count());
    assert!(report.contains("and 399,900 more"), "{}", report.lines().last().unwrap_or(""));
}

// 6. Folded meshes are invalid input, naming the fold.

#[test]
fn a_folded_mesh_is_invalid_and_the_fold_is_named() {
    let (positions, faces) = folded(&roof_mesh());
    let error = TriMesh::from_vertices_and_faces(positions.clone(), faces.clone()).expect_err("a fold is refused");
    assert!(matches!(error, MeshError::FoldedEdge { .. }), "{error}");
    assert!(error.to_string().contains("fold"), "{error}");
    // Through OBJ and the command line: info says invalid, design exits 2 naming the faces.
    let mesh_text = obj_text(&(positions, faces));
    let dir = Scratch::new("fold");
    std::fs::write(dir.path("folded.obj"), mesh_text).expect("write");
    let info = lamella(&dir.0, &["info", "folded.obj"]);
    assert_eq!(info.status.code(), Some(2), "{}", stdout(&info));
    assert!(stdout(&info).contains("fold over at edge"), "{}", stdout(&info));
    assert_bad_input(&dir.0, &["design", "--mesh", "folded.obj", "--out", "d", "--max-iterations", "5"], &["folded.obj", "fold over", "faces"]);
}

// 7. An out-of-range field value is named, not reported as a constant field.

#[test]
fn a_huge_field_value_is_named_at_its_vertex() {
    let mesh = roof_mesh();
    let mut field = axis_field(&mesh);
    field[7] = 1e300;
    assert_eq!(FieldSolver::new(&mesh, &field, FieldParams::pseudo_geodesic(60.0)).err(), Some(FieldError::ValueOutOfRange { vertex: 7, value: 1e300 }));
    assert_eq!(uniform_levels(&mesh, &field, 3), Err(CurveError::FieldValueOutOfRange { vertex: 7, value: 1e300 }));
    field[7] = FIELD_VALUE_LIMIT;
    assert!(uniform_levels(&mesh, &field, 3).is_ok(), "the limit itself is allowed");
    // The C ABI: INVALID_ARGUMENT naming the vertex.
    field[7] = 1e300;
    let (status, message) = Session::start(&mesh, &field).err().expect("refused");
    assert_eq!(status, LmlStatus::InvalidArgument);
    assert!(message.contains("vertex 7") && message.contains("out of range"), "{message}");
    // The command line.
    let dir = Scratch::new("huge");
    small_roof(&dir, 60);
    let roof = TriMesh::read_obj(&dir.path("roof.obj")).expect("roof");
    let mut values = axis_field(&roof);
    values[3] = 1e300;
    let csv: String = values.iter().map(|v| format!("{v}\n")).collect();
    std::fs::write(dir.path("field.csv"), csv).expect("write");
    assert_bad_input(&dir.0, &["strips", "--mesh", "roof.obj", "--field", "field.csv", "--out", "s", "--quiet"], &["vertex 3", "out of range"]);
}

// 8. Input files are read up to a limit.

#[test]
fn an_endless_input_file_is_refused_at_the_size_limit() {
    if !Path::new("/dev/zero").exists() {
        return;
    }
    let dir = Scratch::new("endless");
    let started = Instant::now();
    assert_bad_input(&dir.0, &["info", "/dev/zero"], &["/dev/zero", "512 MiB"]);
    assert!(started.elapsed().as_secs_f64() < 30.0);
    assert_bad_input(&dir.0, &["info", "."], &["directory"]);
}

// 9. A sliver mesh is bad input naming the sliver (it made the initial field's systems singular).

/// The 8 × 8 dome with a boundary sliver of area ≈ eps / 2 (face 8), as OBJ text.
fn sliver_obj(eps: f64) -> String {
    obj_text(&sliver_grid(8, eps))
}

#[test]
fn a_sliver_mesh_is_bad_input_naming_the_sliver() {
    let dir = Scratch::new("sliver");
    std::fs::write(dir.path("sliver.obj"), sliver_obj(1e-11)).expect("write");
    let error = TriMesh::parse_obj(&sliver_obj(1e-11)).expect_err("refused");
    assert!(matches!(&error, MeshError::ObjLine { error, .. } if matches!(**error, MeshError::SliverFace { face: 8, .. })), "{error}");
    assert_bad_input(&dir.0, &["design", "--mesh", "sliver.obj", "--guides", "3", "--out", "d", "--quiet"], &["sliver.obj", "face 8 is a sliver"]);
    // A mild sliver (area ratio 2e-6) is valid and designs.
    std::fs::write(dir.path("mild.obj"), sliver_obj(1e-6)).expect("write");
    let output = lamella(&dir.0, &["design", "--mesh", "mild.obj", "--guides", "3", "--out", "d", "--max-iterations", "10", "--strips", "2", "--quiet"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
}

// Found by the fuzzer (fuzz/regressions/session/): a session whose saved solver options ask for
// 2^64 − 1 damped trials per iteration hung in its first step.

#[test]
fn a_session_asking_for_endless_damped_trials_is_corrupt_data() {
    let bytes = std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/regressions/session/lm-max-trials")).expect("reproducer");
    match FieldSolver::from_bytes(&bytes) {
        Err(FieldError::CorruptData { message }) => assert!(message.contains("lm.max_trials"), "{message}"),
        Err(other) => panic!("expected corrupt data, got {other}"),
        Ok(_) => panic!("accepted"),
    }
    let mut params = FieldParams::pseudo_geodesic(60.0);
    params.lm.max_trials = usize::MAX;
    let mesh = roof_mesh();
    let error = FieldSolver::new(&mesh, &axis_field(&mesh), params).err().expect("refused");
    assert!(matches!(error, FieldError::InvalidParameter { name: "lm.max_trials", .. }), "{error}");
}
