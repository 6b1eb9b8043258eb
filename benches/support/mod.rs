//! The benchmark problem: a θ = 60° field on the hall roof, started from the coordinate along
//! the hall (the command-line demo's job), at the benchmark sizes.
#![allow(dead_code)]

use lamella::field::{FieldParams, FieldSolver};
use lamella::mesh::TriMesh;
use lamella::surfaces::hall_roof;

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
