//! unrolled.svg: the flat strips as a cut sheet in millimetres, one row per strip so that no two
//! outlines overlap, each labelled with its id, length and width.
use super::{points, Svg};
use lamella::strips::Unrolling;

/// Millimetres per metre (mesh units are metres).
const MM: f64 = 1000.0;
/// Width of the cut lines: a hairline of one device pixel (or the cutter's finest line) at any zoom.
const CUT_LINE: &str = "stroke-width=\"1\" vector-effect=\"non-scaling-stroke\"";
/// Margin around the sheet and gap between rows, in mm.
const MARGIN_MM: f64 = 20.0;

/// One piece to cut.
pub struct CutPiece<'a> {
    pub name: String,
    pub unrolling: &'a Unrolling,
}

/// The outline of a flat strip: left boundary forward, right boundary backward.
fn outline(u: &Unrolling) -> Vec<[f64; 2]> {
    u.left.iter().chain(u.right.iter().rev()).copied().collect()
}

/// `points` turned so that the chord of `centre` is horizontal, scaled to mm and moved so that
/// their bounding box starts at the origin; returns the points and the box size.
fn placed(points: &[[f64; 2]], centre: &[[f64; 2]]) -> (Vec<[f64; 2]>, [f64; 2]) {
    let angle = match (centre.first(), centre.last()) {
        (Some(a), Some(b)) if a != b => (b[1] - a[1]).atan2(b[0] - a[0]),
        _ => 0.0,
    };
    let (s, c) = (-angle).sin_cos();
    let turned: Vec<[f64; 2]> = points.iter().map(|p| [MM * (c * p[0] - s * p[1]), MM * (s * p[0] + c * p[1])]).collect();
    let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &turned {
        for k in 0..2 {
            low[k] = low[k].min(p[k]);
            high[k] = high[k].max(p[k]);
        }
    }
    if turned.is_empty() {
        return (turned, [0.0, 0.0]);
    }
    let moved = turned.iter().map(|p| [p[0] - low[0], p[1] - low[1]]).collect();
    (moved, [high[0] - low[0], high[1] - low[1]])
}

/// The cut sheet of `pieces`.
pub fn cut_sheet_svg(pieces: &[CutPiece]) -> String {
    let laid: Vec<(Vec<[f64; 2]>, [f64; 2])> = pieces.iter().map(|p| placed(&outline(p.unrolling), &p.unrolling.centre)).collect();
    let widest = laid.iter().map(|(_, size)| size[0]).fold(0.0, f64::max);
    let tallest = laid.iter().map(|(_, size)| size[1]).fold(0.0, f64::max);
    let font = (0.3 * tallest).clamp(8.0, 200.0);
    let sheet_width = widest.max(40.0 * font) + 2.0 * MARGIN_MM;
    let row_height = |size: [f64; 2]| 1.5 * font + size[1] + MARGIN_MM;
    let sheet_height = laid.iter().map(|(_, size)| row_height(*size)).sum::<f64>() + MARGIN_MM;
    let mut svg = Svg::new(sheet_width, sheet_height, "mm", "lamella cut sheet (mm)");
    svg.element(&format!("<g fill=\"none\" stroke=\"#d00\" {CUT_LINE}>"));
    let mut top = MARGIN_MM;
    for ((outline, size), piece) in laid.iter().zip(pieces) {
        let y0 = top + 1.5 * font;
        let shifted = outline.iter().map(|p| [MARGIN_MM + p[0], y0 + p[1]]);
        svg.element(&format!("<polygon class=\"strip\" id=\"{}\" points=\"{}\"/>", piece.name, points(shifted)));
        let label = format!("{}  length {:.0} mm  width {:.0} mm", piece.name, MM * piece.unrolling.length, size[1]);
        svg.text(MARGIN_MM, top + font, &format!("class=\"label\" font-size=\"{}\" fill=\"#000\" stroke=\"none\" font-family=\"sans-serif\"", super::num(font)), &label);
        top += row_height(*size);
    }
    svg.element("</g>");
    svg.finish()
}
