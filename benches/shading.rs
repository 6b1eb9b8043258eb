//! A shading design (Sec. 6) and its sun-path evaluation. The design: one iteration of
//! `ShadingSolver::step(1)` on the hall roof at the size of the paper's Fig. 36 model (4,427
//! vertices, 0.46 s per iteration on the authors' Xeon, Table 2, weights 0.1 / 0.3 / 1e-3)
//! and at 3,000 vertices, blocking the sun of June to August, 10 to 16 h, at 47.4° N; start
//! the height along the earth axis; 5 warm-up iterations, then the median of `SAMPLES` steps.
//! The evaluation: the rays per second of `evaluate_sun_path` from every vertex against the
//! strips of 20 level curves, hourly suns of every day.
//!
//! Run: `cargo bench --bench shading`.

mod support;

use lamella::shading::{
    evaluate_sun_path, samples_behind, shading_strips, strip_triangles, sun_samples, Clock, DateRange, HourRange, LightRegion, MonthDay, ShadingParams,
    ShadingSolver, Site, VertexLabel,
};
use lamella::mesh::Vec3;
use std::time::Instant;
use support::{median_seconds, roof};

const SAMPLES: usize = 11;

fn main() {
    let site = Site {
        latitude_degrees: 47.4,
        clock: Clock::solar(),
        north: Vec3::y(),
        up: Vec3::z(),
        dates: DateRange { first: MonthDay { month: 6, day: 1 }, last: MonthDay { month: 8, day: 31 } },
        hours: HourRange { first: 10.0, last: 16.0 },
    };
    let frame = site.frame().expect("valid site");
    let region = LightRegion::of_site(&site).expect("valid region");
    println!("| vertices | time per `step(1)` (median of {SAMPLES}) | paper (Table 2) | rays | rays per second |");
    println!("|---:|---:|---:|---:|---:|");
    for (vertices, paper) in [(3_000, ""), (4_427, "0.46 s (Fig. 36(a), 4,427 vertices)")] {
        let mesh = roof(vertices);
        let field: Vec<f64> = mesh.positions().iter().map(|p| p.dot(&frame.axes[2])).collect();
        let labels = vec![VertexLabel::Block; mesh.vertex_count()];
        let mut params = ShadingParams::new(frame, region);
        // No convergence test: every sample runs one iteration.
        params.relative_tolerance = 0.0;
        params.lm.gradient_tolerance = 0.0;
        params.lm.step_tolerance = 0.0;
        params.lm.energy_tolerance = 0.0;
        let mut solver = ShadingSolver::new(&mesh, &field, &labels, params).expect("valid input");
        solver.step(5).expect("solver runs");
        let before = solver.iterations();
        let median = median_seconds(SAMPLES, || {
            solver.step(1).expect("solver runs");
        });
        assert_eq!(solver.iterations(), before + SAMPLES, "every sample ran an iteration");
        let strips = shading_strips(&mesh, &solver.field(), &solver.binormals(), 20, 1.0, 2.0).expect("strips");
        let suns = sun_samples(&site, 1, 1.0).expect("suns");
        let samples = samples_behind(&mesh, &labels, &suns, 0.05).expect("samples");
        let triangles = strip_triangles(&strips.pattern.strips);
        let started = Instant::now();
        let evaluation = evaluate_sun_path(&triangles, &samples, &suns).expect("evaluation");
        let seconds = started.elapsed().as_secs_f64();
        println!("| {} | {:.1} ms | {paper} | {} | {:.2e} |", mesh.vertex_count(), 1e3 * median, evaluation.rays, evaluation.rays as f64 / seconds);
    }
}
