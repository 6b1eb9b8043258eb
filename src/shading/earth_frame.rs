//! The paper's earth-axis frame of Sec. 6 and its placement in the model: `z` parallel to the
//! earth's axis (towards the celestial north pole), the `xz`-plane the building's meridian plane,
//! `x` towards the sun's culmination (up and towards the equator), `y = z × x` east. A light
//! direction is `l = (cos δ cos γ, sin δ cos γ, sin γ)`; γ is the solar declination and δ the
//! negated hour angle ([`super::solar_position`]).

use super::error::ShadingError;
use crate::mesh::Vec3;

/// The earth-axis frame of a site, expressed in model coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EarthFrame {
    /// The frame's axes `x`, `y`, `z` as unit model vectors.
    pub axes: [Vec3; 3],
    /// Model up (unit).
    pub up: Vec3,
}

impl EarthFrame {
    /// The frame at geographic `latitude_degrees` (north positive, in [−90°, 90°]) for a model
    /// whose `north` and `up` directions are given (model vectors, not parallel; `north` is made
    /// horizontal). Errors name the offending parameter.
    pub fn new(latitude_degrees: f64, north: Vec3, up: Vec3) -> Result<EarthFrame, ShadingError> {
        if !(latitude_degrees.is_finite() && (-90.0..=90.0).contains(&latitude_degrees)) {
            return Err(ShadingError::invalid("latitude", format!("must lie in [-90°, 90°], got {latitude_degrees}")));
        }
        let up = up.try_normalize(1e-12).filter(|u| u.iter().all(|c| c.is_finite()));
        let Some(up) = up else {
            return Err(ShadingError::invalid("up", "must be a finite non-zero vector".to_string()));
        };
        let horizontal = north - up * north.dot(&up);
        let north = horizontal.try_normalize(1e-9 * north.norm().max(1e-300)).filter(|n| n.iter().all(|c| c.is_finite()));
        let Some(north) = north else {
            return Err(ShadingError::invalid("north", "must be a finite vector not parallel to up".to_string()));
        };
        let east = north.cross(&up);
        let (sin, cos) = latitude_degrees.to_radians().sin_cos();
        let axes = [up * cos - north * sin, east, north * cos + up * sin];
        Ok(EarthFrame { axes, up })
    }

    /// The model vector of earth-frame components `e`.
    pub fn to_model(&self, e: &Vec3) -> Vec3 {
        self.axes[0] * e.x + self.axes[1] * e.y + self.axes[2] * e.z
    }

    /// The earth-frame components of model vector `m`.
    pub fn to_earth(&self, m: &Vec3) -> Vec3 {
        Vec3::new(self.axes[0].dot(m), self.axes[1].dot(m), self.axes[2].dot(m))
    }

    /// The horizontal north direction in the model.
    pub fn north(&self) -> Vec3 {
        self.up.cross(&self.axes[1])
    }

    /// Elevation over the horizon of model direction `l` (unit), in degrees.
    pub fn elevation_degrees(&self, l: &Vec3) -> f64 {
        l.dot(&self.up).clamp(-1.0, 1.0).asin().to_degrees()
    }

    /// Azimuth of model direction `l` in degrees, clockwise from north (east = 90°).
    pub fn azimuth_degrees(&self, l: &Vec3) -> f64 {
        let a = l.dot(&self.axes[1]).atan2(l.dot(&self.north())).to_degrees();
        if a < 0.0 { a + 360.0 } else { a }
    }
}

/// The unit light direction of the paper's angles (δ, γ) in degrees, in the earth-axis frame.
pub fn light_direction(delta_degrees: f64, gamma_degrees: f64) -> Vec3 {
    let (sd, cd) = delta_degrees.to_radians().sin_cos();
    let (sg, cg) = gamma_degrees.to_radians().sin_cos();
    Vec3::new(cd * cg, sd * cg, sg)
}

/// The paper's angles (δ, γ) in degrees of an earth-frame unit direction.
pub fn light_angles(l: &Vec3) -> (f64, f64) {
    (l.y.atan2(l.x).to_degrees(), l.z.clamp(-1.0, 1.0).asin().to_degrees())
}
