//! The sun's position from the date and the time of day: the NOAA "General Solar Position
//! Calculations" model (Spencer's 1971 Fourier series for the solar declination and the
//! equation of time, then the hour angle from the true solar time). Accurate to about 0.5° in
//! the declination and 1 minute in the equation of time, ample for the light regions of Sec. 6.
//!
//! The results are the paper's angles directly: the declination is γ (the light's elevation over
//! the equatorial plane) and the hour angle is −δ (δ grows towards the east, the morning side,
//! in the earth-axis frame of [`super::EarthFrame`]).

use super::error::ShadingError;

/// Days in the (non-leap) year the model uses.
pub const DAYS_PER_YEAR: f64 = 365.0;

/// The sun's equatorial position at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolarPosition {
    /// Solar declination in degrees (the paper's γ).
    pub declination_degrees: f64,
    /// Hour angle in degrees: 0 at true solar noon, negative in the morning (the paper's −δ).
    pub hour_angle_degrees: f64,
    /// Equation of time in minutes (true minus mean solar time).
    pub equation_of_time_minutes: f64,
}

/// Where and in which clock the times are given: without a longitude the hours are true solar
/// time (noon = the sun in the meridian); with a longitude (degrees, east positive) and the time
/// zone (hours east of UTC) they are clock time and the equation of time is applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Clock {
    pub longitude_degrees: Option<f64>,
    pub time_zone_hours: Option<f64>,
}

impl Clock {
    /// Hours are true solar time.
    pub fn solar() -> Clock {
        Clock { longitude_degrees: None, time_zone_hours: None }
    }

    pub(crate) fn validate(&self) -> Result<(), ShadingError> {
        if let Some(longitude) = self.longitude_degrees {
            if !(longitude.is_finite() && (-180.0..=180.0).contains(&longitude)) {
                return Err(ShadingError::invalid("longitude", format!("must lie in [-180°, 180°], got {longitude}")));
            }
        }
        if let Some(zone) = self.time_zone_hours {
            if !(zone.is_finite() && (-14.0..=14.0).contains(&zone)) {
                return Err(ShadingError::invalid("time_zone", format!("must lie in [-14 h, 14 h], got {zone}")));
            }
        }
        if self.longitude_degrees.is_some() != self.time_zone_hours.is_some() {
            return Err(ShadingError::invalid("time_zone", "longitude and time zone go together (clock time needs both)".to_string()));
        }
        Ok(())
    }
}

/// The sun at `hour` (0–24, in the clock of `clock`) on day `day_of_year` (1 = 1 January).
pub fn solar_position(day_of_year: f64, hour: f64, clock: &Clock) -> SolarPosition {
    // Fractional year in radians.
    let y = std::f64::consts::TAU / DAYS_PER_YEAR * (day_of_year - 1.0 + (hour - 12.0) / 24.0);
    let (s1, c1) = y.sin_cos();
    let (s2, c2) = (2.0 * y).sin_cos();
    let (s3, c3) = (3.0 * y).sin_cos();
    let equation_of_time = 229.18 * (0.000075 + 0.001868 * c1 - 0.032077 * s1 - 0.014615 * c2 - 0.040849 * s2);
    let declination = 0.006918 - 0.399912 * c1 + 0.070257 * s1 - 0.006758 * c2 + 0.000907 * s2 - 0.002697 * c3 + 0.00148 * s3;
    let offset_minutes = match (clock.longitude_degrees, clock.time_zone_hours) {
        (Some(longitude), Some(zone)) => equation_of_time + 4.0 * longitude - 60.0 * zone,
        _ => 0.0,
    };
    let true_solar_minutes = hour * 60.0 + offset_minutes;
    SolarPosition {
        declination_degrees: declination.to_degrees(),
        hour_angle_degrees: true_solar_minutes / 4.0 - 180.0,
        equation_of_time_minutes: equation_of_time,
    }
}

/// The day of the year (1–365, no leap day) of `month` (1–12) and `day`.
pub fn day_of_year(month: u32, day: u32) -> Result<u32, ShadingError> {
    const LENGTHS: [u32; 12] = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31];
    if !(1..=12).contains(&month) {
        return Err(ShadingError::invalid("dates", format!("month {month} is not 1 to 12")));
    }
    let length = LENGTHS[month as usize - 1];
    if !(1..=length).contains(&day) {
        return Err(ShadingError::invalid("dates", format!("day {day} is not 1 to {length} in month {month}")));
    }
    Ok(LENGTHS[..month as usize - 1].iter().sum::<u32>() + day)
}
