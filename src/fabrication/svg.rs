//! cut.svg: the same cut drawing as cut.dxf (see [`super::sheet`]) as SVG in millimetres (y down,
//! so `y_svg = height − y_dxf`): boards in grey, each piece's outline filled with its
//! utilisation colour (red and labelled with its utilisation when over 100 %), centre lines,
//! marks and labels. Polygons carry the piece id and the class `outline`.
use super::plan::FabricationPlan;
use super::sheet::{sheet, utilisation_rgb, Item, Layer};
use std::fmt::Write as _;

/// A length in mm with 4 decimals (never NaN).
fn number(value: f64) -> String {
    format!("{:.4}", if value.is_finite() { value } else { 0.0 })
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The SVG text of `plan`'s cut drawing.
pub fn cut_svg(plan: &FabricationPlan) -> String {
    let drawing = sheet(plan);
    let height = drawing.size[1];
    let flip = |p: &[f64; 2]| format!("{},{}", number(p[0]), number(height - p[1]));
    let mut text = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let (w, h) = (number(drawing.size[0]), number(height));
    let _ = writeln!(text, "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\">");
    let _ = writeln!(text, "<title>lamella cut plan (mm): {} pieces on {} boards</title>", plan.pieces.len(), plan.boards);
    text.push_str("<g stroke-width=\"1\" vector-effect=\"non-scaling-stroke\" stroke-linejoin=\"round\">\n");
    for item in &drawing.items {
        match item {
            Item::Polyline { layer, points, closed, piece } => {
                let coordinates = points.iter().map(flip).collect::<Vec<_>>().join(" ");
                let (style, id) = match (layer, piece) {
                    (Layer::Outline, Some(k)) => {
                        let [r, g, b] = utilisation_rgb(plan.pieces[*k].max_utilisation);
                        (format!("fill=\"#{r:02x}{g:02x}{b:02x}\" fill-opacity=\"0.35\" stroke=\"#000\""), format!(" id=\"{}\"", escape(&plan.pieces[*k].id)))
                    }
                    (Layer::Stock, _) => ("fill=\"#eee\" stroke=\"#888\"".to_string(), String::new()),
                    _ => ("fill=\"none\" stroke=\"#00c\" stroke-dasharray=\"8 4\"".to_string(), String::new()),
                };
                let element = if *closed { "polygon" } else { "polyline" };
                let _ = writeln!(text, "<{element} class=\"{}\"{id} {style} points=\"{coordinates}\"/>", layer.name().to_lowercase());
            }
            Item::Line { from, to } => {
                let (a, b) = ([from[0], height - from[1]], [to[0], height - to[1]]);
                let _ = writeln!(
                    text,
                    "<line class=\"marks\" stroke=\"#080\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
                    number(a[0]),
                    number(a[1]),
                    number(b[0]),
                    number(b[1])
                );
            }
            Item::Circle { centre, radius } => {
                let _ = writeln!(
                    text,
                    "<circle class=\"marks\" fill=\"none\" stroke=\"#080\" cx=\"{}\" cy=\"{}\" r=\"{}\"/>",
                    number(centre[0]),
                    number(height - centre[1]),
                    number(*radius)
                );
            }
            Item::Text { position, height: size, text: label, piece } => {
                let fill = if plan.pieces[*piece].is_overstressed() { "#d00" } else { "#000" };
                let _ = writeln!(
                    text,
                    "<text class=\"label\" x=\"{}\" y=\"{}\" font-size=\"{}\" font-family=\"sans-serif\" fill=\"{fill}\" stroke=\"none\">{}</text>",
                    number(position[0]),
                    number(height - position[1]),
                    number(*size),
                    escape(label)
                );
            }
        }
    }
    text.push_str("</g>\n</svg>\n");
    text
}
