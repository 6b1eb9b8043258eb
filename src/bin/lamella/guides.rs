//! Guide curves (paper Sec. 3.2.1): traced from evenly spaced points of one side of the outer
//! boundary, written to and read from guides.json (the file `lamella trace` hands to `field` and
//! `design`), and drawn as guides.obj.
use crate::config::GuideSide;
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::input::clip_words;
use lamella::mesh::{EdgePoint, TriMesh};
use lamella::tracing::{intersections, trace_guide_set, IntersectionReport, StopReason, TracedCurve};
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use std::path::Path;

/// Traced guides with how they were made.
pub struct Guides {
    pub curves: Vec<TracedCurve>,
    /// The boundary side they start from (index among the sides of the outer loop).
    pub side: usize,
    pub theta: f64,
    pub start_angle: f64,
}

/// Traces `count` P-curves of angle `theta` from evenly spaced points of a side of the outer
/// boundary, leaving it at `start_angle` (see [`trace_guide_set`]).
pub fn trace_guides(mesh: &TriMesh, count: usize, side: GuideSide, start_angle: f64, theta: f64) -> CliResult<Guides> {
    let index = match side {
        GuideSide::Index(k) => Some(k),
        GuideSide::Longest => None,
    };
    let set = trace_guide_set(mesh, count, index, start_angle, theta).map_err(|(guide, e)| match (guide, index) {
        (Some(i), _) => CliError::bad_input(format!("guide {i}: {e}")),
        (None, Some(k)) => CliError::bad_input(format!("--guide-side {k}: {e}")),
        (None, None) => CliError::bad_input(format!("guides: {e}")),
    })?;
    Ok(Guides { curves: set.curves, side: set.side, theta, start_angle })
}

/// Fails with a message naming the first crossing when guides cross (an initial field needs
/// an ordered, intersection-free set, Sec. 3.2.2).
pub fn require_no_crossings(report: &IntersectionReport) -> CliResult<()> {
    let first = report.crossings.first().or(report.self_intersections.first());
    match first {
        None => Ok(()),
        Some(c) => {
            let p = c.position;
            let which = if c.curves[0] == c.curves[1] {
                format!("guide {} crosses itself", c.curves[0])
            } else {
                format!("guides {} and {} cross", c.curves[0], c.curves[1])
            };
            Err(CliError::bad_input(format!(
                "{which} at ({:.3}, {:.3}, {:.3}) ({} crossing(s), {} self-intersection(s)); try another --guide-angle or --guide-side",
                p.x,
                p.y,
                p.z,
                report.crossings.len(),
                report.self_intersections.len()
            )))
        }
    }
}

/// Crossings of traced guides.
pub fn crossings(mesh: &TriMesh, guides: &Guides) -> IntersectionReport {
    intersections(mesh, &guides.curves)
}

pub fn stop_name(stop: StopReason) -> &'static str {
    match stop {
        StopReason::Boundary => "boundary",
        StopReason::NoValidCandidate => "no valid continuation",
        StopReason::LengthLimit => "length limit",
        StopReason::PointLimit => "point limit",
    }
}

/// guides.json: how the guides were traced and, per guide, its edge points (edge, t) and their
/// positions. `field --guides-file` reads the edge points (and θ).
#[derive(Serialize, Deserialize)]
pub struct GuidesFile {
    pub theta_degrees: f64,
    pub start_angle_degrees: f64,
    pub side: usize,
    pub guides: Vec<GuideRecord>,
}

#[derive(Serialize, Deserialize)]
pub struct GuideRecord {
    pub stop: String,
    pub length: f64,
    pub points: Vec<GuidePoint>,
}

#[derive(Serialize, Deserialize)]
pub struct GuidePoint {
    pub edge: [u32; 2],
    pub t: f64,
    pub position: [f64; 3],
}

pub fn guides_json(guides: &Guides) -> String {
    let file = GuidesFile {
        theta_degrees: guides.theta,
        start_angle_degrees: guides.start_angle,
        side: guides.side,
        guides: guides
            .curves
            .iter()
            .map(|c| GuideRecord {
                stop: stop_name(c.stop()).to_string(),
                length: c.length(),
                points: c
                    .points()
                    .iter()
                    .zip(c.positions())
                    .map(|(p, x)| GuidePoint { edge: p.edge, t: p.t, position: [x.x, x.y, x.z] })
                    .collect(),
            })
            .collect(),
    };
    // Serialising plain numbers and strings cannot fail; traced positions are finite.
    serde_json::to_string_pretty(&file).unwrap_or_default()
}

/// Reads guides.json: θ and each guide's edge points.
/// The file is read up to the input limit.
pub fn read_guides_json(path: &Path) -> CliResult<(f64, Vec<Vec<EdgePoint>>)> {
    parse_guides_json(&read_text(path)?, &path.display().to_string())
}

/// θ and the guides' edge points in the JSON `text` of the file `name` (named in errors, which
/// clip quoted input).
pub fn parse_guides_json(text: &str, name: &str) -> CliResult<(f64, Vec<Vec<EdgePoint>>)> {
    let file: GuidesFile =
        serde_json::from_str(text).map_err(|e| CliError::bad_input(format!("{name}: not a guides file: {}", clip_words(&e.to_string()))))?;
    let curves = file.guides.iter().map(|g| g.points.iter().map(|p| EdgePoint { edge: p.edge, t: p.t }).collect()).collect();
    Ok((file.theta_degrees, curves))
}

/// guides.obj: one named polyline (`l` element) per guide.
pub fn guides_obj(guides: &Guides) -> String {
    let mut obj = String::from("# guide P-curves traced by lamella\n");
    let mut next = 1;
    for (i, curve) in guides.curves.iter().enumerate() {
        let _ = writeln!(obj, "o guide_{i}");
        for p in curve.positions() {
            let _ = writeln!(obj, "v {} {} {}", p.x, p.y, p.z);
        }
        let indices: Vec<String> = (next..next + curve.positions().len()).map(|k| k.to_string()).collect();
        if indices.len() >= 2 {
            let _ = writeln!(obj, "l {}", indices.join(" "));
        }
        next += curve.positions().len();
    }
    obj
}
