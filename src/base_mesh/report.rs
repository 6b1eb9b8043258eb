//! What a base-mesh optimisation reports, measured as an outside reviewer would: each family's
//! angle at the net's own vertices against the reference surface's smooth normal
//! ([`crate::quality::polyline_family_angles`]), the distance of the net from the reference, and
//! the torsion at the nodes ([`super::node_torsion`]).

use super::net_mesh::NetMesh;
use super::node_torsion::{node_rulings, polyline_rulings, NodeRuling, NodeTorsion, PolylineRulings, TORSION_FREE_DEGREES};
use crate::curves::LevelCurve;
use crate::field::Family;
use crate::mesh::{FaceBvh, TriMesh, Vec3};
use crate::quality::{polyline_family_angles, CurveAngles, FamilyAngles, WorstPoint};
use crate::strips::project_on;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// Distance of the net's vertices from the reference surface.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Deviation {
    pub max: f64,
    pub rms: f64,
    /// `max` in % of the reference's bounding-box diagonal.
    pub max_percent: f64,
    /// The vertex farthest from the reference.
    pub worst_vertex: usize,
}

/// The state of a base-mesh optimisation.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BaseMeshReport {
    /// Iterations run so far, in all.
    pub iterations: usize,
    /// Iterations the last step ran.
    pub step_iterations: usize,
    pub converged: bool,
    /// The torsion-free rows of Eq. 21 are on: with torsion-free nodes asked for, the families
    /// are optimised alone first, then with the nodes.
    pub torsion_free_stage: bool,
    /// The weighted energy (sum of squared residuals) at the current net.
    pub energy: f64,
    /// Each family's target angle along its polylines' direction (a pseudo-geodesic family whose
    /// polylines run the other way is held at `180° − θ`, the same curves).
    pub targets_degrees: Vec<f64>,
    /// Each family measured at its polylines' inner vertices.
    pub families: Vec<FamilyAngles>,
    pub deviation: Deviation,
    pub node_torsion: NodeTorsion,
    /// Every measured vertex of both families is within the tolerance of its angle, and a
    /// pseudo-geodesic family is not straight at any of them.
    pub families_met: bool,
    /// Every measured node is within [`TORSION_FREE_DEGREES`].
    pub torsion_free: bool,
}

/// The measures of a net (caller units) against its reference.
pub(crate) struct Measures {
    /// The net's vertices as measured, and the reference's closest point, smooth normal and
    /// distance for each ([`Reference::closest`]).
    pub positions: Vec<Vec3>,
    pub closest: Vec<(Vec3, Vec3, f64)>,
    pub families: Vec<FamilyAngles>,
    pub deviation: Deviation,
    pub rulings: PolylineRulings,
    pub nodes: Vec<NodeRuling>,
    pub node_torsion: NodeTorsion,
}

/// The reference surface with its closest-point hierarchy.
pub(crate) struct Reference {
    pub mesh: TriMesh,
    pub bvh: FaceBvh,
    pub diagonal: f64,
}

impl Reference {
    pub fn new(mesh: &TriMesh) -> Reference {
        let (low, high) = mesh.bounding_box();
        Reference { bvh: FaceBvh::new(mesh), mesh: mesh.clone(), diagonal: (high - low).norm().max(f64::MIN_POSITIVE) }
    }

    /// The closest point of `p` on the reference and the smooth normal there (`p` and the
    /// z axis for a non-finite query, which a valid net never holds).
    pub fn closest(&self, p: &Vec3) -> (Vec3, Vec3, f64) {
        project_on(&self.mesh, &self.bvh, p).map_or((*p, Vec3::z(), f64::INFINITY), |s| (s.point, s.normal, s.distance))
    }

    /// Each polyline of family `k` as a curve with the reference's `normals` (one per vertex).
    fn curves(net: &NetMesh, k: usize, normals: &[Vec3]) -> Vec<LevelCurve> {
        net.polylines(k)
            .iter()
            .enumerate()
            .map(|(index, line)| LevelCurve {
                level: index as f64,
                points: line.iter().map(|&v| net.positions()[v as usize]).collect(),
                normals: line.iter().map(|&v| normals[v as usize]).collect(),
                closed: false,
                singular_vertices: Vec::new(),
            })
            .collect()
    }

    /// Each family of `net` measured at `targets_degrees` (in parallel, deterministic).
    pub fn family_angles(&self, net: &NetMesh, families: &[Family], targets_degrees: &[f64]) -> Vec<FamilyAngles> {
        let normals: Vec<Vec3> = net.positions().par_iter().map(|p| self.closest(p).1).collect();
        self.families_with(net, families, targets_degrees, &normals)
    }

    /// Each family of `net` measured at `targets_degrees` with the reference's `normals` at its
    /// vertices: pseudo-geodesics and geodesics by their binormals
    /// ([`polyline_family_angles`]), constant slopes and asymptotic curves by their segments
    /// ([`segment_angles`]).
    fn families_with(&self, net: &NetMesh, families: &[Family], targets_degrees: &[f64], normals: &[Vec3]) -> Vec<FamilyAngles> {
        (0..families.len())
            .map(|k| match target_family(families[k], targets_degrees[k]) {
                slope @ Family::ConstantSlope { slope_degrees, .. } => {
                    let axis = slope.slope_axis().unwrap_or_else(Vec3::z);
                    let p = net.positions();
                    segment_angles(net, k, slope_degrees, |a, b| (p[b] - p[a]).normalize().dot(&axis).clamp(-1.0, 1.0).asin().to_degrees())
                }
                Family::Asymptotic => segment_angles(net, k, 0.0, |a, b| {
                    let along = (net.positions()[b] - net.positions()[a]).normalize();
                    along.dot(&normals[a]).abs().max(along.dot(&normals[b]).abs()).min(1.0).asin().to_degrees()
                }),
                family => polyline_family_angles(&Self::curves(net, k, normals), family, self.diagonal),
            })
            .collect()
    }

    /// Measures `net` for the families `families` at the targets `targets_degrees`.
    pub fn measure(&self, net: &NetMesh, families: &[Family], targets_degrees: &[f64]) -> Measures {
        let closest: Vec<(Vec3, Vec3, f64)> = net.positions().par_iter().map(|p| self.closest(p)).collect();
        let normals: Vec<Vec3> = closest.iter().map(|c| c.1).collect();
        let family_angles = self.families_with(net, families, targets_degrees, &normals);
        let mut deviation = Deviation::default();
        let mut squares = 0.0;
        for (v, &(_, _, distance)) in closest.iter().enumerate() {
            squares += distance * distance;
            if distance > deviation.max || v == 0 {
                deviation.max = distance;
                deviation.worst_vertex = v;
            }
        }
        deviation.rms = (squares / net.vertex_count() as f64).sqrt();
        deviation.max_percent = 100.0 * deviation.max / self.diagonal;
        let rulings = polyline_rulings(net);
        let (nodes, node_torsion) = node_rulings(net, &rulings);
        Measures { positions: net.positions().to_vec(), closest, families: family_angles, deviation, rulings, nodes, node_torsion }
    }
}

impl Measures {
    /// [`Reference::closest`] of `p` as measured here, if `p` is vertex `v` as measured (bit for
    /// bit): the next iteration's anchors start where the last report measured.
    pub fn closest_as_measured(&self, v: usize, p: &Vec3) -> Option<(Vec3, Vec3, f64)> {
        let measured = self.positions.get(v)?;
        measured.iter().zip(p.iter()).all(|(a, b)| a.to_bits() == b.to_bits()).then(|| self.closest[v])
    }
}

/// `family` with its angle (or slope) read along the polylines' direction.
pub(crate) fn target_family(family: Family, target_degrees: f64) -> Family {
    match family {
        Family::PseudoGeodesic { .. } => Family::PseudoGeodesic { theta_degrees: target_degrees },
        Family::ConstantSlope { axis, free_slope, .. } => Family::ConstantSlope { axis, slope_degrees: target_degrees, free_slope },
        other => other,
    }
}

/// Every segment of family `k`'s polylines (along their direction) measured by `measure(a, b)`
/// (its end vertices) against `target_degrees`: one value per segment, the worst at its midpoint. A
/// constant-slope family's segments by their slope `asin(ê·a)`; an asymptotic family's by the
/// larger angle `asin|ê·n|` of the segment to the reference's tangent plane at its two ends (the
/// discrete condition Sec. 3.5 holds, `n·ê = 0`; a binormal is undefined on the straight
/// asymptotic lines of a ruled surface).
fn segment_angles(net: &NetMesh, k: usize, target_degrees: f64, measure: impl Fn(usize, usize) -> f64) -> FamilyAngles {
    let p = net.positions();
    let mut angles = FamilyAngles::default();
    let mut squares = 0.0;
    for (index, line) in net.polylines(k).iter().enumerate() {
        let mut curve = CurveAngles { length: line.windows(2).map(|w| (p[w[1] as usize] - p[w[0] as usize]).norm()).sum(), ..CurveAngles::default() };
        let mut curve_squares = 0.0;
        for w in line.windows(2) {
            let measured = measure(w[0] as usize, w[1] as usize);
            let (a, b) = (p[w[0] as usize], p[w[1] as usize]);
            let error = (measured - target_degrees).abs();
            curve.measured += 1;
            curve_squares += error * error;
            curve.max_error_degrees = curve.max_error_degrees.max(error);
            if angles.worst.is_none_or(|w| error > w.error_degrees) {
                let middle = (a + b) * 0.5;
                angles.worst = Some(WorstPoint { curve: index, point: [middle.x, middle.y, middle.z], error_degrees: error, measured_degrees: measured });
            }
        }
        if curve.measured > 0 {
            curve.rms_error_degrees = (curve_squares / curve.measured as f64).sqrt();
        }
        squares += curve_squares;
        angles.measured += curve.measured;
        angles.max_error_degrees = angles.max_error_degrees.max(curve.max_error_degrees);
        angles.curves.push(curve);
    }
    if angles.measured > 0 {
        angles.rms_error_degrees = (squares / angles.measured as f64).sqrt();
    }
    angles
}

impl BaseMeshReport {
    /// The report of `measures` with the solver's counters, judged at `tolerance_degrees`.
    pub(crate) fn new(measures: &Measures, targets_degrees: &[f64], tolerance_degrees: f64) -> BaseMeshReport {
        let families_met = measures.families.iter().all(|f| f.max_error_degrees <= tolerance_degrees && f.straight == 0);
        BaseMeshReport {
            targets_degrees: targets_degrees.to_vec(),
            families: measures.families.clone(),
            deviation: measures.deviation,
            node_torsion: measures.node_torsion.clone(),
            families_met,
            torsion_free: measures.node_torsion.max_degrees <= TORSION_FREE_DEGREES,
            ..BaseMeshReport::default()
        }
    }
}
