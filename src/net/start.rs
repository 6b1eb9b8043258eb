//! The default start of a net (Sec. 4.1): the two families' starts are judged together, by a
//! short net solve from each candidate pair, because a pair whose families are each fine alone can
//! still run tangent somewhere. On the hall roof the two mirror families of 60° pseudo-geodesics
//! (the start search's winner and a second one crossing it at 45° on average) touch along a line
//! across the roof, where no solve can pull them apart; two heights tilted ±30° about one axis,
//! with the families' orientations free, lead to a net crossing at 40° or more everywhere.
//!
//! Candidates, in this order (the order settles ties, so the start is deterministic):
//! 1. each family from the single-family start search ([`StartSearch`]), the second one among
//!    the candidates crossing the first at [`START_CROSSING_DEGREES`] or more on average;
//! 2. only if that pair is not acceptable: pairs of heights along `a cos α ± b sin α`, for each
//!    principal axis `a` of the surface (`b` the other one in the principal plane) and
//!    α = [`PAIR_HALF_ANGLE_DEGREES`], each height with both signs where the family has two
//!    orientations (a pseudo-geodesic family and its mirror 180° − θ). A 3-web's pairs are its
//!    first two fields, the third starting as `−F − H`.
//!
//! Every pair is probed by a short net solve (on the start search's stand-in of a large mesh) and
//! scored: the sum of the families' scores along their level curves
//! ([`crate::initialisation::StartSearch`]'s judge) plus [`TANGENT_PENALTY`] per unit of the
//! surface area where the families cross less than [`CLEARANCE_DEGREES`] above the minimum angle.
//! A pair is acceptable when each family scores at most [`ACCEPTABLE_FAMILY_SCORE`] and at most
//! [`MAX_TANGENT_AREA`] of the area crosses that close. A 3-web is probed as a web: the
//! scores of its three families, the closest-crossing pair's area.
//!
//! As in the single-family search, a pair rejected only because one of its families is nearly
//! straight over most of the surface stays a fallback: when no pair is accepted, the best of those
//! (same score) is the winner, its `rejected` saying why, and the strips' verdict judges the net.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::intersection::intersection_angles;
use super::params::NetParams;
use super::solver::NetSolver;
use crate::field::{Family, FieldError, FieldParams, FieldSolver};
use crate::initialisation::{carried_to, family_judgement, keep_lower, level_curve_measure, principal_plane, search_proxy, FamilyJudgement, SearchError, SearchOptions, StartSearch};
use crate::mesh::TriMesh;

/// Smallest area-weighted mean angle (degrees) at which the second family's start must cross the
/// first's in the separate searches: well above the default minimum angle, so that the solve
/// does not have to turn one family across the other.
pub const START_CROSSING_DEGREES: f64 = 45.0;
/// Half the angle between the two heights of a pair candidate (degrees): they start crossing at
/// 60°, between the default minimum (30°) and a right angle.
pub const PAIR_HALF_ANGLE_DEGREES: f64 = 30.0;
/// A probed pair crossing less than this many degrees above the minimum angle is too close to
/// it: there the minimum-angle term is about to hold the families apart, against their own
/// terms. On the hall roof the PP60 pairs scoring best on their families after the probe crossed
/// that close on 10 % of the area and ended with a strip 3.4° off θ; pairs about the other axis
/// crossed close on at most 1 % and ended with every strip within 1.3°.
pub const CLEARANCE_DEGREES: f64 = 10.0;
/// Largest fraction of the surface's area where an acceptable pair crosses within
/// [`CLEARANCE_DEGREES`] of the minimum angle (or below it).
pub const MAX_TANGENT_AREA: f64 = 0.01;
/// Largest score (degrees) of each family of an acceptable pair. Stricter than the single-family
/// search's [`SearchOptions::acceptable_score`] (4): a net's families must also keep their angle
/// where they cross, and the pair search's behaviour on the hall roof (below) was measured with 3.
pub const ACCEPTABLE_FAMILY_SCORE: f64 = 3.0;
/// Score (degrees) per unit fraction of the area crossing within [`CLEARANCE_DEGREES`] of the
/// minimum angle (or below it).
pub const TANGENT_PENALTY: f64 = 100.0;

/// How a candidate pair of start fields is made.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum NetStartKind {
    /// Each family from its own start search, the second crossing the first.
    Separate,
    /// Heights along `axis cos α + other sin α` and `axis cos α − other sin α`, each negated as
    /// given (`F → −F` turns a pseudo-geodesic family into its mirror).
    Pair { axis: [f64; 3], other: [f64; 3], half_angle_degrees: f64, negated: [bool; 2] },
}

impl NetStartKind {
    /// A short description for reports.
    pub fn describe(&self) -> String {
        match self {
            NetStartKind::Separate => "each family from its own start search".into(),
            NetStartKind::Pair { axis: a, half_angle_degrees, negated, .. } => {
                let sign = |n: bool| if n { "−" } else { "+" };
                format!(
                    "heights ±{half_angle_degrees}° about ({:.3}, {:.3}, {:.3}), signs {}{}",
                    a[0],
                    a[1],
                    a[2],
                    sign(negated[0]),
                    sign(negated[1])
                )
            }
        }
    }
}

/// One candidate pair and how its short net solve ended.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NetCandidate {
    pub kind: NetStartKind,
    /// Lower is better; `None` when rejected.
    pub score: Option<f64>,
    /// Each family's own score after the short solve (three for a 3-web), when measured.
    pub family_scores: Vec<Option<f64>>,
    /// Fraction of the area where two families cross within [`CLEARANCE_DEGREES`] of the minimum
    /// angle (or below it) after the short solve: the largest over the pairs of a 3-web.
    pub tangent_area_fraction: f64,
    /// Why the candidate was rejected.
    pub rejected: Option<String>,
}

/// What [`net_start_search`] found: one start field per given family, every candidate probed and
/// the winner.
#[derive(Clone, Debug, PartialEq)]
pub struct NetStart {
    /// One field per vertex of the mesh for each family of a net (the first two of a 3-web).
    pub fields: Vec<Vec<f64>>,
    pub candidates: Vec<NetCandidate>,
    /// Index into `candidates`.
    pub winner: usize,
    /// Vertex count of the coarsening the pairs were probed on, if any.
    pub proxy_vertices: Option<usize>,
}

/// The start fields of [`net_start_search`].
pub fn net_start(mesh: &TriMesh, params: &NetParams, options: &SearchOptions) -> Result<Vec<Vec<f64>>, SearchError> {
    net_start_search(mesh, params, options).map(|start| start.fields)
}

/// The default start of a net of `params` on `mesh` (see the module notes). Errors:
/// `SearchError::Field` for invalid parameters, `SearchError::NoStart` with every candidate's
/// reason when all were rejected and none only for a nearly straight family (see the module notes).
pub fn net_start_search(mesh: &TriMesh, params: &NetParams, options: &SearchOptions) -> Result<NetStart, SearchError> {
    params.validate().map_err(SearchError::Field)?;
    let separate = separate_starts(mesh, params, options);
    let proxy = search_proxy(mesh, options.proxy_vertices);
    let mut search = PairSearch { mesh: proxy.as_ref().unwrap_or(mesh), params, options, candidates: Vec::new(), best: None, fallback: None };
    match separate {
        Ok(fields) => {
            let on_probed = match &proxy {
                Some(proxy) => fields.iter().map(|field| carried_to(mesh, field, proxy)).collect(),
                None => fields,
            };
            let probed = search.probe(&on_probed)?;
            search.record(NetStartKind::Separate, probed);
        }
        Err(SearchError::NoStart { reasons }) => search.reject(NetStartKind::Separate, format!("no start: {}", reasons.join("; "))),
        Err(error) => return Err(error),
    }
    if !search.has_acceptable() {
        search.probe_all(pair_candidates(search.mesh, params))?;
    }
    let Some((winner, _, probed)) = search.best.take().or(search.fallback.take()) else {
        let reasons = search.candidates.iter().map(|c| format!("{}: {}", c.kind.describe(), c.rejected.as_deref().unwrap_or("not probed"))).collect();
        return Err(SearchError::NoStart { reasons });
    };
    let fields = match &proxy {
        Some(proxy) => probed.iter().map(|field| carried_to(proxy, field, mesh)).collect(),
        None => probed,
    };
    Ok(NetStart { fields, candidates: search.candidates, winner, proxy_vertices: proxy.as_ref().map(TriMesh::vertex_count) })
}

/// Each of the first two families from its own start search, the second among the candidates
/// crossing the first at [`START_CROSSING_DEGREES`] or more on average.
fn separate_starts(mesh: &TriMesh, params: &NetParams, options: &SearchOptions) -> Result<Vec<Vec<f64>>, SearchError> {
    let mut fields: Vec<Vec<f64>> = Vec::with_capacity(2);
    for &family in &params.families[..2] {
        let mut search = StartSearch::new(mesh, FieldParams { family, ..params.field.clone() }, options.clone()).map_err(SearchError::Field)?;
        if let Some(first) = fields.first() {
            search = search.crossing(first, START_CROSSING_DEGREES).map_err(SearchError::Field)?;
        }
        search.run().map_err(SearchError::Field)?;
        let solver: FieldSolver = search.into_solver()?;
        fields.push(solver.field());
    }
    Ok(fields)
}

/// The pair candidates on `mesh` for the two families of `params`, in order.
fn pair_candidates(mesh: &TriMesh, params: &NetParams) -> Vec<(NetStartKind, Vec<Vec<f64>>)> {
    let [first, second] = principal_plane(mesh);
    let (sin, cos) = PAIR_HALF_ANGLE_DEGREES.to_radians().sin_cos();
    // Negating a field reverses its curves: a pseudo-geodesic or constant-slope family becomes
    // its mirror; geodesics and asymptotic curves stay the same family.
    let signs = |k: usize| -> &'static [bool] {
        if matches!(params.families[k], Family::PseudoGeodesic { .. } | Family::ConstantSlope { .. }) { &[false, true] } else { &[false] }
    };
    let mut candidates = Vec::new();
    for (axis, other) in [(first, second), (second, first)] {
        let directions = [axis * cos + other * sin, axis * cos - other * sin];
        for &negate_f in signs(0) {
            for &negate_g in signs(1) {
                let negated = [negate_f, negate_g];
                let fields = (0..2)
                    .map(|k| {
                        let sign = if negated[k] { -1.0 } else { 1.0 };
                        mesh.positions().iter().map(|p| sign * p.dot(&directions[k])).collect()
                    })
                    .collect();
                let kind = NetStartKind::Pair { axis: [axis.x, axis.y, axis.z], other: [other.x, other.y, other.z], half_angle_degrees: PAIR_HALF_ANGLE_DEGREES, negated };
                candidates.push((kind, fields));
            }
        }
    }
    candidates
}

/// The pairs probed so far and the best one.
struct PairSearch<'a> {
    /// The mesh the pairs are probed on (the stand-in of a large mesh).
    mesh: &'a TriMesh,
    params: &'a NetParams,
    options: &'a SearchOptions,
    candidates: Vec<NetCandidate>,
    /// Index, score and the given fields the short solve reached.
    best: Option<(usize, f64, Vec<Vec<f64>>)>,
    /// The same for the best pair rejected only for a nearly straight family.
    fallback: Option<(usize, f64, Vec<Vec<f64>>)>,
}

/// Where a candidate's short net solve ended: every family's score, the close-crossing area, the
/// fields and, if some family is degenerate (nearly straight), why; or why it was rejected.
type Probed = Result<(Vec<f64>, f64, Vec<Vec<f64>>, Option<String>), String>;

impl PairSearch<'_> {
    fn reject(&mut self, kind: NetStartKind, reason: String) {
        self.candidates.push(NetCandidate { kind, score: None, family_scores: Vec::new(), tangent_area_fraction: 0.0, rejected: Some(reason) });
    }

    fn has_acceptable(&self) -> bool {
        self.best.as_ref().is_some_and(|(index, _, _)| {
            let candidate = &self.candidates[*index];
            candidate.tangent_area_fraction <= MAX_TANGENT_AREA && candidate.family_scores.iter().all(|s| s.is_some_and(|s| s <= ACCEPTABLE_FAMILY_SCORE))
        })
    }

    /// Probes every candidate (in parallel: each short solve is independent, and they are
    /// recorded in order, so the outcome does not depend on the number of threads).
    fn probe_all(&mut self, candidates: Vec<(NetStartKind, Vec<Vec<f64>>)>) -> Result<(), SearchError> {
        let outcomes: Vec<Result<Probed, SearchError>> = candidates.par_iter().map(|(_, fields)| self.probe(fields)).collect();
        for ((kind, _), outcome) in candidates.into_iter().zip(outcomes) {
            self.record(kind, outcome?);
        }
        Ok(())
    }

    fn record(&mut self, kind: NetStartKind, probed: Probed) {
        let (scores, tangent_area_fraction, fields, degenerate) = match probed {
            Ok(probed) => probed,
            Err(reason) => return self.reject(kind, reason),
        };
        let score = scores.iter().sum::<f64>() + TANGENT_PENALTY * tangent_area_fraction;
        let index = self.candidates.len();
        let family_scores = scores.into_iter().map(Some).collect();
        let slot = if degenerate.is_some() { &mut self.fallback } else { &mut self.best };
        keep_lower(slot, index, score, fields);
        let score = degenerate.is_none().then_some(score);
        self.candidates.push(NetCandidate { kind, score, family_scores, tangent_area_fraction, rejected: degenerate });
    }

    /// Runs the short net solve from `fields` and measures where it ends. Errors only for invalid
    /// parameters; `Ok(Err(reason))` rejects the candidate.
    fn probe(&self, fields: &[Vec<f64>]) -> Result<Probed, SearchError> {
        let mut params = self.params.clone();
        for stage in &mut params.field.schedule {
            stage.iterations = stage.iterations.min(self.options.probe_warm_up);
        }
        params.field.schedule.retain(|stage| stage.iterations > 0);
        let mut solver = match NetSolver::new(self.mesh, fields, params) {
            Ok(solver) => solver,
            Err(error @ FieldError::InvalidParameter { .. }) => return Err(SearchError::Field(error)),
            Err(error) => return Ok(Err(format!("cannot start: {error}"))),
        };
        let report = match solver.step(self.options.probe_iterations) {
            Ok(report) => report,
            Err(error) => return Ok(Err(format!("short solve failed: {error}"))),
        };
        let probed = solver.fields();
        let vertices = self.mesh.vertex_count() as f64;
        let mut scores = Vec::with_capacity(probed.len());
        let mut degenerate = None;
        for (k, field) in probed.iter().enumerate() {
            let family = self.params.families[k];
            let singular = report.families[k].singular_vertices.len() as f64 / vertices;
            match level_curve_measure(self.mesh, field, family, self.options).and_then(|measure| family_judgement(&measure, family, singular)) {
                Ok(FamilyJudgement { score, degenerate: reason }) => {
                    scores.push(score);
                    degenerate = degenerate.or(reason.map(|reason| format!("family {}: {reason}", k + 1)));
                }
                Err(reason) => return Ok(Err(format!("family {}: {reason}", k + 1))),
            }
        }
        let pairs: &[(usize, usize)] = if self.params.is_web() { &[(0, 1), (0, 2), (1, 2)] } else { &[(0, 1)] };
        let close = pairs.iter().map(|&(a, b)| self.close_crossing_area(&probed[a], &probed[b])).fold(0.0, f64::max);
        // A 3-web is started from its first two fields (the third is −F − H).
        let given = if self.params.is_web() { 2 } else { probed.len() };
        Ok(Ok((scores, close, probed[..given].to_vec(), degenerate)))
    }

    /// Fraction of the area where the level sets of `f` and `g` cross less than
    /// [`CLEARANCE_DEGREES`] above the minimum angle (or not at all).
    fn close_crossing_area(&self, f: &[f64], g: &[f64]) -> f64 {
        let areas = self.mesh.face_areas();
        let close = intersection_angles(self.mesh, f, g)
            .into_iter()
            .zip(areas)
            .filter(|(angle, _)| angle.is_none_or(|a| a < self.params.min_intersection_degrees + CLEARANCE_DEGREES))
            .fold(0.0, |sum, (_, area)| sum + area);
        close / areas.iter().sum::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surfaces::hall_roof;

    #[test]
    fn pairs_tilt_each_principal_axis_both_ways_with_every_orientation_of_a_family() {
        let mesh = hall_roof(400).into_mesh().unwrap();
        let p60 = Family::PseudoGeodesic { theta_degrees: 60.0 };
        assert_eq!(pair_candidates(&mesh, &NetParams::new(p60, p60)).len(), 8);
        assert_eq!(pair_candidates(&mesh, &NetParams::new(p60, Family::Geodesic)).len(), 4);
        let pairs = pair_candidates(&mesh, &NetParams::new(Family::Asymptotic, Family::Asymptotic));
        assert_eq!(pairs.len(), 2);
        for (_, fields) in &pairs {
            // Two heights 2α apart: their gradients (constant on the flat part) cross at 2α.
            let angles: Vec<f64> = intersection_angles(&mesh, &fields[0], &fields[1]).into_iter().flatten().collect();
            let in_plan = angles.iter().filter(|a| (**a - 2.0 * PAIR_HALF_ANGLE_DEGREES).abs() < 15.0).count();
            assert!(in_plan * 2 > angles.len(), "{in_plan} of {} faces cross near 60°", angles.len());
        }
    }

    #[test]
    fn the_start_has_the_same_bits_on_any_number_of_threads() {
        let mesh = hall_roof(400).into_mesh().unwrap();
        let p60 = Family::PseudoGeodesic { theta_degrees: 60.0 };
        let params = NetParams::new(p60, p60);
        let on = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            pool.install(|| net_start_search(&mesh, &params, &SearchOptions::default()).unwrap())
        };
        let (one, two) = (on(1), on(2));
        assert!(one.candidates.len() > 1, "the pairs were probed: {:?}", one.candidates);
        assert_eq!(one, two);
    }
}
