//! The default start: which initial field leads to the asked family on a surface nobody has
//! prepared guides or strokes for.
//!
//! The level-set optimisation (Sec. 3.2.2) converges to a family near its start, and a poor
//! start leads to a poor or degenerate family: the coordinate along a cylinder's circumference
//! has the rulings as level sets, which are straight, so every P-curve condition holds in the
//! limit and the optimiser stays there (`../shared/docs/fidelity-notes.md`). The search therefore
//! tries several starts, runs a short solve from each (a few iterations cost milliseconds each),
//! judges the level curves each one reaches as an outside reviewer would
//! ([`crate::quality::family_angles`]), rejects degenerate families, and hands the best one on.
//!
//! On a mesh of more than 1.5 × [`SearchOptions::proxy_vertices`] vertices the short solves run
//! on a coarsening of it to that size (`super::proxy`): probes converge more slowly on finer
//! meshes, and the choice of start does not depend on the resolution. The winner's field is
//! then carried to the mesh, where the solve continues with the final weights.
//!
//! Candidates, in this order (the order settles ties, so the search is deterministic):
//! 1. heights along directions in the principal plane of the surface (the two largest axes of
//!    the vertex positions' covariance), at `directions` evenly spaced angles, each with both
//!    signs (`F` and `−F` lead to the two mirror families of pseudo-geodesics; for geodesics
//!    and asymptotic curves they are the same family and only one is tried);
//! 2. only if no height is acceptable: guide P-curves traced from each side of the outer boundary
//!    (Sec. 3.2.1) at each of `guide_angles`, turned into a field by Eq. 5–7.
//!
//! A candidate's score is the family's RMS angle error plus a quarter of its largest error (in
//! degrees, along the curves), plus penalties for nearly straight pieces and singular vertices;
//! lower is better. A candidate is rejected when more than half of its measured curve is nearly
//! straight (a degenerate pseudo-geodesic family), when its level curves cannot be measured, when
//! its short solve fails, or when that solve stalls (its field stops moving) while its curves score
//! far above the best so far ([`SearchOptions::stall_factor`]; the solve is then cut short); a
//! start whose level curves are straight lines to begin with (90 % or more) is rejected without a
//! solve.
//!
//! Where every candidate is rejected and some only for being nearly straight, the search falls
//! back on the best of those (by the same score, penalties included) rather than give up: on a
//! surface that is nearly flat at the model's scale for the asked θ (a helicoid's outer part at
//! θ = 60°, say) every pseudo-geodesic family is nearly straight, and its strips can still meet
//! θ. The winner then stays marked as rejected ([`Candidate::rejected`]), so that callers say
//! so, and the strips' verdict judges the result as always.

use std::collections::VecDeque;

use nalgebra::{Matrix3, SymmetricEigen};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::guide_curves::{GuideCurveOptions, GuideFieldBasis};
use super::proxy::{carried_to, search_proxy};
use crate::field::{validate_params, Family, FieldError, FieldParams, FieldSolver};
use crate::mesh::{TriMesh, Vec3};
use crate::net::intersection_angles;
use crate::quality::{level_set_angles, FamilyAngles};
use crate::tracing::{boundary_segments, intersections, trace_guide_set, DEFAULT_CORNER_TURN_DEGREES};

/// Settings of the search.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SearchOptions {
    /// Iterations of each candidate's short solve, ≥ 1. Default 20.
    pub probe_iterations: usize,
    /// Iterations each warm-up stage of the field's schedule keeps in a short solve (at most its
    /// own), so that the probe reaches the final weights. Default 3: with the default schedule a
    /// probe then spends 14 of its 20 iterations at the final weights, enough to tell where a
    /// start leads (on a cylinder the height along the axis, which ends on the catenaries, then
    /// ranks first; after the full 8 + 8 warm-up iterations it ranked last).
    pub probe_warm_up: usize,
    /// Level curves extracted to judge a candidate, ≥ 2. Default 12.
    pub levels: usize,
    /// Resampling step of the curve measure, in mean edge lengths, > 0. Default 3.
    pub spacing_edges: f64,
    /// Height directions in the principal plane, ≥ 1. Default 4 (every 45°).
    pub directions: usize,
    /// Start angles (degrees, in (0, 180)) of the guide candidates. Default 60°, 90°, 120°.
    pub guide_angles: Vec<f64>,
    /// Guides per guide candidate, ≥ 2. Default 4.
    pub guides: usize,
    /// A candidate scoring at most this is good enough to skip the guide candidates. Default 4
    /// (about 1.5° RMS with a largest error of 10°, before the solve to convergence lowers both):
    /// on eight unseen surfaces at four angles (`cargo bench --bench unseen_surfaces`) the best
    /// height scored 3–4 on six designs (the wave at every θ, a saddle at 60°, a helicoid at
    /// 30°), where the 12 guide candidates won once (the helicoid, 2.1 against 3.4) and every
    /// design met θ with either winner; skipping them saved 0.5–0.6 s of each.
    pub acceptable_score: f64,
    /// A probe is abandoned as stalled (rejected, its solve cut short after 12 of its 20
    /// iterations) when its field has stopped moving while its level curves score above this many
    /// times the best score accepted before its step began (see [`STALL_FIELD_CHANGE`]); ≥ 1,
    /// `f64::INFINITY` never abandons one. Default 3. Such a probe's iterations cost two to three
    /// damped solves each: on a monkey saddle at θ = 45° seven of the ten traced guide candidates
    /// stalled, scoring 61–96 after 12 iterations and within 2 % of that after 20, the best
    /// height 5.8.
    pub stall_factor: f64,
    /// Size of the stand-in the candidates are probed on when the mesh has more than 1.5 times
    /// as many vertices (0: always probe on the mesh itself). Default 1,500: a probe's 20
    /// iterations there reach a family that judges the start fairly, at half the cost of a
    /// 3,000-vertex probe (on the hall roof, a cylinder, a cone, a hyperbolic paraboloid, a
    /// sphere cap and the paper's meshes of about 3,000 vertices the winners' strips met θ
    /// where they had with 3,000-vertex probes, and the default design took 0.9–2.1 s instead of
    /// 1.5–3.8 s).
    pub proxy_vertices: usize,
}

impl Default for SearchOptions {
    fn default() -> Self {
        SearchOptions {
            probe_iterations: 20,
            probe_warm_up: 3,
            levels: 12,
            spacing_edges: 3.0,
            directions: 4,
            guide_angles: vec![60.0, 90.0, 120.0],
            guides: 4,
            acceptable_score: 4.0,
            stall_factor: 3.0,
            proxy_vertices: 1_500,
        }
    }
}

/// How a candidate's initial field is made.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum StartKind {
    /// `F = ±x·d`: the height along a direction `d` of the principal plane.
    Height { direction: [f64; 3], negated: bool },
    /// Guides traced from boundary side `side` at `start_angle_degrees` (Eq. 5–7).
    Guides { side: usize, start_angle_degrees: f64 },
}

/// One candidate start and how its short solve ended.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Candidate {
    pub kind: StartKind,
    /// Lower is better; `None` until probed or when rejected.
    pub score: Option<f64>,
    /// The curve measure after the short solve (RMS, max, straight fraction), when measured.
    pub rms_error_degrees: f64,
    pub max_error_degrees: f64,
    pub straight_fraction: f64,
    pub singular_vertices: usize,
    /// Why the candidate was rejected.
    pub rejected: Option<String>,
}

impl StartKind {
    /// A short description for reports.
    pub fn describe(&self) -> String {
        match self {
            StartKind::Height { direction: d, negated } => {
                format!("{}height along ({:.3}, {:.3}, {:.3})", if *negated { "minus " } else { "" }, d[0], d[1], d[2])
            }
            StartKind::Guides { side, start_angle_degrees } => format!("guides from boundary side {side} at {start_angle_degrees}°"),
        }
    }
}

/// The search, stepped one candidate at a time. A step that runs a short solve runs the short
/// solve of the next pending candidate that needs one beside it, on a second solver (two probes
/// side by side use the machine's two cores better than one probe's passes split between them;
/// candidates rejected without a solve, such as traced guides that cross, are passed over so
/// that no probe runs alone while others wait), and that candidate's step only records it. Each
/// probe is the same whichever solver runs it, so candidates, scores and the winner do not
/// depend on it.
pub struct StartSearch {
    mesh: TriMesh,
    /// The coarsening of `mesh` the candidates are probed on, when `mesh` is large.
    proxy: Option<TriMesh>,
    params: FieldParams,
    options: SearchOptions,
    /// Two solvers restarted for every candidate, so the problem is prepared twice at most: the
    /// current candidate's probe runs on the first, the next one's beside it on the second.
    solvers: [Option<FieldSolver>; 2],
    pending: VecDeque<Pending>,
    candidates: Vec<Candidate>,
    /// The best candidate so far: its index and its field after the short solve.
    best: Option<(usize, f64, Vec<f64>)>,
    /// The best of the candidates rejected only for nearly straight level curves, taken when no
    /// candidate is accepted: as `best`.
    fallback: Option<(usize, f64, Vec<f64>)>,
    guides_queued: bool,
    /// A field (on the probed mesh) whose level sets the candidates must cross at a mean angle
    /// of at least this many degrees: the other family of a net ([`Self::crossing`]).
    crossing: Option<(Vec<f64>, f64)>,
}

/// A candidate not recorded yet: its kind, initial field (or why it has none, a straight start
/// included: [`StartSearch::screened`]) and `E_grad` target, and its probe when it ran beside an
/// earlier candidate's.
struct Pending {
    kind: StartKind,
    field: Result<Vec<f64>, String>,
    gradient_target: Option<f64>,
    probed: Option<Probed>,
}

impl Pending {
    fn new(kind: StartKind, field: Result<Vec<f64>, String>, gradient_target: Option<f64>) -> Pending {
        Pending { kind, field, gradient_target, probed: None }
    }
}

/// How a probe ended: `Err` for a failure no other candidate could avoid (an invalid parameter),
/// `Ok(Err(reason))` for a rejected candidate, else the family measure of the level curves its
/// short solve reached, its singular vertex count and its field.
type Probed = Result<Result<(FamilyAngles, usize, Vec<f64>), String>, FieldError>;

impl StartSearch {
    /// Prepares the search for a field of `params` (its family, weights and schedule; its
    /// gradient target is replaced by each candidate's) on `mesh`.
    /// Errors: `InvalidParameter` for parameters (of the field or the search) out of range.
    pub fn new(mesh: &TriMesh, mut params: FieldParams, options: SearchOptions) -> Result<StartSearch, FieldError> {
        validate_params(&params)?;
        validate(&options)?;
        if let Family::ConstantSlope { .. } = params.family {
            // Height, guide and conformal candidates are starts of angle families; a constant-slope
            // family has its own start, the slope directions.
            return Err(FieldError::InvalidParameter {
                name: "family",
                message: "the start search covers the families by θ; a constant-slope field starts from slope_start_field".into(),
            });
        }
        params.family = params.family.by_name();
        let mut search = StartSearch {
            mesh: mesh.clone(),
            proxy: search_proxy(mesh, options.proxy_vertices),
            params,
            options,
            solvers: [None, None],
            pending: VecDeque::new(),
            candidates: Vec::new(),
            best: None,
            fallback: None,
            guides_queued: false,
            crossing: None,
        };
        search.queue_heights();
        Ok(search)
    }

    /// Probes the next candidate. Returns `Ok(true)` while candidates remain. Errors only for a
    /// failure that no other candidate could avoid (e.g. an invalid θ); a candidate whose own
    /// solve fails is rejected and the search goes on.
    pub fn step(&mut self) -> Result<bool, FieldError> {
        if self.pending.is_empty() && !self.guides_queued && !self.has_acceptable() {
            self.queue_guides();
        }
        let Some(next) = self.pending.pop_front() else { return Ok(false) };
        let index = self.candidates.len();
        let mut candidate = Candidate {
            kind: next.kind,
            score: None,
            rms_error_degrees: 0.0,
            max_error_degrees: 0.0,
            straight_fraction: 0.0,
            singular_vertices: 0,
            rejected: None,
        };
        match next.field {
            Err(reason) => candidate.rejected = Some(reason),
            Ok(field) => match next.probed.unwrap_or_else(|| self.probe_beside_next(&field, next.gradient_target))? {
                Err(reason) => candidate.rejected = Some(reason),
                Ok((measure, singular, probed)) => {
                    candidate.rms_error_degrees = measure.rms_error_degrees;
                    candidate.max_error_degrees = measure.max_error_degrees;
                    candidate.straight_fraction = measure.straight_fraction();
                    candidate.singular_vertices = singular;
                    let singular_fraction = singular as f64 / self.probed_mesh().vertex_count() as f64;
                    match family_judgement(&measure, self.params.family, singular_fraction).and_then(|judged| self.check_crossing(&probed).map(|()| judged)) {
                        Err(reason) => candidate.rejected = Some(reason),
                        Ok(FamilyJudgement { score, degenerate: Some(reason) }) => {
                            keep_lower(&mut self.fallback, index, score, probed);
                            candidate.rejected = Some(reason);
                        }
                        Ok(FamilyJudgement { score, degenerate: None }) => {
                            candidate.score = Some(score);
                            keep_lower(&mut self.best, index, score, probed);
                        }
                    }
                }
            },
        }
        self.candidates.push(candidate);
        Ok(!self.pending.is_empty() || (!self.guides_queued && !self.has_acceptable()))
    }

    /// Rejects every candidate whose level sets cross those of `field` (one value per vertex of
    /// the mesh) at an area-weighted mean angle below `min_mean_degrees` (in [0°, 90°]): the
    /// start of the second family of a net (Sec. 4.1), which must not run along the first.
    /// Errors: `FieldLength`, `NonFiniteValue`, `ValueOutOfRange` or `ConstantField` for
    /// `field`, `InvalidParameter` for the angle.
    pub fn crossing(mut self, field: &[f64], min_mean_degrees: f64) -> Result<StartSearch, FieldError> {
        crate::field::validate_field(&self.mesh, field)?;
        if !(min_mean_degrees.is_finite() && (0.0..=90.0).contains(&min_mean_degrees)) {
            return Err(FieldError::InvalidParameter { name: "min_mean_degrees", message: format!("must lie in [0°, 90°], got {min_mean_degrees}") });
        }
        let field = match &self.proxy {
            Some(proxy) => carried_to(&self.mesh, field, proxy),
            None => field.to_vec(),
        };
        self.crossing = Some((field, min_mean_degrees));
        Ok(self)
    }

    /// `Err(reason)` when `probed` runs too close to the field of [`Self::crossing`].
    fn check_crossing(&self, probed: &[f64]) -> Result<(), String> {
        let Some((other, min_mean)) = &self.crossing else { return Ok(()) };
        let mesh = self.probed_mesh();
        let (mut weighted, mut area) = (0.0, 0.0);
        for (f, angle) in intersection_angles(mesh, other, probed).into_iter().enumerate() {
            weighted += angle.unwrap_or(0.0) * mesh.face_areas()[f];
            area += mesh.face_areas()[f];
        }
        let mean = weighted / area;
        if mean >= *min_mean {
            Ok(())
        } else {
            Err(format!("crosses the other family at {mean:.1}° on average, below {min_mean}°"))
        }
    }

    /// Every candidate probed so far, in order.
    pub fn candidates(&self) -> &[Candidate] {
        &self.candidates
    }

    /// Vertex count of the coarsening the candidates are probed on; `None` when they are probed
    /// on the mesh itself.
    pub fn proxy_vertex_count(&self) -> Option<usize> {
        self.proxy.as_ref().map(TriMesh::vertex_count)
    }

    /// Index (into [`Self::candidates`]) of the best candidate so far: the best accepted one,
    /// else the best of those rejected only for nearly straight level curves (see the module
    /// notes; its `rejected` says why it would have been).
    pub fn winner(&self) -> Option<usize> {
        self.best.as_ref().or(self.fallback.as_ref()).map(|(i, _, _)| *i)
    }

    /// Probes every remaining candidate.
    pub fn run(&mut self) -> Result<(), FieldError> {
        while self.step()? {}
        Ok(())
    }

    /// The solver for the winner: restarted from the field its short solve reached (carried to
    /// the mesh when probed on a coarsening), with the final weights of `params` (its warm-up is
    /// behind it), ready to be stepped to convergence.
    /// `Err(NoStart)` names every candidate's reason when all were rejected and none of them
    /// only for nearly straight level curves.
    pub fn into_solver(mut self) -> Result<FieldSolver, SearchError> {
        let Some((_, _, probed)) = self.best.take().or(self.fallback.take()) else {
            let reasons = self.candidates.iter().map(|c| format!("{}: {}", c.kind.describe(), c.rejected.as_deref().unwrap_or("not probed"))).collect();
            return Err(SearchError::NoStart { reasons });
        };
        let mut params = self.params.clone();
        params.schedule.clear();
        params.gradient_target = None;
        if let Some(proxy) = self.proxy.take() {
            let field = carried_to(&proxy, &probed, &self.mesh);
            // The stand-in and its probes' solvers are done with: free them before the mesh's
            // solver is built, so that they do not add to the design's peak memory.
            drop(proxy);
            self.solvers = [None, None];
            return FieldSolver::new(&self.mesh, &field, params).map_err(SearchError::Field);
        }
        // A new solver, not a probe's: the design's solve has both cores to itself.
        self.solvers = [None, None];
        FieldSolver::new(&self.mesh, &probed, params).map_err(SearchError::Field)
    }

    fn has_acceptable(&self) -> bool {
        self.best.as_ref().is_some_and(|(_, score, _)| *score <= self.options.acceptable_score)
    }

    fn is_pseudo_geodesic(&self) -> bool {
        matches!(self.params.family, Family::PseudoGeodesic { .. })
    }

    /// The mesh the candidates are probed on.
    fn probed_mesh(&self) -> &TriMesh {
        self.proxy.as_ref().unwrap_or(&self.mesh)
    }

    fn queue_heights(&mut self) {
        let [first, second] = principal_plane(self.probed_mesh());
        let signs: &[bool] = if self.is_pseudo_geodesic() { &[false, true] } else { &[false] };
        for k in 0..self.options.directions {
            let angle = std::f64::consts::PI * k as f64 / self.options.directions as f64;
            let d = first * angle.cos() + second * angle.sin();
            for &negated in signs {
                let sign = if negated { -1.0 } else { 1.0 };
                let field = self.probed_mesh().positions().iter().map(|p| sign * p.dot(&d)).collect();
                self.pending.push_back(Pending::new(StartKind::Height { direction: [d.x, d.y, d.z], negated }, self.screened(field), None));
            }
        }
    }

    /// Queues the guide candidates, their fields built in parallel (each on its own, so the
    /// fields do not depend on the thread count), in the order of sides and angles.
    fn queue_guides(&mut self) {
        self.guides_queued = true;
        let mesh = self.probed_mesh();
        let sides = boundary_segments(mesh, 0, DEFAULT_CORNER_TURN_DEGREES).map_or(0, |s| s.len());
        let theta = self.params.family.theta_degrees();
        let starts: Vec<(usize, f64)> = (0..sides).flat_map(|side| self.options.guide_angles.iter().map(move |&angle| (side, angle))).collect();
        let basis = GuideFieldBasis::new(mesh).map_err(|e| format!("no field from the guides: {e}"));
        let queued: Vec<Pending> = starts
            .par_iter()
            .map(|&(side, start_angle)| {
                let kind = StartKind::Guides { side, start_angle_degrees: start_angle };
                match guide_field(&basis, mesh, self.options.guides, side, start_angle, theta) {
                    Ok((field, target)) => Pending::new(kind, self.screened(field), Some(target)),
                    Err(reason) => Pending::new(kind, Err(reason), None),
                }
            })
            .collect();
        self.pending.extend(queued);
    }

    /// The probe of the current candidate from `field`, with the probe of the first pending
    /// candidate that needs one run beside it on the second solver and kept for that candidate's
    /// step. Both may be abandoned as stalled against the best score accepted before this step
    /// ([`probe`]), so a candidate's outcome does not depend on which of the two it was.
    fn probe_beside_next(&mut self, field: &[f64], gradient_target: Option<f64>) -> Probed {
        let mesh = self.proxy.as_ref().unwrap_or(&self.mesh);
        let (params, options) = (&self.params, &self.options);
        let stall_above = self.best.as_ref().map(|(_, score, _)| options.stall_factor * score).filter(|limit| limit.is_finite());
        let current = ProbeStart { field, gradient_target, stall_above };
        let [first, second] = &mut self.solvers;
        let next = self.pending.iter_mut().find(|pending| pending.field.is_ok() && pending.probed.is_none());
        match next {
            Some(Pending { field: Ok(next_field), gradient_target: next_target, probed, .. }) => {
                let beside = ProbeStart { field: next_field, gradient_target: *next_target, stall_above };
                let (current, beside) = rayon::join(|| probe(first, mesh, params, options, current), || probe(second, mesh, params, options, beside));
                *probed = Some(beside);
                current
            }
            _ => probe(first, mesh, params, options, current),
        }
    }

    /// `field`, or why its start is rejected unsolved ([`Self::reject_straight_start`]).
    fn screened(&self, field: Vec<f64>) -> Result<Vec<f64>, String> {
        self.reject_straight_start(&field).map_or(Ok(field), Err)
    }

    /// A pseudo-geodesic start whose level curves are already nearly all straight (the rulings of
    /// a developable surface, say) stays on them: every P-curve condition holds there in the
    /// limit, so no solve moves it. Rejected without a solve; `None` otherwise.
    fn reject_straight_start(&self, field: &[f64]) -> Option<String> {
        if !self.is_pseudo_geodesic() {
            return None;
        }
        let measure = self.measure(field).ok()?;
        (measure.measured + measure.straight > 0 && measure.straight_fraction() > STRAIGHT_START_FRACTION).then(|| {
            format!("degenerate: {:.0} % of its level curves are straight lines from the start", 100.0 * measure.straight_fraction())
        })
    }

    /// The family measure of `field`'s level curves.
    fn measure(&self, field: &[f64]) -> Result<FamilyAngles, String> {
        level_curve_measure(self.probed_mesh(), field, self.params.family, &self.options)
    }
}

/// Runs the short solve of a candidate from `field` on `mesh` (on the solver in `solver`,
/// restarted, or a new one there) and measures where it ends. With `stall_above`, the probe is
/// abandoned as stalled ([`stall`]) when it has not converged by iteration [`STALL_CHECKS`]`[1]`.
fn probe(solver: &mut Option<FieldSolver>, mesh: &TriMesh, params: &FieldParams, options: &SearchOptions, start: ProbeStart<'_>) -> Probed {
    let mut params = params.clone();
    params.gradient_target = start.gradient_target;
    for stage in &mut params.schedule {
        stage.iterations = stage.iterations.min(options.probe_warm_up);
    }
    params.schedule.retain(|stage| stage.iterations > 0);
    let family = params.family;
    let restarted = match solver.as_mut() {
        Some(solver) => solver.restart(start.field, params),
        // Two probes run side by side.
        None => FieldSolver::new_sharing_cores(mesh, start.field, params).map(|new| *solver = Some(new)),
    };
    if let Err(error) = restarted {
        return match error {
            FieldError::InvalidParameter { .. } => Err(error),
            other => Ok(Err(format!("cannot start: {other}"))),
        };
    }
    // Invariant: set just above.
    let solver = solver.as_mut().expect("solver prepared");
    solver.set_short_solve();
    let short_solve = |solver: &mut FieldSolver, iterations: usize| solver.step(iterations).map_err(|error| format!("short solve failed: {error}"));
    let mut done = 0;
    if let Some(limit) = start.stall_above.filter(|_| options.probe_iterations > STALL_CHECKS[1]) {
        let [first, second] = STALL_CHECKS;
        if let Err(reason) = short_solve(solver, first) {
            return Ok(Err(reason));
        }
        let before = solver.field();
        match short_solve(solver, second - first) {
            Err(reason) => return Ok(Err(reason)),
            Ok(report) if !report.converged => {
                if let Some(reason) = stall(mesh, family, options, &before, &solver.field(), limit) {
                    return Ok(Err(reason));
                }
            }
            Ok(_) => {}
        }
        done = second;
    }
    let report = match short_solve(solver, options.probe_iterations - done) {
        Ok(report) => report,
        Err(reason) => return Ok(Err(reason)),
    };
    let probed = solver.field();
    Ok(level_curve_measure(mesh, &probed, family, options).map(|measure| (measure, report.singular_vertices.len(), probed)))
}

/// Why a probe whose field went from `before` to `after` over the iterations between the
/// [`STALL_CHECKS`] is abandoned: its field moved by less than [`STALL_FIELD_CHANGE`] of its range
/// (largest change of a vertex value) while its level curves score above `limit`; `None` when it
/// is not stalled.
fn stall(mesh: &TriMesh, family: Family, options: &SearchOptions, before: &[f64], after: &[f64], limit: f64) -> Option<String> {
    let (low, high) = before.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(low, high), &f| (low.min(f), high.max(f)));
    let change = before.iter().zip(after).fold(0.0f64, |largest, (b, a)| largest.max((a - b).abs())) / (high - low);
    if !(change < STALL_FIELD_CHANGE) {
        return None;
    }
    let score = level_curve_measure(mesh, after, family, options).ok()?.score();
    let [first, second] = STALL_CHECKS;
    (score > limit).then(|| {
        format!("stalled: its field moved by {:.2} % of its range from iteration {first} to {second}, its level curves scoring {score:.1}", 100.0 * change)
    })
}

/// The start of a probe: the initial field, its `E_grad` target and the score above which a
/// stalled probe is abandoned (see [`probe`]).
#[derive(Clone, Copy)]
struct ProbeStart<'a> {
    field: &'a [f64],
    gradient_target: Option<f64>,
    stall_above: Option<f64>,
}

/// Keeps candidate `index` with its `score` and probed fields in `slot` when the slot is empty or
/// holds a higher score (the earlier candidate wins a tie).
pub(crate) fn keep_lower<T>(slot: &mut Option<(usize, f64, T)>, index: usize, score: f64, fields: T) {
    if slot.as_ref().is_none_or(|(_, kept, _)| score < *kept) {
        *slot = Some((index, score, fields));
    }
}

/// The search's judge: [`level_set_angles`] with the search's count of levels and resampling step.
pub(crate) fn level_curve_measure(mesh: &TriMesh, field: &[f64], family: Family, options: &SearchOptions) -> Result<FamilyAngles, String> {
    level_set_angles(mesh, field, family, options.levels, options.spacing_edges)
}

/// How a probed family is judged: its score (degrees; lower is better): RMS angle error plus a
/// quarter of the largest, plus penalties for nearly straight points and for the fraction of
/// singular vertices; and, for a degenerate pseudo-geodesic family (more than half of its points
/// nearly straight), why it is rejected, though it may still be the fallback of a search that
/// accepts nothing (see the module notes).
pub(crate) struct FamilyJudgement {
    pub score: f64,
    pub degenerate: Option<String>,
}

/// The [`FamilyJudgement`] of a family's curve measure. `Err(reason)` when nothing was measured.
pub(crate) fn family_judgement(measure: &FamilyAngles, family: Family, singular_fraction: f64) -> Result<FamilyJudgement, String> {
    if measure.measured == 0 {
        return Err("no level curve could be measured".into());
    }
    let straight = measure.straight_fraction();
    let degenerate = (matches!(family, Family::PseudoGeodesic { .. }) && straight > MAX_STRAIGHT_FRACTION)
        .then(|| format!("degenerate: {:.0} % of the level curves are nearly straight, where a pseudo-geodesic has no binormal", 100.0 * straight));
    let score = measure.score() + SINGULAR_PENALTY * singular_fraction;
    Ok(FamilyJudgement { score, degenerate })
}

/// What [`search_start`] found: the solver to continue, every candidate and the winner.
pub struct SearchOutcome {
    /// Restarted from the winner's short solve with the final weights: step it to convergence.
    pub solver: FieldSolver,
    pub candidates: Vec<Candidate>,
    /// Index into `candidates`.
    pub winner: usize,
    /// Vertex count of the coarsening the candidates were probed on, if any
    /// ([`StartSearch::proxy_vertex_count`]).
    pub proxy_vertices: Option<usize>,
}

/// Runs the whole search for a field of `params` on `mesh` (see [`StartSearch`]).
pub fn search_start(mesh: &TriMesh, params: FieldParams, options: SearchOptions) -> Result<SearchOutcome, SearchError> {
    let mut search = StartSearch::new(mesh, params, options).map_err(SearchError::Field)?;
    search.run().map_err(SearchError::Field)?;
    let candidates = search.candidates().to_vec();
    let winner = search.winner();
    let proxy_vertices = search.proxy_vertex_count();
    let solver = search.into_solver()?;
    // Invariant: into_solver succeeds only with a winner.
    Ok(SearchOutcome { solver, candidates, winner: winner.unwrap_or(0), proxy_vertices })
}

/// Above this fraction of straight level-curve points a pseudo-geodesic start is rejected unsolved.
const STRAIGHT_START_FRACTION: f64 = 0.9;
/// Above this fraction of nearly straight measured points a pseudo-geodesic family is degenerate.
const MAX_STRAIGHT_FRACTION: f64 = 0.5;
/// Score added per unit fraction of singular vertices (degrees).
const SINGULAR_PENALTY: f64 = 100.0;
/// The iterations of a probe between which its field's change tells whether it has stalled: with
/// the default schedule and [`SearchOptions::probe_warm_up`], 2 and 6 iterations into the final
/// weights.
const STALL_CHECKS: [usize; 2] = [8, 12];
/// Largest change of a vertex value between the [`STALL_CHECKS`], as a fraction of the field's
/// range, of a stalled probe. On the unseen-surface battery the 18 probes this abandons (all on
/// the monkey saddle) moved by 0.04–0.9 %, and their full probes ended at scores of 35–112
/// against winners of 4.7–9.3; the probes whose curves were still improving moved by 1.3–13 %,
/// and some nearly converged ones (scores 3.6–9.6, below the limit) by 0.5–0.9 %.
const STALL_FIELD_CHANGE: f64 = 0.01;


/// Why no start could be found.
#[derive(Clone, Debug, PartialEq)]
pub enum SearchError {
    /// Every candidate was rejected; one reason per candidate.
    NoStart { reasons: Vec<String> },
    Field(FieldError),
}

impl std::fmt::Display for SearchError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SearchError::NoStart { reasons } => write!(f, "no candidate start leads to a family: {}", reasons.join("; ")),
            SearchError::Field(error) => write!(f, "{error}"),
        }
    }
}

impl std::error::Error for SearchError {}

fn validate(options: &SearchOptions) -> Result<(), FieldError> {
    let invalid = |name: &'static str, message: &str| Err(FieldError::InvalidParameter { name, message: message.into() });
    if options.probe_iterations == 0 {
        return invalid("probe_iterations", "must be ≥ 1");
    }
    if options.levels < 2 {
        return invalid("levels", "must be ≥ 2");
    }
    if !(options.spacing_edges.is_finite() && options.spacing_edges > 0.0) {
        return invalid("spacing_edges", "must be finite and > 0");
    }
    if options.directions == 0 {
        return invalid("directions", "must be ≥ 1");
    }
    if options.guides < 2 {
        return invalid("guides", "must be ≥ 2");
    }
    if options.guide_angles.iter().any(|a| !(a.is_finite() && *a > 0.0 && *a < 180.0)) {
        return invalid("guide_angles", "each must lie in (0°, 180°)");
    }
    if (1..100).contains(&options.proxy_vertices) {
        return invalid("proxy_vertices", "must be 0 (no stand-in) or ≥ 100");
    }
    if !options.acceptable_score.is_finite() {
        return invalid("acceptable_score", "must be finite");
    }
    if !(options.stall_factor >= 1.0) {
        return invalid("stall_factor", "must be ≥ 1 (infinity: never abandon a probe)");
    }
    Ok(())
}

/// The two largest principal axes of the vertex positions (unit vectors, each oriented to have a
/// non-negative largest component, so the result does not depend on the eigen solver's signs).
pub(crate) fn principal_plane(mesh: &TriMesh) -> [Vec3; 2] {
    let n = mesh.vertex_count() as f64;
    let mean: Vec3 = mesh.positions().iter().sum::<Vec3>() / n;
    let mut covariance = Matrix3::zeros();
    for p in mesh.positions() {
        let d = p - mean;
        covariance += d * d.transpose();
    }
    let eigen = SymmetricEigen::new(covariance);
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eigen.eigenvalues[b].total_cmp(&eigen.eigenvalues[a]));
    let axis = |k: usize| {
        let v: Vec3 = eigen.eigenvectors.column(order[k]).into();
        if v[v.iamax()] < 0.0 { -v } else { v }
    };
    [axis(0), axis(1)]
}

/// The field of `count` guides from boundary side `side` at `start_angle`, with its `E_grad`
/// target, on `mesh`, the mesh of `basis`; `Err(reason)` when they cannot be traced, cross, or
/// give no field (the basis's own error included).
fn guide_field(basis: &Result<GuideFieldBasis<'_>, String>, mesh: &TriMesh, count: usize, side: usize, start_angle: f64, theta: f64) -> Result<(Vec<f64>, f64), String> {
    let set = trace_guide_set(mesh, count, Some(side), start_angle, theta).map_err(|(_, e)| format!("cannot trace guides: {e}"))?;
    if !intersections(mesh, &set.curves).is_intersection_free() {
        return Err("the traced guides cross".into());
    }
    let points: Vec<_> = set.curves.iter().map(|c| c.points().to_vec()).collect();
    let basis = basis.as_ref().map_err(Clone::clone)?;
    let guided = basis.field(&points, &GuideCurveOptions::default()).map_err(|e| format!("no field from the guides: {e}"))?;
    Ok((guided.field, guided.gradient_target))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surfaces::hall_roof;

    /// A candidate rejected without a solve between two that need one: the first step's probe
    /// runs the third candidate's beside its own (rather than alone), and that probe scores what
    /// a probe of the same start on a solver of its own scores.
    #[test]
    fn a_probe_runs_beside_the_next_candidate_that_needs_a_solve() {
        let mesh = hall_roof(600).into_mesh().expect("a valid roof");
        let params = FieldParams::pseudo_geodesic(60.0);
        let options = SearchOptions::default();
        let mut search = StartSearch::new(&mesh, params.clone(), options.clone()).expect("a search");
        assert!(search.proxy.is_none(), "probed on the mesh itself");
        search.pending[1].field = Err("rejected for the test".to_string());
        let third = search.pending[2].field.clone().expect("a height field");

        search.step().expect("the first candidate probed");
        assert!(search.pending[0].probed.is_none(), "the unsolved candidate got a probe");
        assert!(search.pending[1].probed.is_some(), "the third candidate's probe did not run beside the first's");
        search.run().expect("the search");
        assert_eq!(search.candidates()[1].rejected.as_deref(), Some("rejected for the test"));

        let alone = ProbeStart { field: &third, gradient_target: None, stall_above: None };
        let (measure, singular, _) = probe(&mut None, &mesh, &params, &options, alone).expect("no invalid parameter").expect("probed");
        let singular_fraction = singular as f64 / mesh.vertex_count() as f64;
        let judged = family_judgement(&measure, params.family, singular_fraction).expect("judged");
        let candidate = &search.candidates()[2];
        assert_eq!(candidate.score.map(f64::to_bits), Some(judged.score.to_bits()), "{candidate:?}");
        assert_eq!(candidate.rms_error_degrees.to_bits(), measure.rms_error_degrees.to_bits());
    }
}
