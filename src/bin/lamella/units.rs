//! Quantities with units on the command line: lengths (`6mm`, `4.8m`, `30cm`, metres without a
//! unit) and stresses or moduli (`11GPa`, `24MPa`, `350kPa`, pascals without a unit).
use crate::error::{CliError, CliResult};
use lamella::input::clip;

/// The number and its unit's factor, from the units in `units` (longest suffix first).
fn quantity(flag: &str, text: &str, units: &[(&str, f64)], what: &str) -> CliResult<f64> {
    let trimmed = text.trim();
    let (number, factor) = units
        .iter()
        .find_map(|(suffix, factor)| trimmed.strip_suffix(suffix).map(|n| (n.trim(), *factor)))
        .unwrap_or((trimmed, 1.0));
    let value: f64 = number.parse().map_err(|_| CliError::bad_input(format!("{flag}: `{}` is not {what}", clip(text))))?;
    if !(value.is_finite() && value > 0.0) {
        return Err(CliError::bad_input(format!("{flag} must be finite and > 0, got `{}`", clip(text))));
    }
    Ok(value * factor)
}

/// A positive length in metres.
pub fn length(flag: &str, text: &str) -> CliResult<f64> {
    quantity(flag, text, &[("mm", 1e-3), ("cm", 1e-2), ("m", 1.0)], "a length (a number with mm, cm or m; metres without a unit)")
}

/// A positive length in metres, or zero.
pub fn length_or_zero(flag: &str, text: &str) -> CliResult<f64> {
    let stripped = text.trim().trim_end_matches(['m', 'c']);
    if stripped.parse::<f64>().is_ok_and(|v| v == 0.0) {
        return Ok(0.0);
    }
    length(flag, text)
}

/// A positive stress or modulus in pascals.
pub fn stress(flag: &str, text: &str) -> CliResult<f64> {
    quantity(flag, text, &[("GPa", 1e9), ("MPa", 1e6), ("kPa", 1e3), ("Pa", 1.0)], "a stress (a number with GPa, MPa, kPa or Pa; pascals without a unit)")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_scale_to_metres_and_pascals() {
        assert_eq!(length("--thickness", "6mm").ok(), Some(0.006));
        assert_eq!(length("--stock", "4.8m").ok(), Some(4.8));
        assert_eq!(length("--stock", "480 cm").ok(), Some(4.8));
        assert_eq!(length("--stock", "2.5").ok(), Some(2.5));
        assert_eq!(length_or_zero("--overlap", "0mm").ok(), Some(0.0));
        assert_eq!(stress("--youngs-modulus", "11GPa").ok(), Some(11e9));
        assert_eq!(stress("--allowable-stress", "24 MPa").ok(), Some(24e6));
        for bad in ["-6mm", "6 inch", "0", "nan", "inf m", ""] {
            let message = length("--thickness", bad).err().and_then(|e| e.message()).unwrap_or_default();
            assert!(message.starts_with("--thickness"), "{bad}: {message}");
        }
    }
}
