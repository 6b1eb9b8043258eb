//! Quantised coordinates: each coordinate stored as a 16-bit step of its axis of a bounding box,
//! little-endian, base64. The error is at most half a step, `extent / (2 · 65535)` per axis.
use super::base64;

/// Steps per axis of the bounding box.
pub const QUANTISATION_STEPS: f64 = 65535.0;

/// Points of `D` coordinates quantised in the box `low .. high`.
#[derive(Clone, Debug, PartialEq)]
pub struct QuantisedPoints<const D: usize> {
    pub low: [f64; D],
    pub high: [f64; D],
    /// Base64 of the little-endian `u16` steps, `D` per point.
    pub base64: String,
}

impl<const D: usize> QuantisedPoints<D> {
    /// Quantises `points` in the box `low .. high`, which must contain them (values outside are
    /// clamped to its faces); an axis of zero extent stores zeros.
    pub fn new(points: impl IntoIterator<Item = [f64; D]>, low: [f64; D], high: [f64; D]) -> QuantisedPoints<D> {
        let mut bytes = Vec::new();
        for p in points {
            for k in 0..D {
                let extent = high[k] - low[k];
                let step = if extent > 0.0 { ((p[k] - low[k]) / extent * QUANTISATION_STEPS).round().clamp(0.0, QUANTISATION_STEPS) } else { 0.0 };
                bytes.extend_from_slice(&(step as u16).to_le_bytes());
            }
        }
        QuantisedPoints { low, high, base64: base64::encode(&bytes) }
    }
}

/// The points of a base64 text written by [`QuantisedPoints::new`] in the box `low .. high`,
/// `D` coordinates each; `None` if the text is not base64 or not whole points.
pub fn dequantise<const D: usize>(text: &str, low: [f64; D], high: [f64; D]) -> Option<Vec<[f64; D]>> {
    let bytes = base64::decode(text)?;
    if bytes.len() % (2 * D) != 0 {
        return None;
    }
    let steps: Vec<f64> = bytes.chunks(2).map(|b| f64::from(u16::from_le_bytes([b[0], b[1]]))).collect();
    Some(steps.chunks(D).map(|s| std::array::from_fn(|k| low[k] + s[k] / QUANTISATION_STEPS * (high[k] - low[k]))).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_come_back_within_half_a_step() {
        let (low, high) = ([-2.0, 0.0, 5.0], [3.0, 10.0, 5.0]);
        let points = [[-2.0, 0.0, 5.0], [3.0, 10.0, 5.0], [0.123456, 7.654321, 5.0]];
        let quantised = QuantisedPoints::new(points, low, high);
        let back = dequantise(&quantised.base64, low, high).unwrap();
        assert_eq!(back.len(), 3);
        for (p, q) in points.iter().zip(&back) {
            for k in 0..3 {
                let half_step = (high[k] - low[k]) / QUANTISATION_STEPS / 2.0;
                assert!((p[k] - q[k]).abs() <= half_step + 1e-12, "{p:?} came back as {q:?}");
            }
        }
        // An axis of zero extent decodes to its one value.
        assert!(back.iter().all(|q| q[2] == 5.0));
    }

    #[test]
    fn broken_text_is_refused() {
        let quantised = QuantisedPoints::new([[1.0, 2.0]], [0.0, 0.0], [4.0, 4.0]);
        assert!(dequantise::<3>(&quantised.base64, [0.0; 3], [1.0; 3]).is_none());
        assert!(dequantise::<2>("not base64!", [0.0; 2], [1.0; 2]).is_none());
    }
}
