//! θ = 0 (asymptotic curves) on the hyperbolic paraboloid z = xy/c: traced along x from the
//! side x = −a, the curve is the straight ruling y = y0, z = x·y0/c.

use crate::tracing_support;

use lamella::mesh::Vec3;
use lamella::tracing::{StopReason, TraceOptions, Tracer};
use tracing_support::{boundary_point_where, saddle};

const C: f64 = 6.0;
const HALF_WIDTH: f64 = 5.0;

#[test]
fn asymptotic_trace_follows_the_ruling() {
    let mesh = saddle(C, HALF_WIDTH, 3000);
    let tracer = Tracer::new(&mesh);
    for (y0, theta) in [(1.5, 0.0), (-2.0, 0.0), (1.5, 180.0)] {
        let start = boundary_point_where(&mesh, |p| (p.x + HALF_WIDTH).abs() < 1e-9, |p| p.y, y0);
        // α = 90° against the side's boundary direction (−y, interior on the left) points along +x.
        let curve = tracer.trace(&start, theta, 90.0, &TraceOptions::default()).expect("valid input");
        assert_eq!(curve.stop(), StopReason::Boundary, "y0 = {y0}");
        let positions = curve.positions();
        let end = positions[positions.len() - 1];
        assert!((end.x - HALF_WIDTH).abs() < 1e-9, "should reach the far side x = a, ends at {end:?}");
        let on_ruling = |x: f64| Vec3::new(x, y0, x * y0 / C);
        let direction = (on_ruling(1.0) - on_ruling(0.0)).normalize();
        let distance = positions
            .iter()
            .map(|p| {
                let q = p - on_ruling(0.0);
                (q - direction * q.dot(&direction)).norm()
            })
            .fold(0.0, f64::max);
        let length = curve.length();
        eprintln!("y0 {y0}, θ {theta}: {} points, length {length}, max distance from the ruling {distance} ({} %)", positions.len(), 100.0 * distance / length);
        assert!(distance <= 0.01 * length, "distance {distance} vs length {length}");
    }
}

