//! The HTML page: the scene as JSON (geometry quantised, base64) in a data block, the viewer's
//! stylesheet and script inline, nothing loaded from elsewhere.
use super::error::ViewError;
use super::flat_layout::flat_layout;
use super::quantise::QuantisedPoints;
use super::scene::ViewScene;
use serde_json::{json, Value};

/// The page skeleton: `{{NAME}}` marks where [`view_html`] fills in the parts.
const TEMPLATE: &str = include_str!("page.html");
const STYLE: &str = include_str!("viewer.css");
const SCRIPT: &str = include_str!("viewer.js");

/// The id of the element into which the page writes its self-check once drawn: JSON with
/// `webgl` (whether a WebGL context was created), `strips_expected` (strips in the data),
/// `strips_drawn` (strips put into the 3D and flat views), `strips_seen` (strips whose ids the
/// picking pass found in the 3D view), `colours` (the first strips' colours, `#rrggbb`),
/// `colouring`, `legend` and `info` (the colouring shown, the legend's and the strip panel's
/// text) and `errors` (script errors and `console.error` messages, empty when all went well).
/// The page's address may choose the colouring and select a strip: `view.html#colour=angle&strip=3`
/// (colourings `strip`, `family`, `angle`, `utilisation`).
pub const SELF_CHECK_ID: &str = "lamella-self-check";

/// Gap between the rows of flat strips, in strip heights.
const FLAT_GAP: f64 = 0.6;

/// The viewer page of `scene`: one self-contained HTML file (no network access, no other files)
/// with the geometry quantised to 16 bits of the scene's bounding box. Deterministic: the same
/// scene gives the same bytes.
pub fn view_html(scene: &ViewScene) -> Result<String, ViewError> {
    scene.validate()?;
    let data = scene_data(scene);
    // `<` only occurs inside JSON strings, where `\u003c` means the same: no `</script>` can end
    // the data block early.
    let data = serde_json::to_string(&data).unwrap_or_default().replace('<', "\\u003c");
    let parts = [("TITLE", escape_html(&scene.title)), ("STYLE", STYLE.to_string()), ("DATA", data), ("SCRIPT", SCRIPT.to_string()), ("SELF_CHECK_ID", SELF_CHECK_ID.to_string())];
    Ok(fill(TEMPLATE, &parts))
}

/// `template` with every `{{NAME}}` replaced by its part (unknown names are kept), in one pass,
/// so that text inside the parts is never taken for a marker.
fn fill(template: &str, parts: &[(&str, String)]) -> String {
    let mut pieces = template.split("{{");
    let mut page = pieces.next().unwrap_or_default().to_string();
    for piece in pieces {
        let known = piece.split_once("}}").and_then(|(name, rest)| parts.iter().find(|p| p.0 == name).map(|p| (&p.1, rest)));
        match known {
            Some((value, rest)) => {
                page.push_str(value);
                page.push_str(rest);
            }
            None => {
                page.push_str("{{");
                page.push_str(piece);
            }
        }
    }
    page
}

fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The scene as the script reads it.
fn scene_data(scene: &ViewScene) -> Value {
    let (low, high) = scene.bounding_box();
    let quantised = |points: Vec<[f64; 3]>| QuantisedPoints::new(points, low, high).base64;
    let surface = scene.surface.as_ref().map(|s| {
        let triangles: Vec<u8> = s.triangles.iter().flatten().flat_map(|v| v.to_le_bytes()).collect();
        json!({
            "vertices": s.positions.len(),
            "positions": quantised(s.positions.iter().map(|p| [p.x, p.y, p.z]).collect()),
            "triangles": super::base64::encode(&triangles),
        })
    });
    let curve_points: Vec<[f64; 3]> = scene.curves.iter().flatten().map(|p| [p.x, p.y, p.z]).collect();
    let strip_points: Vec<[f64; 3]> =
        scene.strips.iter().flat_map(|s| s.left.iter().zip(&s.right).flat_map(|(l, r)| [[l.x, l.y, l.z], [r.x, r.y, r.z]])).collect();
    let flat = flat_layout(&scene.strips, FLAT_GAP);
    let flat_points: Vec<[f64; 2]> = flat.iter().flat_map(|p| p.left.iter().zip(&p.right).flat_map(|(l, r)| [*l, *r])).collect();
    let (flat_low, flat_high) = flat_points.iter().fold(([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]), |(low, high), p| {
        ([low[0].min(p[0]), low[1].min(p[1])], [high[0].max(p[0]), high[1].max(p[1])])
    });
    let (flat_low, flat_high) = if flat_points.is_empty() { ([0.0; 2], [1.0; 2]) } else { (flat_low, flat_high) };
    let strips: Vec<Value> = scene
        .strips
        .iter()
        .map(|s| json!({ "name": s.name, "family": s.family, "rulings": s.left.len(), "metrics": s.metrics, "utilisation": s.utilisation }))
        .collect();
    json!({
        "title": scene.title,
        "lamella_version": env!("CARGO_PKG_VERSION"),
        "families": scene.families,
        "box": { "low": low, "high": high },
        "surface": surface,
        "curves": { "counts": scene.curves.iter().map(Vec::len).collect::<Vec<_>>(), "positions": quantised(curve_points) },
        "strips": strips,
        "strip_positions": quantised(strip_points),
        "flat": { "low": flat_low, "high": flat_high, "positions": QuantisedPoints::new(flat_points, flat_low, flat_high).base64 },
        "has_utilisation": scene.strips.iter().any(|s| s.utilisation.is_some()),
    })
}
