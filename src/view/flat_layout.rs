//! The flat strips side by side for the viewer: each unrolling turned so that its chord (first
//! to last centre point) runs along +x, and the strips stacked in rows, one above the other.
use super::scene::ViewStrip;

/// A flat strip placed in the layout (metres): its boundaries, one point per ruling.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FlatPlacement {
    pub left: Vec<[f64; 2]>,
    pub right: Vec<[f64; 2]>,
}

/// Places the unrollings of `strips` (validated) one row each, from the top down, separated by
/// `gap` times the widest strip's height.
pub fn flat_layout(strips: &[ViewStrip], gap: f64) -> Vec<FlatPlacement> {
    let turned: Vec<FlatPlacement> = strips.iter().map(turned_flat).collect();
    let extent = |p: &FlatPlacement| {
        p.left.iter().chain(&p.right).fold([f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY], |e, q| {
            [e[0].min(q[0]), e[1].max(q[0]), e[2].min(q[1]), e[3].max(q[1])]
        })
    };
    let extents: Vec<[f64; 4]> = turned.iter().map(extent).collect();
    let tallest = extents.iter().map(|e| e[3] - e[2]).fold(0.0, f64::max);
    let mut top = 0.0;
    turned
        .into_iter()
        .zip(&extents)
        .map(|(p, e)| {
            let shift = [-e[0], top - e[3]];
            top -= (e[3] - e[2]) + gap * tallest;
            let moved = |q: &[f64; 2]| [q[0] + shift[0], q[1] + shift[1]];
            FlatPlacement { left: p.left.iter().map(moved).collect(), right: p.right.iter().map(moved).collect() }
        })
        .collect()
}

/// The unrolling of `strip` turned so that its centre line's chord runs along +x.
fn turned_flat(strip: &ViewStrip) -> FlatPlacement {
    let u = &strip.unrolling;
    let centre = |i: usize| [(u.left[i][0] + u.right[i][0]) / 2.0, (u.left[i][1] + u.right[i][1]) / 2.0];
    let (first, last) = (centre(0), centre(u.left.len() - 1));
    let angle = (last[1] - first[1]).atan2(last[0] - first[0]);
    let (sin, cos) = (-angle).sin_cos();
    let turn = |q: &[f64; 2]| {
        let (x, y) = (q[0] - first[0], q[1] - first[1]);
        [cos * x - sin * y, sin * x + cos * y]
    };
    FlatPlacement { left: u.left.iter().map(turn).collect(), right: u.right.iter().map(turn).collect() }
}
