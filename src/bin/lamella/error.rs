//! The ways a command fails, and their exit codes: bad input (2), an internal failure or a
//! failed write to stdout (1), no acceptable family (3, outputs written), or a closed stdout
//! pipe (0, quietly).
use std::fmt;

/// Longest error message printed, in characters (a safety net: every message quotes tokens and
/// lists in bounded form already; paths and library messages are not otherwise bounded).
const MAX_MESSAGE_CHARS: usize = 4000;

/// A failed command: the one-line message printed on stderr and its exit code.
#[derive(Debug)]
pub enum CliError {
    /// The user's input (file, mesh, parameter, output directory) cannot be used: exit code 2.
    BadInput(String),
    /// A computation failed on valid input: exit code 1.
    Internal(String),
    /// Writing to stdout failed (e.g. a full disk): exit code 1.
    Write(String),
    /// The reader of stdout closed the pipe (`lamella metrics … | head -c 1`): the command stops
    /// quietly with exit code 0.
    ClosedPipe,
    /// The computation ran and wrote its outputs, but they miss the asked angle (or have
    /// flipped quads): exit code 3; the message starts with "no acceptable family".
    NoAcceptableFamily(String),
}

impl CliError {
    pub fn bad_input(message: impl Into<String>) -> CliError {
        CliError::BadInput(message.into())
    }

    pub fn internal(message: impl Into<String>) -> CliError {
        CliError::Internal(message.into())
    }

    /// The process exit code.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::BadInput(_) => 2,
            CliError::Internal(_) | CliError::Write(_) => 1,
            CliError::NoAcceptableFamily(_) => 3,
            CliError::ClosedPipe => 0,
        }
    }

    /// The message for stderr: one line (line breaks escaped), at most [`MAX_MESSAGE_CHARS`]
    /// characters; `None` for a closed pipe, which ends quietly.
    pub fn message(&self) -> Option<String> {
        match self {
            CliError::ClosedPipe => None,
            _ => {
                let text = self.to_string().replace('\n', " ");
                let clipped = if text.chars().count() > MAX_MESSAGE_CHARS {
                    let head: String = text.chars().take(MAX_MESSAGE_CHARS).collect();
                    format!("{head}… (message cut at {MAX_MESSAGE_CHARS} characters)")
                } else {
                    text
                };
                Some(clipped)
            }
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::BadInput(message) | CliError::Internal(message) | CliError::Write(message) | CliError::NoAcceptableFamily(message) => {
                f.write_str(message)
            }
            CliError::ClosedPipe => f.write_str("standard output was closed"),
        }
    }
}

pub type CliResult<T> = Result<T, CliError>;
