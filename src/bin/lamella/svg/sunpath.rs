//! sunpath.svg: the sky as a polar diagram (north up, east right, the horizon the outer circle,
//! the zenith the centre, elevation linear in the radius) with the sampled sun positions coloured
//! by the share of the samples in direct sun that the strips block at that hour, and the
//! boundary of the light region R_l (Eq. 24) in the earth-axis frame.
use super::shading::fraction_colour;
use super::{num, points, Svg};
use lamella::shading::{light_direction, EarthFrame, LightRegion, SunSample};

const SIZE: f64 = 640.0;
const RADIUS: f64 = 280.0;
/// Points along each side of the region's boundary.
const SIDE_POINTS: usize = 24;

pub fn sunpath_svg(frame: &EarthFrame, suns: &[SunSample], fractions: &[Option<f64>], region: &LightRegion) -> String {
    let c = SIZE / 2.0;
    let plot = |elevation: f64, azimuth: f64| {
        let r = RADIUS * (90.0 - elevation.clamp(0.0, 90.0)) / 90.0;
        let a = azimuth.to_radians();
        [c + r * a.sin(), c - r * a.cos()]
    };
    let mut svg = Svg::new(SIZE, SIZE + 40.0, "", "Sun path and light region");
    for elevation in [0.0, 30.0, 60.0] {
        let r = RADIUS * (90.0 - elevation) / 90.0;
        svg.element(&format!("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"none\" stroke=\"#999999\" stroke-width=\"1\"/>", num(c), num(c), num(r)));
    }
    for (label, azimuth) in [("N", 0.0), ("E", 90.0), ("S", 180.0), ("W", 270.0)] {
        let [x, y] = plot(-4.0, azimuth);
        svg.text(x - 5.0, y + 5.0, "font-family=\"sans-serif\" font-size=\"14\"", label);
    }
    let [d0, d1] = region.delta_degrees;
    let [g0, g1] = region.gamma_degrees;
    let lerp = |a: f64, b: f64, k: usize| a + (b - a) * k as f64 / SIDE_POINTS as f64;
    let boundary = (0..=SIDE_POINTS)
        .map(|k| (lerp(d0, d1, k), g0))
        .chain((0..=SIDE_POINTS).map(|k| (d1, lerp(g0, g1, k))))
        .chain((0..=SIDE_POINTS).map(|k| (lerp(d1, d0, k), g1)))
        .chain((0..=SIDE_POINTS).map(|k| (d0, lerp(g1, g0, k))))
        .map(|(d, g)| {
            let l = frame.to_model(&light_direction(d, g));
            plot(frame.elevation_degrees(&l), frame.azimuth_degrees(&l))
        });
    svg.element(&format!("<polygon points=\"{}\" fill=\"#f5e9a8\" fill-opacity=\"0.5\" stroke=\"#b08a00\" stroke-width=\"1.5\"/>", points(boundary)));
    for (sun, fraction) in suns.iter().zip(fractions) {
        let [x, y] = plot(sun.elevation_degrees, sun.azimuth_degrees);
        svg.element(&format!("<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{}\"/>", num(x), num(y), fraction_colour(*fraction)));
    }
    svg.text(
        10.0,
        SIZE + 25.0,
        "font-family=\"sans-serif\" font-size=\"12\"",
        "suns coloured by blocked share (blue 0 %, red 100 %, grey: no sample in direct sun); yellow: light region R_l",
    );
    svg.finish()
}
