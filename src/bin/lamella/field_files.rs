//! The field's files: field.csv (one value per vertex) and energies.csv (the per-iteration
//! energy history, so a resumed optimisation extends it).
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::input::clip;
use lamella::field::{Energies, StepReport};
use std::fmt::Write as _;
use std::path::Path;

const ENERGIES_HEADER: &str = "iteration,stage,e_angle,e_frame,e_fair,e_grad,e_total,angle_error_max_degrees";

/// One row of the energy history.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HistoryRow {
    pub iteration: usize,
    pub stage: usize,
    pub energies: Energies,
    pub angle_error_max_degrees: f64,
}

impl HistoryRow {
    pub fn of(report: &StepReport) -> HistoryRow {
        HistoryRow {
            iteration: report.iterations,
            stage: report.stage,
            energies: report.energies,
            angle_error_max_degrees: report.angle_error_max_degrees,
        }
    }
}

/// field.csv text: a comment line, then one value per vertex (shortest round-trip form).
pub fn field_csv(field: &[f64]) -> String {
    let mut text = String::from("# field value per mesh vertex\n");
    for value in field {
        let _ = writeln!(text, "{value}");
    }
    text
}

/// Reads field.csv (up to the input limit): one finite number per non-comment line.
pub fn read_field_csv(path: &Path) -> CliResult<Vec<f64>> {
    parse_field_csv(&read_text(path)?, &path.display().to_string())
}

/// The values of field.csv `text` from the file `name` (named in errors, which quote the
/// offending line clipped to 80 characters).
pub fn parse_field_csv(text: &str, name: &str) -> CliResult<Vec<f64>> {
    let mut values = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        match line.parse::<f64>() {
            Ok(v) if v.is_finite() => values.push(v),
            _ => {
                return Err(CliError::bad_input(format!(
                    "{name}: line {}: expected one finite number, found `{}`",
                    i + 1,
                    clip(line)
                )))
            }
        }
    }
    Ok(values)
}

/// energies.csv text.
pub fn energies_csv(history: &[HistoryRow]) -> String {
    let mut text = format!("{ENERGIES_HEADER}\n");
    for row in history {
        let e = &row.energies;
        let _ = writeln!(
            text,
            "{},{},{},{},{},{},{},{}",
            row.iteration, row.stage, e.angle, e.frame, e.fair, e.grad, e.total, row.angle_error_max_degrees
        );
    }
    text
}

/// Reads energies.csv (written by [`energies_csv`]).
pub fn read_energies_csv(path: &Path) -> CliResult<Vec<HistoryRow>> {
    let text = read_text(path)?;
    let bad = |line: usize| CliError::bad_input(format!("{}: line {line}: not an energies.csv row", path.display()));
    let mut rows = Vec::new();
    for (i, line) in text.lines().enumerate().skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        let [iteration, stage, angle, frame, fair, grad, total, error] = cells[..] else { return Err(bad(i + 1)) };
        let number = |s: &str| s.trim().parse::<f64>().map_err(|_| bad(i + 1));
        let count = |s: &str| s.trim().parse::<usize>().map_err(|_| bad(i + 1));
        rows.push(HistoryRow {
            iteration: count(iteration)?,
            stage: count(stage)?,
            energies: Energies {
                angle: number(angle)?,
                frame: number(frame)?,
                fair: number(fair)?,
                grad: number(grad)?,
                total: number(total)?,
            },
            angle_error_max_degrees: number(error)?,
        });
    }
    Ok(rows)
}
