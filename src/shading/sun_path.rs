//! The sun directions of a site's dates and hours (not in the paper: what the light region is
//! derived from and what the sun-path evaluation casts its rays along).

use super::earth_frame::{light_angles, EarthFrame};
use super::error::ShadingError;
use super::site::Site;
use super::solar_position::solar_position;
use crate::mesh::Vec3;

/// One sun position above the horizon.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SunSample {
    /// Day of the year (1–365).
    pub day: u32,
    /// Hour in the site's clock.
    pub hour: f64,
    /// Unit direction towards the sun, model coordinates.
    pub direction: Vec3,
    /// The paper's angles (δ, γ) in degrees (earth-axis frame, Sec. 6).
    pub delta_degrees: f64,
    pub gamma_degrees: f64,
    pub elevation_degrees: f64,
    /// Clockwise from north, degrees.
    pub azimuth_degrees: f64,
}

/// The sun above the horizon on every `day_step`-th day of the site's dates (and the last day),
/// every `hour_step` hours from the first hour to the last (both included). Days and hours in
/// increasing order; deterministic.
pub fn sun_samples(site: &Site, day_step: usize, hour_step: f64) -> Result<Vec<SunSample>, ShadingError> {
    let frame = site.frame()?;
    if day_step == 0 {
        return Err(ShadingError::invalid("day_step", "must be at least 1".to_string()));
    }
    if !(hour_step.is_finite() && hour_step > 0.0) {
        return Err(ShadingError::invalid("hour_step", format!("must be finite and > 0, got {hour_step}")));
    }
    let all_days = site.dates.days()?;
    let mut days: Vec<u32> = all_days.iter().copied().step_by(day_step).collect();
    if let Some(&last) = all_days.last() {
        if days.last() != Some(&last) {
            days.push(last);
        }
    }
    let hour_count = ((site.hours.last - site.hours.first) / hour_step + 1e-9).floor() as usize;
    let mut hours: Vec<f64> = (0..=hour_count).map(|k| site.hours.first + k as f64 * hour_step).collect();
    if hours.last().is_some_and(|&h| h < site.hours.last - 1e-9) {
        hours.push(site.hours.last);
    }
    let mut samples = Vec::new();
    for &day in &days {
        for &hour in &hours {
            if let Some(sample) = sample_at(&frame, site, day, hour) {
                samples.push(sample);
            }
        }
    }
    Ok(samples)
}

fn sample_at(frame: &EarthFrame, site: &Site, day: u32, hour: f64) -> Option<SunSample> {
    let position = solar_position(day as f64, hour, &site.clock);
    let (delta, gamma) = (-position.hour_angle_degrees, position.declination_degrees);
    let earth = super::earth_frame::light_direction(delta, gamma);
    let direction = frame.to_model(&earth);
    let elevation = frame.elevation_degrees(&direction);
    if elevation <= 0.0 {
        return None;
    }
    let (delta_degrees, gamma_degrees) = light_angles(&earth);
    Some(SunSample { day, hour, direction, delta_degrees, gamma_degrees, elevation_degrees: elevation, azimuth_degrees: frame.azimuth_degrees(&direction) })
}
