//! How far a net's nodes are from torsion-free (Sec. 5.2.1), judged from its polylines alone.
//!
//! Each polyline carries a one-parameter family of developable strips of planar quads, their
//! rulings in the outer bisecting planes (Eq. 16–17, [`crate::strips::reflected_rulings`]). A
//! node is torsion-free when the strips of its row and its column share the ruling there. The
//! strips are chosen as a whole: each first fitted to the line its rectifying plane shares with
//! the crossing polyline's at each node (where the two planes are apart), elsewhere to its own
//! version-1 rulings (Fig. 19); then, in turn, each family's strips refitted to the other family's rulings at their nodes
//! ([`crate::strips::fitted_rulings`]), a few rounds. A node's torsion is the angle between the two
//! strips' rulings there: 0 everywhere exactly when the strips share every node's ruling, what
//! Eq. 21 asks of the optimised net. In a web, the nodes are those of its rows and columns; the
//! diagonals' strips are fitted to their own version-1 rulings.

use super::net_mesh::NetMesh;
use crate::mesh::Vec3;
use crate::strips::{fitted_rulings, version_one_rulings};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Largest ruling angle at a node (degrees) that counts as torsion-free.
pub const TORSION_FREE_DEGREES: f64 = 0.5;

/// The ruling angles at the nodes inside a row and a column.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct NodeTorsion {
    /// Nodes measured.
    pub nodes: usize,
    pub max_degrees: f64,
    pub rms_degrees: f64,
    /// The vertex of the node with the largest angle.
    pub worst_vertex: Option<usize>,
}

/// One node inside a row and a column: the angle between its two strips' rulings (as lines,
/// degrees in `[0°, 90°]`; `None` where a polyline carries no strip) and their mean, the node axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NodeRuling {
    pub vertex: usize,
    pub angle_degrees: Option<f64>,
    pub axis: Option<Vec3>,
}

/// Each family's strip rulings, per polyline (`None` where no member of the family fits).
pub type PolylineRulings = Vec<Vec<Option<Vec<Vec3>>>>;

/// Rounds of refitting each family to the other's rulings.
const ROUNDS: usize = 3;

/// The points of each polyline of family `k`.
fn polyline_points(net: &NetMesh, k: usize) -> Vec<Vec<Vec3>> {
    net.polylines(k).iter().map(|line| line.iter().map(|&v| net.positions()[v as usize]).collect()).collect()
}

/// Each family's rulings at the vertices they pass through.
fn rulings_at(net: &NetMesh, rulings: &PolylineRulings) -> Vec<[Option<Vec3>; 2]> {
    let mut at: Vec<[Option<Vec3>; 2]> = vec![[None; 2]; net.vertex_count()];
    for (k, family) in rulings.iter().enumerate().take(2) {
        for (line, lines) in net.polylines(k).iter().zip(family) {
            let Some(lines) = lines else { continue };
            for (&v, d) in line.iter().zip(lines) {
                at[v as usize][k] = Some(*d);
            }
        }
    }
    at
}

/// Least angle between the rectifying planes of a row and a column for their common line to
/// count as a candidate ruling (about 10°): planes nearer to each other (a net of geodesics,
/// whose rectifying planes are both the tangent plane) leave it undetermined.
const MIN_PLANE_ANGLE_SINE: f64 = 0.17;

/// At each vertex inside a row and a column whose rectifying planes cross at
/// [`MIN_PLANE_ANGLE_SINE`] or more, the line they share: the only ruling both strips could
/// have there.
fn common_rulings(net: &NetMesh) -> Vec<Option<Vec3>> {
    let p = net.positions();
    (0..net.vertex_count())
        .map(|v| {
            let bisector_normal = |k: usize| {
                let (back, front) = net.along(v, k).inner()?;
                let (f, b) = ((p[front as usize] - p[v]).try_normalize(0.0)?, (p[back as usize] - p[v]).try_normalize(0.0)?);
                (f + b).try_normalize(1e-9)
            };
            let line = bisector_normal(0)?.cross(&bisector_normal(1)?);
            (line.norm() >= MIN_PLANE_ANGLE_SINE).then(|| line.normalize())
        })
        .collect()
}

/// The strip of every polyline, chosen as the module describes.
pub fn polyline_rulings(net: &NetMesh) -> PolylineRulings {
    let points: Vec<Vec<Vec<Vec3>>> = (0..net.family_count()).map(|k| polyline_points(net, k)).collect();
    let common = common_rulings(net);
    let mut rulings: PolylineRulings = (0..net.family_count())
        .map(|k| {
            net.polylines(k)
                .par_iter()
                .zip(&points[k])
                .map(|(line, p)| {
                    let shared = |v: u32| if k < 2 { common[v as usize] } else { None };
                    let targets: Vec<Option<Vec3>> = line.iter().zip(version_one_rulings(p, &[])).map(|(&v, own)| shared(v).or(own)).collect();
                    fitted_rulings(p, &targets)
                })
                .collect()
        })
        .collect();
    for _ in 0..ROUNDS {
        for k in 0..2 {
            let at = rulings_at(net, &rulings);
            let refitted: Vec<Option<Vec<Vec3>>> = net
                .polylines(k)
                .par_iter()
                .zip(&points[k])
                .map(|(line, p)| fitted_rulings(p, &line.iter().map(|&v| at[v as usize][1 - k]).collect::<Vec<_>>()))
                .collect();
            for (old, new) in rulings[k].iter_mut().zip(refitted) {
                if new.is_some() {
                    *old = new;
                }
            }
        }
    }
    rulings
}

/// The ruling angle at every node inside a row and a column, and their summary.
pub fn node_rulings(net: &NetMesh, rulings: &PolylineRulings) -> (Vec<NodeRuling>, NodeTorsion) {
    let at = rulings_at(net, rulings);
    let mut nodes = Vec::new();
    let mut summary = NodeTorsion::default();
    let mut squares = 0.0;
    for v in 0..net.vertex_count() {
        if net.along(v, 0).inner().is_none() || net.along(v, 1).inner().is_none() {
            continue;
        }
        let (angle_degrees, axis) = match at[v] {
            [Some(a), Some(b)] => {
                let b = if a.dot(&b) < 0.0 { -b } else { b };
                (Some(a.dot(&b).clamp(-1.0, 1.0).acos().to_degrees()), (a + b).try_normalize(0.0))
            }
            _ => (None, None),
        };
        if let Some(angle) = angle_degrees {
            summary.nodes += 1;
            squares += angle * angle;
            if summary.worst_vertex.is_none() || angle > summary.max_degrees {
                summary.max_degrees = angle;
                summary.worst_vertex = Some(v);
            }
        }
        nodes.push(NodeRuling { vertex: v, angle_degrees, axis });
    }
    if summary.nodes > 0 {
        summary.rms_degrees = (squares / summary.nodes as f64).sqrt();
    }
    (nodes, summary)
}
