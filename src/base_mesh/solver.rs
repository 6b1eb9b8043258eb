//! The stepwise base-mesh optimiser (Sec. 3.5, and Eq. 21 for torsion-free nodes), stepped like
//! [`crate::field::FieldSolver`]: create, step, inspect, take the net and its strips.

use super::error::BaseMeshError;
use super::net_mesh::NetMesh;
use super::node_torsion::NodeRuling;
use super::params::{BaseMeshParams, BaseMeshWeights};
use super::problem::{vec3, Anchor, BaseMeshProblem, CurveRows};
use super::report::{target_family, BaseMeshReport, Measures, Reference};
use super::start::{initialise_auxiliaries, mirror_degrees, oriented_target};
use super::strips::FamilyStrips;
use crate::field::Family;
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{LeastSquaresProblem, LevenbergMarquardt};
use crate::strips::{StripPattern, SurfaceProjector};
use rayon::prelude::*;

/// Optimises a net's vertices so that its rows and columns form the asked families on (near) a
/// reference surface, optionally with torsion-free nodes: then in two stages (unless
/// [`BaseMeshParams::families_first`] is off), the families alone until they settle, then with
/// the rows of Eq. 21 (the rulings started from the net's strips, [`super::node_torsion`]).
///
/// Works on a copy of the net scaled to mean segment length 1 (the weights are meant for that
/// scale); everything handed back is in the caller's units.
pub struct BaseMeshSolver {
    /// The net as given (the caller's units), for saving the session.
    pub(super) given: NetMesh,
    pub(super) reference: Reference,
    /// Internal lengths = caller lengths × `scale`.
    pub(super) scale: f64,
    pub(super) problem: BaseMeshProblem,
    pub(super) lm: LevenbergMarquardt,
    pub(super) params: BaseMeshParams,
    pub(super) x: Vec<f64>,
    pub(super) targets_degrees: Vec<f64>,
    pub(super) iterations: usize,
    pub(super) converged: bool,
    pub(super) initial: BaseMeshReport,
    pub(super) last_report: BaseMeshReport,
    pub(super) measures: Measures,
    /// Vertices found past the reference's boundary once: their tangential offset is held from
    /// then on (released, they would slide out again, and the solve would cycle).
    pub(super) held: Vec<bool>,
}

impl BaseMeshSolver {
    /// Prepares the optimisation of `net` toward `params.families` (rows, columns, and a web's
    /// diagonals) near
    /// `reference`. Each pseudo-geodesic family is held at `θ` or `180° − θ`, whichever its
    /// polylines are nearer to as given (see [`BaseMeshReport::targets_degrees`]).
    ///
    /// Errors: `InvalidParameter` naming the parameter (also when the net's family count is not
    /// the parameters'); `NothingToOptimise` when no vertex is
    /// inside a polyline of three or more vertices; `Solver` if the problem cannot be set up.
    pub fn new(net: &NetMesh, reference: &TriMesh, mut params: BaseMeshParams) -> Result<BaseMeshSolver, BaseMeshError> {
        params.validate()?;
        params.families.iter_mut().for_each(|f| *f = f.by_name());
        if net.family_count() != params.families.len() {
            let message = format!("{} families for a net of {} (rows, columns{})", params.families.len(), net.family_count(), if net.family_count() == 3 { ", diagonals" } else { "" });
            return Err(BaseMeshError::InvalidParameter { name: "families", message });
        }
        if !has_inner_vertex(net) {
            return Err(BaseMeshError::NothingToOptimise);
        }
        let reference = Reference::new(reference);
        let scale = unit_scale(net);
        let given: Vec<f64> = params.families.iter().map(|f| f.theta_degrees()).collect();
        let as_given = reference.family_angles(net, &params.families, &given);
        let mirrored = reference.family_angles(net, &params.families, &params.families.iter().copied().map(mirror_degrees).collect::<Vec<_>>());
        let targets_degrees: Vec<f64> = (0..params.families.len()).map(|k| oriented_target(params.families[k], &as_given[k], &mirrored[k])).collect();
        let measures = reference.measure(net, &params.families, &targets_degrees);
        let Start { problem, lm, x, held, energy } = Start::new(&reference, net, scale, &params, &targets_degrees, &measures)?;
        let mut report = BaseMeshReport::new(&measures, &targets_degrees, params.tolerance_degrees);
        report.energy = energy;
        Ok(BaseMeshSolver {
            given: net.clone(),
            reference,
            scale,
            problem,
            lm,
            params,
            x,
            targets_degrees,
            iterations: 0,
            converged: false,
            initial: report.clone(),
            last_report: report,
            measures,
            held,
        })
    }

    /// Replaces the weights of a session that has not iterated yet: the same as creating it with
    /// them in [`BaseMeshParams::weights`] (the paper's Table 3 varies them from figure to figure).
    /// Errors: `InvalidParameter` naming the weight out of range (as [`BaseMeshParams::validate`]),
    /// or `weights` once an iteration has run (the net has moved under the old ones).
    pub fn set_weights(&mut self, weights: BaseMeshWeights) -> Result<(), BaseMeshError> {
        if self.iterations > 0 {
            let message = format!("are set before the first iteration; this session has run {}", self.iterations);
            return Err(BaseMeshError::InvalidParameter { name: "weights", message });
        }
        let params = BaseMeshParams { weights, ..self.params.clone() };
        params.validate()?;
        let start = Start::new(&self.reference, &self.given, self.scale, &params, &self.targets_degrees, &self.measures)?;
        (self.problem, self.lm, self.x, self.held, self.params) = (start.problem, start.lm, start.x, start.held, params);
        self.initial.energy = start.energy;
        self.last_report.energy = start.energy;
        Ok(())
    }

    /// Runs at most `max_iterations` Levenberg–Marquardt iterations (the reference's closest
    /// points re-found before each) and reports the state.
    pub fn step(&mut self, max_iterations: usize) -> Result<BaseMeshReport, BaseMeshError> {
        rayon::scope(|_| self.run(max_iterations))
    }

    fn run(&mut self, max_iterations: usize) -> Result<BaseMeshReport, BaseMeshError> {
        let mut ran = 0;
        let mut energy = self.last_report.energy;
        while ran < max_iterations && !self.converged {
            let vertices = self.problem.net().vertex_count();
            let points = self.x[..3 * vertices].par_chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2]));
            self.problem.anchors = anchors(&self.reference, points, self.scale, &mut self.held, Some(&self.measures));
            let outcome = self.lm.iterate(&self.problem, &mut self.x)?;
            ran += 1;
            self.iterations += 1;
            energy = outcome.energy_after;
            let decrease = outcome.energy_before - outcome.energy_after;
            let settled = outcome.converged.is_some() || !outcome.accepted || decrease <= self.params.relative_tolerance * outcome.energy_before;
            if settled && self.params.torsion_free && !self.problem.torsion_free {
                // The families are met: now the nodes, from the strips of the net as it stands.
                self.measures = self.reference.measure(&self.net(), &self.params.families, &self.targets_degrees);
                let (problem, lm, x) = stage(&self.reference, self.scaled_net(), self.scale, &self.params, &self.targets_degrees, true, &self.measures, &mut self.held)?;
                (self.problem, self.lm, self.x) = (problem, lm, x);
            } else {
                self.converged = settled;
            }
        }
        self.measures = self.reference.measure(&self.net(), &self.params.families, &self.targets_degrees);
        let mut report = BaseMeshReport::new(&self.measures, &self.targets_degrees, self.params.tolerance_degrees);
        report.iterations = self.iterations;
        report.step_iterations = ran;
        report.converged = self.converged;
        report.torsion_free_stage = self.problem.torsion_free;
        report.energy = energy;
        self.last_report = report;
        Ok(self.last_report.clone())
    }

    /// The report of the last `step` (or of the start).
    pub fn report(&self) -> &BaseMeshReport {
        &self.last_report
    }

    /// The report of the net as given, before any iteration.
    pub fn initial_report(&self) -> &BaseMeshReport {
        &self.initial
    }

    /// The net as given to [`BaseMeshSolver::new`], in the caller's units: what the optimisation
    /// started from.
    pub fn given_net(&self) -> &NetMesh {
        &self.given
    }

    /// The net at the current positions, in the caller's units.
    pub fn net(&self) -> NetMesh {
        self.problem.net().with_positions(self.positions())
    }

    /// The current vertex positions, in the caller's units.
    pub fn positions(&self) -> Vec<Vec3> {
        (0..self.problem.net().vertex_count()).map(|v| vec3(&self.x, 3 * v) / self.scale).collect()
    }

    /// The node at every vertex inside a row and a column: its ruling angle and axis, from the
    /// strips of the current net.
    pub fn nodes(&self) -> &[NodeRuling] {
        &self.measures.nodes
    }

    /// Each family's rectifying strips of `width` on the current net (the developable strip of
    /// planar quads fitted to the common node rulings, [`super::node_torsion`]), judged against
    /// the reference at each family's target angle with `tolerance_degrees` (a constant-slope
    /// family's strips each at their own mean angle).
    /// Errors: `InvalidParameter` for a width or tolerance that is not finite and positive.
    pub fn strips(&self, width: f64, tolerance_degrees: f64) -> Result<Vec<StripPattern>, BaseMeshError> {
        self.with_strips(width, tolerance_degrees, |family| (0..self.params.families.len()).map(|k| family.build(k, &self.measures.rulings[k], self.strip_theta(k))).collect())
    }

    /// Family `k`'s strips (0: rows, 1: columns, 2: a web's diagonals) as [`Self::strips`]
    /// builds them. Errors: `InvalidParameter` for `k` past the last family, or as [`Self::strips`].
    pub fn family_strips(&self, k: usize, width: f64, tolerance_degrees: f64) -> Result<StripPattern, BaseMeshError> {
        let count = self.params.families.len();
        if k >= count {
            return Err(BaseMeshError::InvalidParameter { name: "k", message: format!("this net has families 0 to {}, got {k}", count - 1) });
        }
        self.with_strips(width, tolerance_degrees, |family| family.build(k, &self.measures.rulings[k], self.strip_theta(k)))
    }

    /// Checks the strip parameters and hands `build` the strip builder of the current net.
    fn with_strips<T>(&self, width: f64, tolerance_degrees: f64, build: impl FnOnce(&FamilyStrips) -> T) -> Result<T, BaseMeshError> {
        if !(width.is_finite() && width > 0.0) {
            return Err(BaseMeshError::InvalidParameter { name: "width", message: format!("must be finite and > 0, got {width}") });
        }
        if !(tolerance_degrees.is_finite() && tolerance_degrees > 0.0 && tolerance_degrees < 180.0) {
            return Err(BaseMeshError::InvalidParameter { name: "tolerance_degrees", message: format!("must lie in (0°, 180°), got {tolerance_degrees}") });
        }
        let net = self.net();
        let projector = SurfaceProjector::new(&self.reference.mesh);
        Ok(build(&FamilyStrips { net: &net, reference: &self.reference, projector: &projector, width, tolerance_degrees }))
    }

    /// The angle family `k`'s strips are judged at: its target, none for a constant slope.
    fn strip_theta(&self, k: usize) -> Option<f64> {
        match self.params.families[k] {
            Family::ConstantSlope { .. } => None,
            family => Some(target_family(family, self.targets_degrees[k]).theta_degrees()),
        }
    }

    pub fn params(&self) -> &BaseMeshParams {
        &self.params
    }

    /// Each family's target along its polylines' direction (see [`BaseMeshReport::targets_degrees`]).
    pub fn targets_degrees(&self) -> &[f64] {
        &self.targets_degrees
    }

    pub fn iterations(&self) -> usize {
        self.iterations
    }

    pub fn is_converged(&self) -> bool {
        self.converged
    }

    fn scaled_net(&self) -> NetMesh {
        self.problem.net().with_positions((0..self.problem.net().vertex_count()).map(|v| vec3(&self.x, 3 * v)).collect())
    }
}

/// A vertex whose offset from its closest reference point leans more than 30° off the normal
/// there has slid past the reference's boundary (inside, the offset is along the normal).
const BEYOND_BOUNDARY: f64 = 0.5;
/// Offsets below this (in mean segment lengths) are rounding: a vertex on the reference.
const MIN_OFFSET: f64 = 1e-6;

/// Whether some vertex of `net` lies inside a polyline: has a curve to hold to its family.
pub(super) fn has_inner_vertex(net: &NetMesh) -> bool {
    (0..net.vertex_count()).any(|v| (0..net.family_count()).any(|k| net.along(v, k).inner().is_some()))
}

/// Internal lengths per caller length: the inverse of the mean segment length of `net` (1 for a
/// degenerate mean).
pub(super) fn unit_scale(net: &NetMesh) -> f64 {
    let segments: Vec<f64> = (0..net.family_count()).flat_map(|k| net.segments(k).map(|[a, b]| (net.positions()[b as usize] - net.positions()[a as usize]).norm()).collect::<Vec<_>>()).collect();
    let mean = segments.iter().sum::<f64>() / segments.len().max(1) as f64;
    if mean > 0.0 && mean.is_finite() {
        1.0 / mean
    } else {
        1.0
    }
}

/// The first stage of a session: its problem on the net scaled to mean segment 1, the solver, the
/// start of the variables, the vertices held past the reference's boundary and the energy there.
struct Start {
    problem: BaseMeshProblem,
    lm: LevenbergMarquardt,
    x: Vec<f64>,
    held: Vec<bool>,
    energy: f64,
}

impl Start {
    /// The first stage on `net` (the caller's units, scaled by `scale`) as measured in `measures`.
    fn new(reference: &Reference, net: &NetMesh, scale: f64, params: &BaseMeshParams, targets_degrees: &[f64], measures: &Measures) -> Result<Start, BaseMeshError> {
        let scaled = net.with_positions(net.positions().iter().map(|p| p * scale).collect());
        let mut held = vec![false; net.vertex_count()];
        let torsion_free = params.torsion_free && !params.families_first;
        let (problem, lm, x) = stage(reference, scaled, scale, params, targets_degrees, torsion_free, measures, &mut held)?;
        let energy = energy(&problem, &x);
        Ok(Start { problem, lm, x, held, energy })
    }
}

/// The problem, its solver and its start for the scaled `net`: the families alone, or with
/// torsion-free nodes (rulings started from the strips of `measures`).
fn stage(
    reference: &Reference,
    net: NetMesh,
    scale: f64,
    params: &BaseMeshParams,
    targets_degrees: &[f64],
    torsion_free: bool,
    measures: &Measures,
    held: &mut [bool],
) -> Result<(BaseMeshProblem, LevenbergMarquardt, Vec<f64>), BaseMeshError> {
    let (problem, lm) = assemble(reference, net, scale, params, targets_degrees, torsion_free, held)?;
    let mut x = vec![0.0; problem.variable_count()];
    for (v, p) in problem.net().positions().iter().enumerate() {
        x[3 * v..3 * v + 3].copy_from_slice(p.as_slice());
    }
    initialise_auxiliaries(&problem, &problem.anchors, &measures.rulings, &mut x);
    Ok((problem, lm, x))
}

/// The problem on the scaled `net` (its positions the pull target) and its solver, without a
/// start: the families alone, or with torsion-free nodes.
pub(super) fn assemble(
    reference: &Reference,
    net: NetMesh,
    scale: f64,
    params: &BaseMeshParams,
    targets_degrees: &[f64],
    torsion_free: bool,
    held: &mut [bool],
) -> Result<(BaseMeshProblem, LevenbergMarquardt), BaseMeshError> {
    let curves: Vec<CurveRows> = (0..params.families.len()).map(|k| CurveRows::new(params.families[k], targets_degrees[k])).collect();
    let anchors = anchors(reference, net.positions().par_iter().copied(), scale, held, None);
    let problem = BaseMeshProblem::new(net, curves, torsion_free, params.weights, anchors);
    let lm = LevenbergMarquardt::new(&problem, params.lm.clone())?;
    Ok((problem, lm))
}

/// The reference's closest point and normal for every one of the scaled net's `points` (in
/// parallel, deterministic), taken from `measured` where a vertex has not moved since; vertices
/// past the reference's boundary are marked in `held` for good.
fn anchors(reference: &Reference, points: impl IndexedParallelIterator<Item = Vec3>, scale: f64, held: &mut [bool], measured: Option<&Measures>) -> Vec<Anchor> {
    let mut anchors: Vec<Anchor> = points
        .enumerate()
        .map(|(v, p)| {
            let query = p / scale;
            let (point, normal, _) = measured.and_then(|m| m.closest_as_measured(v, &query)).unwrap_or_else(|| reference.closest(&query));
            let point = point * scale;
            let offset = p - point;
            let along = offset.dot(&normal);
            let beyond_boundary = offset.norm() > MIN_OFFSET && (offset - normal * along).norm() > BEYOND_BOUNDARY * offset.norm();
            Anchor { point, normal, beyond_boundary }
        })
        .collect();
    for (anchor, held) in anchors.iter_mut().zip(held.iter_mut()) {
        *held |= anchor.beyond_boundary;
        anchor.beyond_boundary = *held;
    }
    anchors
}

/// `E(x)`, the weighted sum of squared residuals.
fn energy(problem: &BaseMeshProblem, x: &[f64]) -> f64 {
    let mut total = 0.0;
    let mut residuals = Vec::new();
    for b in 0..problem.block_count() {
        residuals.clear();
        residuals.resize(problem.block_residual_count(b), 0.0);
        problem.evaluate_block(b, x, &mut residuals, None);
        total += residuals.iter().map(|r| r * r).sum::<f64>();
    }
    total
}
