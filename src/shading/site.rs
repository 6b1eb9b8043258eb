//! A site: where the building stands, how the model is oriented, and which dates and daily hours
//! the shading is for.

use super::earth_frame::EarthFrame;
use super::error::ShadingError;
use super::solar_position::{day_of_year, Clock};
use crate::mesh::Vec3;

/// A day of the year as month (1–12) and day of the month (no leap day).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MonthDay {
    pub month: u32,
    pub day: u32,
}

/// Dates from `first` to `last`, both included; a range with `last` before `first` runs over
/// the new year (`11-01..02-28`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DateRange {
    pub first: MonthDay,
    pub last: MonthDay,
}

impl DateRange {
    /// The days of the year (1–365) of the range, in order.
    pub fn days(&self) -> Result<Vec<u32>, ShadingError> {
        let first = day_of_year(self.first.month, self.first.day)?;
        let last = day_of_year(self.last.month, self.last.day)?;
        Ok(if last >= first { (first..=last).collect() } else { (first..=365).chain(1..=last).collect() })
    }
}

/// Daily hours `[first, last]` (0–24, `first < last`), in the site's clock.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HourRange {
    pub first: f64,
    pub last: f64,
}

impl HourRange {
    fn validate(&self) -> Result<(), ShadingError> {
        if !(self.first.is_finite() && self.last.is_finite() && 0.0 <= self.first && self.first < self.last && self.last <= 24.0) {
            return Err(ShadingError::invalid("hours", format!("must satisfy 0 ≤ first < last ≤ 24, got {}..{}", self.first, self.last)));
        }
        Ok(())
    }
}

/// Where, in which orientation and when.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Site {
    /// Geographic latitude in degrees, north positive.
    pub latitude_degrees: f64,
    /// Clock of the hours: true solar time, or clock time with longitude and time zone.
    pub clock: Clock,
    /// North in model coordinates (made horizontal).
    pub north: Vec3,
    /// Up in model coordinates.
    pub up: Vec3,
    pub dates: DateRange,
    pub hours: HourRange,
}

impl Site {
    /// Validates every field (errors name it) and returns the site's earth-axis frame.
    pub fn frame(&self) -> Result<EarthFrame, ShadingError> {
        self.clock.validate()?;
        self.hours.validate()?;
        self.dates.days()?;
        EarthFrame::new(self.latitude_degrees, self.north, self.up)
    }
}
