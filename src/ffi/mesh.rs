//! `LmlMesh`: a validated triangle mesh, a topological disk possibly with holes (paper Sec. 7).

use super::guard::guarded;
use super::layout::flat_xyz;
use super::raw::{copy_out, element_count, handle, input, release, utf8, Out};
use super::status::LmlStatus;
use crate::mesh::TriMesh;
use std::ffi::c_char;
use std::path::Path;

/// A validated triangle mesh (opaque). Create it with `lml_mesh_new` or `lml_mesh_read_obj`,
/// release it with `lml_mesh_free`. Immutable once created.
pub struct LmlMesh {
    pub(crate) mesh: TriMesh,
}

/// Creates a mesh from flat arrays and validates it.
///
/// - `xyz`: `3 * vertex_count` doubles, vertex `i` at `xyz[3i..3i+3]` (x, y, z), any length unit.
/// - `triangles`: `3 * triangle_count` zero-based vertex indices, triangle `j` at
///   `triangles[3j..3j+3]`, consistently oriented (the normal follows the right-hand rule).
/// - `out`: receives the new mesh, owned by the caller (release with `lml_mesh_free`); set to
///   NULL on failure.
///
/// The arrays are copied; the caller keeps ownership of them. A pointer may be NULL only when
/// its count is 0 (and such a mesh is then reported invalid).
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL `out`, NULL array with a non-zero
/// count, count overflow); `LML_STATUS_INVALID_MESH` (no vertices or faces, NaN/infinite
/// coordinate, index out of range, repeated index, zero-area face, isolated vertex,
/// non-manifold edge or vertex, inconsistent orientation, a fold: two neighbouring faces whose
/// normals are more than 120° apart, e.g. an inverted triangle; a sliver: a face with less than
/// 1e-8 times the area of a neighbouring face); `LML_STATUS_NOT_A_DISK` (several
/// components, closed surfaces, handles). The message names the vertex, face or edge.
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_new(
    xyz: *const f64,
    vertex_count: usize,
    triangles: *const u32,
    triangle_count: usize,
    out: *mut *mut LmlMesh,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let xyz = unsafe { input(xyz, element_count(vertex_count, 3, "vertex_count")?, "xyz") }?;
        let triangles = unsafe { input(triangles, element_count(triangle_count, 3, "triangle_count")?, "triangles") }?;
        out.set_owned(LmlMesh { mesh: TriMesh::from_arrays(xyz, triangles)? });
        Ok(LmlStatus::Ok)
    })
}

/// Reads and validates a Wavefront OBJ file (`v` and `f` statements; polygons are fanned into
/// triangles; texture and normal indices are ignored). Files larger than 512 MiB are refused
/// (the size is checked first; a device or pipe is read up to that limit).
///
/// - `path`: NUL-terminated UTF-8 file path.
/// - `out`: receives the new mesh, owned by the caller; set to NULL on failure.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_INVALID_ARGUMENT` (NULL or non-UTF-8 path, unreadable
/// file, a directory, a file over 512 MiB); `LML_STATUS_INVALID_MESH` (malformed line (the
/// offending token is quoted, clipped to 80 characters), or any mesh problem of
/// `lml_mesh_new`, with its 1-based OBJ line); `LML_STATUS_NOT_A_DISK`.
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_read_obj(path: *const c_char, out: *mut *mut LmlMesh) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): the pointer contracts are those documented above.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let path = unsafe { utf8(path, "path") }?;
        out.set_owned(LmlMesh { mesh: TriMesh::read_obj(Path::new(path))? });
        Ok(LmlStatus::Ok)
    })
}

/// Releases a mesh. NULL is accepted and ignored. Fields created from the mesh keep working
/// (they hold their own copy). The handle must not be used (or freed) again.
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_free(mesh: *mut LmlMesh) {
    guarded(|| {
        // SAFETY: `mesh` is NULL or a live handle from lml_mesh_new / lml_mesh_read_obj.
        unsafe { release(mesh) };
        Ok(LmlStatus::Ok)
    });
}

/// Writes the number of vertices to `*count`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_vertex_count(mesh: *const LmlMesh, count: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        unsafe { Out::new(count, "count") }?.set(mesh.mesh.vertex_count());
        Ok(LmlStatus::Ok)
    })
}

/// Writes the number of triangles to `*count`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_triangle_count(mesh: *const LmlMesh, count: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle, writable `count`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        unsafe { Out::new(count, "count") }?.set(mesh.mesh.face_count());
        Ok(LmlStatus::Ok)
    })
}

/// Copies the vertex positions, `3 * vertex_count` doubles laid out as in `lml_mesh_new`.
///
/// Two-call pattern: `*needed` is always set to `3 * vertex_count`; if `out` is NULL or
/// `capacity` (in doubles) is smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is
/// returned. The buffer stays owned by the caller.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_positions(mesh: *const LmlMesh, out: *mut f64, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` doubles; writable `needed`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        unsafe { copy_out(&flat_xyz(mesh.mesh.positions()), out, capacity, needed, "out") }
    })
}

/// Copies the triangles, `3 * triangle_count` vertex indices laid out as in `lml_mesh_new`.
///
/// Two-call pattern as `lml_mesh_positions` (`capacity` and `*needed` count indices).
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_mesh_triangles(mesh: *const LmlMesh, out: *mut u32, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` indices; writable `needed`.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let triangles: Vec<u32> = mesh.mesh.faces().iter().flatten().copied().collect();
        unsafe { copy_out(&triangles, out, capacity, needed, "out") }
    })
}
