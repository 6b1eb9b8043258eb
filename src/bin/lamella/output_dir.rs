//! An output directory that is never half-overwritten: files go to a temporary sibling directory
//! that is renamed into place at the end; an existing directory is refused unless `--force`.
use crate::error::{CliError, CliResult};
use std::path::{Path, PathBuf};

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
        if target.exists() && !force {
            return Err(CliError::bad_input(format!(
                "output directory {} already exists (use --force to replace it)",
                target.display()
            )));
        }
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

    /// Moves the staging directory into place (replacing an existing target under `--force`).
    pub fn commit(mut self) -> CliResult<()> {
        if self.target.exists() {
            if !self.force {
                return Err(CliError::bad_input(format!(
                    "output directory {} appeared while running (use --force to replace it)",
                    self.target.display()
                )));
            }
            std::fs::rename(&self.target, &self.replaced).map_err(|e| unwritable(&self.target, &e))?;
            std::fs::rename(&self.staging, &self.target).map_err(|e| unwritable(&self.target, &e))?;
            let removed = if self.replaced.is_dir() {
                std::fs::remove_dir_all(&self.replaced)
            } else {
                std::fs::remove_file(&self.replaced)
            };
            // The new output is in place; a leftover of the old one is worth a warning, not a failure.
            if let Err(e) = removed {
                eprintln!("lamella: warning: could not remove the replaced output {}: {e}", self.replaced.display());
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

fn unwritable(target: &Path, error: &std::io::Error) -> CliError {
    CliError::bad_input(format!("cannot write output directory {}: {error}", target.display()))
}
