//! convergence.svg: the energy terms of Eq. 12 against iteration, like the paper's Fig. 40:
//! E_angle on a log scale in the upper panel, the other terms (also log scale) in the lower one.
use super::{points, Svg};
use crate::field_files::HistoryRow;
use lamella::field::Energies;

const WIDTH: f64 = 800.0;
const PANEL_HEIGHT: f64 = 260.0;
const LEFT: f64 = 70.0;
const RIGHT: f64 = 150.0;
const TOP: f64 = 30.0;
const GAP: f64 = 60.0;

/// A plotted energy term: name, colour and how to read it.
struct Series {
    name: &'static str,
    colour: &'static str,
    value: fn(&Energies) -> f64,
}

const ANGLE: [Series; 1] = [Series { name: "E_angle", colour: "#c00", value: |e| e.angle }];
const OTHERS: [Series; 4] = [
    Series { name: "E_fair", colour: "#06c", value: |e| e.fair },
    Series { name: "E_grad", colour: "#090", value: |e| e.grad },
    Series { name: "E_frame", colour: "#c80", value: |e| e.frame },
    Series { name: "total", colour: "#000", value: |e| e.total },
];

/// `log10 v` for finite positive `v`; zero (e.g. E_frame at the start) has no place on a log scale.
fn log_value(v: f64) -> Option<f64> {
    (v.is_finite() && v > 0.0).then(|| v.log10())
}

/// One panel at vertical offset `top`.
fn panel(svg: &mut Svg, top: f64, title: &str, series: &[Series], history: &[HistoryRow]) {
    let plot_width = WIDTH - LEFT - RIGHT;
    let values = history.iter().flat_map(|h| series.iter().filter_map(move |s| log_value((s.value)(&h.energies))));
    let (low, high) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)));
    let (low, high) = if low.is_finite() { (low.floor(), high.ceil().max(low.floor() + 1.0)) } else { (0.0, 1.0) };
    let first = history.first().map_or(0, |h| h.iteration) as f64;
    let last = history.last().map_or(1, |h| h.iteration) as f64;
    let span = (last - first).max(1.0);
    let x = |iteration: usize| LEFT + plot_width * (iteration as f64 - first) / span;
    let y = |log: f64| top + PANEL_HEIGHT * (high - log) / (high - low);
    svg.text(LEFT, top - 10.0, "font-size=\"14\" font-family=\"sans-serif\"", title);
    svg.element(&format!(
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#888\"/>",
        super::num(LEFT),
        super::num(top),
        super::num(plot_width),
        super::num(PANEL_HEIGHT)
    ));
    // One tick per decade (at most about ten labels).
    let decades = (high - low) as usize;
    let every = decades.div_ceil(10).max(1);
    for d in (0..=decades).step_by(every) {
        let exponent = low + d as f64;
        svg.element(&format!("<line x1=\"{l}\" x2=\"{r}\" y1=\"{y}\" y2=\"{y}\" stroke=\"#ddd\"/>", l = super::num(LEFT), r = super::num(LEFT + plot_width), y = super::num(y(exponent))));
        svg.text(LEFT - 8.0, y(exponent) + 4.0, "font-size=\"11\" text-anchor=\"end\" font-family=\"sans-serif\"", &format!("1e{exponent}"));
    }
    for (k, s) in series.iter().enumerate() {
        // Zero values sit on the panel's lower edge.
        let line = points(history.iter().map(|h| [x(h.iteration), y(log_value((s.value)(&h.energies)).unwrap_or(low))]));
        svg.element(&format!("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\" points=\"{line}\"/>", s.colour));
        let ly = top + 20.0 + 18.0 * k as f64;
        svg.element(&format!("<line x1=\"{a}\" x2=\"{b}\" y1=\"{y}\" y2=\"{y}\" stroke=\"{}\" stroke-width=\"2\"/>", s.colour, a = super::num(WIDTH - RIGHT + 10.0), b = super::num(WIDTH - RIGHT + 30.0), y = super::num(ly)));
        svg.text(WIDTH - RIGHT + 36.0, ly + 4.0, "font-size=\"12\" font-family=\"sans-serif\"", s.name);
    }
    let bottom = top + PANEL_HEIGHT + 16.0;
    svg.text(LEFT, bottom, "font-size=\"11\" font-family=\"sans-serif\"", &format!("iteration {first}"));
    svg.text(LEFT + plot_width, bottom, "font-size=\"11\" text-anchor=\"end\" font-family=\"sans-serif\"", &format!("{last}"));
}

/// The plot of a field optimisation's history.
pub fn convergence_svg(history: &[HistoryRow]) -> String {
    let height = TOP + 2.0 * PANEL_HEIGHT + GAP + 30.0;
    let mut svg = Svg::new(WIDTH, height, "", "lamella field convergence");
    svg.element(&format!("<rect width=\"{}\" height=\"{}\" fill=\"#fff\"/>", super::num(WIDTH), super::num(height)));
    panel(&mut svg, TOP, "E_angle (log scale) against iteration", &ANGLE, history);
    panel(&mut svg, TOP + PANEL_HEIGHT + GAP, "E_fair, E_grad, E_frame and the weighted total (log scale)", &OTHERS, history);
    svg.finish()
}
