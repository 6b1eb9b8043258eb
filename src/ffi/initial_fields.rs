//! Initial fields (paper Sec. 3.2.2): from traced guide curves (Eq. 5–7) and from sketched
//! strokes, as per-vertex values to pass to `lml_field_new`.

use super::failure::Failure;
use super::guard::guarded;
use super::guides::LmlGuides;
use super::mesh::LmlMesh;
use super::raw::{copy_out, element_count, handle, input, Out};
use super::status::LmlStatus;
use crate::initialisation::{estimate_target_angle, field_from_guide_curves, field_from_strokes, GuideCurveOptions, StrokeOptions};
use crate::mesh::{EdgePoint, Vec3};

/// Computes the initial field of ordered guide curves (paper Eq. 5–7, weights λ0 = 3 for the
/// curves and λ1 = 1 for fairness): a smooth field whose level set `F = i` follows guide curve
/// `i`, and the matching gradient target.
///
/// - `mesh`: the surface the guides were traced on (the same vertices and edges).
/// - `guides`: at least two curves, ordered (see `lml_guides_check_order`; not checked here).
/// - `out`: one double per vertex. Two-call pattern: `*needed` is set to the vertex count; if
///   `out` is NULL or `capacity` (in doubles) is smaller, nothing is copied and
///   `LML_STATUS_BUFFER_TOO_SMALL` is returned (the field is computed either way: for a cheap
///   size query use `lml_mesh_vertex_count`). The buffer stays owned by the caller.
/// - `gradient_target`: may be NULL; on `LML_STATUS_OK` receives the mean ‖∇F‖ between the first
///   and the last guide (field units per mesh length unit), to put into
///   `LmlFieldParams.gradient_target` so that the optimisation keeps the spacing of the guides.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_BUFFER_TOO_SMALL`; `LML_STATUS_INVALID_GUIDES` (fewer
/// than two curves, or the first and the last curve start at the same point);
/// `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, guides traced on another mesh: the vertex count
/// differs, or a guide point (curve and point named) lies on no edge of `mesh`);
/// `LML_STATUS_SINGULAR_FIELD` (the linear system is singular).
#[no_mangle]
pub unsafe extern "C" fn lml_field_values_from_guides(
    mesh: *const LmlMesh,
    guides: *const LmlGuides,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
    gradient_target: *mut f64,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let guides = unsafe { handle(guides, "guides") }?;
        let gradient_target = unsafe { Out::optional(gradient_target, "gradient_target") }?;
        let (ours, theirs) = (mesh.mesh.vertex_count(), guides.mesh.vertex_count());
        if ours != theirs {
            return Err(Failure::argument("guides", format!("were traced on a mesh with {theirs} vertices; `mesh` has {ours}")));
        }
        let curves: Vec<Vec<EdgePoint>> = guides.curves.iter().map(|c| c.points().to_vec()).collect();
        let guide_field = field_from_guide_curves(&mesh.mesh, &curves, &GuideCurveOptions::default())?;
        let status = unsafe { copy_out(&guide_field.field, out, capacity, needed, "out") }?;
        if let Some(mut target) = gradient_target {
            target.set(guide_field.gradient_target);
        }
        Ok(status)
    })
}

/// Checks the stroke offset table: first 0, last `point_count`, non-decreasing.
fn check_offsets(offsets: &[usize], point_count: usize) -> Result<(), Failure> {
    let last = offsets.len() - 1; // `offsets` holds stroke_count + 1 ≥ 1 values.
    if offsets[0] != 0 {
        return Err(Failure::argument("offsets", format!("offsets[0] = {} must be 0", offsets[0])));
    }
    if offsets[last] != point_count {
        return Err(Failure::argument("offsets", format!("offsets[{last}] = {} must equal point_count = {point_count}", offsets[last])));
    }
    if let Some(i) = (1..offsets.len()).find(|&i| offsets[i] < offsets[i - 1]) {
        return Err(Failure::argument("offsets", format!("offsets[{i}] = {} is smaller than offsets[{}] = {}", offsets[i], i - 1, offsets[i - 1])));
    }
    Ok(())
}

/// Computes a smooth field whose level sets follow sketched strokes (paper Sec. 3.2.2,
/// "Interactive steering", Fig. 14 b), about one mean edge length apart, increasing from the
/// earlier to the later of the two strokes whose starts lie farthest apart; and the angle θ its
/// level sets make with the surface along the strokes, the target to optimise for.
///
/// - `points`: `point_count` stroke points (3 doubles each, mesh units), each within one mean
///   edge length of the surface; the points of all strokes one after another.
/// - `offsets`: `stroke_count + 1` values cutting `points` into strokes (stroke `s` is points
///   `offsets[s] .. offsets[s + 1]`): first 0, last `point_count`, non-decreasing. Copied.
/// - `out`: one double per vertex; two-call pattern as `lml_field_values_from_guides` (the field
///   is computed either way).
/// - `theta_degrees`: may be NULL (then θ is not estimated); on `LML_STATUS_OK` receives the mean
///   signed angle θ ∈ [0, 180] between the level-set binormals and the surface normals at the
///   strokes' middle halves, for `lml_field_params_default`.
///
/// Returns `LML_STATUS_OK`; `LML_STATUS_BUFFER_TOO_SMALL`; `LML_STATUS_INVALID_STROKES` (fewer
/// than two strokes, a stroke with fewer than two points (or in fewer than two triangles), a point
/// farther than a mean edge length from the surface, two strokes through one triangle: they
/// cross; the message names stroke and point); `LML_STATUS_INVALID_ARGUMENT` (NULL pointer, a bad
/// offset (named), a NaN or infinite coordinate (stroke and point named));
/// `LML_STATUS_SINGULAR_FIELD` (a linear system is singular, or θ cannot be measured: no stroke
/// passes a regular interior vertex in its middle half).
#[no_mangle]
pub unsafe extern "C" fn lml_field_values_from_strokes(
    mesh: *const LmlMesh,
    points: *const f64,
    point_count: usize,
    offsets: *const usize,
    stroke_count: usize,
    out: *mut f64,
    capacity: usize,
    needed: *mut usize,
    theta_degrees: *mut f64,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): the pointer contracts are those documented above.
        let mesh = unsafe { handle(mesh, "mesh") }?;
        let points = unsafe { input(points, element_count(point_count, 3, "point_count")?, "points") }?;
        let offset_count = stroke_count.checked_add(1).ok_or_else(|| Failure::argument("stroke_count", "is too large"))?;
        let offsets = unsafe { input(offsets, offset_count, "offsets") }?;
        let theta = unsafe { Out::optional(theta_degrees, "theta_degrees") }?;
        check_offsets(offsets, point_count)?;
        let strokes: Vec<Vec<Vec3>> = offsets
            .windows(2)
            .map(|w| points[3 * w[0]..3 * w[1]].chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2])).collect())
            .collect();
        let stroke_field = field_from_strokes(&mesh.mesh, &strokes, &StrokeOptions::default())?;
        let angle = theta.map(|t| estimate_target_angle(&mesh.mesh, &stroke_field.field, &stroke_field.samples).map(|a| (t, a))).transpose()?;
        let status = unsafe { copy_out(&stroke_field.field, out, capacity, needed, "out") }?;
        if let Some((mut t, a)) = angle {
            t.set(a);
        }
        Ok(status)
    })
}
