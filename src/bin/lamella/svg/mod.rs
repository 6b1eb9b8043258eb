//! SVG output: the cut sheet, the convergence plot and the shaded preview, over a small
//! document writer that escapes text and never writes a non-finite number.
pub mod convergence;
pub mod cut_sheet;
pub mod preview;
pub mod shading;
pub mod sunpath;

use std::fmt::Write as _;

/// A number as SVG writes it: 3 decimals, non-finite values as 0 (never NaN in a file).
pub fn num(value: f64) -> String {
    if value.is_finite() {
        let text = format!("{value:.3}");
        let trimmed = text.trim_end_matches('0').trim_end_matches('.');
        if trimmed == "-0" || trimmed.is_empty() {
            "0".to_string()
        } else {
            trimmed.to_string()
        }
    } else {
        "0".to_string()
    }
}

/// Text escaped for XML character data and attribute values.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// `points` attribute value of a polygon or polyline.
pub fn points(ps: impl IntoIterator<Item = [f64; 2]>) -> String {
    ps.into_iter().map(|[x, y]| format!("{},{}", num(x), num(y))).collect::<Vec<_>>().join(" ")
}

/// An SVG document being written.
pub struct Svg {
    text: String,
}

impl Svg {
    /// A document of `width × height` user units, each `unit` long (e.g. "mm", or "" for pixels).
    pub fn new(width: f64, height: f64, unit: &str, title: &str) -> Svg {
        let mut text = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        let _ = writeln!(
            text,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}{unit}\" height=\"{h}{unit}\" viewBox=\"0 0 {w} {h}\">",
            w = num(width),
            h = num(height)
        );
        let _ = writeln!(text, "<title>{}</title>", escape(title));
        Svg { text }
    }

    /// Appends one element (already formatted).
    pub fn element(&mut self, element: &str) {
        self.text.push_str(element);
        self.text.push('\n');
    }

    /// A `<text>` element at `(x, y)` with extra attributes.
    pub fn text(&mut self, x: f64, y: f64, attributes: &str, content: &str) {
        let _ = writeln!(self.text, "<text x=\"{}\" y=\"{}\" {attributes}>{}</text>", num(x), num(y), escape(content));
    }

    pub fn finish(mut self) -> String {
        self.text.push_str("</svg>\n");
        self.text
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_always_finite() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(-0.0001), "0");
        assert_eq!(num(2.5), "2.5");
        assert_eq!(num(1234.56789), "1234.568");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(num(f64::INFINITY), "0");
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
    }
}
