//! `LmlStripNet`: a gridshell as built from two strip families (paper Sec. 4.1 and 5.1): the
//! quad net where the level curves carrying strips cross, and the nodes where the strips cross.

use super::failure::Failure;
use super::guard::guarded;
use super::layout::flat_xyz;
use super::net::LmlNet;
use super::raw::{copy_out, handle, release, Out};
use super::status::LmlStatus;
use super::strips::LmlStrips;
use crate::net::{strip_net, Node, QuadNet, StripNet};

/// The quad net and nodes of two strip families (opaque). Create it with `lml_strip_net_new`,
/// release it with `lml_strip_net_free`.
pub struct LmlStripNet {
    net: StripNet,
}

impl LmlStripNet {
    /// The quad net of crossings (for `lml_base_mesh_from_strip_net`).
    pub(crate) fn quad_net(&self) -> &QuadNet {
        &self.net.net
    }
}

/// One node of a gridshell: where a strip of the first family crosses one of the second.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlNode {
    /// Index of the crossing among the net's vertices (`lml_strip_net_vertices`).
    pub vertex: u64,
    /// Index of the strip of each family (as in `lml_strips_metrics` of that family's strips).
    pub strips: [u64; 2],
    /// Arc length of the node along each strip's centre line, from its first point: where the
    /// hole or slot goes on the flat strip.
    pub arc_lengths: [f64; 2],
    /// The crossing on the surface.
    pub position: [f64; 3],
    /// Unit node axis: the mean of the two strips' unit rulings at the node.
    pub axis: [f64; 3],
    /// Angle between the two rulings as lines, in degrees, [0°, 90°]: 0 for a torsion-free node
    /// (Sec. 5.2).
    pub ruling_angle_degrees: f64,
    /// Sec. 5.1 diagnostics of each strip at its centre-line vertex nearest to the node: 1 when
    /// the strip bends there, so that the next three are defined (else they are 0: on a straight
    /// stretch the conical curvature has no value).
    pub diagnostics_defined: [u32; 2],
    /// 1 when the singular point of the strip's ruling there lies inside the strip or within one
    /// strip width of it (Prop. 1), else 0.
    pub singular_point_near: [u32; 2],
    /// Conical curvature k = τ/κ.
    pub conical_curvature: [f64; 2],
    /// Angle atan |k| in degrees between the binormal and the ruling of the rectifying developable.
    pub darboux_angle_degrees: [f64; 2],
    /// κ k² v² / 2 at v = half the strip width (Prop. 2): how far the binormal's point at the strip
    /// edge lies from the rectifying developable, in the mesh's units.
    pub binormal_offset: [f64; 2],
}

impl From<&Node> for LmlNode {
    fn from(n: &Node) -> LmlNode {
        LmlNode {
            vertex: n.vertex as u64,
            strips: n.strips.map(|s| s as u64),
            arc_lengths: n.arc_lengths,
            position: [n.position.x, n.position.y, n.position.z],
            axis: [n.axis.x, n.axis.y, n.axis.z],
            ruling_angle_degrees: n.ruling_angle_degrees,
            // atan |k| and the offset are defined exactly where k is.
            diagnostics_defined: n.diagnostics.map(|d| u32::from(d.conical_curvature.is_some())),
            singular_point_near: n.diagnostics.map(|d| u32::from(d.singular_point_near)),
            conical_curvature: n.diagnostics.map(|d| d.conical_curvature.unwrap_or(0.0)),
            darboux_angle_degrees: n.diagnostics.map(|d| d.darboux_angle_degrees.unwrap_or(0.0)),
            binormal_offset: n.diagnostics.map(|d| d.binormal_offset.unwrap_or(0.0)),
        }
    }
}

/// Builds the quad net of a net session's two fields at the levels of their strips, and the
/// strips' nodes.
///
/// - `net`: the session (converged or not); its current fields are used. Not retained.
/// - `strips_f`, `strips_g`: the strips built on level curves of field 0 and of field 1
///   (`lml_curves_new_from_net`, then `lml_strips_new`); the net's levels are the levels of
///   these strips. Not retained.
/// - `out`: receives the new net (release with `lml_strip_net_free`); NULL on failure.
///
/// A crossing becomes a node when each family has a strip on its level passing within two mean
/// edge lengths of it; crossings where a strip was skipped are net vertices without a node.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL pointer);
/// `LML_STATUS_SINGULAR_FIELD` (a field has become constant).
#[no_mangle]
pub unsafe extern "C" fn lml_strip_net_new(net: *const LmlNet, strips_f: *const LmlStrips, strips_g: *const LmlStrips, out: *mut *mut LmlStripNet) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live handles.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let net = unsafe { handle(net, "net") }?;
        let patterns = unsafe { [&handle(strips_f, "strips_f")?.pattern, &handle(strips_g, "strips_g")?.pattern] };
        out.set_owned(LmlStripNet { net: strip_net(&net.mesh, &net.field(0)?, &net.field(1)?, patterns)? });
        Ok(LmlStatus::Ok)
    })
}

/// Releases a net. NULL is accepted and ignored. The handle must not be used again.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_net_free(net: *mut LmlStripNet) {
    guarded(|| {
        // SAFETY: `net` is NULL or a live handle from lml_strip_net_new.
        unsafe { release(net) };
        Ok(LmlStatus::Ok)
    });
}

/// Copies the net's vertices (the crossings of level `i` of `f` with level `j` of `g`, ordered
/// by `i` then `j`) as `3 * count` doubles (x, y, z) into `xyz`, with the two-call pattern of
/// `lml_net_field`. Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or
/// `LML_STATUS_INVALID_ARGUMENT` (NULL net or `needed`).
#[no_mangle]
pub unsafe extern "C" fn lml_strip_net_vertices(net: *const LmlStripNet, xyz: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `xyz` writable for `capacity` doubles; `needed` writable.
        let net = unsafe { handle(net, "net") }?;
        let positions: Vec<_> = net.net.net.vertices.iter().map(|v| v.position).collect();
        unsafe { copy_out(&flat_xyz(&positions), xyz, capacity, needed, "xyz") }
    })
}

/// Copies the level indices of the net's vertices as `2 * count` values (`i`, `j`: vertex `k` is
/// the crossing of the `i`-th level of `f` with the `j`-th of `g`, levels counted in increasing
/// order) into `ij`, with the two-call pattern. Rows of the net are the vertices of equal `i`,
/// columns those of equal `j`. Returns as `lml_strip_net_vertices`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_net_levels(net: *const LmlStripNet, ij: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `ij` writable for `capacity` values; `needed` writable.
        let net = unsafe { handle(net, "net") }?;
        let indices = net.net.net.vertices.iter().flat_map(|v| [v.i, v.j]).map(level_index).collect::<Result<Vec<u32>, _>>()?;
        unsafe { copy_out(&indices, ij, capacity, needed, "ij") }
    })
}

/// Copies the net's quads as `4 * count` vertex indices (`(i, j)`, `(i, j + 1)`, `(i + 1, j + 1)`,
/// `(i + 1, j)`: a quad wherever all four crossings exist) into `quads`, with the two-call
/// pattern. Returns as `lml_strip_net_vertices`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_net_quads(net: *const LmlStripNet, quads: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `quads` writable for `capacity` values; `needed` writable.
        let net = unsafe { handle(net, "net") }?;
        unsafe { copy_out(net.net.net.quads.as_flattened(), quads, capacity, needed, "quads") }
    })
}

/// Copies the nodes into `nodes`, with the two-call pattern (`*needed` receives the node count).
/// Returns as `lml_strip_net_vertices`.
#[no_mangle]
pub unsafe extern "C" fn lml_strip_net_nodes(net: *const LmlStripNet, nodes: *mut LmlNode, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `nodes` writable for `capacity` structs; `needed` writable.
        let net = unsafe { handle(net, "net") }?;
        let flat: Vec<LmlNode> = net.net.nodes.iter().map(LmlNode::from).collect();
        unsafe { copy_out(&flat, nodes, capacity, needed, "nodes") }
    })
}

/// A level index as the ABI's `uint32_t`.
pub(super) fn level_index(index: usize) -> Result<u32, Failure> {
    u32::try_from(index).map_err(|_| Failure::new(LmlStatus::InvalidArgument, format!("level index {index} exceeds uint32_t")))
}
