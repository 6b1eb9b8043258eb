//! Sketched strokes from a JSON file: `{"strokes": [[[x, y, z], ...], ...]}`, in metres.
use crate::error::{CliError, CliResult};
use lamella::mesh::Vec3;
use serde::Deserialize;
use std::path::Path;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StrokesFile {
    strokes: Vec<Vec<[f64; 3]>>,
}

/// The strokes of `path` as polylines (their validity against the surface is checked by the
/// library, which names the stroke and point).
pub fn read_strokes(path: &Path) -> CliResult<Vec<Vec<Vec3>>> {
    let text = std::fs::read_to_string(path).map_err(|e| CliError::bad_input(format!("cannot read {}: {e}", path.display())))?;
    let file: StrokesFile = serde_json::from_str(&text)
        .map_err(|e| CliError::bad_input(format!("{}: not a strokes file ({{\"strokes\": [[[x, y, z], ...], ...]}}): {e}", path.display())))?;
    Ok(file.strokes.into_iter().map(|s| s.into_iter().map(Vec3::from).collect()).collect())
}
