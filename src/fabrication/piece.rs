//! A piece to cut: the part of a strip's unrolling between two arc lengths, turned so that its
//! chord is horizontal and moved so that its bounding box starts at the origin, with its splice
//! marks, node marks and label.
use super::splicing::locate;
use crate::strips::Unrolling;

/// Characters' advance in text heights (sans-serif, generous), used to fit labels inside pieces.
pub const CHARACTER_WIDTH: f64 = 0.6;
/// Label height as a fraction of the strip's width.
const LABEL_HEIGHT_PER_WIDTH: f64 = 0.4;
/// Part of a piece's length a label may take.
const LABEL_LENGTH_FRACTION: f64 = 0.8;

/// A label: its text, the left end of its baseline and its height (metres, piece coordinates).
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    pub text: String,
    pub position: [f64; 2],
    pub height: f64,
}

impl Label {
    /// The label's box: lower-left and upper-right corners (baseline to cap height, estimated width).
    pub fn bounds(&self) -> [[f64; 2]; 2] {
        let width = CHARACTER_WIDTH * self.height * self.text.chars().count() as f64;
        [self.position, [self.position[0] + width, self.position[1] + self.height]]
    }
}

/// The flat shape of a piece in its own coordinates (metres): bounding box `[0, size]`.
#[derive(Clone, Debug, PartialEq)]
pub struct FlatShape {
    /// Closed outline: the boundary on the rulings' side forward, the other backward.
    pub outline: Vec<[f64; 2]>,
    /// The centre line.
    pub centre: Vec<[f64; 2]>,
    /// Splice marks: the ruling across the piece where the neighbouring piece's overlap ends.
    pub splice_marks: Vec<[[f64; 2]; 2]>,
    /// Node marks: points of the centre line.
    pub node_marks: Vec<[f64; 2]>,
    /// Size of the bounding box.
    pub size: [f64; 2],
    pub label: Label,
}

/// The unrolling's centre, left and right points at arc length `s` (`arc_length` per point).
fn section(unrolling: &Unrolling, arc_length: &[f64], s: f64) -> [[f64; 2]; 3] {
    let (i, f) = locate(arc_length, s);
    let j = (i + 1).min(arc_length.len() - 1);
    let lerp = |a: &[f64; 2], b: &[f64; 2]| [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])];
    [lerp(&unrolling.centre[i], &unrolling.centre[j]), lerp(&unrolling.left[i], &unrolling.left[j]), lerp(&unrolling.right[i], &unrolling.right[j])]
}

/// The piece `[start, end]` of `unrolling` with marks at `splices` and `nodes` (arc lengths)
/// and the label `text`, for a strip of width `width`.
pub fn cut_piece(unrolling: &Unrolling, arc_length: &[f64], interval: [f64; 2], splices: &[f64], nodes: &[f64], text: &str, width: f64) -> FlatShape {
    let [start, end] = interval;
    let inner = arc_length.iter().enumerate().filter(|(_, s)| **s > start && **s < end).map(|(i, _)| [unrolling.centre[i], unrolling.left[i], unrolling.right[i]]);
    let sections: Vec<[[f64; 2]; 3]> =
        std::iter::once(section(unrolling, arc_length, start)).chain(inner).chain(std::iter::once(section(unrolling, arc_length, end))).collect();
    let (first, last) = (sections[0][0], sections[sections.len() - 1][0]);
    let angle = (last[1] - first[1]).atan2(last[0] - first[0]);
    let (sin, cos) = (-angle).sin_cos();
    let turn = |p: [f64; 2]| [cos * p[0] - sin * p[1], sin * p[0] + cos * p[1]];
    let outline: Vec<[f64; 2]> = sections.iter().map(|s| turn(s[1])).chain(sections.iter().rev().map(|s| turn(s[2]))).collect();
    let mut low = [f64::INFINITY; 2];
    let mut high = [f64::NEG_INFINITY; 2];
    for p in &outline {
        for k in 0..2 {
            low[k] = low[k].min(p[k]);
            high[k] = high[k].max(p[k]);
        }
    }
    let place = |p: [f64; 2]| {
        let q = turn(p);
        [q[0] - low[0], q[1] - low[1]]
    };
    let outline = outline.iter().map(|p| [p[0] - low[0], p[1] - low[1]]).collect();
    let centre: Vec<[f64; 2]> = sections.iter().map(|s| place(s[0])).collect();
    let splice_marks = splices.iter().map(|s| section(unrolling, arc_length, *s)).map(|[_, l, r]| [place(l), place(r)]).collect();
    let node_marks = nodes.iter().filter(|s| **s >= start && **s <= end).map(|s| place(section(unrolling, arc_length, *s)[0])).collect();
    let size = [high[0] - low[0], high[1] - low[1]];
    let label = place_label(text, &centre, end - start, width);
    FlatShape { outline, centre, splice_marks, node_marks, size, label }
}

/// A label centred on the middle of the centre line, as high as 0.4 widths unless the piece is
/// too short for its text.
fn place_label(text: &str, centre: &[[f64; 2]], length: f64, width: f64) -> Label {
    let characters = text.chars().count().max(1) as f64;
    let height = (LABEL_HEIGHT_PER_WIDTH * width).min(LABEL_LENGTH_FRACTION * length / (CHARACTER_WIDTH * characters));
    // The centre point halfway along the centre line.
    let mut lengths = vec![0.0];
    for w in centre.windows(2) {
        lengths.push(lengths[lengths.len() - 1] + (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]));
    }
    let (i, f) = locate(&lengths, 0.5 * lengths[lengths.len() - 1]);
    let j = (i + 1).min(centre.len() - 1);
    let middle = [centre[i][0] + f * (centre[j][0] - centre[i][0]), centre[i][1] + f * (centre[j][1] - centre[i][1])];
    let text_width = CHARACTER_WIDTH * height * characters;
    Label { text: text.to_string(), position: [middle[0] - 0.5 * text_width, middle[1] - 0.5 * height], height }
}
