//! The cut files of a fabrication plan: cut.dxf read back by an independent DXF reader (the `dxf`
//! crate) holds the same outlines as cut.svg to 0.01 mm, on the layers a workshop expects; the
//! pieces cover their strips with the splice overlaps; the packing keeps pieces apart and on
//! their boards; labels sit inside their pieces; the files are the same bits on every run.

use crate::fabrication_support;

use dxf::entities::EntityType;
use dxf::Drawing;
use fabrication_support::{helix_length, helix_pattern, timber_params};
use lamella::fabrication::{bom_csv, cut_dxf, cut_svg, plan_fabrication, FabricationPlan, Stock};
use std::collections::BTreeMap;

fn plan() -> FabricationPlan {
    plan_fabrication(&helix_pattern(), &timber_params()).expect("valid plan")
}

/// A polyline of the drawing: its layer, whether it is closed, its points (mm).
type Polyline = (String, bool, Vec<[f64; 2]>);

/// Polylines as read by the `dxf` crate, and the drawing.
fn dxf_polylines(text: &str) -> (Vec<Polyline>, Drawing) {
    let drawing = Drawing::load(&mut text.as_bytes()).expect("the DXF parses");
    let polylines = drawing
        .entities()
        .filter_map(|e| match &e.specific {
            EntityType::Polyline(p) => Some((e.common.layer.clone(), p.is_closed(), p.vertices().map(|v| [v.location.x, v.location.y]).collect())),
            _ => None,
        })
        .collect();
    (polylines, drawing)
}

/// The value of attribute `name` in an SVG element.
fn attribute<'a>(element: &'a str, name: &str) -> Option<&'a str> {
    let start = element.find(&format!(" {name}=\""))? + name.len() + 3;
    Some(&element[start..start + element[start..].find('"')?])
}

/// The outline polygons of cut.svg by piece id, and the document height (mm).
fn svg_outlines(text: &str) -> (BTreeMap<String, Vec<[f64; 2]>>, f64) {
    let height: f64 = attribute(&text[text.find("<svg").expect("svg element")..], "height").expect("height").trim_end_matches("mm").parse().expect("number");
    let outlines = text
        .lines()
        .filter(|l| l.starts_with("<polygon class=\"outline\""))
        .map(|l| {
            let points = attribute(l, "points")
                .expect("points")
                .split(' ')
                .map(|pair| {
                    let (x, y) = pair.split_once(',').expect("x,y");
                    [x.parse().expect("x"), y.parse().expect("y")]
                })
                .collect();
            (attribute(l, "id").expect("id").to_string(), points)
        })
        .collect();
    (outlines, height)
}

#[test]
fn dxf_reads_back_with_the_svg_outlines_on_the_workshop_layers() {
    let plan = plan();
    let (polylines, drawing) = dxf_polylines(&cut_dxf(&plan));
    let layers: Vec<String> = drawing.layers().map(|l| l.name.clone()).collect();
    for name in ["OUTLINE", "LABEL", "MARKS", "CENTRELINE"] {
        assert!(layers.iter().any(|l| l == name), "layer {name} missing from {layers:?}");
    }
    let outlines: Vec<&Vec<[f64; 2]>> = polylines.iter().filter(|(layer, closed, _)| layer == "OUTLINE" && *closed).map(|(_, _, p)| p).collect();
    let centre_lines = polylines.iter().filter(|(layer, closed, _)| layer == "CENTRELINE" && !*closed).count();
    assert_eq!(outlines.len(), plan.pieces.len());
    assert_eq!(centre_lines, plan.pieces.len());
    let texts: Vec<String> = drawing
        .entities()
        .filter(|e| e.common.layer == "LABEL")
        .filter_map(|e| match &e.specific {
            EntityType::Text(t) => Some(t.value.clone()),
            _ => None,
        })
        .collect();
    let ids: Vec<String> = plan.pieces.iter().map(|p| p.id.clone()).collect();
    assert_eq!(texts, ids, "one label per piece, its id (none is over 100 % here)");
    // Splices: two marks per splice (one on each piece), on MARKS.
    let splices: usize = plan.pieces.iter().filter(|p| p.next.is_some()).count();
    let marks = drawing.entities().filter(|e| e.common.layer == "MARKS" && matches!(e.specific, EntityType::Line(_))).count();
    assert_eq!(marks, 2 * splices);

    let (svg, height) = svg_outlines(&cut_svg(&plan));
    assert_eq!(svg.len(), plan.pieces.len());
    for (piece, dxf_points) in plan.pieces.iter().zip(&outlines) {
        let svg_points = &svg[&piece.id];
        assert_eq!(svg_points.len(), dxf_points.len(), "{}", piece.id);
        for (a, b) in dxf_points.iter().zip(svg_points) {
            // SVG's y runs down from the top of the same drawing.
            let gap = (a[0] - b[0]).hypot((height - a[1]) - b[1]);
            assert!(gap <= 0.01, "{}: DXF {a:?} vs SVG {b:?} ({gap} mm)", piece.id);
        }
    }
}

#[test]
fn pieces_cover_each_strip_with_the_overlaps_and_fit_the_stock() {
    let plan = plan();
    let strips = helix_pattern();
    let lengths = [helix_length(6.0, 0.4, 0.5), helix_length(8.0, 0.3, 1.6), helix_length(12.0, 0.5, 0.9), helix_length(5.0, 1.0, 1.2)];
    let (polylines, _) = dxf_polylines(&cut_dxf(&plan));
    let centre_lines: Vec<&Vec<[f64; 2]>> = polylines.iter().filter(|(layer, _, _)| layer == "CENTRELINE").map(|(_, _, p)| p).collect();
    let overlap = plan.params.stock.overlap;
    for (index, (strip, analytic)) in strips.iter().zip(lengths).enumerate() {
        let pieces: Vec<usize> = (0..plan.pieces.len()).filter(|&k| plan.pieces[k].strip == index).collect();
        // The sampled helix is a polygon inscribed in the curve: shorter by O(h²).
        let polygon: f64 = strip.centre.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
        assert!((polygon / analytic - 1.0).abs() < 1e-4);
        let expected_count = if polygon <= 4.8 { 1 } else { ((polygon - overlap) / (4.8 - overlap)).ceil() as usize };
        assert_eq!(pieces.len(), expected_count, "{}", strip.name);
        let sum: f64 = pieces.iter().map(|&k| plan.pieces[k].length()).sum();
        let expected = polygon + overlap * (pieces.len() - 1) as f64;
        assert!((sum - expected).abs() < 1e-9, "{}: {sum} vs {expected}", strip.name);
        // The same from the drawing: the flat centre lines, in mm.
        let drawn: f64 = pieces.iter().map(|&k| centre_lines[k].windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum::<f64>()).sum();
        assert!((drawn / 1000.0 - expected).abs() < 1e-5, "{}: drawn {drawn} mm vs {expected} m", strip.name);
        for (n, &k) in pieces.iter().enumerate() {
            let piece = &plan.pieces[k];
            assert_eq!(piece.id, format!("{}-{}", strip.name, n + 1));
            assert!(piece.shape.size[0] <= 4.8 + 1e-12, "{} is {} m long", piece.id, piece.shape.size[0]);
            assert_eq!(piece.previous, (n > 0).then(|| k - 1));
        }
    }
    assert!(plan.pieces.len() > strips.len(), "the long strips were split");
}

/// Whether `p` lies inside the polygon (even-odd rule).
fn inside(p: [f64; 2], polygon: &[[f64; 2]]) -> bool {
    let mut crossings = false;
    for i in 0..polygon.len() {
        let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            crossings = !crossings;
        }
    }
    crossings
}

fn bounds(points: &[[f64; 2]]) -> [[f64; 2]; 2] {
    points.iter().fold([[f64::INFINITY; 2], [f64::NEG_INFINITY; 2]], |[lo, hi], p| [[lo[0].min(p[0]), lo[1].min(p[1])], [hi[0].max(p[0]), hi[1].max(p[1])]])
}

#[test]
fn packing_keeps_pieces_apart_inside_their_boards_with_labels_inside() {
    for width in [None, Some(0.65)] {
        let mut params = timber_params();
        params.stock = Stock { width, ..Stock::boards(4.8) };
        let plan = plan_fabrication(&helix_pattern(), &params).expect("valid plan");
        let [length, board_width] = plan.board_size;
        let boxes: Vec<(usize, [[f64; 2]; 2])> = plan
            .pieces
            .iter()
            .map(|p| {
                let placed: Vec<[f64; 2]> = p.shape.outline.iter().map(|q| [q[0] + p.placement.position[0], q[1] + p.placement.position[1]]).collect();
                (p.placement.board, bounds(&placed))
            })
            .collect();
        for (k, (board, [lo, hi])) in boxes.iter().enumerate() {
            assert!(*board < plan.boards);
            assert!(lo[0] >= -1e-12 && lo[1] >= -1e-12 && hi[0] <= length + 1e-12 && hi[1] <= board_width + 1e-12, "{} leaves its board", plan.pieces[k].id);
            for (other, (board2, [lo2, hi2])) in boxes.iter().enumerate().skip(k + 1) {
                let apart = board != board2 || hi[0] <= lo2[0] || hi2[0] <= lo[0] || hi[1] <= lo2[1] || hi2[1] <= lo[1];
                assert!(apart, "{} overlaps {}", plan.pieces[k].id, plan.pieces[other].id);
            }
        }
        // Yield: the pieces' area (≈ length × width of each) over the boards'.
        let area: f64 = plan.pieces.iter().map(|p| p.length() * p.width).sum();
        let stock = plan.boards as f64 * length * board_width;
        assert!((plan.material_yield() - area / stock).abs() < 0.01 * area / stock, "yield {} vs {}", plan.material_yield(), area / stock);
        assert!(plan.material_yield() <= 1.0);
        for piece in &plan.pieces {
            let [lo, hi] = piece.shape.label.bounds();
            for corner in [lo, hi, [lo[0], hi[1]], [hi[0], lo[1]]] {
                assert!(inside(corner, &piece.shape.outline), "label of {} leaves it at {corner:?}", piece.id);
            }
        }
    }
    // Wider sheets hold several rows: fewer boards than pieces.
    let mut params = timber_params();
    params.stock.width = Some(0.65);
    let plan = plan_fabrication(&helix_pattern(), &params).expect("valid plan");
    assert!(plan.boards < plan.pieces.len() / 2, "{} boards for {} pieces", plan.boards, plan.pieces.len());
}

#[test]
fn files_are_the_same_bits_on_every_run() {
    let (a, b) = (plan(), plan());
    assert_eq!(cut_dxf(&a), cut_dxf(&b));
    assert_eq!(cut_svg(&a), cut_svg(&b));
    assert_eq!(bom_csv(&a), bom_csv(&b));
    // The bill of materials: one line per piece with its board.
    let csv = bom_csv(&a);
    assert_eq!(csv.lines().count(), a.pieces.len() + 1);
    for (line, piece) in csv.lines().skip(1).zip(&a.pieces) {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields[0], piece.id);
        assert_eq!(fields[2], "geodesic");
        let length: f64 = fields[4].parse().expect("length");
        assert!((length - piece.length()).abs() < 1e-6);
        assert_eq!(fields[10].parse::<usize>().expect("board"), piece.placement.board + 1);
    }
}
