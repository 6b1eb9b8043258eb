//! unrolled.svg: the flat strips as a cut sheet in millimetres, packed in rows so that no two
//! outlines (or labels) overlap, each labelled with its id, length and width.
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
    /// Node marks on the flat strip (a gridshell's crossings, `lamella net`).
    pub marks: Vec<CutMark>,
}

/// A hole mark on a flat strip, in the unrolling's coordinates, labelled with the crossing strip.
pub struct CutMark {
    pub at: [f64; 2],
    pub label: String,
}

/// Radius of a node mark, in mm.
const MARK_RADIUS_MM: f64 = 4.0;

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

/// Estimated advance of sans-serif text per character, in font sizes.
const CHARACTER_WIDTH: f64 = 0.6;

/// The cut sheet of `pieces`, packed in shelves: left to right in the given order, a new row
/// when the next piece (or its label) would pass the widest piece's length.
pub fn cut_sheet_svg(pieces: &[CutPiece]) -> String {
    // Marks are placed with their outline (they lie on its centre line, inside it), then split off.
    let laid_with_marks: Vec<(Vec<[f64; 2]>, [f64; 2])> = pieces
        .iter()
        .map(|p| placed(&outline(p.unrolling).into_iter().chain(p.marks.iter().map(|m| m.at)).collect::<Vec<_>>(), &p.unrolling.centre))
        .collect();
    let laid: Vec<(Vec<[f64; 2]>, [f64; 2])> = laid_with_marks
        .iter()
        .zip(pieces)
        .map(|((points, size), p)| (points[..points.len() - p.marks.len()].to_vec(), *size))
        .collect();
    let tallest = laid.iter().map(|(_, size)| size[1]).fold(0.0, f64::max);
    let font = (0.3 * tallest).clamp(8.0, 200.0);
    let labels: Vec<String> = pieces
        .iter()
        .zip(&laid)
        .map(|(p, (_, size))| format!("{}  length {:.0} mm  width {:.0} mm", p.name, MM * p.unrolling.length, size[1]))
        .collect();
    // Each piece's slot: wide enough for its outline and its label.
    let slots: Vec<f64> = laid
        .iter()
        .zip(&labels)
        .map(|((_, size), label)| size[0].max(CHARACTER_WIDTH * font * label.chars().count() as f64))
        .collect();
    let inner_width = slots.iter().copied().fold(0.0, f64::max);
    let mut origins = Vec::with_capacity(pieces.len());
    let (mut x, mut top, mut row_height) = (0.0, MARGIN_MM, 0.0_f64);
    for ((_, size), slot) in laid.iter().zip(&slots) {
        if x > 0.0 && x + slot > inner_width {
            top += row_height + MARGIN_MM;
            x = 0.0;
            row_height = 0.0;
        }
        origins.push([MARGIN_MM + x, top]);
        x += slot + MARGIN_MM;
        row_height = row_height.max(1.5 * font + size[1]);
    }
    let sheet_width = inner_width + 2.0 * MARGIN_MM;
    let sheet_height = top + row_height + MARGIN_MM;
    let mut svg = Svg::new(sheet_width, sheet_height, "mm", "lamella cut sheet (mm)");
    svg.element(&format!("<g fill=\"none\" stroke=\"#d00\" {CUT_LINE}>"));
    let label_style = format!("class=\"label\" font-size=\"{}\" fill=\"#000\" stroke=\"none\" font-family=\"sans-serif\"", super::num(font));
    for (((outline, _), piece), (origin, label)) in laid.iter().zip(pieces).zip(origins.iter().zip(&labels)) {
        let shifted = outline.iter().map(|p| [origin[0] + p[0], origin[1] + 1.5 * font + p[1]]);
        svg.element(&format!("<polygon class=\"strip\" id=\"{}\" points=\"{}\"/>", piece.name, points(shifted)));
        svg.text(origin[0], origin[1] + font, &label_style, label);
    }
    let mark_style = format!("class=\"node\" font-size=\"{}\" fill=\"#000\" stroke=\"none\" font-family=\"sans-serif\"", super::num(0.5 * font));
    for (((points, _), piece), origin) in laid_with_marks.iter().zip(pieces).zip(&origins) {
        let marks = &points[points.len() - piece.marks.len()..];
        for (p, mark) in marks.iter().zip(&piece.marks) {
            let (x, y) = (origin[0] + p[0], origin[1] + 1.5 * font + p[1]);
            svg.element(&format!("<circle class=\"node\" cx=\"{}\" cy=\"{}\" r=\"{}\"/>", super::num(x), super::num(y), super::num(MARK_RADIUS_MM)));
            svg.text(x + MARK_RADIUS_MM, y - MARK_RADIUS_MM, &mark_style, &mark.label);
        }
    }
    svg.element("</g>");
    svg.finish()
}
