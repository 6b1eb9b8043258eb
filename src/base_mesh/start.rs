//! The start of a base-mesh optimisation: the target orientation of each pseudo-geodesic family,
//! and the auxiliary variables from the net's geometry (Sec. 3.5: normals from the polylines'
//! tangents, binormals of the polylines, side vectors `n × t`; Sec. 5.2.1: rulings where the
//! strips of row and column meet, segment normals across consecutive rulings).

use super::node_torsion::{node_rulings, PolylineRulings};
use super::problem::{vec3, Anchor, BaseMeshProblem};
use crate::field::Family;
use crate::mesh::Vec3;
use crate::quality::FamilyAngles;

/// The target of `family` read along polylines of the other direction: `180° − θ` for
/// pseudo-geodesics, `−β` for a slope; geodesics and asymptotic curves read the same both ways.
pub(crate) fn mirror_degrees(family: Family) -> f64 {
    match family {
        Family::PseudoGeodesic { theta_degrees } => 180.0 - theta_degrees,
        Family::ConstantSlope { slope_degrees, .. } => -slope_degrees,
        other => other.theta_degrees(),
    }
}

/// Of the family's target and its [`mirror_degrees`], the one the measured family is nearer to:
/// the polylines of a net have no preferred direction.
pub(crate) fn oriented_target(family: Family, measured: &FamilyAngles, measured_mirror: &FamilyAngles) -> f64 {
    if measured_mirror.rms_error_degrees < measured.rms_error_degrees {
        mirror_degrees(family)
    } else {
        family.theta_degrees()
    }
}

/// Unit `a`, or `fallback` where `a` vanishes.
fn unit_or(a: Vec3, fallback: Vec3) -> Vec3 {
    a.try_normalize(1e-12).unwrap_or(fallback)
}

/// Writes the auxiliary variables of `problem` into `x` (whose positions are set), from the net
/// at those positions, the reference normals in `anchors` and the strips' `rulings` of each
/// polyline (torsion-free nodes).
pub(crate) fn initialise_auxiliaries(problem: &BaseMeshProblem, anchors: &[Anchor], rulings: &PolylineRulings, x: &mut [f64]) {
    let net = problem.net();
    let n = net.vertex_count();
    let p = |x: &[f64], v: u32| vec3(x, 3 * v as usize);
    let set = |x: &mut [f64], start: usize, value: Vec3| x[start..start + 3].copy_from_slice(value.as_slice());
    for v in 0..n {
        let reference = anchors[v].normal;
        let tangent = |k: usize| {
            let along = net.along(v, k);
            let (front, back) = (along.front.unwrap_or(v as u32), along.back.unwrap_or(v as u32));
            along.on_polyline().then(|| p(x, front) - p(x, back))
        };
        let normal = match (tangent(0), tangent(1)) {
            (Some(a), Some(b)) => unit_or(a.cross(&b), reference),
            _ => reference,
        };
        let normal = if normal.dot(&reference) < 0.0 { -normal } else { normal };
        set(x, problem.normal(v), normal);
        for k in 0..problem.curves.len() {
            let (Some(start), Some((back, front))) = (problem.binormal(v, k), net.along(v, k).inner()) else { continue };
            let here = p(x, v as u32);
            let t = unit_or(p(x, front) - p(x, back), Vec3::x());
            let side = unit_or(normal.cross(&t), Vec3::y());
            let frenet = (here - p(x, back)).cross(&(p(x, front) - here));
            let binormal = match problem.curves[k] {
                super::problem::CurveRows::Pseudo { cos, sin } => unit_or(frenet, normal * cos + side * sin),
                _ => unit_or(frenet, side),
            };
            set(x, start, binormal);
            if matches!(problem.curves[k], super::problem::CurveRows::Pseudo { .. }) {
                set(x, start + 3, side);
            }
        }
    }
    if !problem.torsion_free {
        return;
    }
    let (nodes, _) = node_rulings(net, rulings);
    let mut ruling: Vec<Option<Vec3>> = vec![None; n];
    for node in &nodes {
        ruling[node.vertex] = node.axis;
    }
    for (k, family) in rulings.iter().enumerate() {
        for (line, lines) in net.polylines(k).iter().zip(family) {
            let Some(lines) = lines else { continue };
            for (&v, d) in line.iter().zip(lines) {
                ruling[v as usize].get_or_insert(*d);
            }
        }
    }
    for (v, d) in ruling.iter().enumerate() {
        let reference = anchors[v].normal;
        let d = d.unwrap_or(reference);
        set(x, problem.ruling(v), if d.dot(&reference) < 0.0 { -d } else { d });
    }
    for ([a, b], start) in problem.segments() {
        let (da, db) = (vec3(x, problem.ruling(a as usize)), vec3(x, problem.ruling(b as usize)));
        let db = if da.dot(&db) < 0.0 { -db } else { db };
        let e = p(x, b) - p(x, a);
        let normal = unit_or(e.cross(&(da + db)), unit_or(e.cross(&anchors[a as usize].normal), Vec3::z()));
        set(x, start, normal);
    }
}
