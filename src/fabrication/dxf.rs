//! cut.dxf: the cut drawing as an ASCII DXF of release 12 (AC1009, read by every CAM program),
//! in millimetres, with the layers STOCK (boards), OUTLINE (cut lines, closed POLYLINEs),
//! CENTRELINE (open POLYLINEs), MARKS (splice LINEs, node CIRCLEs) and LABEL (TEXT).
//! Outlines of pieces stressed beyond the allowable stress are drawn in red (colour 1).
use super::plan::FabricationPlan;
use super::sheet::{sheet, Item, Layer};
use std::fmt::Write as _;

/// The layers with their AutoCAD colour indices.
const LAYERS: [(Layer, u8); 5] = [(Layer::Stock, 8), (Layer::Outline, 7), (Layer::CentreLine, 5), (Layer::Marks, 3), (Layer::Label, 2)];
/// Colour index of an overstressed piece's outline.
const OVERSTRESSED_COLOUR: u8 = 1;

/// A DXF document being written: group code and value pairs, one per line each.
struct Dxf {
    text: String,
}

impl Dxf {
    fn pair(&mut self, code: u16, value: impl std::fmt::Display) {
        let _ = write!(self.text, "{code:>3}\n{value}\n");
    }

    /// A coordinate pair with the codes `10 + offset`, `20 + offset`, `30 + offset` (z = 0).
    fn point(&mut self, offset: u16, p: [f64; 2]) {
        self.pair(10 + offset, number(p[0]));
        self.pair(20 + offset, number(p[1]));
        self.pair(30 + offset, "0.0");
    }

    fn section(&mut self, name: &str) {
        self.pair(0, "SECTION");
        self.pair(2, name);
    }

    fn entity(&mut self, kind: &str, layer: Layer) {
        self.pair(0, kind);
        self.pair(8, layer.name());
    }
}

/// A coordinate in mm with 4 decimals; never NaN (non-finite values, which validated input
/// cannot produce, are written as 0).
fn number(value: f64) -> String {
    format!("{:.4}", if value.is_finite() { value } else { 0.0 })
}

/// The DXF text of `plan`'s cut drawing.
pub fn cut_dxf(plan: &FabricationPlan) -> String {
    let drawing = sheet(plan);
    let mut dxf = Dxf { text: String::new() };
    dxf.section("HEADER");
    dxf.pair(9, "$ACADVER");
    dxf.pair(1, "AC1009");
    dxf.pair(9, "$EXTMIN");
    dxf.point(0, [0.0, 0.0]);
    dxf.pair(9, "$EXTMAX");
    dxf.point(0, drawing.size);
    dxf.pair(0, "ENDSEC");
    dxf.section("TABLES");
    dxf.pair(0, "TABLE");
    dxf.pair(2, "LTYPE");
    dxf.pair(70, 1);
    dxf.pair(0, "LTYPE");
    dxf.pair(2, "CONTINUOUS");
    dxf.pair(70, 0);
    dxf.pair(3, "Solid line");
    dxf.pair(72, 65);
    dxf.pair(73, 0);
    dxf.pair(40, "0.0");
    dxf.pair(0, "ENDTAB");
    dxf.pair(0, "TABLE");
    dxf.pair(2, "LAYER");
    dxf.pair(70, LAYERS.len());
    for (layer, colour) in LAYERS {
        dxf.pair(0, "LAYER");
        dxf.pair(2, layer.name());
        dxf.pair(70, 0);
        dxf.pair(62, colour);
        dxf.pair(6, "CONTINUOUS");
    }
    dxf.pair(0, "ENDTAB");
    dxf.pair(0, "ENDSEC");
    dxf.section("ENTITIES");
    for item in &drawing.items {
        match item {
            Item::Polyline { layer, points, closed, piece } => {
                dxf.entity("POLYLINE", *layer);
                if piece.is_some_and(|k| *layer == Layer::Outline && plan.pieces[k].is_overstressed()) {
                    dxf.pair(62, OVERSTRESSED_COLOUR);
                }
                dxf.pair(66, 1);
                dxf.point(0, [0.0, 0.0]);
                dxf.pair(70, if *closed { 1 } else { 0 });
                for p in points {
                    dxf.entity("VERTEX", *layer);
                    dxf.point(0, *p);
                }
                dxf.entity("SEQEND", *layer);
            }
            Item::Line { from, to } => {
                dxf.entity("LINE", Layer::Marks);
                dxf.point(0, *from);
                dxf.point(1, *to);
            }
            Item::Circle { centre, radius } => {
                dxf.entity("CIRCLE", Layer::Marks);
                dxf.point(0, *centre);
                dxf.pair(40, number(*radius));
            }
            Item::Text { position, height, text, .. } => {
                dxf.entity("TEXT", Layer::Label);
                dxf.point(0, *position);
                dxf.pair(40, number(*height));
                // DXF text is one line of printable ASCII here: anything else becomes '?'.
                dxf.pair(1, text.chars().map(|c| if c.is_ascii_graphic() || c == ' ' { c } else { '?' }).collect::<String>());
            }
        }
    }
    dxf.pair(0, "ENDSEC");
    dxf.pair(0, "EOF");
    dxf.text
}
