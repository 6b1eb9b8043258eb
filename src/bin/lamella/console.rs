//! Writing to the terminal without panicking: `println!`/`eprintln!` panic when the stream
//! fails (stdout redirected to a full disk, a closed pipe). Here a failed stdout write becomes
//! [`CliError::Write`] (exit 1, one line on stderr) and a closed pipe [`CliError::ClosedPipe`]
//! (exit 0, nothing printed: the reader chose to stop); stderr is best effort (when stderr
//! itself is gone, nothing can be reported).
use crate::error::{CliError, CliResult};
use std::fmt::Display;
use std::io::Write;

/// Writes `text` and a line break to stdout and flushes it.
pub fn out_line(text: impl Display) -> CliResult<()> {
    let mut out = std::io::stdout().lock();
    writeln!(out, "{text}").and_then(|()| out.flush()).map_err(stdout_error)
}

/// Writes `text` and a line break to stderr, ignoring failure.
pub fn err_line(text: impl Display) {
    let _ = writeln!(std::io::stderr().lock(), "{text}");
}

fn stdout_error(error: std::io::Error) -> CliError {
    if error.kind() == std::io::ErrorKind::BrokenPipe {
        CliError::ClosedPipe
    } else {
        CliError::Write(format!("cannot write to standard output: {error}"))
    }
}
