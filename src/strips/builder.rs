//! The strip pipeline of Sec. 3.4 for each level curve:
//! 1. binormal strip: rounds of (project onto the surface, freeze normals and side vectors, run
//!    Levenberg–Marquardt on Eq. 8–9 with surface proximity and fairness);
//! 2. rectifying strip: rulings initialised in the outer bisecting planes from the version-1 model
//!    (Fig. 19), then Levenberg–Marquardt on Eq. 16–17 with Eq. 8 on the quad normals, the
//!    fairness regulariser and a ruling anchor, and a final round with both at weight 0 (the
//!    surface normals refreshed halfway);
//! 3. boundaries at the requested width, flat unrolling, Table 4 metrics and warnings.

use rayon::prelude::*;

use super::error::{StripError, StripWarning};
use super::frenet::{initial_rulings, unit_edges};
use super::metrics::{PatternMetrics, StripMetrics, StripShape};
use super::params::{StripParams, StripWeights, MAX_STRIP_ITERATIONS, MAX_STRIP_ROUNDS};
use super::problem::{binormal, position, ruling, vec3, StripProblem};
use super::strip::{RectifyingStrip, SkippedCurve, StripPattern};
use super::surface_distance::SurfaceProjector;
use super::unrolling::unroll;
use super::verdict::Verdict;
use crate::curves::LevelCurve;
use crate::mesh::{TriMesh, Vec3};
use crate::solver::{LeastSquaresProblem, LevenbergMarquardt, LmOptions};

/// Below this `sin α` a ruling is taken as tangent to the polyline (the strip would be unbounded).
const MIN_SINE: f64 = 1e-6;

/// Builds a rectifying strip on every curve (in parallel; the result does not depend on the
/// number of threads). Curves that cannot carry a strip are listed in `skipped` with the reason.
///
/// Curves are expected to run along `∇F × n`, as [`crate::curves::extract_level_curves`] orients
/// them: the signed angle (Eq. 8) then asks for the family θ of the field; a reversed curve is
/// pulled towards the mirror family 180° − θ. Resample them first
/// ([`LevelCurve::resampled`]) to the vertex spacing the strips should have.
pub fn rectifying_strips(mesh: &TriMesh, curves: &[LevelCurve], params: &StripParams) -> Result<StripPattern, StripError> {
    validate(params)?;
    let projector = SurfaceProjector::new(mesh);
    let (low, high) = mesh.bounding_box();
    let diagonal = (high - low).norm().max(f64::MIN_POSITIVE);
    let results: Vec<Result<RectifyingStrip, Vec<StripWarning>>> = curves
        .par_iter()
        .enumerate()
        .map(|(index, curve)| build_strip(&projector, index, curve, params, diagonal))
        .collect();
    let mut strips = Vec::new();
    let mut skipped = Vec::new();
    for (curve, result) in results.into_iter().enumerate() {
        match result {
            Ok(strip) => strips.push(strip),
            Err(warnings) => skipped.push(SkippedCurve { curve, warnings }),
        }
    }
    let metrics = PatternMetrics::from_strips(strips.iter().map(|s| &s.metrics));
    let verdict = Verdict::judge(&strips, params.tolerance_degrees);
    Ok(StripPattern { strips, skipped, metrics, verdict })
}

fn validate(params: &StripParams) -> Result<(), StripError> {
    if !(params.width.is_finite() && params.width > 0.0) {
        return Err(StripError::InvalidWidth { width: params.width });
    }
    let theta = params.theta_degrees;
    if !(theta.is_finite() && (0.0..=180.0).contains(&theta)) {
        return Err(StripError::InvalidTheta { theta_degrees: theta });
    }
    let tolerance = params.tolerance_degrees;
    if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 180.0) {
        return Err(StripError::InvalidParameter { name: "tolerance_degrees", message: format!("must lie in (0°, 180°), got {tolerance}") });
    }
    let w = &params.weights;
    let weights = [
        ("weights.angle", w.angle),
        ("weights.binormal", w.binormal),
        ("weights.surface", w.surface),
        ("weights.slide", w.slide),
        ("weights.fair", w.fair),
        ("weights.planarity", w.planarity),
        ("weights.ruling_anchor", w.ruling_anchor),
    ];
    for (name, value) in weights {
        if !(value.is_finite() && value >= 0.0) {
            return Err(StripError::InvalidParameter { name, message: format!("must be finite and ≥ 0, got {value}") });
        }
    }
    if w.planarity <= 0.0 {
        return Err(StripError::InvalidParameter { name: "weights.planarity", message: "must be > 0".into() });
    }
    if params.binormal_rounds > MAX_STRIP_ROUNDS {
        let message = format!("must be at most {MAX_STRIP_ROUNDS}, got {}", params.binormal_rounds);
        return Err(StripError::InvalidParameter { name: "binormal_rounds", message });
    }
    let counts = [
        ("iterations_per_round", params.iterations_per_round),
        ("final_iterations", params.final_iterations),
        ("polish_iterations", params.polish_iterations),
    ];
    for (name, value) in counts {
        if value > MAX_STRIP_ITERATIONS {
            return Err(StripError::InvalidParameter { name, message: format!("must be at most {MAX_STRIP_ITERATIONS}, got {value}") });
        }
    }
    Ok(())
}

/// The strip on one curve, or the warnings that prevented it.
fn build_strip(
    projector: &SurfaceProjector,
    index: usize,
    curve: &LevelCurve,
    params: &StripParams,
    diagonal: f64,
) -> Result<RectifyingStrip, Vec<StripWarning>> {
    let mut warnings = Vec::new();
    if !curve.singular_vertices.is_empty() {
        warnings.push(StripWarning::SingularVertices { vertices: curve.singular_vertices.clone() });
    }
    let mut points = curve.points.clone();
    if curve.closed && points.len() >= 3 {
        points.push(points[0]);
        warnings.push(StripWarning::ClosedCurveOpened);
    }
    let skip = |mut warnings: Vec<StripWarning>, warning| {
        warnings.push(warning);
        Err(warnings)
    };
    if points.len() < 3 {
        return skip(warnings, StripWarning::TooFewPoints { points: points.len() });
    }
    if !points.iter().all(|p| p.iter().all(|x| x.is_finite())) {
        return skip(warnings, StripWarning::NonFiniteInput);
    }
    let length: f64 = points.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
    if let Some(segment) = points.windows(2).position(|w| (w[1] - w[0]).norm() <= 1e-12 * length) {
        return skip(warnings, StripWarning::ZeroLengthSegment { segment });
    }
    let mut optimiser = match StripOptimiser::new(projector, &points, params) {
        Ok(optimiser) => optimiser,
        Err(message) => return skip(warnings, StripWarning::SolverFailed { message }),
    };
    if let Err(message) = optimiser.run(params) {
        return skip(warnings, StripWarning::SolverFailed { message });
    }
    let strip = optimiser.finish(index, curve.level, params, diagonal, warnings);
    if strip.is_finite() {
        Ok(strip)
    } else {
        skip(strip.warnings, StripWarning::SolverFailed { message: "the optimisation produced non-finite values".into() })
    }
}

/// The optimisation state of one strip.
struct StripOptimiser<'a> {
    projector: &'a SurfaceProjector<'a>,
    problem: StripProblem,
    lm: LevenbergMarquardt,
    x: Vec<f64>,
    n: usize,
}

impl<'a> StripOptimiser<'a> {
    fn new(projector: &'a SurfaceProjector<'a>, points: &[Vec3], params: &StripParams) -> Result<Self, String> {
        let n = points.len();
        let mean_edge = points.windows(2).map(|w| (w[1] - w[0]).norm()).sum::<f64>() / (n - 1) as f64;
        let weights = StripWeights { planarity: 0.0, ruling_anchor: 0.0, ..params.weights };
        let problem = StripProblem::new(n, params.theta_degrees, mean_edge, weights);
        let lm = LevenbergMarquardt::new(&problem, LmOptions::default()).map_err(|e| e.to_string())?;
        let mut optimiser = StripOptimiser { projector, x: vec![0.0; problem.variable_count()], problem, lm, n };
        for (i, p) in points.iter().enumerate() {
            optimiser.set(position(i), p);
        }
        optimiser.problem.frozen.rulings = vec![Vec3::zeros(); n];
        optimiser.refresh();
        // Binormals start on the target cone, on the side of u the signed angle asks for.
        let (sin, cos) = params.theta_degrees.to_radians().sin_cos();
        for i in 0..n {
            let b = optimiser.problem.frozen.normals[i] * cos + optimiser.problem.frozen.sides[i] * sin;
            optimiser.set(binormal(i), &b);
        }
        Ok(optimiser)
    }

    fn set(&mut self, start: usize, v: &Vec3) {
        self.x[start..start + 3].copy_from_slice(v.as_slice());
    }

    fn positions(&self) -> Vec<Vec3> {
        (0..self.n).map(|i| vec3(&self.x, position(i))).collect()
    }

    /// Projects the vertices onto the surface and freezes normals, side vectors and anchors.
    fn refresh(&mut self) {
        let points = self.positions();
        let frozen = &mut self.problem.frozen;
        frozen.normals.clear();
        frozen.anchors.clear();
        frozen.sides.clear();
        for (i, p) in points.iter().enumerate() {
            // Finite positions (checked on input, and LM never accepts a non-finite step) always project.
            let surface = self.projector.project(p).expect("finite position");
            let tangent = points[(i + 1).min(self.n - 1)] - points[i.saturating_sub(1)];
            let side = surface.normal.cross(&tangent).try_normalize(0.0);
            let previous = frozen.sides.last().copied().unwrap_or_else(|| any_perpendicular(&surface.normal));
            frozen.sides.push(side.unwrap_or(previous));
            frozen.normals.push(surface.normal);
            frozen.anchors.push(surface.point);
        }
        frozen.quad_normals.clear();
        frozen.quad_sides.clear();
        for (j, e) in unit_edges(&points).iter().enumerate() {
            let normal = (frozen.normals[j] + frozen.normals[j + 1]).try_normalize(0.0).unwrap_or(frozen.normals[j]);
            let side = normal.cross(e).try_normalize(0.0).unwrap_or(frozen.sides[j]);
            frozen.quad_normals.push(normal);
            frozen.quad_sides.push(side);
        }
    }

    /// Up to `iterations` Levenberg–Marquardt iterations with the current weights.
    fn iterate(&mut self, iterations: usize) -> Result<(), String> {
        self.lm.reset_damping();
        for _ in 0..iterations {
            let outcome = self.lm.iterate(&self.problem, &mut self.x).map_err(|e| e.to_string())?;
            if outcome.converged.is_some() || !outcome.accepted {
                break;
            }
        }
        Ok(())
    }

    fn run(&mut self, params: &StripParams) -> Result<(), String> {
        for round in 0..params.binormal_rounds {
            if round > 0 {
                self.refresh();
            }
            self.iterate(params.iterations_per_round)?;
        }
        self.refresh();
        self.initialise_rulings();
        self.problem.weights = params.weights;
        self.iterate(params.iterations_per_round)?;
        self.problem.weights = StripWeights { fair: 0.0, ruling_anchor: 0.0, ..params.weights };
        // The final round in two halves, the surface normals the quads are held to refreshed
        // before each: the centre line moves in it, most in the first half.
        let first = params.final_iterations / 2;
        for iterations in [first, params.final_iterations - first] {
            self.refresh();
            self.iterate(iterations)?;
        }
        self.polish(params)
    }

    /// Holds the positions where they are (`slide` anchors at the current vertices, every other
    /// term off but Eq. 16–17): a consistent system, since rulings alone can make every quad planar
    /// for a fixed polyline (Sec. 3.4: successive reflection), on which Levenberg–Marquardt
    /// converges fast to exact planarity and straightness.
    fn polish(&mut self, params: &StripParams) -> Result<(), String> {
        self.problem.frozen.anchors = self.positions();
        let off = StripWeights { angle: 0.0, binormal: 0.0, surface: 0.0, slide: 0.0, fair: 0.0, planarity: 0.0, ruling_anchor: 0.0 };
        self.problem.weights = StripWeights { slide: 1.0, planarity: params.weights.planarity, ..off };
        self.iterate(params.polish_iterations)
    }

    /// Rulings from the version-1 model (averaged `L_i`, `L_{i+1}` in `R_i`) and quad normals
    /// `N_{j,j+1} ∥ ê_j × (d_j + d_{j+1})`.
    fn initialise_rulings(&mut self) {
        let points = self.positions();
        let binormals: Vec<Vec3> = (0..self.n).map(|i| vec3(&self.x, binormal(i)).try_normalize(0.0).unwrap_or_else(Vec3::z)).collect();
        let rulings = initial_rulings(&points, &binormals);
        for (i, d) in rulings.iter().enumerate() {
            self.set(ruling(i), d);
        }
        for (j, e) in unit_edges(&points).iter().enumerate() {
            let normal = e.cross(&(rulings[j] + rulings[j + 1])).try_normalize(0.0).unwrap_or_else(|| any_perpendicular(e));
            let start = self.problem.edge_normal(j);
            self.set(start, &normal);
        }
        self.problem.frozen.rulings = rulings;
    }

    fn finish(self, curve: usize, level: f64, params: &StripParams, diagonal: f64, warnings: Vec<StripWarning>) -> RectifyingStrip {
        let centre = self.positions();
        let binormals: Vec<Vec3> = (0..self.n).map(|i| vec3(&self.x, binormal(i)).try_normalize(0.0).unwrap_or_else(Vec3::zeros)).collect();
        let rulings: Vec<Vec3> = (0..self.n)
            .map(|i| {
                let d = vec3(&self.x, ruling(i)).try_normalize(0.0).unwrap_or(binormals[i]);
                if d.dot(&binormals[i]) < 0.0 { -d } else { d }
            })
            .collect();
        let lines = StripLines { curve, level, centre, binormals, rulings };
        strip_with_rulings(self.projector, lines, params.width, params.theta_degrees, diagonal, warnings)
    }
}

/// A strip's centre line with a binormal and a unit ruling per vertex, before it is given a width.
pub(crate) struct StripLines {
    /// Index of the curve it is built on, and that curve's level value.
    pub curve: usize,
    pub level: f64,
    pub centre: Vec<Vec3>,
    pub binormals: Vec<Vec3>,
    pub rulings: Vec<Vec3>,
}

/// The strip of `width` on `lines` (Fig. 20): boundaries `c_i ± s_i d_i` with
/// `s_i = width / (2 sin α_i)`, its flat unrolling and its Table 4 metrics against the surface of
/// `projector` for the family of `theta_degrees`. Warns of a width the quads cannot carry and of
/// flipped quads.
pub(crate) fn strip_with_rulings(
    projector: &SurfaceProjector,
    lines: StripLines,
    width: f64,
    theta_degrees: f64,
    diagonal: f64,
    mut warnings: Vec<StripWarning>,
) -> RectifyingStrip {
    let StripLines { curve, level, centre, binormals, rulings } = lines;
    let n = centre.len();
    let edges = unit_edges(&centre);
    // Ruling offsets of unit distance from the centre line in the flat strip: d / sin α.
    let unit_offsets: Vec<Vec3> = (0..n)
        .map(|i| {
            let around = [i.checked_sub(1), (i < n - 1).then_some(i)];
            let sines: Vec<f64> = around.iter().flatten().map(|&j| rulings[i].cross(&edges[j]).norm()).collect();
            let sine = sines.iter().sum::<f64>() / sines.len() as f64;
            rulings[i] / sine.max(MIN_SINE)
        })
        .collect();
    let half = 0.5 * width;
    let max_width = (0..n - 1)
        .map(|j| {
            let spread = (unit_offsets[j + 1] - unit_offsets[j]).dot(&edges[j]).abs();
            let length = (centre[j + 1] - centre[j]).norm();
            if spread > 0.0 { 2.0 * length / spread } else { f64::INFINITY }
        })
        .fold(f64::INFINITY, f64::min);
    if width >= max_width {
        warnings.push(StripWarning::WidthTooLarge { width, max_width });
    }
    let offsets: Vec<Vec3> = unit_offsets.iter().map(|o| o * half).collect();
    let unrolling = unroll(&centre, &offsets);
    // A vertex that cannot be projected (never expected: LM keeps x finite) gets an infinite
    // distance, which `is_finite` turns into a skip rather than a wrong metric.
    let shape = StripShape { centre: &centre, rulings: &rulings, offsets: &offsets, unrolling: &unrolling, width };
    let metrics = StripMetrics::on_surface(projector, &shape, theta_degrees, diagonal);
    if metrics.flipped_quads > 0 {
        warnings.push(StripWarning::FlippedQuads { count: metrics.flipped_quads });
    }
    RectifyingStrip {
        curve,
        level,
        left: centre.iter().zip(&offsets).map(|(c, o)| c + o).collect(),
        right: centre.iter().zip(&offsets).map(|(c, o)| c - o).collect(),
        centre,
        binormals,
        rulings,
        unrolling,
        metrics,
        warnings,
    }
}

impl RectifyingStrip {
    /// Whether every output number is finite (the builder never returns a strip that is not).
    pub(crate) fn is_finite(&self) -> bool {
        let vectors = [&self.centre, &self.binormals, &self.rulings, &self.left, &self.right];
        let planar = [&self.unrolling.centre, &self.unrolling.left, &self.unrolling.right];
        let m = &self.metrics;
        vectors.iter().all(|v| v.iter().all(|p| p.iter().all(|x| x.is_finite())))
            && planar.iter().all(|v| v.iter().all(|p| p.iter().all(|x| x.is_finite())))
            && [m.max_diff_theta_degrees, m.e_straight, m.e_planar, m.max_planar, m.appro_percent, m.length].iter().all(|x| x.is_finite())
    }
}

fn any_perpendicular(v: &Vec3) -> Vec3 {
    let helper = if v.x.abs() < 0.9 { Vec3::x() } else { Vec3::y() };
    v.cross(&helper).try_normalize(0.0).unwrap_or_else(Vec3::z)
}
