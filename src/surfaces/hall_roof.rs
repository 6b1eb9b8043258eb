//! The default architectural surface of the demo and the benchmarks: a doubly curved hall roof.
//!
//! In plan the roof covers `x ∈ [−20, 20]` (length 40 m) and `|y| ≤ w(x)`; every cross-section
//! `x = const` is a circular arch through the eaves `(x, ±w(x), 0)` and the crown `(x, 0, h(x))`.
//! With the blend `b(x) = (1 + cos(π x / 20)) / 2` (1 in the middle, 0 at the gable ends) the arch
//! is high and narrow in the middle and low and wide at the ends:
//! `h(x) = 5 + 3 b(x)` (rise 8 m → 5 m) and `w(x) = 12 − 1.5 b(x)` (span 21 m → 24 m).
//! Along the crown the curvature `h''(x)` changes sign at `|x| = 10`, so the Gaussian curvature is
//! positive in the middle third (dome-like) and negative towards the ends (saddle-like).

use super::jittered_grid::{jittered_grid, ParameterRectangle};
use super::random::SplitMix64;
use super::GeneratedSurface;
use crate::mesh::Vec3;
use std::f64::consts::PI;

/// Half the length of the hall along `x`.
pub const HALL_ROOF_HALF_LENGTH: f64 = 20.0;
/// Jitter of the hall roof grid, as a fraction of the cell size.
const HALL_ROOF_IRREGULARITY: f64 = 0.25;
/// Fixed seed: the hall roof is one deterministic surface per vertex count.
const HALL_ROOF_SEED: u64 = 0x4A11_2023;

/// The circular arch of the hall roof cross-section at a given `x`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HallRoofSection {
    /// Half the span `w(x)`: the eaves are at `y = ±w`, `z = 0`.
    pub half_span: f64,
    /// Rise `h(x)` of the crown above the eaves.
    pub rise: f64,
}

impl HallRoofSection {
    /// The cross-section at `x` (meant for `|x| ≤ HALL_ROOF_HALF_LENGTH`).
    pub fn at(x: f64) -> HallRoofSection {
        let blend = 0.5 * (1.0 + (PI * x / HALL_ROOF_HALF_LENGTH).cos());
        HallRoofSection { half_span: 12.0 - 1.5 * blend, rise: 5.0 + 3.0 * blend }
    }

    /// Radius of the arch circle, whose centre is at `(y, z) = (0, rise − radius)`.
    pub fn radius(&self) -> f64 {
        (self.half_span * self.half_span + self.rise * self.rise) / (2.0 * self.rise)
    }

    /// Half the opening angle of the arch, seen from the circle centre.
    fn half_angle(&self) -> f64 {
        self.half_span.atan2(self.radius() - self.rise)
    }

    /// Arc length of the arch from eave to eave.
    fn arc_length(&self) -> f64 {
        2.0 * self.radius() * self.half_angle()
    }

    /// The arch point `(y, z)` at the normalised arc-length parameter `t ∈ [−1, 1]` (eave to eave).
    fn point(&self, t: f64) -> (f64, f64) {
        let radius = self.radius();
        let angle = t * self.half_angle();
        (radius * angle.sin(), self.rise - radius + radius * angle.cos())
    }
}

/// The hall roof with about `target_vertices` vertices (at least 4), triangulated by a gently
/// jittered grid in `(x, arc length of the arch)` with a fixed seed. z is up; face normals point
/// up and outwards (away from the hall's interior).
pub fn hall_roof(target_vertices: usize) -> GeneratedSurface {
    // Cells are square for the mean arch length; it varies by only a few per cent along x.
    let samples = 9;
    let mean_arc = (0..samples)
        .map(|k| {
            let x = HALL_ROOF_HALF_LENGTH * (2.0 * k as f64 / (samples - 1) as f64 - 1.0);
            HallRoofSection::at(x).arc_length()
        })
        .sum::<f64>()
        / samples as f64;
    let domain = ParameterRectangle { width: 2.0 * HALL_ROOF_HALF_LENGTH, height: mean_arc };
    let mut rng = SplitMix64::new(HALL_ROOF_SEED);
    jittered_grid(&domain, target_vertices, HALL_ROOF_IRREGULARITY, &mut rng, |u, v| {
        let x = u - HALL_ROOF_HALF_LENGTH;
        let (y, z) = HallRoofSection::at(x).point(2.0 * v / mean_arc - 1.0);
        Vec3::new(x, y, z)
    })
}
