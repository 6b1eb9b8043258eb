//! The cut drawing of a plan, once, for every file format: the boards one above the other, the
//! pieces on them, in millimetres with y up (board 1 at the bottom). The DXF and SVG writers draw
//! exactly these items, so the two files hold the same outlines.
use super::plan::FabricationPlan;

/// Millimetres per metre (mesh units are metres).
pub const MM: f64 = 1000.0;
/// Space between boards in the drawing, mm.
const BOARD_SPACING_MM: f64 = 100.0;

/// What a drawing item is, which decides its layer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layer {
    /// A board's or sheet's outline.
    Stock,
    /// A piece's cut line.
    Outline,
    /// A piece's centre line.
    CentreLine,
    /// Splice and node marks.
    Marks,
    /// Piece labels.
    Label,
}

impl Layer {
    /// The layer's name in DXF (and its class in SVG, lower case).
    pub fn name(self) -> &'static str {
        match self {
            Layer::Stock => "STOCK",
            Layer::Outline => "OUTLINE",
            Layer::CentreLine => "CENTRELINE",
            Layer::Marks => "MARKS",
            Layer::Label => "LABEL",
        }
    }
}

/// One item of the drawing, in mm.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A polyline on `layer`, closed or open; `piece` indexes the plan's pieces (None for a board).
    Polyline { layer: Layer, points: Vec<[f64; 2]>, closed: bool, piece: Option<usize> },
    /// A straight mark.
    Line { from: [f64; 2], to: [f64; 2] },
    /// A node mark.
    Circle { centre: [f64; 2], radius: f64 },
    /// A label: left end of the baseline, height.
    Text { position: [f64; 2], height: f64, text: String, piece: usize },
}

/// The drawing of a plan: its items and its extent (mm).
#[derive(Clone, Debug, PartialEq)]
pub struct Sheet {
    pub items: Vec<Item>,
    pub size: [f64; 2],
}

/// The drawing of `plan`.
pub fn sheet(plan: &FabricationPlan) -> Sheet {
    let [length, width] = plan.board_size.map(|x| x * MM);
    let board_bottom = |b: usize| b as f64 * (width + BOARD_SPACING_MM);
    let mut items: Vec<Item> = (0..plan.boards)
        .map(|b| {
            let y = board_bottom(b);
            Item::Polyline { layer: Layer::Stock, points: vec![[0.0, y], [length, y], [length, y + width], [0.0, y + width]], closed: true, piece: None }
        })
        .collect();
    for (k, piece) in plan.pieces.iter().enumerate() {
        let origin = [piece.placement.position[0] * MM, board_bottom(piece.placement.board) + piece.placement.position[1] * MM];
        let at = |p: &[f64; 2]| [origin[0] + p[0] * MM, origin[1] + p[1] * MM];
        let shape = &piece.shape;
        items.push(Item::Polyline { layer: Layer::Outline, points: shape.outline.iter().map(at).collect(), closed: true, piece: Some(k) });
        items.push(Item::Polyline { layer: Layer::CentreLine, points: shape.centre.iter().map(at).collect(), closed: false, piece: Some(k) });
        items.extend(shape.splice_marks.iter().map(|[a, b]| Item::Line { from: at(a), to: at(b) }));
        items.extend(shape.node_marks.iter().map(|p| Item::Circle { centre: at(p), radius: 0.1 * piece.width * MM }));
        items.push(Item::Text { position: at(&shape.label.position), height: shape.label.height * MM, text: shape.label.text.clone(), piece: k });
    }
    let size = [length, if plan.boards == 0 { 0.0 } else { board_bottom(plan.boards - 1) + width }];
    Sheet { items, size }
}

/// The colour of a utilisation: green at 0, yellow at 0.5, orange at 1, red beyond (RGB bytes).
pub fn utilisation_rgb(utilisation: f64) -> [u8; 3] {
    let u = if utilisation.is_finite() { utilisation.max(0.0) } else { 2.0 };
    let rgb = if u > 1.0 {
        [0.85, 0.0, 0.1]
    } else if u > 0.5 {
        [1.0, 0.85 - 0.45 * (u - 0.5) / 0.5, 0.0]
    } else {
        [u / 0.5, 0.65 + 0.2 * u / 0.5, 0.0]
    };
    rgb.map(|c: f64| (255.0 * c).round() as u8)
}
