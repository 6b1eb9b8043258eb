//! The input surface: an OBJ file (with every problem listed when it is not a valid mesh) or the
//! built-in hall roof.
use crate::error::{CliError, CliResult};
use lamella::input::{read_limited, summarise_list, MAX_LISTED_ITEMS};
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

/// Reads an OBJ mesh; an invalid mesh is reported on one line with its problem count and the
/// first [`MAX_LISTED_ITEMS`] problems ("… and N more").
pub fn read_mesh(path: &Path) -> CliResult<TriMesh> {
    let text = read_text(path)?;
    TriMesh::parse_obj(&text).map_err(|first| {
        let problems = match TriMesh::diagnose_obj(&text) {
            Ok(problems) if !problems.is_empty() => problems,
            _ => vec![first],
        };
        let list = summarise_list(&problems, MAX_LISTED_ITEMS, "; ");
        CliError::bad_input(format!("{}: invalid mesh ({} problem(s)): {list}", path.display(), problems.len()))
    })
}

/// The file's bytes, up to the input limit [`lamella::input::MAX_INPUT_BYTES`] (a larger file,
/// a device such as `/dev/zero` or a directory is bad input).
pub fn read_bytes(path: &Path) -> CliResult<Vec<u8>> {
    read_limited(path).map_err(|e| CliError::bad_input(format!("cannot read {}: {e}", path.display())))
}

/// The file's text (invalid UTF-8 replaced, as the OBJ reader does), read as [`read_bytes`].
pub fn read_text(path: &Path) -> CliResult<String> {
    read_bytes(path).map(|bytes| String::from_utf8_lossy(&bytes).into_owned())
}

/// How a report names the surface.
pub fn mesh_name(path: Option<&Path>) -> String {
    path.map_or_else(|| BUILT_IN.to_string(), |p| p.display().to_string())
}
