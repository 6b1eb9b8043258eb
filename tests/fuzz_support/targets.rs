//! The fuzz targets: each reader of hostile input with the invariants it must keep, and a seed
//! corpus made from the project's own surfaces and writers.
use super::{Target, Verdict};
use crate::config::GuideSide;
use crate::field_files::{field_csv, parse_field_csv};
use crate::mesh_support::{folded, obj_text as soup_obj, sliver_grid};
use crate::guides::{guides_json, parse_guides_json, trace_guides};
use crate::strokes_file::parse_strokes;
use lamella::base_mesh::{BaseMeshParams, BaseMeshSolver, NetMesh};
use lamella::curves::{extract_level_curves, uniform_levels};
use lamella::ffi::*;
use lamella::field::{Family, FieldParams, FieldSolver, FIELD_VALUE_LIMIT};
use lamella::initialisation::{field_from_guide_curves, field_from_strokes, GuideCurveOptions, StrokeOptions};
use lamella::mesh::{TriMesh, Vec3};
use lamella::net::{NetParams, NetSolver};
use lamella::reshape::{ReshapeParams, ReshapeSolver};
use lamella::surfaces::{cylinder_patch, hall_roof, CylinderPatch};
use std::ffi::CStr;
use std::sync::OnceLock;

/// Longest error message a reader may produce for an input of at most 64 KiB (tokens are
/// clipped to 80 characters, lists to 10 items).
const MAX_MESSAGE_CHARS: usize = 2000;
/// Inputs with more stroke or guide points than this are only parsed (keeps a run fast).
const MAX_FITTED_POINTS: usize = 400;

pub fn all() -> Vec<Target> {
    vec![
        Target { name: "obj", text: true, seeds: obj_seeds, run: obj },
        Target { name: "session", text: false, seeds: session_seeds, run: session },
        Target { name: "reshape_session", text: false, seeds: reshape_session_seeds, run: reshape_session },
        Target { name: "net_session", text: false, seeds: net_session_seeds, run: net_session },
        Target { name: "base_mesh_session", text: false, seeds: base_mesh_session_seeds, run: base_mesh_session },
        Target { name: "field_csv", text: true, seeds: field_csv_seeds, run: field_csv_target },
        Target { name: "strokes", text: true, seeds: strokes_seeds, run: strokes },
        Target { name: "guides", text: true, seeds: guides_seeds, run: guides },
        Target { name: "c_abi", text: false, seeds: c_abi_seeds, run: c_abi },
    ]
}

/// The small hall roof every target works on (about 40 vertices).
fn roof() -> &'static TriMesh {
    static ROOF: OnceLock<TriMesh> = OnceLock::new();
    ROOF.get_or_init(|| hall_roof(40).into_mesh().expect("the hall roof is valid"))
}

fn axis_field(mesh: &TriMesh) -> Vec<f64> {
    mesh.positions().iter().map(|p| p.x).collect()
}

fn obj_text(mesh: &TriMesh) -> Vec<u8> {
    let mut bytes = Vec::new();
    mesh.write_obj(&mut bytes).expect("writing to memory");
    bytes
}

/// A bounded message, or the broken invariant.
fn bounded(message: String) -> Verdict {
    if message.chars().count() > MAX_MESSAGE_CHARS {
        return Err(format!("a message of {} characters: {}…", message.chars().count(), message.chars().take(200).collect::<String>()));
    }
    Ok(message)
}

fn obj_seeds() -> Vec<Vec<u8>> {
    let mut seeds = vec![obj_text(roof()), obj_text(&hall_roof(12).into_mesh().expect("valid"))];
    seeds.push(b"# quads, relative indices, texture and normal indices\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\ng patch\nf 1/1/1 2/1/1 3/1/1 4/1/1\nv 2 0 0\nf -4//1 -1//1 -3//1\n".to_vec());
    // A fold (a vertex pulled across its neighbour), a sliver, and a sliver just above the limit.
    seeds.push(soup_obj(&folded(roof())).into_bytes());
    seeds.push(soup_obj(&sliver_grid(4, 1e-11)).into_bytes());
    seeds.push(soup_obj(&sliver_grid(4, 1e-6)).into_bytes());
    seeds
}

/// `parse_obj` accepts exactly the inputs `diagnose_obj` finds no problem in; messages are bounded.
fn obj(input: &[u8]) -> Verdict {
    let text = String::from_utf8_lossy(input);
    let parsed = TriMesh::parse_obj(&text);
    let diagnosed = TriMesh::diagnose_obj(&text);
    match (&parsed, &diagnosed) {
        (Ok(_), Ok(problems)) if problems.is_empty() => {}
        (Err(_), Ok(problems)) if !problems.is_empty() => {}
        (Err(a), Err(b)) if a == b => {}
        _ => return Err(format!("parse_obj {:?} disagrees with diagnose_obj {:?}", parsed.as_ref().err(), diagnosed.as_ref().map(Vec::len))),
    }
    match parsed {
        Ok(mesh) => {
            if !mesh.vertex_areas().iter().chain(mesh.face_areas()).all(|a| a.is_finite() && *a > 0.0) {
                return Err("an accepted mesh has a non-finite or zero area".into());
            }
            Ok(format!("ok {}", mesh.boundary_loops().len()))
        }
        Err(e) => bounded(e.to_string()),
    }
}

fn session_seeds() -> Vec<Vec<u8>> {
    let mesh = roof();
    let mut solver = FieldSolver::new(mesh, &axis_field(mesh), FieldParams::pseudo_geodesic(60.0)).expect("a field on the roof");
    let mut seeds = vec![solver.to_bytes()];
    solver.step(2).expect("two steps");
    seeds.push(solver.to_bytes());
    let geodesic = FieldSolver::new(mesh, &axis_field(mesh), FieldParams::new(Family::Geodesic)).expect("a geodesic field");
    seeds.push(geodesic.to_bytes());
    seeds
}

/// What a saved-session loader must keep: a restored session's values (`finite`) are finite and
/// in range, it saves to the very bytes it came from, and one step (`step`, which describes its
/// outcome) neither panics nor makes a value non-finite. `what` names the kind of session.
struct SessionChecks<S> {
    what: &'static str,
    load: fn(&[u8]) -> Result<S, String>,
    save: fn(&S) -> Vec<u8>,
    finite: fn(&S) -> bool,
    step: fn(&mut S) -> String,
}

impl<S> SessionChecks<S> {
    fn run(&self, input: &[u8]) -> Verdict {
        let mut session = match (self.load)(input) {
            Ok(session) => session,
            Err(message) => return bounded(message),
        };
        if !(self.finite)(&session) {
            return Err(format!("a restored {} session has a value that is not finite or out of range", self.what));
        }
        if (self.save)(&session) != input {
            return Err(format!("a restored {} session saves to other bytes", self.what));
        }
        let outcome = (self.step)(&mut session);
        if !(self.finite)(&session) {
            return Err(format!("a step made a value of a {} session non-finite", self.what));
        }
        bounded(outcome)
    }
}

/// "stepped true|false", or the error.
fn stepped<R, E: std::fmt::Display>(result: Result<R, E>, converged: impl Fn(&R) -> bool) -> String {
    match result {
        Ok(report) => format!("stepped {}", converged(&report)),
        Err(e) => e.to_string(),
    }
}

fn session(input: &[u8]) -> Verdict {
    SessionChecks {
        what: "field",
        load: |b| FieldSolver::from_bytes(b).map_err(|e| e.to_string()),
        save: FieldSolver::to_bytes,
        finite: |s| s.field().iter().all(|f| f.is_finite() && f.abs() <= FIELD_VALUE_LIMIT),
        step: |s| stepped(s.step(1), |r| r.converged),
    }
    .run(input)
}

fn reshape_session_seeds() -> Vec<Vec<u8>> {
    let mesh = roof();
    let field: Vec<f64> = mesh.positions().iter().map(|p| p.x + 0.05 * p.y * p.y).collect();
    let mut solver = ReshapeSolver::new(mesh, &field, ReshapeParams::new(45.0)).expect("a surface session on the roof");
    let mut seeds = vec![solver.to_bytes()];
    solver.step(2).expect("two steps");
    seeds.push(solver.to_bytes());
    seeds
}

fn reshape_session(input: &[u8]) -> Verdict {
    SessionChecks {
        what: "surface",
        load: |b| ReshapeSolver::from_bytes(b).map_err(|e| e.to_string()),
        save: ReshapeSolver::to_bytes,
        finite: |s| s.positions().iter().all(|p| p.iter().all(|v| v.is_finite())),
        step: |s| stepped(s.step(1), |r| r.converged),
    }
    .run(input)
}

fn net_session_seeds() -> Vec<Vec<u8>> {
    let mesh = roof();
    let g: Vec<f64> = mesh.positions().iter().map(|p| p.y - 0.1 * p.x).collect();
    let theta = Family::PseudoGeodesic { theta_degrees: 60.0 };
    let mut params = NetParams::new(theta, theta);
    params.intersection_degrees = Some(80.0);
    let mut solver = NetSolver::new(mesh, &[axis_field(mesh), g], params).expect("a net on the roof");
    let mut seeds = vec![solver.to_bytes()];
    solver.step(2).expect("two steps");
    seeds.push(solver.to_bytes());
    seeds
}

fn net_session(input: &[u8]) -> Verdict {
    SessionChecks {
        what: "net",
        load: |b| NetSolver::from_bytes(b).map_err(|e| e.to_string()),
        save: NetSolver::to_bytes,
        finite: |s| s.fields().iter().flatten().all(|f| f.is_finite() && f.abs() <= FIELD_VALUE_LIMIT),
        step: |s| stepped(s.step(1), |r| r.converged),
    }
    .run(input)
}

/// Five rows and five columns of ±45° helices on a small cylinder patch (about 60 vertices),
/// each vertex moved a little, and the patch.
fn helix_net() -> (NetMesh, TriMesh) {
    let radius = 2.0;
    let surface = cylinder_patch(&CylinderPatch { radius, span: 2.0, height: 4.0, target_vertices: 60, irregularity: 0.2, seed: 3 });
    let surface = surface.expect("a valid patch").into_mesh().expect("a valid mesh");
    let positions = (0..25)
        .map(|v| {
            let (i, j) = (f64::from(v / 5), f64::from(v % 5));
            let (s, z) = (1.0 + 0.25 * (i + j), 2.0 + 0.25 * (j - i));
            let wobble = 0.02 * (3.7 * f64::from(v)).sin();
            Vec3::new(radius * (s / radius).cos() + wobble, radius * (s / radius).sin(), z - wobble)
        })
        .collect();
    let rows = (0..5).map(|i| (0..5).map(|j| 5 * i + j).collect()).collect();
    let columns = (0..5).map(|j| (0..5).map(|i| 5 * i + j).collect()).collect();
    (NetMesh::new(positions, rows, columns).expect("a valid net"), surface)
}

fn base_mesh_session_seeds() -> Vec<Vec<u8>> {
    let (net, surface) = helix_net();
    let mut geodesic = BaseMeshParams::new(Family::Geodesic, Family::Geodesic);
    geodesic.torsion_free = true;
    let mut solver = BaseMeshSolver::new(&net, &surface, geodesic.clone()).expect("a base-mesh session on the patch");
    let mut seeds = vec![solver.to_bytes()];
    solver.step(2).expect("two steps");
    seeds.push(solver.to_bytes());
    // The torsion-free rows on from the start, and a pseudo-geodesic family.
    let at_once = BaseMeshParams { families_first: false, ..geodesic };
    seeds.push(BaseMeshSolver::new(&net, &surface, at_once).expect("torsion-free at once").to_bytes());
    let pseudo = BaseMeshParams::new(Family::PseudoGeodesic { theta_degrees: 60.0 }, Family::Geodesic);
    seeds.push(BaseMeshSolver::new(&net, &surface, pseudo).expect("a pseudo-geodesic family").to_bytes());
    seeds
}

fn base_mesh_session(input: &[u8]) -> Verdict {
    SessionChecks {
        what: "base-mesh",
        load: |b| BaseMeshSolver::from_bytes(b).map_err(|e| e.to_string()),
        save: BaseMeshSolver::to_bytes,
        finite: |s| s.positions().iter().all(|p| p.iter().all(|v| v.is_finite())),
        step: |s| stepped(s.step(1), |r| r.converged),
    }
    .run(input)
}

fn field_csv_seeds() -> Vec<Vec<u8>> {
    let field = axis_field(roof());
    let mut commented = field_csv(&field);
    commented.push_str("# trailing comment\n\n");
    vec![field_csv(&field).into_bytes(), commented.into_bytes()]
}

/// The reader returns finite values only; a field of the roof's length goes through the level
/// functions the `strips` command uses, which never panic.
fn field_csv_target(input: &[u8]) -> Verdict {
    let values = match parse_field_csv(&String::from_utf8_lossy(input), "fuzz.csv") {
        Ok(values) => values,
        Err(e) => return bounded(e.to_string()),
    };
    if !values.iter().all(|v| v.is_finite()) {
        return Err("field.csv reader returned a non-finite value".into());
    }
    let mesh = roof();
    if values.len() != mesh.vertex_count() {
        return Ok(format!("values {}", values.len().min(3)));
    }
    let outcome = uniform_levels(mesh, &values, 5).and_then(|levels| extract_level_curves(mesh, &values, &levels));
    match outcome {
        Ok(curves) => Ok(format!("curves {}", curves.len().min(3))),
        Err(e) => bounded(e.to_string()),
    }
}

fn strokes_json(strokes: &[Vec<Vec3>]) -> Vec<u8> {
    let arrays: Vec<Vec<[f64; 3]>> = strokes.iter().map(|s| s.iter().map(|p| [p.x, p.y, p.z]).collect()).collect();
    serde_json::to_vec(&serde_json::json!({ "strokes": arrays })).expect("json")
}

fn strokes_seeds() -> Vec<Vec<u8>> {
    // Two and three pieces of the boundary: polylines on the surface.
    let mesh = roof();
    let boundary: Vec<Vec3> = mesh.boundary_loops()[0].iter().map(|&v| mesh.positions()[v as usize]).collect();
    let n = boundary.len();
    let piece = |from: usize| boundary[from..from + n / 4].to_vec();
    vec![strokes_json(&[piece(0), piece(n / 2)]), strokes_json(&[piece(0), piece(n / 4), piece(n / 2)])]
}

/// Parsed strokes go through the stroke fit, which fails with an error or gives a finite field.
fn strokes(input: &[u8]) -> Verdict {
    let strokes = match parse_strokes(&String::from_utf8_lossy(input), "fuzz.json") {
        Ok(strokes) => strokes,
        Err(e) => return bounded(e.to_string()),
    };
    if strokes.iter().map(Vec::len).sum::<usize>() > MAX_FITTED_POINTS {
        return Ok("parsed".into());
    }
    match field_from_strokes(roof(), &strokes, &StrokeOptions::default()) {
        Ok(fitted) if fitted.field.iter().all(|f| f.is_finite()) => Ok("fitted".into()),
        Ok(_) => Err("the stroke fit returned a non-finite field".into()),
        Err(e) => bounded(e.to_string()),
    }
}

fn guides_seeds() -> Vec<Vec<u8>> {
    let mesh = roof();
    [2, 3]
        .iter()
        .map(|&count| guides_json(&trace_guides(mesh, count, GuideSide::Longest, 90.0, 60.0).expect("guides on the roof")).into_bytes())
        .collect()
}

/// Parsed guides go through the guide-curve field (Eq. 5–7), which fails with an error or gives
/// a finite field.
fn guides(input: &[u8]) -> Verdict {
    let (_, curves) = match parse_guides_json(&String::from_utf8_lossy(input), "fuzz.json") {
        Ok(parsed) => parsed,
        Err(e) => return bounded(e.to_string()),
    };
    if curves.iter().map(Vec::len).sum::<usize>() > MAX_FITTED_POINTS {
        return Ok("parsed".into());
    }
    match field_from_guide_curves(roof(), &curves, &GuideCurveOptions::default()) {
        Ok(start) if start.field.iter().all(|f| f.is_finite()) && start.gradient_target.is_finite() => Ok("fitted".into()),
        Ok(_) => Err("the guide-curve field is not finite".into()),
        Err(e) => bounded(e.to_string()),
    }
}

/// Reads the C ABI target's input: little-endian numbers, zero past the end.
struct Reader<'a> {
    data: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn bytes<const N: usize>(&mut self) -> [u8; N] {
        let mut out = [0u8; N];
        for b in &mut out {
            *b = self.data.get(self.at).copied().unwrap_or(0);
            self.at += 1;
        }
        out
    }
    fn u8(&mut self) -> u8 {
        self.bytes::<1>()[0]
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes(self.bytes())
    }
    fn u64(&mut self) -> u64 {
        u64::from_le_bytes(self.bytes())
    }
    fn f64(&mut self) -> f64 {
        f64::from_le_bytes(self.bytes())
    }
}

/// The C ABI target's input layout: vertex count (u8), triangle count (u8), family (u8), θ (f64),
/// coordinates (3 f64 per vertex), triangles (3 u32 each), one field value (f64) per vertex, the
/// uniform level count (u64) and the resampling spacing (f64).
fn c_abi_input(mesh: &TriMesh, field: &[f64], levels: u64, spacing: f64) -> Vec<u8> {
    let mut bytes = vec![mesh.vertex_count() as u8, mesh.face_count() as u8, 0];
    bytes.extend(60f64.to_le_bytes());
    for p in mesh.positions() {
        bytes.extend(p.iter().flat_map(|c| c.to_le_bytes()));
    }
    for f in mesh.faces() {
        bytes.extend(f.iter().flat_map(|i| i.to_le_bytes()));
    }
    bytes.extend(field.iter().flat_map(|v| v.to_le_bytes()));
    bytes.extend(levels.to_le_bytes());
    bytes.extend(spacing.to_le_bytes());
    bytes
}

fn c_abi_seeds() -> Vec<Vec<u8>> {
    let small = hall_roof(12).into_mesh().expect("valid");
    let roof = roof();
    assert!(roof.vertex_count() < 256 && roof.face_count() < 256, "the seed meshes fit the u8 counts");
    vec![
        c_abi_input(&small, &axis_field(&small), 3, 0.0),
        c_abi_input(roof, &axis_field(roof), 5, roof.mean_edge_length()),
    ]
}

/// The thread's last error message.
fn last_error() -> String {
    // SAFETY: lml_last_error_message never returns NULL and its string lives until the next call.
    unsafe { CStr::from_ptr(lml_last_error_message()) }.to_string_lossy().into_owned()
}

/// A status of the C ABI: an internal error (a caught panic) or a failure without a bounded
/// message is a finding.
fn check(status: LmlStatus, call: &str) -> Result<bool, String> {
    if status == LmlStatus::InternalError {
        return Err(format!("{call}: internal error: {}", last_error()));
    }
    if (status as i32) < 0 {
        let message = last_error();
        if message.is_empty() || message.chars().count() > MAX_MESSAGE_CHARS {
            return Err(format!("{call}: a failure with a message of {} characters", message.chars().count()));
        }
    }
    Ok((status as i32) >= 0)
}

/// Mesh creation, a field session, one step and uniform level curves through the C ABI: no
/// internal error, bounded messages, every handle released.
fn c_abi(input: &[u8]) -> Verdict {
    let mut r = Reader { data: input, at: 0 };
    let (vertices, triangles, family) = (usize::from(r.u8()), usize::from(r.u8()), u32::from(r.u8() % 4));
    let theta = r.f64();
    let xyz: Vec<f64> = (0..3 * vertices).map(|_| r.f64()).collect();
    let faces: Vec<u32> = (0..3 * triangles).map(|_| r.u32()).collect();
    let values: Vec<f64> = (0..vertices).map(|_| r.f64()).collect();
    let (levels, spacing) = (r.u64(), r.f64());
    let live = lml_debug_live_handles();
    let mut outcome = String::new();
    // SAFETY (all blocks): every pointer points at a live local of the stated length; handles
    // are used on this thread only and freed once.
    unsafe {
        let mut mesh = std::ptr::null_mut();
        let created = lml_mesh_new(xyz.as_ptr(), vertices, faces.as_ptr(), triangles, &mut mesh);
        outcome.push_str(&last_error());
        if check(created, "lml_mesh_new")? {
            let mut params = std::mem::zeroed::<LmlFieldParams>();
            let defaulted = lml_field_params_default(family, theta, &mut params);
            if check(defaulted, "lml_field_params_default")? {
                let mut field = std::ptr::null_mut();
                let started = check(lml_field_new(mesh, values.as_ptr(), values.len(), &params, &mut field), "lml_field_new");
                outcome.push_str(&last_error());
                if started? {
                    let mut report = std::mem::zeroed::<LmlReport>();
                    let stepped = check(lml_field_step(field, 1, &mut report), "lml_field_step");
                    let mut curves = std::ptr::null_mut();
                    let extracted = check(lml_curves_new_uniform(field, levels as usize, spacing, &mut curves), "lml_curves_new_uniform");
                    outcome.push_str(&last_error());
                    lml_curves_free(curves);
                    lml_field_free(field);
                    stepped?;
                    extracted?;
                }
            }
            lml_mesh_free(mesh);
        }
    }
    if lml_debug_live_handles() != live {
        return Err("a handle was not released".into());
    }
    Ok(outcome)
}
