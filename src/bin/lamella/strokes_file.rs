//! Sketched strokes from a JSON file: `{"strokes": [[[x, y, z], ...], ...]}`, in metres.
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use lamella::input::clip_words;
use lamella::mesh::Vec3;
use serde::Deserialize;
use std::path::Path;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StrokesFile {
    strokes: Vec<Vec<[f64; 3]>>,
}

/// The strokes of `path` as polylines (their validity against the surface is checked by the
/// library, which names the stroke and point). The file is read up to the input limit.
pub fn read_strokes(path: &Path) -> CliResult<Vec<Vec<Vec3>>> {
    parse_strokes(&read_text(path)?, &path.display().to_string())
}

/// The strokes in the JSON `text` of the file `name` (named in errors, which clip quoted input).
pub fn parse_strokes(text: &str, name: &str) -> CliResult<Vec<Vec<Vec3>>> {
    let file: StrokesFile = serde_json::from_str(text).map_err(|e| {
        CliError::bad_input(format!("{name}: not a strokes file ({{\"strokes\": [[[x, y, z], ...], ...]}}): {}", clip_words(&e.to_string())))
    })?;
    Ok(file.strokes.into_iter().map(|s| s.into_iter().map(Vec3::from).collect()).collect())
}
