//! An output directory that is never half-overwritten: files go to a temporary sibling directory
//! that is renamed into place at the end; an existing directory is refused unless `--force`, and
//! `--force` replaces only a previous Lamella output: a directory holding Lamella's marker file
//! [`MARKER`] and nothing but the files that marker lists (what Lamella wrote there).
use crate::console::err_line;
use crate::error::{CliError, CliResult};
use crate::mesh_input::read_text;
use std::path::{Path, PathBuf};

/// The marker file in every output directory: its first line is [`MARKER_HEADER`], then the
/// name of each file Lamella wrote into the directory, one per line.
pub const MARKER: &str = ".lamella-output";
const MARKER_HEADER: &str = "# written by lamella; --force may replace this directory";

/// A temporary directory that becomes `target` on [`OutputDir::commit`] and is removed if dropped
/// uncommitted.
pub struct OutputDir {
    target: PathBuf,
    staging: PathBuf,
    /// Where a replaced target is moved before it is deleted.
    replaced: PathBuf,
    force: bool,
    committed: bool,
}

impl OutputDir {
    /// Checks that `target` may be written and creates the staging directory beside it.
    pub fn create(target: &Path, force: bool) -> CliResult<OutputDir> {
        check_replaceable(target, force)?;
        let name = target
            .file_name()
            .ok_or_else(|| CliError::bad_input(format!("output directory {} has no name", target.display())))?;
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let stem = format!(".{}.{}", name.to_string_lossy(), std::process::id());
        let staging = parent.join(format!("{stem}.tmp"));
        let replaced = parent.join(format!("{stem}.old"));
        // A leftover of a crashed run with the same process id is ours to replace.
        let _ = std::fs::remove_dir_all(&staging);
        std::fs::create_dir(&staging).map_err(|e| unwritable(target, &e))?;
        Ok(OutputDir { target: target.to_path_buf(), staging, replaced, force, committed: false })
    }

    /// Path of a file inside the staging directory.
    pub fn file(&self, name: &str) -> PathBuf {
        self.staging.join(name)
    }

    /// Writes a whole file into the staging directory.
    pub fn write(&self, name: &str, contents: impl AsRef<[u8]>) -> CliResult<()> {
        std::fs::write(self.file(name), contents).map_err(|e| unwritable(&self.target, &e))
    }

    /// The final directory's path.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Writes the marker listing the staged files and moves the staging directory into place
    /// (replacing an existing target under `--force` if it is still a previous Lamella output).
    pub fn commit(mut self) -> CliResult<()> {
        self.write_marker()?;
        if present(&self.target) {
            check_replaceable(&self.target, self.force)?;
            std::fs::rename(&self.target, &self.replaced).map_err(|e| unwritable(&self.target, &e))?;
            std::fs::rename(&self.staging, &self.target).map_err(|e| unwritable(&self.target, &e))?;
            let removed = if self.replaced.is_dir() {
                std::fs::remove_dir_all(&self.replaced)
            } else {
                std::fs::remove_file(&self.replaced)
            };
            // The new output is in place; a leftover of the old one is worth a warning, not a failure.
            if let Err(e) = removed {
                err_line(format!("lamella: warning: could not remove the replaced output {}: {e}", self.replaced.display()));
            }
        } else {
            std::fs::rename(&self.staging, &self.target).map_err(|e| unwritable(&self.target, &e))?;
        }
        self.committed = true;
        Ok(())
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.staging);
        }
    }
}

impl OutputDir {
    /// Writes [`MARKER`] with the names of the files in the staging directory.
    fn write_marker(&self) -> CliResult<()> {
        let entries = std::fs::read_dir(&self.staging).map_err(|e| unwritable(&self.target, &e))?;
        let mut names = Vec::new();
        for entry in entries {
            let entry = entry.map_err(|e| unwritable(&self.target, &e))?;
            names.push(entry.file_name().to_string_lossy().into_owned());
        }
        names.sort();
        let mut text = format!("{MARKER_HEADER}\n");
        for name in names {
            text.push_str(&name);
            text.push('\n');
        }
        self.write(MARKER, text)
    }
}

/// Adds `name` to the [`MARKER`] of the previous Lamella output `dir` (after a command wrote
/// that file into it), so that `--force` may still replace the directory; a directory without
/// the marker is left alone.
pub fn record_in_marker(dir: &Path, name: &str) -> CliResult<()> {
    let marker = dir.join(MARKER);
    if !marker.is_file() {
        return Ok(());
    }
    let text = read_text(&marker)?;
    if text.lines().next() != Some(MARKER_HEADER) || text.lines().any(|l| l == name) {
        return Ok(());
    }
    let separator = if text.ends_with('\n') { "" } else { "\n" };
    std::fs::write(&marker, format!("{text}{separator}{name}\n")).map_err(|e| unwritable(dir, &e))
}

/// Whether anything (a file, directory or symbolic link, even a dangling one) is at `path`.
fn present(path: &Path) -> bool {
    path.symlink_metadata().is_ok()
}

/// Refuses an existing `target` unless `force` is given and it is a previous Lamella output: a
/// real directory (not a symbolic link) with a [`MARKER`] that lists every other entry, each a
/// regular file. Anything else is bad input naming the target and the reason.
fn check_replaceable(target: &Path, force: bool) -> CliResult<()> {
    let Ok(metadata) = target.symlink_metadata() else { return Ok(()) };
    if !force {
        return Err(CliError::bad_input(format!(
            "output directory {} already exists (use --force to replace it)",
            target.display()
        )));
    }
    let refuse = |why: String| {
        CliError::bad_input(format!(
            "output directory {} is not a previous Lamella output ({why}); --force replaces only those: remove it yourself or choose another --out",
            target.display()
        ))
    };
    if !metadata.is_dir() {
        let kind = if metadata.file_type().is_symlink() { "a symbolic link" } else { "not a directory" };
        return Err(refuse(format!("it is {kind}")));
    }
    let marker = target.join(MARKER);
    if !marker.is_file() {
        return Err(refuse(format!("it has no {MARKER} marker")));
    }
    let text = read_text(&marker)?;
    let mut lines = text.lines();
    if lines.next() != Some(MARKER_HEADER) {
        return Err(refuse(format!("its {MARKER} is not Lamella's")));
    }
    let written: std::collections::BTreeSet<&str> = lines.collect();
    let entries = std::fs::read_dir(target).map_err(|e| refuse(format!("cannot list it ({e})")))?;
    for entry in entries {
        let entry = entry.map_err(|e| refuse(format!("cannot list it ({e})")))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if name == MARKER {
            continue;
        }
        let regular_file = entry.file_type().is_ok_and(|t| t.is_file());
        if !regular_file || !written.contains(name.as_str()) {
            return Err(refuse(format!("it holds `{}`, which Lamella did not write", lamella::input::clip(&name))));
        }
    }
    Ok(())
}

fn unwritable(target: &Path, error: &std::io::Error) -> CliError {
    CliError::bad_input(format!("cannot write output directory {}: {error}", target.display()))
}
