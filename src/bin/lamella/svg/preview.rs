//! preview.svg: an orthographic, flat-shaded view of the surface with the strips coloured per
//! strip, painted back to front, from a camera above and in front of the surface (z up).
use super::{points, Svg};
use lamella::mesh::{TriMesh, Vec3};
use lamella::strips::StripPattern;

const IMAGE_WIDTH: f64 = 1000.0;
const MARGIN: f64 = 20.0;
/// Camera direction (towards the viewer): azimuth and elevation in degrees.
const AZIMUTH: f64 = -60.0;
const ELEVATION: f64 = 30.0;
const SURFACE_RGB: [f64; 3] = [0.85, 0.85, 0.82];

/// An orthographic camera looking along `-view`, z up.
struct Camera {
    view: Vec3,
    right: Vec3,
    up: Vec3,
    light: Vec3,
}

impl Camera {
    fn default_view() -> Camera {
        let (az, el) = (AZIMUTH.to_radians(), ELEVATION.to_radians());
        let view = Vec3::new(el.cos() * az.cos(), el.cos() * az.sin(), el.sin());
        let right = (-view).cross(&Vec3::z()).normalize();
        let up = right.cross(&-view);
        let light = (view + Vec3::z() + right * 0.5).normalize();
        Camera { view, right, up, light }
    }

    /// Screen coordinates before fitting (y up).
    fn project(&self, p: &Vec3) -> [f64; 2] {
        [p.dot(&self.right), p.dot(&self.up)]
    }

    /// Lambert shading of a facet with normal `n` (two-sided).
    fn shade(&self, rgb: [f64; 3], n: &Vec3) -> String {
        let light = n.try_normalize(0.0).map_or(0.5, |n| n.dot(&self.light).abs());
        let k = 0.35 + 0.65 * light;
        let [r, g, b] = rgb.map(|c| (255.0 * c * k).round().clamp(0.0, 255.0) as u8);
        format!("#{r:02x}{g:02x}{b:02x}")
    }
}

/// Distinct colour of strip `id` (golden-angle hues).
fn strip_rgb(id: usize) -> [f64; 3] {
    let hue = (id as f64 * 137.507_764) % 360.0 / 60.0;
    let x = 1.0 - (hue % 2.0 - 1.0).abs();
    let [r, g, b] = match hue as usize {
        0 => [1.0, x, 0.0],
        1 => [x, 1.0, 0.0],
        2 => [0.0, 1.0, x],
        3 => [0.0, x, 1.0],
        4 => [x, 0.0, 1.0],
        _ => [1.0, 0.0, x],
    };
    // Saturation 0.75, value 0.95.
    [r, g, b].map(|c| 0.95 * (0.25 + 0.75 * c))
}

/// A facet to paint: corners, fill and outline.
struct Facet {
    corners: Vec<Vec3>,
    fill: String,
    stroke: String,
    depth: f64,
    /// Added to the depth: strips straddle the surface (half of each quad lies under it), so
    /// without a nudge towards the viewer the painter's order lets the nearby surface triangles
    /// cut every strip into a saw-tooth.
    lift: f64,
}

/// One strip to draw: its boundaries and the colour of each quad.
pub struct ColouredStrip<'a> {
    pub left: &'a [Vec3],
    pub right: &'a [Vec3],
    /// One colour per quad `(left_j, left_{j+1}, right_{j+1}, right_j)`.
    pub quad_rgb: Vec<[f64; 3]>,
}

/// Each strip of `pattern` in its own colour.
fn coloured_strips(pattern: &StripPattern) -> Vec<ColouredStrip<'_>> {
    pattern
        .strips
        .iter()
        .enumerate()
        .map(|(id, s)| ColouredStrip { left: &s.left, right: &s.right, quad_rgb: vec![strip_rgb(id); s.left.len().saturating_sub(1)] })
        .collect()
}

/// The preview image of `mesh` with `pattern`.
pub fn preview_svg(mesh: &TriMesh, pattern: &StripPattern) -> String {
    strips_view_svg(Some(mesh), &coloured_strips(pattern), "lamella preview: surface and strips")
}

/// The preview of a reshaped surface: each face coloured by the mean displacement of its
/// corners (`displacement`, one per vertex) from white (none) to red (the largest), with the strips.
pub fn displacement_preview_svg(mesh: &TriMesh, pattern: &StripPattern, displacement: &[f64]) -> String {
    let largest = displacement.iter().copied().filter(|d| d.is_finite()).fold(0.0, f64::max);
    let face_rgb = |f: usize| {
        let mean = mesh.faces()[f].iter().map(|&v| displacement.get(v as usize).copied().unwrap_or(0.0)).sum::<f64>() / 3.0;
        let k = if largest > 0.0 && mean.is_finite() { (mean / largest).clamp(0.0, 1.0) } else { 0.0 };
        [0.95, 0.95 * (1.0 - 0.8 * k), 0.95 * (1.0 - 0.8 * k)]
    };
    let title = format!("lamella reshape: displacement from the original surface (white 0, red {largest:.4})");
    view_svg(Some((mesh, &face_rgb)), &coloured_strips(pattern), &title)
}

/// The shaded view of `strips` (each quad in its colour) over the surface `mesh`, if given.
pub fn strips_view_svg(mesh: Option<&TriMesh>, strips: &[ColouredStrip], title: &str) -> String {
    view_svg(mesh.map(|m| (m, &(|_| SURFACE_RGB) as FaceColours)), strips, title)
}

/// The colour of each face of the surface, by face index.
type FaceColours<'a> = &'a dyn Fn(usize) -> [f64; 3];

/// [`strips_view_svg`] with each face of the surface in the colour `face_rgb` gives it.
fn view_svg(surface: Option<(&TriMesh, FaceColours)>, strips: &[ColouredStrip], title: &str) -> String {
    let camera = Camera::default_view();
    let mut facets: Vec<Facet> = Vec::new();
    if let Some((mesh, face_rgb)) = surface {
        for (f, face) in mesh.faces().iter().enumerate() {
            let corners: Vec<Vec3> = face.iter().map(|&v| mesh.positions()[v as usize]).collect();
            let fill = camera.shade(face_rgb(f), &mesh.face_normals()[f]);
            facets.push(Facet { depth: 0.0, lift: 0.0, stroke: fill.clone(), fill, corners });
        }
    }
    for strip in strips {
        for (j, rgb) in strip.quad_rgb.iter().enumerate().take(strip.left.len().min(strip.right.len()).saturating_sub(1)) {
            let corners = vec![strip.left[j], strip.left[j + 1], strip.right[j + 1], strip.right[j]];
            let normal = (corners[1] - corners[3]).cross(&(corners[2] - corners[0]));
            let fill = camera.shade(*rgb, &normal);
            let lift = (strip.left[j] - strip.right[j]).norm();
            facets.push(Facet { depth: 0.0, lift, stroke: "#333".into(), fill, corners });
        }
    }
    for facet in &mut facets {
        let n = facet.corners.len().max(1) as f64;
        facet.depth = facet.corners.iter().map(|c| c.dot(&camera.view)).sum::<f64>() / n + facet.lift;
    }
    // Far to near; ties keep the input order (stable sort), so the image is deterministic.
    facets.sort_by(|a, b| a.depth.total_cmp(&b.depth));
    let projected: Vec<Vec<[f64; 2]>> = facets.iter().map(|f| f.corners.iter().map(|c| camera.project(c)).collect()).collect();
    let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in projected.iter().flatten() {
        for k in 0..2 {
            low[k] = low[k].min(p[k]);
            high[k] = high[k].max(p[k]);
        }
    }
    let extent = [(high[0] - low[0]).max(f64::MIN_POSITIVE), (high[1] - low[1]).max(f64::MIN_POSITIVE)];
    let scale = if low[0].is_finite() { (IMAGE_WIDTH - 2.0 * MARGIN) / extent[0] } else { 1.0 };
    let height = if low[0].is_finite() { extent[1] * scale + 2.0 * MARGIN } else { 2.0 * MARGIN };
    let to_screen = |p: &[f64; 2]| [MARGIN + (p[0] - low[0]) * scale, MARGIN + (high[1] - p[1]) * scale];
    let mut svg = Svg::new(IMAGE_WIDTH, height, "", title);
    svg.element(&format!("<rect width=\"{}\" height=\"{}\" fill=\"#fff\"/>", super::num(IMAGE_WIDTH), super::num(height)));
    svg.element("<g stroke-width=\"0.4\" stroke-linejoin=\"round\">");
    for (facet, corners) in facets.iter().zip(&projected) {
        svg.element(&format!(
            "<polygon fill=\"{}\" stroke=\"{}\" points=\"{}\"/>",
            facet.fill,
            facet.stroke,
            points(corners.iter().map(to_screen))
        ));
    }
    svg.element("</g>");
    svg.finish()
}
