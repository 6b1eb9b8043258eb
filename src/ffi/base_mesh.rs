//! `LmlBaseMesh`: a base-mesh optimisation session (paper Sec. 3.5, with the torsion-free nodes
//! of Sec. 5.2.1, Eq. 21), stepped like `LmlField`: create from a net of rows and columns near a
//! reference surface (given, or the quad net of an `LmlStripNet`), or from a 3-web of rows,
//! columns and diagonals (given, or the web of an `LmlStripWeb`), step until converged, read
//! the positions, the nodes' ruling angles, each family's report and strips and a web's
//! triangles, save and load, free.

use super::failure::Failure;
use super::guard::guarded;
use super::last_error::set_last_error;
use super::layout::flat_xyz;
use super::mesh::LmlMesh;
use super::net::family;
use super::raw::{copy_out, element_count, handle, handle_mut, input, release, Out};
use super::status::LmlStatus;
use super::strip_net::LmlStripNet;
use super::strip_web::LmlStripWeb;
use super::strips::LmlStrips;
use crate::base_mesh::{BaseMeshError, BaseMeshParams, BaseMeshReport, BaseMeshSolver, BaseMeshWeights, NetMesh, NodeRuling};
use crate::field::{Family, FieldError};
use crate::mesh::{TriMesh, Vec3};

/// A base-mesh optimisation session (opaque): a copy of the reference surface, the net with its
/// auxiliary variables (normals, binormals, rulings) and the solver state. Create it with
/// `lml_base_mesh_new`, `lml_base_mesh_new_slopes` or `lml_base_mesh_from_strip_net` (a net of
/// two families), or `lml_base_mesh_new_web` or `lml_base_mesh_from_strip_web` (a 3-web of
/// three), release it with `lml_base_mesh_free`.
pub struct LmlBaseMesh {
    solver: BaseMeshSolver,
}

/// The state of a base-mesh optimisation (written by the library; the caller owns the struct),
/// measured from outside: each family's angle at the net's own vertices against the reference's
/// smooth normal, the distance of the net from the reference, and the ruling angle at the nodes.
/// Lengths in the net's units, angles in degrees; index 0 is the rows, 1 the columns (a web's
/// diagonals, family 2, are reported by `lml_base_mesh_family_report`). Never NaN.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlBaseMeshReport {
    /// Iterations run since the session was created.
    pub iterations: u64,
    /// 1 when converged (further steps do nothing), else 0.
    pub converged: u64,
    /// Each family's target angle along its polylines' direction: θ, or 180° − θ for a
    /// pseudo-geodesic family whose polylines run the other way (the same curves).
    pub target_degrees: [f64; 2],
    /// RMS and maximum of each family's |θ_measured − target| over its measured vertices.
    pub angle_error_rms_degrees: [f64; 2],
    pub angle_error_max_degrees: [f64; 2],
    /// Inner vertices of each family where the angle was measured, and those where the polyline
    /// is straight (no osculating plane: exact for geodesics and asymptotic curves, a miss for
    /// pseudo-geodesics).
    pub measured_vertices: [u64; 2],
    pub straight_vertices: [u64; 2],
    /// Largest and RMS distance of a vertex from the reference, and the largest in % of the
    /// reference's bounding-box diagonal.
    pub max_deviation: f64,
    pub rms_deviation: f64,
    pub max_deviation_percent: f64,
    /// Nodes (vertices inside a row and a column) whose two strips both exist, and the largest
    /// and RMS angle between their rulings there (0 at a torsion-free node, Sec. 5.2.1).
    pub node_count: u64,
    pub node_ruling_angle_max_degrees: f64,
    pub node_ruling_angle_rms_degrees: f64,
    /// 1 when every measured vertex of every family (a web's diagonals too) is within 1° of its
    /// target (and a pseudo-geodesic family is nowhere straight), else 0.
    pub families_met: u64,
    /// 1 when every measured node's ruling angle is at most 0.5°, else 0.
    pub torsion_free: u64,
    /// The weighted energy (sum of squared residuals) being minimised, on the net scaled to mean
    /// segment length 1.
    pub energy: f64,
}

/// One family's part of a base-mesh report (written by the library; the caller owns the struct):
/// its angle measured from outside at its polylines' inner vertices against the reference's
/// smooth normal, as `LmlBaseMeshReport` reports the rows and columns. Angles in degrees; never NaN.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlBaseMeshFamilyReport {
    /// The family's target angle along its polylines' direction (as `target_degrees` of
    /// `LmlBaseMeshReport`; a slope for a constant-slope family).
    pub target_degrees: f64,
    /// RMS and maximum of |θ_measured − target| over the measured vertices.
    pub angle_error_rms_degrees: f64,
    pub angle_error_max_degrees: f64,
    /// Inner vertices of the family's polylines where the angle was measured, and those where the
    /// polyline is straight (no osculating plane: exact for geodesics and asymptotic curves,
    /// counted among the measured with no error; a miss for pseudo-geodesics).
    pub measured_vertices: u64,
    pub straight_vertices: u64,
}

impl LmlBaseMeshFamilyReport {
    /// Family `k` (below the report's family count) of `r`.
    fn of(r: &BaseMeshReport, k: usize) -> LmlBaseMeshFamilyReport {
        let family = &r.families[k];
        LmlBaseMeshFamilyReport {
            target_degrees: r.targets_degrees[k],
            angle_error_rms_degrees: family.rms_error_degrees,
            angle_error_max_degrees: family.max_error_degrees,
            measured_vertices: family.measured as u64,
            straight_vertices: family.straight as u64,
        }
    }
}

impl From<&BaseMeshReport> for LmlBaseMeshReport {
    fn from(r: &BaseMeshReport) -> LmlBaseMeshReport {
        let count = |n: usize| n as u64;
        let families = [0, 1].map(|k| LmlBaseMeshFamilyReport::of(r, k));
        LmlBaseMeshReport {
            iterations: count(r.iterations),
            converged: u64::from(r.converged),
            target_degrees: families.map(|f| f.target_degrees),
            angle_error_rms_degrees: families.map(|f| f.angle_error_rms_degrees),
            angle_error_max_degrees: families.map(|f| f.angle_error_max_degrees),
            measured_vertices: families.map(|f| f.measured_vertices),
            straight_vertices: families.map(|f| f.straight_vertices),
            max_deviation: r.deviation.max,
            rms_deviation: r.deviation.rms,
            max_deviation_percent: r.deviation.max_percent,
            node_count: count(r.node_torsion.nodes),
            node_ruling_angle_max_degrees: r.node_torsion.max_degrees,
            node_ruling_angle_rms_degrees: r.node_torsion.rms_degrees,
            families_met: u64::from(r.families_met),
            torsion_free: u64::from(r.torsion_free),
            energy: r.energy,
        }
    }
}

/// One node of the optimised net (a vertex inside a row and a column): the angle between the
/// rulings of its row's and its column's strips there (Sec. 5.2.1), and the node axis.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlBaseMeshNode {
    /// The vertex (index into the net's positions).
    pub vertex: u32,
    /// 1 when both polylines through the node carry a strip, so that the next two are defined;
    /// else 0 and they are 0.
    pub defined: u32,
    /// Angle between the two rulings as lines, in [0°, 90°]: 0 for a torsion-free node.
    pub ruling_angle_degrees: f64,
    /// Unit node axis: the mean of the two unit rulings.
    pub axis: [f64; 3],
}

impl From<&NodeRuling> for LmlBaseMeshNode {
    fn from(n: &NodeRuling) -> LmlBaseMeshNode {
        let defined = n.angle_degrees.zip(n.axis);
        LmlBaseMeshNode {
            // A net has at most MAX_NET_VERTICES (below 2^32) vertices.
            vertex: n.vertex as u32,
            defined: u32::from(defined.is_some()),
            ruling_angle_degrees: defined.map_or(0.0, |(angle, _)| angle),
            axis: defined.map_or([0.0; 3], |(_, axis)| [axis.x, axis.y, axis.z]),
        }
    }
}

impl From<BaseMeshError> for Failure {
    fn from(e: BaseMeshError) -> Failure {
        match e {
            BaseMeshError::Solver(error) => Failure::from(FieldError::Solver(error)),
            corrupt @ (BaseMeshError::CorruptData { .. } | BaseMeshError::UnsupportedVersion { .. }) => Failure::new(LmlStatus::CorruptData, corrupt.to_string()),
            other => Failure::new(LmlStatus::InvalidArgument, other.to_string()),
        }
    }
}

/// A session optimising `net` near `reference` with the default weights, its families (two for a
/// net, three for a web) by their angles θ, each given with its argument's name.
fn session(net: &NetMesh, reference: &TriMesh, thetas: &[(&str, f64)], torsion_free: u32) -> Result<LmlBaseMesh, Failure> {
    let families = thetas.iter().map(|&(name, theta)| family(theta, name)).collect::<Result<Vec<Family>, Failure>>()?;
    let mut params = match families[..] {
        [rows, columns] => BaseMeshParams::new(rows, columns),
        [rows, columns, diagonals] => BaseMeshParams::web(rows, columns, diagonals),
        _ => unreachable!("a net has two families and a web three"),
    };
    params.torsion_free = torsion_free != 0;
    Ok(LmlBaseMesh { solver: BaseMeshSolver::new(net, reference, params)? })
}

/// The two families of a net by their angles θ, named as `lml_base_mesh_new`'s arguments.
fn net_thetas(theta_degrees_rows: f64, theta_degrees_columns: f64) -> [(&'static str, f64); 2] {
    [("theta_degrees_rows", theta_degrees_rows), ("theta_degrees_columns", theta_degrees_columns)]
}

/// The polyline counts of a net's two families, named as `lml_base_mesh_new`'s arguments.
fn net_counts(row_count: usize, column_count: usize) -> [(usize, &'static str); 2] {
    [(row_count, "row_count"), (column_count, "column_count")]
}

/// The three families of a web by their angles θ: `thetas[0]` to `thetas[2]`, as `lml_web_new`.
///
/// # Safety
/// `thetas` NULL (refused) or readable for 3 doubles.
unsafe fn web_thetas(thetas: *const f64) -> Result<[(&'static str, f64); 3], Failure> {
    // SAFETY: the caller's contract.
    let t = unsafe { input(thetas, 3, "thetas") }?;
    Ok([("thetas[0]", t[0]), ("thetas[1]", t[1]), ("thetas[2]", t[2])])
}

/// The net of `lml_base_mesh_new`'s arrays, or of `lml_base_mesh_new_web`'s (their contracts as
/// documented there): `counts` holds the polyline count of each family (two or three) with its
/// argument's name.
///
/// # Safety
/// `xyz` readable for `3 vertex_count` doubles, `polyline_vertices` for `polyline_vertex_count`
/// and `polyline_lengths` for the sum of `counts` values (or NULL, refused).
unsafe fn net_from_arrays(
    xyz: *const f64,
    vertex_count: usize,
    polyline_vertices: *const u32,
    polyline_vertex_count: usize,
    polyline_lengths: *const u32,
    counts: &[(usize, &str)],
) -> Result<NetMesh, Failure> {
    // SAFETY (all blocks): the caller's contract.
    let xyz = unsafe { input(xyz, element_count(vertex_count, 3, "vertex_count")?, "xyz") }?;
    let sum = counts.iter().map(|&(_, name)| name).collect::<Vec<_>>().join(" + ");
    let polyline_count = counts.iter().try_fold(0usize, |total, &(count, name)| total.checked_add(count).ok_or_else(|| Failure::argument(name, format!("{sum} is too large"))))?;
    let lengths = unsafe { input(polyline_lengths, polyline_count, "polyline_lengths") }?;
    let vertices = unsafe { input(polyline_vertices, polyline_vertex_count, "polyline_vertices") }?;
    let total = lengths.iter().try_fold(0usize, |total, &length| total.checked_add(length as usize));
    if total != Some(polyline_vertex_count) {
        let sum = total.map_or_else(|| "exceed the address space".to_string(), |t| format!("sum to {t}"));
        return Err(Failure::argument("polyline_lengths", format!("the {polyline_count} lengths {sum}, not polyline_vertex_count = {polyline_vertex_count}")));
    }
    let mut rest = vertices;
    let mut polylines = lengths.iter().map(|&length| {
        let (line, tail) = rest.split_at(length as usize);
        rest = tail;
        line.to_vec()
    });
    let mut families = counts.iter().map(|&(count, _)| polylines.by_ref().take(count).collect::<Vec<Vec<u32>>>());
    let (rows, columns) = (families.next().unwrap_or_default(), families.next().unwrap_or_default());
    let positions = xyz.chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2])).collect();
    Ok(match families.next() {
        Some(diagonals) => NetMesh::web(positions, rows, columns, diagonals)?,
        None => NetMesh::new(positions, rows, columns)?,
    })
}

/// Starts optimising a net of rows and columns (paper Sec. 3.5) so that each family of polylines
/// becomes the asked curves (pseudo-geodesic, geodesic or asymptotic) on or near `reference`,
/// with the default weights; with `torsion_free` non-zero, also so that the strips of the row and
/// of the column through every node share its ruling (Eq. 21), in a second stage once the
/// families have settled. Then every polyline carries a developable strip of planar quads
/// (`lml_base_mesh_strips`).
///
/// - `reference`: the surface the net should stay on (copied).
/// - `xyz`: `3 * vertex_count` doubles, the net's vertices (finite, in the reference's units).
/// - `polyline_vertices`: `polyline_vertex_count` zero-based vertex indices: the rows, then the
///   columns, each in order along its polyline, one after another.
/// - `polyline_lengths`: `row_count + column_count` vertex counts (each ≥ 2), the rows' first;
///   they must sum to `polyline_vertex_count`. A vertex lies on at most one row and one column;
///   consecutive vertices of a polyline are at distinct points.
/// - `theta_degrees_rows`, `theta_degrees_columns`: each family by its angle θ in [0°, 180°]:
///   0° and 180° asymptotic curves, 90° geodesics, others pseudo-geodesics of that signed angle
///   (each held at θ or 180° − θ, whichever its polylines are nearer to as given).
/// - `out`: receives the new session (release with `lml_base_mesh_free`); NULL on failure.
///
/// The arrays are copied; the caller keeps them.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer with a non-zero count, a
/// count overflow, lengths not summing to `polyline_vertex_count`, θ out of range, a non-finite
/// coordinate, a polyline of fewer than two vertices or referring to a vertex out of range, a
/// vertex on two rows or two columns, coincident consecutive vertices, no vertex inside a
/// polyline of three or more: the message names the argument, vertex or polyline);
/// `LML_STATUS_INTERNAL_ERROR` (the problem could not be set up).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_new(
    reference: *const LmlMesh,
    xyz: *const f64,
    vertex_count: usize,
    polyline_vertices: *const u32,
    polyline_vertex_count: usize,
    polyline_lengths: *const u32,
    row_count: usize,
    column_count: usize,
    theta_degrees_rows: f64,
    theta_degrees_columns: f64,
    torsion_free: u32,
    out: *mut *mut LmlBaseMesh,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let reference = unsafe { handle(reference, "reference") }?;
        let net = unsafe { net_from_arrays(xyz, vertex_count, polyline_vertices, polyline_vertex_count, polyline_lengths, &net_counts(row_count, column_count)) }?;
        out.set_owned(session(&net, &reference.mesh, &net_thetas(theta_degrees_rows, theta_degrees_columns), torsion_free)?);
        Ok(LmlStatus::Ok)
    })
}

/// Starts optimising a net of rows and columns (given as in `lml_base_mesh_new`) so that both
/// families become curves of constant slope about one axis (Sec. 5.2.2–5.2.3): every segment
/// makes the angle β of its family with the planes orthogonal to `axis` (`ê·a = sin β`, Eq. 22
/// per segment) and the axis lies in every rectifying plane, so the rulings of every strip, and
/// the axis of every node, are parallel to `axis`: a torsion-free structure (Sec. 5.2.2).
///
/// - `reference`, `xyz`, `vertex_count`, `polyline_vertices`, `polyline_vertex_count`,
///   `polyline_lengths`, `row_count`, `column_count`, `out`: as in `lml_base_mesh_new`.
/// - `slope_degrees_rows`, `slope_degrees_columns`: each family's slope β in (−90°, 90°) (held at
///   β or −β, whichever its polylines are nearer to as given); the report's `target_degrees` and
///   angle errors are slopes then.
/// - `axis`: 3 doubles, finite, not all zero (any length).
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (as `lml_base_mesh_new`, or a slope or
/// the axis out of range, named); `LML_STATUS_INTERNAL_ERROR` (the problem could not be set up).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_new_slopes(
    reference: *const LmlMesh,
    xyz: *const f64,
    vertex_count: usize,
    polyline_vertices: *const u32,
    polyline_vertex_count: usize,
    polyline_lengths: *const u32,
    row_count: usize,
    column_count: usize,
    slope_degrees_rows: f64,
    slope_degrees_columns: f64,
    axis: *const f64,
    out: *mut *mut LmlBaseMesh,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let reference = unsafe { handle(reference, "reference") }?;
        let axis = unsafe { input(axis, 3, "axis") }?;
        if !(axis.iter().all(|a| a.is_finite()) && axis.iter().any(|&a| a != 0.0)) {
            return Err(Failure::argument("axis", format!("must be finite and not zero, got ({}, {}, {})", axis[0], axis[1], axis[2])));
        }
        let slope = |degrees: f64, name: &str| {
            if !(degrees.is_finite() && degrees.abs() < 90.0) {
                return Err(Failure::argument(name, format!("must lie in (-90, 90), got {degrees}")));
            }
            Ok(Family::ConstantSlope { axis: [axis[0], axis[1], axis[2]], slope_degrees: degrees, free_slope: false })
        };
        let params = BaseMeshParams::new(slope(slope_degrees_rows, "slope_degrees_rows")?, slope(slope_degrees_columns, "slope_degrees_columns")?);
        let net = unsafe { net_from_arrays(xyz, vertex_count, polyline_vertices, polyline_vertex_count, polyline_lengths, &net_counts(row_count, column_count)) }?;
        out.set_owned(LmlBaseMesh { solver: BaseMeshSolver::new(&net, &reference.mesh, params)? });
        Ok(LmlStatus::Ok)
    })
}

/// Starts optimising the quad net of a gridshell (`lml_strip_net_new`; its rows are the runs of
/// crossings along one level of the first field, its columns those along one level of the
/// second) as `lml_base_mesh_new` does: the net's vertices are `lml_strip_net_vertices`.
///
/// - `net`: the strip net (not retained); `reference`: the surface (copied), usually the mesh of
///   the net session the strip net came from.
/// - θ, `torsion_free` and `out` as in `lml_base_mesh_new`.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, θ out of range, named;
/// a net without a vertex inside a row or column of three or more); `LML_STATUS_INTERNAL_ERROR`.
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_from_strip_net(
    net: *const LmlStripNet,
    reference: *const LmlMesh,
    theta_degrees_rows: f64,
    theta_degrees_columns: f64,
    torsion_free: u32,
    out: *mut *mut LmlBaseMesh,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live handles.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let net = NetMesh::from_quad_net(unsafe { handle(net, "net") }?.quad_net())?;
        let reference = unsafe { handle(reference, "reference") }?;
        out.set_owned(session(&net, &reference.mesh, &net_thetas(theta_degrees_rows, theta_degrees_columns), torsion_free)?);
        Ok(LmlStatus::Ok)
    })
}

/// Starts optimising a 3-web (paper Sec. 3.5 and 4.2: a net of rows, columns and diagonals, such
/// as Table 1's AAG, AGG or PPG webs) so that each of its three families of polylines becomes the
/// asked curves on or near `reference`, with the default weights. Then every polyline carries a
/// developable strip of planar quads (`lml_base_mesh_strips`, k = 0, 1 or 2), and the web's
/// triangles are those of `lml_base_mesh_triangles`. Torsion-free nodes (Eq. 21) are held for
/// nets of two families only: a web has no such option.
///
/// - `reference`, `xyz`, `vertex_count`, `polyline_vertices`, `polyline_vertex_count`, `out`: as
///   in `lml_base_mesh_new`.
/// - `polyline_lengths`: `row_count + column_count + diagonal_count` vertex counts (each ≥ 2):
///   the rows', then the columns', then the diagonals'; they must sum to `polyline_vertex_count`.
///   A vertex lies on at most one polyline of each family; consecutive vertices of a polyline are
///   at distinct points. `polyline_vertices` holds the polylines in the same order.
/// - `diagonal_count`: at least 1.
/// - `thetas`: 3 doubles, the families of the rows, the columns and the diagonals by their
///   angles θ in [0°, 180°], as `theta_degrees_rows` of `lml_base_mesh_new` (e.g. {0, 0, 90}: an
///   AAG web, its rows and columns asymptotic curves, its diagonals geodesics).
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (as `lml_base_mesh_new`: the message
/// names the argument, vertex or polyline, `thetas[i]` for a θ out of range, `diagonal_count` for
/// none); `LML_STATUS_INTERNAL_ERROR` (the problem could not be set up).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_new_web(
    reference: *const LmlMesh,
    xyz: *const f64,
    vertex_count: usize,
    polyline_vertices: *const u32,
    polyline_vertex_count: usize,
    polyline_lengths: *const u32,
    row_count: usize,
    column_count: usize,
    diagonal_count: usize,
    thetas: *const f64,
    out: *mut *mut LmlBaseMesh,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let reference = unsafe { handle(reference, "reference") }?;
        let thetas = unsafe { web_thetas(thetas) }?;
        if diagonal_count == 0 {
            return Err(Failure::argument("diagonal_count", "is 0: a web has diagonals (lml_base_mesh_new optimises a net of rows and columns)"));
        }
        let counts = [(row_count, "row_count"), (column_count, "column_count"), (diagonal_count, "diagonal_count")];
        let net = unsafe { net_from_arrays(xyz, vertex_count, polyline_vertices, polyline_vertex_count, polyline_lengths, &counts) }?;
        out.set_owned(session(&net, &reference.mesh, &thetas, 0)?);
        Ok(LmlStatus::Ok)
    })
}

/// Starts optimising the web of a 3-web gridshell (`lml_strip_web_new`) as `lml_base_mesh_new_web`
/// does: its vertices are `lml_strip_web_vertices`, its rows, columns and diagonals the polylines
/// of its families 0, 1 and 2 (`lml_strip_web_polyline_vertices`), in that order. A Kagome
/// pattern's web is taken as it is (every vertex on two of the families; its triangles are the
/// pattern's triangles).
///
/// - `web`: the strip web (not retained); `reference`: the surface (copied), usually the mesh of
///   the 3-web session the strip web came from.
/// - `thetas` and `out` as in `lml_base_mesh_new_web`.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, θ out of range, named;
/// a web without a vertex inside a polyline of three or more); `LML_STATUS_INTERNAL_ERROR`.
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_from_strip_web(web: *const LmlStripWeb, reference: *const LmlMesh, thetas: *const f64, out: *mut *mut LmlBaseMesh) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live handles; `thetas` readable for 3 doubles.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let net = NetMesh::from_web(unsafe { handle(web, "web") }?.web())?;
        let reference = unsafe { handle(reference, "reference") }?;
        let thetas = unsafe { web_thetas(thetas) }?;
        out.set_owned(session(&net, &reference.mesh, &thetas, 0)?);
        Ok(LmlStatus::Ok)
    })
}

/// Releases a session. NULL is accepted and ignored. The handle must not be used again.
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_free(base_mesh: *mut LmlBaseMesh) {
    guarded(|| {
        // SAFETY: `base_mesh` is NULL or a live handle from lml_base_mesh_new / _from_strip_net.
        unsafe { release(base_mesh) };
        Ok(LmlStatus::Ok)
    });
}

/// Serialises the whole session (the net as given, the reference surface, the families with
/// their oriented targets, the stage and the net it started from, the positions with their
/// auxiliary variables, the vertices held past the reference's boundary, solver damping, the
/// initial and the last report) as bytes: the magic `"LMLB"`, a little-endian `uint32_t` format
/// version, then the state. Portable across platforms; a restored session continues bit for bit
/// as the original would have.
///
/// Two-call pattern: `*needed` is always set to the byte count; if `out` is NULL or `capacity`
/// (in bytes) is smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. The
/// buffer stays owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_save(base_mesh: *const LmlBaseMesh, out: *mut u8, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` bytes; writable `needed`.
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        unsafe { copy_out(&base_mesh.solver.to_bytes(), out, capacity, needed, "out") }
    })
}

/// Restores a session from `length` bytes written by `lml_base_mesh_save` (copied; the caller
/// keeps them). `out` receives the new session, owned by the caller (release with
/// `lml_base_mesh_free`); set to NULL on failure.
///
/// Every restored quantity is checked: the net as in `lml_base_mesh_new` and the reference as in
/// `lml_mesh_new`, the parameters in range (and at most 100 damped trials per iteration), each
/// target the family's angle or that angle read backwards (θ or 180° − θ), the stage one the
/// parameters lead to, every value finite, counters and damping in range, both reports about the
/// net's vertices.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_CORRUPT_DATA` (empty, truncated, damaged or inconsistent
/// bytes, another kind of session, or another format version: the message says which);
/// `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, NULL `bytes` with a non-zero length).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_load(bytes: *const u8, length: usize, out: *mut *mut LmlBaseMesh) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): writable `out`; `bytes` readable for `length` bytes.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let bytes = unsafe { input(bytes, length, "bytes") }?;
        out.set_owned(LmlBaseMesh { solver: BaseMeshSolver::from_bytes(bytes)? });
        Ok(LmlStatus::Ok)
    })
}

/// Runs at most `max_iterations` iterations (the reference's closest points found again before
/// each) and writes the state to `*report` (may be NULL). With torsion-free nodes asked for, the
/// second stage starts within a step once the families have settled.
///
/// Returns `LML_STATUS_MORE` (step again), `LML_STATUS_CONVERGED`, `LML_STATUS_INVALID_ARGUMENT`
/// (NULL or misaligned pointer) or `LML_STATUS_DID_NOT_CONVERGE` (an iteration failed
/// numerically; the net keeps its last good positions).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_step(base_mesh: *mut LmlBaseMesh, max_iterations: u32, report: *mut LmlBaseMeshReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle used by this thread only; `report` NULL or writable.
        let base_mesh = unsafe { handle_mut(base_mesh, "base_mesh") }?;
        let report = unsafe { Out::optional(report, "report") }?;
        let step = base_mesh.solver.step(usize::try_from(max_iterations).unwrap_or(usize::MAX))?;
        if let Some(mut report) = report {
            report.set(LmlBaseMeshReport::from(&step));
        }
        Ok(if step.converged { LmlStatus::Converged } else { LmlStatus::More })
    })
}

/// The weights of a base-mesh optimisation's terms (paper Sec. 3.5; Table 3 gives them per
/// figure), on the net scaled to mean segment length 1 (written by the library or the caller; the
/// caller owns the struct). Each finite and ≥ 0; `curve` > 0, and `torsion` > 0 for a session
/// with torsion-free nodes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlBaseMeshWeights {
    /// The curve conditions: vertex normals, binormals and each family's own rows. Default 1.
    pub curve: f64,
    /// Fairness `‖v_back − 2v + v_front‖²` along each polyline. Default 1e-3.
    pub fair: f64,
    /// Closeness: the distance to the reference along its normal (and, past its boundary, the
    /// tangential offset). Default 1.
    pub close: f64,
    /// The pull `‖v − v_start‖²` to the start positions: what holds a net's extent (a net that
    /// cannot meet its families where it was extracted shrinks toward its centre). Default 1e-4.
    pub pull: f64,
    /// The torsion-free node rows of Eq. 21 (torsion-free sessions only). Default 1.
    pub torsion: f64,
}

impl From<BaseMeshWeights> for LmlBaseMeshWeights {
    fn from(w: BaseMeshWeights) -> Self {
        LmlBaseMeshWeights { curve: w.curve, fair: w.fair, close: w.close, pull: w.pull, torsion: w.torsion }
    }
}

impl From<LmlBaseMeshWeights> for BaseMeshWeights {
    fn from(w: LmlBaseMeshWeights) -> Self {
        BaseMeshWeights { curve: w.curve, fair: w.fair, close: w.close, pull: w.pull, torsion: w.torsion }
    }
}

/// Fills `*out` with the default weights (the sessions' own unless changed with
/// `lml_base_mesh_set_weights`). Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL
/// `out`).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_weights_default(out: *mut LmlBaseMeshWeights) -> LmlStatus {
    guarded(|| {
        // SAFETY: writable `out`.
        unsafe { Out::new(out, "out") }?.set(BaseMeshWeights::default().into());
        Ok(LmlStatus::Ok)
    })
}

/// Writes the weights `base_mesh` optimises with to `*out`. Returns `LML_STATUS_OK` or
/// `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_weights(base_mesh: *const LmlBaseMesh, out: *mut LmlBaseMeshWeights) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `out`.
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        unsafe { Out::new(out, "out") }?.set(base_mesh.solver.params().weights.into());
        Ok(LmlStatus::Ok)
    })
}

/// Replaces the weights of a session that has not stepped an iteration yet (the same as creating
/// it with them; `*weights` is copied). Returns `LML_STATUS_OK`, or `LML_STATUS_INVALID_ARGUMENT`
/// for a NULL argument, a weight out of range (named, e.g. `weights.pull`) or a session that has
/// already iterated (`weights`); the session is then unchanged.
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_set_weights(base_mesh: *mut LmlBaseMesh, weights: *const LmlBaseMeshWeights) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle used by this thread only; readable `weights`.
        let base_mesh = unsafe { handle_mut(base_mesh, "base_mesh") }?;
        let weights = unsafe { input(weights, 1, "weights") }?[0];
        base_mesh.solver.set_weights(weights.into())?;
        Ok(LmlStatus::Ok)
    })
}

/// Writes the state after the last step (or after creation) to `*report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_report(base_mesh: *const LmlBaseMesh, report: *mut LmlBaseMeshReport) -> LmlStatus {
    // SAFETY: the caller's contract, as documented above.
    unsafe { write_report(base_mesh, report, BaseMeshSolver::report) }
}

/// Writes the state of the net as given, before any iteration, to `*report`: what the
/// optimisation started from.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_initial_report(base_mesh: *const LmlBaseMesh, report: *mut LmlBaseMeshReport) -> LmlStatus {
    // SAFETY: the caller's contract, as documented above.
    unsafe { write_report(base_mesh, report, BaseMeshSolver::initial_report) }
}

/// Writes `which` report of a live session to `*report` (writable), or fails naming the NULL argument.
unsafe fn write_report(base_mesh: *const LmlBaseMesh, report: *mut LmlBaseMeshReport, which: fn(&BaseMeshSolver) -> &BaseMeshReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report` (the callers' contracts).
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        unsafe { Out::new(report, "report") }?.set(LmlBaseMeshReport::from(which(&base_mesh.solver)));
        Ok(LmlStatus::Ok)
    })
}

/// Copies the current vertex positions (xyz per vertex, `3 n` doubles, in the net's units, in
/// the order they were given) into `xyz` with the two-call pattern: `*needed` receives `3 n`;
/// with `capacity` below it nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned
/// (`xyz` may be NULL then). Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or
/// `LML_STATUS_INVALID_ARGUMENT` (NULL session or `needed`).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_positions(base_mesh: *const LmlBaseMesh, xyz: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `xyz` writable for `capacity` doubles; `needed` writable.
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        unsafe { copy_out(&flat_xyz(&base_mesh.solver.positions()), xyz, capacity, needed, "xyz") }
    })
}

/// Copies the nodes (every vertex inside a row and a column, in vertex order) with their ruling
/// angles from the strips of the net as it stands after the last step, into `nodes` with the
/// two-call pattern (`*needed` receives the node count). Returns as `lml_base_mesh_positions`.
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_nodes(base_mesh: *const LmlBaseMesh, nodes: *mut LmlBaseMeshNode, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `nodes` writable for `capacity` structs; `needed` writable.
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        let flat: Vec<LmlBaseMeshNode> = base_mesh.solver.nodes().iter().map(LmlBaseMeshNode::from).collect();
        unsafe { copy_out(&flat, nodes, capacity, needed, "nodes") }
    })
}

/// `k` as the index of one of the session's families, or the failure naming `k`.
fn family_index(base_mesh: &LmlBaseMesh, k: u32) -> Result<usize, Failure> {
    match base_mesh.solver.params().families.len() {
        count if (k as usize) < count => Ok(k as usize),
        2 => Err(Failure::argument("k", format!("a net has families 0 (rows) and 1 (columns), got {k}"))),
        _ => Err(Failure::argument("k", format!("a web has families 0 (rows), 1 (columns) and 2 (diagonals), got {k}"))),
    }
}

/// Writes the session's number of families to `*count`: 2 for a net of rows and columns, 3 for a
/// web of rows, columns and diagonals.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_family_count(base_mesh: *const LmlBaseMesh, count: *mut u32) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `count`.
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        // Two or three families.
        unsafe { Out::new(count, "count") }?.set(base_mesh.solver.params().families.len() as u32);
        Ok(LmlStatus::Ok)
    })
}

/// Writes family `k`'s part (0: rows, 1: columns, 2: a web's diagonals) of the state after the
/// last step (or after creation) to `*report`: for k = 0 and 1 the same numbers as index k of
/// `lml_base_mesh_report`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument, `k` not below
/// `lml_base_mesh_family_count`, named).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_family_report(base_mesh: *const LmlBaseMesh, k: u32, report: *mut LmlBaseMeshFamilyReport) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `report`.
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        let mut report = unsafe { Out::new(report, "report") }?;
        let k = family_index(base_mesh, k)?;
        report.set(LmlBaseMeshFamilyReport::of(base_mesh.solver.report(), k));
        Ok(LmlStatus::Ok)
    })
}

/// Copies a web's triangles into `indices`, three vertex indices (into the positions) per
/// triangle, with the two-call pattern (`*needed` receives 3 × the triangle count): the cycles of
/// one segment of each family, `[a, b, c]` with `a → b` a row segment (in a 3-web the halves of
/// the rows' and columns' quads, in a Kagome pattern its triangles). None for a net of two
/// families (`*needed` is 0). Returns as `lml_base_mesh_positions`.
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_triangles(base_mesh: *const LmlBaseMesh, indices: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `indices` writable for `capacity` values; `needed` writable.
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        // The polylines never change: the net as given has the current net's triangles.
        let flat = base_mesh.solver.given_net().triangles().concat();
        unsafe { copy_out(&flat, indices, capacity, needed, "indices") }
    })
}

/// Builds the rectifying strips of family `k` (0: rows, 1: columns, 2: a web's diagonals) on the
/// current net: on every polyline, the developable strip of planar quads whose rulings are fitted
/// to the nodes' common rulings (Sec. 5.2.1; a web's diagonals, which share no node rulings, to
/// their own), cut to `width` (> 0, the net's units) and unrolled, judged with
/// `tolerance_degrees` in (0, 180) against the family's target angle (`target_degrees` of
/// `lml_base_mesh_family_report`) on the reference. The strips are a new `LmlStrips` handle
/// (read it with the `lml_strips_*` functions, release it with `lml_strips_free`); a strip's
/// curve index is its polyline's index within the family. Polylines that carry no strip are
/// listed by `lml_strips_skipped`.
///
/// Returns `LML_STATUS_OK` (every strip within the tolerance, no flipped quad);
/// `LML_STATUS_NO_ACCEPTABLE_FAMILY` (the strips are built and `*out` is valid, but some miss the
/// angle by more than the tolerance, have flipped quads or leave the surface, or no strip could
/// be built: `lml_last_error_message()` names the worst strip, `lml_strips_verdict` gives the
/// numbers); `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `k` not below
/// `lml_base_mesh_family_count`, `width` or `tolerance_degrees` out of range, named).
#[no_mangle]
pub unsafe extern "C" fn lml_base_mesh_strips(base_mesh: *const LmlBaseMesh, k: u32, width: f64, tolerance_degrees: f64, out: *mut *mut LmlStrips) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live handle.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let base_mesh = unsafe { handle(base_mesh, "base_mesh") }?;
        let k = family_index(base_mesh, k)?;
        let pattern = base_mesh.solver.family_strips(k, width, tolerance_degrees)?;
        let status = if pattern.verdict.is_acceptable() {
            LmlStatus::Ok
        } else {
            set_last_error(&pattern.verdict.message());
            LmlStatus::NoAcceptableFamily
        };
        // Each family's strips are judged at its target (the solver's own reading of θ).
        // A constant-slope family prescribes no angle: its strips have one each (as shading strips).
        let theta_degrees = match base_mesh.solver.params().families[k] {
            Family::ConstantSlope { .. } => None,
            _ => Some(base_mesh.solver.targets_degrees()[k]),
        };
        out.set_owned(LmlStrips { pattern, theta_degrees });
        Ok(status)
    })
}
