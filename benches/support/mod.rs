//! The benchmark problem: a θ = 60° field on the hall roof, started from the coordinate along
//! the hall (the command-line demo's job), at the benchmark sizes; and one default design as
//! `lamella design` runs it ([`default_design`]).
#![allow(dead_code)]

use lamella::curves::{extract_level_curves, uniform_levels, LevelCurve};
use lamella::field::{FieldParams, FieldSolver, StepReport};
use lamella::initialisation::{search_start, SearchOptions};
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::{rectifying_strips, StripParams, StripPattern};
use lamella::surfaces::hall_roof;
use std::time::Instant;

/// Vertex counts of the hall-roof benchmark meshes.
pub const ROOF_VERTICES: [usize; 4] = [600, 3_000, 10_000, 50_000];

pub fn roof(vertices: usize) -> TriMesh {
    hall_roof(vertices).into_mesh().expect("the built-in roof is valid")
}

pub fn solver(mesh: &TriMesh) -> FieldSolver {
    let initial: Vec<f64> = mesh.positions().iter().map(|p| p.x).collect();
    FieldSolver::new(mesh, &initial, FieldParams::pseudo_geodesic(60.0)).expect("valid input")
}

/// The median wall time in seconds of `samples` calls of `step`.
pub fn median_seconds(samples: usize, mut step: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..samples)
        .map(|_| {
            let started = std::time::Instant::now();
            step();
            started.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[samples / 2]
}

/// One default design as `lamella design` runs it, without the files and the reshape trial: the
/// start search, the winner's solve to convergence, 20 level curves and their rectifying strips.
pub struct DesignRun {
    /// Wall times in seconds of the search, the solve and the strips.
    pub search: f64,
    pub solve: f64,
    pub strips: f64,
    pub candidates: usize,
    /// Vertex count the search probed on (the mesh's own, or its coarsening's).
    pub searched_on: usize,
    pub report: StepReport,
    /// The level curves as extracted (before the resampling the strips use).
    pub curves: Vec<LevelCurve>,
    pub pattern: StripPattern,
}

/// [`DesignRun`] of θ = `theta` on `mesh`, with strips of `width` (`None`: half the level curves'
/// mean spacing, as `lamella design` takes by default).
pub fn default_design(mesh: &TriMesh, theta: f64, width: Option<f64>) -> DesignRun {
    let started = Instant::now();
    let outcome = search_start(mesh, FieldParams::pseudo_geodesic(theta), SearchOptions::default()).expect("a start");
    let search = started.elapsed().as_secs_f64();
    let mut solver = outcome.solver;
    let report = solver.step(400).expect("solver runs");
    let solve = started.elapsed().as_secs_f64() - search;
    let field = solver.field();
    let levels = uniform_levels(mesh, &field, 20).expect("levels");
    let curves = extract_level_curves(mesh, &field, &levels).expect("curves");
    let resampled: Vec<LevelCurve> = curves.iter().map(|c| c.resampled(mesh.mean_edge_length()).expect("resampled")).collect();
    let width = width.unwrap_or_else(|| 0.5 * (levels[1] - levels[0]) / mean_gradient(mesh, &field));
    let pattern = rectifying_strips(mesh, &resampled, &StripParams::new(theta, width)).expect("strips");
    let strips = started.elapsed().as_secs_f64() - search - solve;
    let searched_on = outcome.proxy_vertices.unwrap_or(mesh.vertex_count());
    DesignRun { search, solve, strips, candidates: outcome.candidates.len(), searched_on, report, curves, pattern }
}

/// Area-weighted mean `‖∇F‖` of the piecewise linear `field`.
fn mean_gradient(mesh: &TriMesh, field: &[f64]) -> f64 {
    let (mut weighted, mut area) = (0.0, 0.0);
    for (f, corners) in mesh.faces().iter().enumerate() {
        let g: Vec3 = mesh.face_gradients(f).iter().zip(corners).map(|(g, &c)| g * field[c as usize]).sum();
        weighted += g.norm() * mesh.face_areas()[f];
        area += mesh.face_areas()[f];
    }
    weighted / area
}
