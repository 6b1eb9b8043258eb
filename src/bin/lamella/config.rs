//! The design parameters in force: flags over a `--config` TOML file over the defaults, checked
//! against their ranges.
use crate::args::{ConfigArgs, FamilyFlags, FieldFlags, GuideSeedingFlags, MeshArgs, OutArgs, StartFlags, StripFlags};
use lamella::mesh::Vec3;
use lamella::strips::DEFAULT_TOLERANCE_DEGREES;
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::input::{clip, clip_words};
use serde::Deserialize;
use std::path::{Path, PathBuf};

pub const DEFAULT_THETA: f64 = 60.0;
pub const DEFAULT_MAX_ITERATIONS: usize = 400;
pub const DEFAULT_STRIPS: usize = 20;
pub const DEFAULT_OUT: &str = "lamella-out";
pub const DEFAULT_GUIDE_ANGLE: f64 = 90.0;
pub const MAX_ITERATIONS_LIMIT: usize = 100_000;
pub const MAX_STRIPS: usize = 1000;
const MAX_GUIDES: usize = 100;

/// The keys a `design.toml` may set (all optional, same units as the flags).
#[derive(Deserialize, Default, Debug)]
#[serde(deny_unknown_fields)]
struct ConfigFile {
    mesh: Option<PathBuf>,
    out: Option<PathBuf>,
    theta: Option<f64>,
    family: Option<String>,
    max_iterations: Option<usize>,
    strips: Option<usize>,
    width: Option<f64>,
    tolerance: Option<f64>,
    guides: Option<usize>,
    guides_file: Option<PathBuf>,
    strokes: Option<PathBuf>,
    direction: Option<[f64; 3]>,
    start_field: Option<PathBuf>,
    guide_side: Option<String>,
    guide_angle: Option<f64>,
}

/// Where the field optimisation starts (paper Sec. 3.2.2).
#[derive(Debug, Clone, PartialEq)]
pub enum Start {
    /// The default start search ([`lamella::initialisation::StartSearch`]).
    Search,
    /// The height along a direction.
    Direction(Vec3),
    /// A field read from a file, one value per vertex.
    FieldFile(PathBuf),
    /// This many guide P-curves traced from the boundary (Sec. 3.2.1).
    Guides(usize),
    /// Guide curves saved by `lamella trace`.
    GuidesFile(PathBuf),
    /// Sketched strokes (Fig. 14).
    Strokes(PathBuf),
}

/// The boundary side guides start from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GuideSide {
    Longest,
    Index(usize),
}

/// Every parameter of a run, resolved and range-checked.
#[derive(Debug, Clone)]
pub struct Settings {
    /// `None`: the built-in hall roof.
    pub mesh: Option<PathBuf>,
    pub out: PathBuf,
    pub force: bool,
    /// Target angle θ in degrees (0 or 180 for the asymptotic family, 90 for the geodesic one).
    pub theta: f64,
    /// Whether θ was given (flag or file, or fixed by a family name) rather than defaulted;
    /// strokes estimate θ otherwise.
    pub theta_given: bool,
    pub start: Start,
    pub guide_side: GuideSide,
    /// Angle of the guides' first segments against the boundary, degrees.
    pub guide_angle: f64,
    pub max_iterations: usize,
    pub strips: usize,
    /// Strip width in mesh units; `None`: half the mean spacing of the level curves.
    pub width: Option<f64>,
    /// Largest angle error of an acceptable strip quad, degrees.
    pub tolerance: f64,
}

/// The flags a command may carry; absent groups stay at their defaults.
#[derive(Default)]
pub struct Flags<'a> {
    pub mesh: Option<&'a MeshArgs>,
    pub out: Option<&'a OutArgs>,
    pub family: Option<&'a FamilyFlags>,
    pub field: Option<&'a FieldFlags>,
    pub strips: Option<&'a StripFlags>,
    pub config: Option<&'a ConfigArgs>,
    pub start: Option<&'a StartFlags>,
}

impl Settings {
    pub fn resolve(flags: Flags) -> CliResult<Settings> {
        let file = match flags.config.and_then(|c| c.config.as_deref()) {
            Some(path) => read_config(path)?,
            None => ConfigFile::default(),
        };
        let family = flags.family.or(flags.field.map(|f| &f.family));
        let theta = family.and_then(|f| f.theta).or(file.theta);
        let name = family.and_then(|f| f.family.clone()).or(file.family.clone());
        let theta = resolve_family(theta, name.as_deref())?;
        let seeding = flags.start.map(|s| &s.seeding);
        let guide_side = match seeding.and_then(|s| s.guide_side.clone()).or(file.guide_side.clone()) {
            Some(text) => parse_guide_side(&text)?,
            None => GuideSide::Longest,
        };
        let settings = Settings {
            theta_given: theta.is_some(),
            start: resolve_start(flags.start, &file)?,
            guide_side,
            guide_angle: seeding.and_then(|s: &GuideSeedingFlags| s.guide_angle).or(file.guide_angle).unwrap_or(DEFAULT_GUIDE_ANGLE),
            mesh: flags.mesh.and_then(|m| m.mesh.clone()).or(file.mesh),
            out: flags.out.and_then(|o| o.out.clone()).or(file.out).unwrap_or_else(|| PathBuf::from(DEFAULT_OUT)),
            force: flags.out.is_some_and(|o| o.force),
            theta: theta.unwrap_or(DEFAULT_THETA),
            max_iterations: flags
                .field
                .and_then(|f| f.max_iterations)
                .or(file.max_iterations)
                .unwrap_or(DEFAULT_MAX_ITERATIONS),
            strips: flags.strips.and_then(|s| s.strips).or(file.strips).unwrap_or(DEFAULT_STRIPS),
            width: flags.strips.and_then(|s| s.width).or(file.width),
            tolerance: flags.strips.and_then(|s| s.tolerance).or(file.tolerance).unwrap_or(DEFAULT_TOLERANCE_DEGREES),
        };
        settings.check()?;
        Ok(settings)
    }

    fn check(&self) -> CliResult<()> {
        check_theta(self.theta)?;
        if !(1..=MAX_ITERATIONS_LIMIT).contains(&self.max_iterations) {
            return Err(out_of_range("max-iterations", self.max_iterations, &format!("1 to {MAX_ITERATIONS_LIMIT}")));
        }
        if !(1..=MAX_STRIPS).contains(&self.strips) {
            return Err(out_of_range("strips", self.strips, &format!("1 to {MAX_STRIPS}")));
        }
        if let Start::Guides(count) = self.start {
            if !(1..=MAX_GUIDES).contains(&count) {
                return Err(out_of_range("guides", count, &format!("1 to {MAX_GUIDES}")));
            }
        }
        if !(self.guide_angle.is_finite() && self.guide_angle > 0.0 && self.guide_angle < 180.0) {
            return Err(out_of_range("guide-angle", self.guide_angle, "between 0 and 180 degrees, exclusive"));
        }
        if let Some(width) = self.width {
            if !(width.is_finite() && width > 0.0) {
                return Err(out_of_range("width", width, "a finite length > 0 m"));
            }
        }
        check_tolerance(self.tolerance)?;
        if let Start::Direction(d) = self.start {
            if !(d.iter().all(|x| x.is_finite()) && d.norm() > 0.0) {
                return Err(CliError::bad_input(format!("parameter --direction = {},{},{} is not a non-zero finite vector", d.x, d.y, d.z)));
            }
        }
        Ok(())
    }
}

/// The tolerance of the verdict must lie in (0°, 180°).
pub fn check_tolerance(tolerance: f64) -> CliResult<()> {
    if tolerance.is_finite() && tolerance > 0.0 && tolerance < 180.0 {
        Ok(())
    } else {
        Err(out_of_range("tolerance", tolerance, "between 0 and 180 degrees, exclusive"))
    }
}

/// θ from `--theta` and `--family` (paper Sec. 3.2.2, Eq. 13): `(Some(θ), true)`-like pairs of
/// the angle and whether it was given. A family name fixes θ (0 for asymptotic curves, 90 for
/// geodesics) and must agree with a given θ; `pseudo-geodesic` needs a θ other than 0, 90, 180.
pub fn resolve_family(theta: Option<f64>, name: Option<&str>) -> CliResult<Option<f64>> {
    let named = |fixed: f64, other: Option<f64>, label: &str| match theta {
        Some(t) if t != fixed && Some(t) != other => {
            Err(CliError::bad_input(format!("--family {label} means θ = {fixed}°, but --theta = {t} was given")))
        }
        Some(t) => Ok(Some(t)),
        None => Ok(Some(fixed)),
    };
    match name {
        None => Ok(theta),
        Some("asymptotic") => named(0.0, Some(180.0), "asymptotic"),
        Some("geodesic") => named(90.0, None, "geodesic"),
        Some("pseudo-geodesic") => match theta {
            Some(t) if t == 0.0 || t == 90.0 || t == 180.0 => Err(CliError::bad_input(format!(
                "--family pseudo-geodesic needs a θ other than 0, 90 and 180 (θ = {t}° is the {} family)",
                if t == 90.0 { "geodesic" } else { "asymptotic" }
            ))),
            other => Ok(other),
        },
        Some(other) => Err(CliError::bad_input(format!(
            "parameter --family = {} is not asymptotic, geodesic or pseudo-geodesic (slope: only in `lamella field`)",
            clip(other)
        ))),
    }
}

/// The start flags win as a group over the file's start keys; at most one start may be given.
fn resolve_start(flags: Option<&StartFlags>, file: &ConfigFile) -> CliResult<Start> {
    let mut from_flags = Vec::new();
    if let Some(f) = flags {
        from_flags.extend(f.guides.map(Start::Guides));
        from_flags.extend(f.guides_file.clone().map(Start::GuidesFile));
        from_flags.extend(f.strokes.clone().map(Start::Strokes));
        if let Some(text) = &f.direction {
            from_flags.push(Start::Direction(parse_vector("--direction", text)?));
        }
        from_flags.extend(f.start_field.clone().map(Start::FieldFile));
    }
    let chosen = if from_flags.is_empty() {
        let mut from_file = Vec::new();
        from_file.extend(file.guides.map(Start::Guides));
        from_file.extend(file.guides_file.clone().map(Start::GuidesFile));
        from_file.extend(file.strokes.clone().map(Start::Strokes));
        from_file.extend(file.direction.map(|d| Start::Direction(Vec3::from(d))));
        from_file.extend(file.start_field.clone().map(Start::FieldFile));
        from_file
    } else {
        from_flags
    };
    match chosen.len() {
        0 => Ok(Start::Search),
        1 => Ok(chosen.into_iter().next().unwrap_or(Start::Search)),
        _ => Err(CliError::bad_input("give at most one of guides, guides_file, strokes, direction and start_field")),
    }
}

/// `X,Y,Z` as a vector of finite numbers; errors name the parameter `flag`.
pub fn parse_vector(flag: &str, text: &str) -> CliResult<Vec3> {
    let bad = || CliError::bad_input(format!("parameter {flag} = {} is not three numbers X,Y,Z", clip(text)));
    let values: Vec<f64> = text.split(',').map(|v| v.trim().parse::<f64>()).collect::<Result<_, _>>().map_err(|_| bad())?;
    match values.as_slice() {
        [x, y, z] if values.iter().all(|v| v.is_finite()) => Ok(Vec3::new(*x, *y, *z)),
        _ => Err(bad()),
    }
}

fn parse_guide_side(text: &str) -> CliResult<GuideSide> {
    if text == "longest" {
        return Ok(GuideSide::Longest);
    }
    text.parse::<usize>()
        .map(GuideSide::Index)
        .map_err(|_| CliError::bad_input(format!("parameter --guide-side = {} is not a side number or 'longest'", clip(text))))
}

/// θ must lie in [0°, 180°].
pub fn check_theta(theta: f64) -> CliResult<()> {
    if theta.is_finite() && (0.0..=180.0).contains(&theta) {
        Ok(())
    } else {
        Err(out_of_range("theta", theta, "0 to 180 degrees"))
    }
}

pub fn out_of_range(name: &str, value: impl std::fmt::Display, range: &str) -> CliError {
    CliError::bad_input(format!("parameter --{name} = {value} is out of range (allowed: {range})"))
}

fn read_config(path: &Path) -> CliResult<ConfigFile> {
    let text = read_text(path)?;
    toml::from_str(&text).map_err(|e| {
        let message = clip_words(e.message());
        match e.span() {
            Some(span) => {
                let line = text.get(..span.start).map_or(1, |before| before.matches('\n').count() + 1);
                CliError::bad_input(format!("{}: line {line}: {message}", path.display()))
            }
            None => CliError::bad_input(format!("{}: {message}", path.display())),
        }
    })
}
