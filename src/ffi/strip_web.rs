//! `LmlStripWeb`: a 3-web gridshell as built from three strip families (paper Sec. 4.2 and 5.1):
//! the web of triangles (or the Kagome pattern of triangles and hexagons) where the level curves
//! carrying strips cross, its polylines per family, and the nodes where the strips cross.

use super::failure::Failure;
use super::guard::guarded;
use super::layout::flat_xyz;
use super::net::LmlNet;
use super::raw::{copy_out, handle, release, Out};
use super::status::LmlStatus;
use super::strip_net::{level_index, LmlNode};
use super::strips::LmlStrips;
use super::web::{levels_of, web_family};
use crate::net::{strip_web, Node, StripWeb, Web};
use crate::strips::StripPattern;

/// The web and nodes of three strip families (opaque). Create it with `lml_strip_web_new`,
/// release it with `lml_strip_web_free`. Immutable once created.
pub struct LmlStripWeb {
    web: StripWeb,
}

impl LmlStripWeb {
    /// The web of crossings (for `lml_base_mesh_from_strip_web`).
    pub(crate) fn web(&self) -> &Web {
        &self.web.web
    }
}

/// One node of a 3-web gridshell: where a strip of one family crosses a strip of another. At a
/// vertex where three families meet there is a node for each pair of them.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlWebNode {
    /// The two families that cross here (0: F, 1: H, 2: G), the smaller first.
    pub families: [u32; 2],
    /// Always 0.
    pub reserved: u32,
    /// The node: `node.vertex` indexes the web's vertices (`lml_strip_web_vertices`);
    /// `node.strips[i]`, `node.arc_lengths[i]` and the diagnostics at index `i` refer to the
    /// strips of family `families[i]` (as in `lml_strips_metrics` of that family's strips).
    pub node: LmlNode,
}

impl From<&Node> for LmlWebNode {
    fn from(n: &Node) -> LmlWebNode {
        // Family indices are 0, 1 or 2.
        LmlWebNode { families: n.families.map(|k| k as u32), reserved: 0, node: LmlNode::from(n) }
    }
}

/// Checks that every strip of `pattern` (the argument `name`) lies on one of `levels`, the
/// family's levels of the web: strips built on other curves (a net of two families' levels, the
/// web's levels for other counts, another family, a session stepped since) would give no nodes.
fn check_levels(pattern: &StripPattern, levels: &[f64], name: &str) -> Result<(), Failure> {
    // The tolerance with which the nodes find a strip on a level.
    let on_level = |level: f64| levels.iter().any(|&l| (l - level).abs() <= 1e-9 * l.abs().max(1.0));
    match pattern.strips.iter().enumerate().find(|(_, s)| !on_level(s.level)) {
        None => Ok(()),
        Some((index, strip)) => Err(Failure::argument(
            name,
            format!(
                "strip {index} lies on level {}, not one of this family's {} levels of the web: build the strips on the curves of lml_curves_new_from_web with the same counts and kagome, on the session as it is now",
                strip.level,
                levels.len()
            ),
        )),
    }
}

/// Builds the web of a 3-web session's fields at its even-pace levels and the nodes of its strips.
///
/// - `net`: a 3-web session (`lml_web_new`), converged or not; its current fields are used. Not
///   retained.
/// - `count_f`, `count_h`, `kagome`: the levels, as in `lml_web_levels`; with `kagome` = 1 the
///   web is a Kagome pattern (every vertex the crossing of two families; faces triangles and
///   hexagons), else a triangle mesh whose vertices are crossings of all three families or of two
///   (where the third's level is missing near the boundary).
/// - `strips_f`, `strips_h`, `strips_g`: the strips of families 0, 1 and 2, built on the curves
///   of `lml_curves_new_from_web` for the same levels (every strip must lie on one of its
///   family's levels). Not retained.
/// - `out`: receives the new web (release with `lml_strip_web_free`); NULL on failure.
///
/// A crossing of two families' levels becomes a node when each has a strip on its level passing
/// within two mean edge lengths of it.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, `net` a net of two
/// families, a count or `kagome` out of range, strips on other levels: named);
/// `LML_STATUS_SINGULAR_FIELD` (a field has become constant).
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_new(
    net: *const LmlNet,
    count_f: usize,
    count_h: usize,
    kagome: u32,
    strips_f: *const LmlStrips,
    strips_h: *const LmlStrips,
    strips_g: *const LmlStrips,
    out: *mut *mut LmlStripWeb,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live handles.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let net = unsafe { handle(net, "net") }?;
        let patterns = unsafe { [&handle(strips_f, "strips_f")?.pattern, &handle(strips_h, "strips_h")?.pattern, &handle(strips_g, "strips_g")?.pattern] };
        let (levels, fields) = levels_of(net, count_f, count_h, kagome)?;
        for (k, name) in ["strips_f", "strips_h", "strips_g"].into_iter().enumerate() {
            check_levels(patterns[k], &levels.levels[k], name)?;
        }
        let web = strip_web(&net.mesh, [&fields[0], &fields[1], &fields[2]], levels, patterns)?;
        out.set_owned(LmlStripWeb { web });
        Ok(LmlStatus::Ok)
    })
}

/// Releases a web. NULL is accepted and ignored. The handle must not be used again.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_free(web: *mut LmlStripWeb) {
    guarded(|| {
        // SAFETY: `web` is NULL or a live handle from lml_strip_web_new.
        unsafe { release(web) };
        Ok(LmlStatus::Ok)
    });
}

/// Copies the web's vertices (crossings of the families' levels, ordered by their levels of F,
/// then of H) as `3 * count` doubles (x, y, z) into `xyz`, with the two-call pattern: `*needed`
/// receives the double count; with `capacity` below it nothing is copied and
/// `LML_STATUS_BUFFER_TOO_SMALL` is returned (`xyz` may be NULL then). Returns `LML_STATUS_OK`,
/// `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT` (NULL web or `needed`).
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_vertices(web: *const LmlStripWeb, xyz: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `xyz` writable for `capacity` doubles; `needed` writable.
        let web = unsafe { handle(web, "web") }?;
        let positions: Vec<_> = web.web.web.vertices.iter().map(|v| v.position).collect();
        unsafe { copy_out(&flat_xyz(&positions), xyz, capacity, needed, "xyz") }
    })
}

/// Copies, for every vertex, the index of the level of each family through it (into that
/// family's `lml_web_levels`), −1 where none of its curves passes: `3 * count` values (family 0,
/// 1, 2 of vertex 0, then of vertex 1, …) into `levels`, with the two-call pattern. Two or three
/// are set at every vertex; exactly two in a Kagome pattern. Returns as `lml_strip_web_vertices`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_vertex_levels(web: *const LmlStripWeb, levels: *mut i64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `levels` writable for `capacity` values; `needed` writable.
        let web = unsafe { handle(web, "web") }?;
        // A level index is below 2 LML_MAX_LEVELS: exact as an int64_t.
        let through: Vec<i64> = web.web.web.vertices.iter().flat_map(|v| v.levels).map(|l| l.map_or(-1, |i| i as i64)).collect();
        unsafe { copy_out(&through, levels, capacity, needed, "levels") }
    })
}

/// Copies the number of vertices of each face (3 for a triangle, 6 for a Kagome pattern's
/// hexagon) into `sizes`, with the two-call pattern (`*needed` receives the face count). Faces
/// are oriented as the net of F and H, (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j).
/// Returns as `lml_strip_web_vertices`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_face_sizes(web: *const LmlStripWeb, sizes: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `sizes` writable for `capacity` values; `needed` writable.
        let web = unsafe { handle(web, "web") }?;
        unsafe { copy_out(&sizes_of(&web.web.web.faces), sizes, capacity, needed, "sizes") }
    })
}

/// Copies the faces' vertex indices (into `lml_strip_web_vertices`), one face after another as
/// `lml_strip_web_face_sizes` cuts them, into `indices`, with the two-call pattern.
/// Returns as `lml_strip_web_vertices`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_face_vertices(web: *const LmlStripWeb, indices: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `indices` writable for `capacity` values; `needed` writable.
        let web = unsafe { handle(web, "web") }?;
        unsafe { copy_out(&web.web.web.faces.concat(), indices, capacity, needed, "indices") }
    })
}

/// The polylines of family `family` (0, 1 or 2) of a live web handle, as `(level index, vertex
/// indices)`.
///
/// # Safety
/// As [`handle`].
unsafe fn polylines<'a>(web: *const LmlStripWeb, family: u32) -> Result<&'a [(usize, Vec<u32>)], Failure> {
    // SAFETY: forwarded contract.
    let web = unsafe { handle(web, "web") }?;
    Ok(&web.web.web.polylines[web_family(family, "family")?])
}

/// Copies the number of vertices of each polyline of family `family` (0, 1 or 2) into `sizes`,
/// with the two-call pattern (`*needed` receives the polyline count). A polyline is a maximal run
/// (2 vertices or more) of consecutive web vertices along one level of the family.
/// Returns as `lml_strip_web_vertices`, and `LML_STATUS_INVALID_ARGUMENT` for `family` > 2.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_polyline_sizes(web: *const LmlStripWeb, family: u32, sizes: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `sizes` writable for `capacity` values; `needed` writable.
        let runs: Vec<&Vec<u32>> = unsafe { polylines(web, family) }?.iter().map(|(_, run)| run).collect();
        unsafe { copy_out(&sizes_of(&runs), sizes, capacity, needed, "sizes") }
    })
}

/// Copies the vertex indices of family `family`'s polylines, one after another as
/// `lml_strip_web_polyline_sizes` cuts them, into `indices`, with the two-call pattern.
/// Returns as `lml_strip_web_polyline_sizes`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_polyline_vertices(web: *const LmlStripWeb, family: u32, indices: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `indices` writable for `capacity` values; `needed` writable.
        let flat: Vec<u32> = unsafe { polylines(web, family) }?.iter().flat_map(|(_, run)| run.iter().copied()).collect();
        unsafe { copy_out(&flat, indices, capacity, needed, "indices") }
    })
}

/// Copies the level index (into the family's `lml_web_levels`) of each of family `family`'s
/// polylines into `levels`, with the two-call pattern. Returns as `lml_strip_web_polyline_sizes`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_polyline_levels(web: *const LmlStripWeb, family: u32, levels: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `levels` writable for `capacity` values; `needed` writable.
        let indices = unsafe { polylines(web, family) }?.iter().map(|(level, _)| level_index(*level)).collect::<Result<Vec<u32>, _>>()?;
        unsafe { copy_out(&indices, levels, capacity, needed, "levels") }
    })
}

/// Copies the nodes into `nodes`, with the two-call pattern (`*needed` receives the node count),
/// ordered by vertex, at a vertex by pair of families.
/// Returns as `lml_strip_web_vertices`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_web_nodes(web: *const LmlStripWeb, nodes: *mut LmlWebNode, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `nodes` writable for `capacity` structs; `needed` writable.
        let web = unsafe { handle(web, "web") }?;
        let flat: Vec<LmlWebNode> = web.web.nodes.iter().map(LmlWebNode::from).collect();
        unsafe { copy_out(&flat, nodes, capacity, needed, "nodes") }
    })
}

/// The length of each item as the ABI's `uint32_t` (faces have 3 or 6 vertices, a polyline at
/// most as many as the web, whose indices are `uint32_t`).
fn sizes_of<T: AsRef<[u32]>>(items: &[T]) -> Vec<u32> {
    items.iter().map(|item| item.as_ref().len() as u32).collect()
}
