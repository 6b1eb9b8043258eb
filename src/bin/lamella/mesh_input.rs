//! The input surface: an OBJ file (with every problem listed when it is not a valid mesh) or the
//! built-in hall roof.
use crate::error::{CliError, CliResult};
use lamella::mesh::TriMesh;
use lamella::surfaces::hall_roof;
use std::path::Path;

/// Vertices of the built-in hall roof.
pub const ROOF_VERTICES: usize = 3000;

/// The built-in surface's name in reports.
pub const BUILT_IN: &str = "built-in hall roof";

/// Reads `path`, or generates the hall roof for `None`.
pub fn load_mesh(path: Option<&Path>) -> CliResult<TriMesh> {
    match path {
        Some(path) => read_mesh(path),
        None => hall_roof(ROOF_VERTICES)
            .into_mesh()
            .map_err(|e| CliError::internal(format!("{BUILT_IN}: {e}"))),
    }
}

/// Reads an OBJ mesh; an invalid mesh is reported with all its problems on one line.
pub fn read_mesh(path: &Path) -> CliResult<TriMesh> {
    let text = read_text(path)?;
    TriMesh::parse_obj(&text).map_err(|first| {
        let problems = match TriMesh::diagnose_obj(&text) {
            Ok(problems) if !problems.is_empty() => problems,
            _ => vec![first],
        };
        let list: Vec<String> = problems.iter().map(ToString::to_string).collect();
        CliError::bad_input(format!("{}: invalid mesh ({} problem(s)): {}", path.display(), list.len(), list.join("; ")))
    })
}

/// The file's text (invalid UTF-8 replaced, as the OBJ reader does).
pub fn read_text(path: &Path) -> CliResult<String> {
    std::fs::read(path)
        .map(|bytes| String::from_utf8_lossy(&bytes).into_owned())
        .map_err(|e| CliError::bad_input(format!("cannot read {}: {e}", path.display())))
}

/// How a report names the surface.
pub fn mesh_name(path: Option<&Path>) -> String {
    path.map_or_else(|| BUILT_IN.to_string(), |p| p.display().to_string())
}
