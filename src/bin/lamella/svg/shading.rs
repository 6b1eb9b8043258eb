//! shading.svg: the surface seen from the sun's side (orthographic, model up upwards), each
//! triangle coloured by the blocked fraction of the direct-sun hours at its corners (blue 0 %,
//! yellow 50 %, red 100 %; grey where the sun never reaches), the strips' centre curves drawn on
//! top, with a legend.
use super::{num, points, Svg};
use lamella::mesh::{TriMesh, Vec3};
use lamella::shading::{EarthFrame, SunSample};
use lamella::strips::StripPattern;

const IMAGE_WIDTH: f64 = 900.0;
const MARGIN: f64 = 20.0;
const LEGEND_HEIGHT: f64 = 50.0;

/// Colour of a blocked fraction in [0, 1].
pub fn fraction_colour(fraction: Option<f64>) -> String {
    let Some(f) = fraction.filter(|f| f.is_finite()) else { return "#bbbbbb".to_string() };
    let f = f.clamp(0.0, 1.0);
    let (low, mid, high) = ([49.0, 104.0, 206.0], [250.0, 214.0, 64.0], [206.0, 49.0, 49.0]);
    let (a, b, t) = if f < 0.5 { (low, mid, 2.0 * f) } else { (mid, high, 2.0 * f - 1.0) };
    let [r, g, bl] = [0, 1, 2].map(|k| (a[k] + (b[k] - a[k]) * t).round() as u8);
    format!("#{r:02x}{g:02x}{bl:02x}")
}

pub fn shading_svg(mesh: &TriMesh, fractions: &[Option<f64>], pattern: &StripPattern, frame: &EarthFrame, suns: &[SunSample]) -> String {
    let mean_sun: Vec3 = suns.iter().map(|s| s.direction).sum();
    let normal: Vec3 = mesh.vertex_normals().iter().sum();
    let view = if normal.dot(&mean_sun) < 0.0 { -normal } else { normal };
    let view = view.try_normalize(1e-12).unwrap_or(-frame.north());
    let right = frame.up.cross(&view).try_normalize(1e-9).unwrap_or_else(|| view.cross(&Vec3::x()).normalize());
    let up = view.cross(&right);
    let project = |p: &Vec3| [p.dot(&right), p.dot(&up)];
    let projected: Vec<[f64; 2]> = mesh.positions().iter().map(project).collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &projected {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-12);
    let scale = (IMAGE_WIDTH - 2.0 * MARGIN) / span;
    let height = (hi[1] - lo[1]) * scale + 2.0 * MARGIN + LEGEND_HEIGHT;
    let screen = |p: [f64; 2]| [MARGIN + (p[0] - lo[0]) * scale, MARGIN + (hi[1] - p[1]) * scale];
    let mut svg = Svg::new(IMAGE_WIDTH, height, "", "Blocked fraction of the direct-sun hours");
    for face in mesh.faces() {
        let known: Vec<f64> = face.iter().filter_map(|&v| fractions[v as usize]).collect();
        let mean = (!known.is_empty()).then(|| known.iter().sum::<f64>() / known.len() as f64);
        let colour = fraction_colour(mean);
        svg.element(&format!(
            "<polygon points=\"{}\" fill=\"{colour}\" stroke=\"{colour}\" stroke-width=\"0.5\"/>",
            points(face.iter().map(|&v| screen(projected[v as usize])))
        ));
    }
    for strip in &pattern.strips {
        svg.element(&format!("<polyline points=\"{}\" fill=\"none\" stroke=\"#222222\" stroke-width=\"1\"/>", points(strip.centre.iter().map(|p| screen(project(p))))));
    }
    let y = height - LEGEND_HEIGHT + 10.0;
    for k in 0..=10 {
        let f = k as f64 / 10.0;
        svg.element(&format!("<rect x=\"{}\" y=\"{}\" width=\"30\" height=\"14\" fill=\"{}\"/>", num(MARGIN + 32.0 * k as f64), num(y), fraction_colour(Some(f))));
    }
    svg.text(MARGIN, y + 32.0, "font-family=\"sans-serif\" font-size=\"12\"", "blocked share of the direct-sun hours: 0 % (left) to 100 % (right); grey: no direct sun");
    svg.finish()
}
