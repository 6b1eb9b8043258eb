//! The light region `R_l` of Sec. 6: intervals of the angles δ and γ in the earth-axis frame,
//! and its inequality form of Eq. 24 (`l_z ∈ [z_min, z_max]`, `l_y / l_x ∈ [g_min, g_max]`).

use super::earth_frame::light_direction;
use super::error::ShadingError;
use super::site::Site;
use super::sun_path::{sun_samples, SunSample};
use crate::mesh::Vec3;

/// Hours between the sun samples a site's region is measured on.
pub const REGION_HOUR_STEP: f64 = 0.25;

/// `δ ∈ [delta[0], delta[1]]`, `γ ∈ [gamma[0], gamma[1]]`, in degrees. δ stays inside
/// (−90°, 90°): the region lies on the side `l_x > 0` of the earth axis, where `l_y / l_x`
/// is monotonic in δ (Eq. 24).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct LightRegion {
    pub delta_degrees: [f64; 2],
    pub gamma_degrees: [f64; 2],
}

/// The bounds of Eq. 24.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RegionBounds {
    pub z_min: f64,
    pub z_max: f64,
    pub g_min: f64,
    pub g_max: f64,
}

impl LightRegion {
    /// A region given directly by its intervals (degrees); errors name the interval.
    pub fn new(delta_degrees: [f64; 2], gamma_degrees: [f64; 2]) -> Result<LightRegion, ShadingError> {
        let region = LightRegion { delta_degrees, gamma_degrees };
        region.validate()?;
        Ok(region)
    }

    pub(crate) fn validate(&self) -> Result<(), ShadingError> {
        let [d0, d1] = self.delta_degrees;
        if !(d0.is_finite() && d1.is_finite() && -90.0 < d0 && d0 <= d1 && d1 < 90.0) {
            return Err(ShadingError::invalid("delta", format!("needs -90° < min ≤ max < 90°, got [{d0}, {d1}] (shorten the hours to within 6 h of solar noon)")));
        }
        let [g0, g1] = self.gamma_degrees;
        if !(g0.is_finite() && g1.is_finite() && -90.0 < g0 && g0 <= g1 && g1 < 90.0) {
            return Err(ShadingError::invalid("gamma", format!("needs -90° < min ≤ max < 90°, got [{g0}, {g1}]")));
        }
        Ok(())
    }

    /// The smallest region holding every sun position of `samples`.
    pub fn enclosing(samples: &[SunSample]) -> Result<LightRegion, ShadingError> {
        if samples.is_empty() {
            return Err(ShadingError::SunNeverUp);
        }
        let span = |value: fn(&SunSample) -> f64| samples.iter().map(value).fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], v| [lo.min(v), hi.max(v)]);
        LightRegion::new(span(|s| s.delta_degrees), span(|s| s.gamma_degrees))
    }

    /// The region of a site: the sun above the horizon on each of its days, every
    /// [`REGION_HOUR_STEP`] hours of its daily hours.
    pub fn of_site(site: &Site) -> Result<LightRegion, ShadingError> {
        LightRegion::enclosing(&sun_samples(site, 1, REGION_HOUR_STEP)?)
    }

    /// The central light direction `l_c` (earth frame) of the mid angles (Sec. 6, letting light through).
    pub fn central_direction(&self) -> Vec3 {
        light_direction(0.5 * (self.delta_degrees[0] + self.delta_degrees[1]), 0.5 * (self.gamma_degrees[0] + self.gamma_degrees[1]))
    }

    /// Whether earth-frame unit direction `l` lies in the region, up to `slack` in the bounds of Eq. 24.
    pub fn contains(&self, l: &Vec3, slack: f64) -> bool {
        let b = self.bounds();
        l.x > 0.0 && l.z >= b.z_min - slack && l.z <= b.z_max + slack && l.y >= (b.g_min - slack) * l.x && l.y <= (b.g_max + slack) * l.x
    }

    pub(crate) fn bounds(&self) -> RegionBounds {
        let [d0, d1] = self.delta_degrees.map(f64::to_radians);
        let [g0, g1] = self.gamma_degrees.map(f64::to_radians);
        RegionBounds { z_min: g0.sin(), z_max: g1.sin(), g_min: d0.tan(), g_max: d1.tan() }
    }
}
