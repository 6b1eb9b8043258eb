//! The design parameters in force: flags over a `--config` TOML file over the defaults, checked
//! against their ranges.
use crate::args::{ConfigArgs, FieldFlags, MeshArgs, OutArgs, StripFlags};
use crate::error::{CliError, CliResult};
use serde::Deserialize;
use std::path::{Path, PathBuf};

pub const DEFAULT_THETA: f64 = 60.0;
pub const DEFAULT_MAX_ITERATIONS: usize = 400;
pub const DEFAULT_STRIPS: usize = 20;
pub const DEFAULT_OUT: &str = "lamella-out";
const MAX_ITERATIONS_LIMIT: usize = 100_000;
const MAX_STRIPS: usize = 1000;

/// The keys a `design.toml` may set (all optional, same units as the flags).
#[derive(Deserialize, Default, Debug)]
#[serde(deny_unknown_fields)]
struct ConfigFile {
    mesh: Option<PathBuf>,
    out: Option<PathBuf>,
    theta: Option<f64>,
    max_iterations: Option<usize>,
    strips: Option<usize>,
    width: Option<f64>,
}

/// Every parameter of a run, resolved and range-checked.
#[derive(Debug, Clone)]
pub struct Settings {
    /// `None`: the built-in hall roof.
    pub mesh: Option<PathBuf>,
    pub out: PathBuf,
    pub force: bool,
    /// Target angle θ in degrees.
    pub theta: f64,
    pub max_iterations: usize,
    pub strips: usize,
    /// Strip width in mesh units; `None`: half the mean spacing of the level curves.
    pub width: Option<f64>,
}

/// The flags a command may carry; absent groups stay at their defaults.
#[derive(Default)]
pub struct Flags<'a> {
    pub mesh: Option<&'a MeshArgs>,
    pub out: Option<&'a OutArgs>,
    pub field: Option<&'a FieldFlags>,
    pub strips: Option<&'a StripFlags>,
    pub config: Option<&'a ConfigArgs>,
}

impl Settings {
    pub fn resolve(flags: Flags) -> CliResult<Settings> {
        let file = match flags.config.and_then(|c| c.config.as_deref()) {
            Some(path) => read_config(path)?,
            None => ConfigFile::default(),
        };
        let settings = Settings {
            mesh: flags.mesh.and_then(|m| m.mesh.clone()).or(file.mesh),
            out: flags.out.and_then(|o| o.out.clone()).or(file.out).unwrap_or_else(|| PathBuf::from(DEFAULT_OUT)),
            force: flags.out.is_some_and(|o| o.force),
            theta: flags.field.and_then(|f| f.theta).or(file.theta).unwrap_or(DEFAULT_THETA),
            max_iterations: flags
                .field
                .and_then(|f| f.max_iterations)
                .or(file.max_iterations)
                .unwrap_or(DEFAULT_MAX_ITERATIONS),
            strips: flags.strips.and_then(|s| s.strips).or(file.strips).unwrap_or(DEFAULT_STRIPS),
            width: flags.strips.and_then(|s| s.width).or(file.width),
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
        if let Some(width) = self.width {
            if !(width.is_finite() && width > 0.0) {
                return Err(out_of_range("width", width, "a finite length > 0 m"));
            }
        }
        Ok(())
    }
}

/// θ must lie in [0°, 180°].
pub fn check_theta(theta: f64) -> CliResult<()> {
    if theta.is_finite() && (0.0..=180.0).contains(&theta) {
        Ok(())
    } else {
        Err(out_of_range("theta", theta, "0 to 180 degrees"))
    }
}

fn out_of_range(name: &str, value: impl std::fmt::Display, range: &str) -> CliError {
    CliError::bad_input(format!("parameter --{name} = {value} is out of range (allowed: {range})"))
}

fn read_config(path: &Path) -> CliResult<ConfigFile> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::bad_input(format!("cannot read config {}: {e}", path.display())))?;
    toml::from_str(&text).map_err(|e| {
        let message = e.message().replace('\n', " ");
        match e.span() {
            Some(span) => {
                let line = text.get(..span.start).map_or(1, |before| before.matches('\n').count() + 1);
                CliError::bad_input(format!("{}: line {line}: {message}", path.display()))
            }
            None => CliError::bad_input(format!("{}: {message}", path.display())),
        }
    })
}
