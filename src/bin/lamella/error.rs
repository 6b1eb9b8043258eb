//! The two ways a command fails, and their exit codes: bad input (2) or an internal failure (1).
use std::fmt;

/// A failed command: the one-line message printed on stderr and its exit code.
#[derive(Debug)]
pub enum CliError {
    /// The user's input (file, mesh, parameter, output directory) cannot be used: exit code 2.
    BadInput(String),
    /// A computation failed on valid input: exit code 1.
    Internal(String),
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
            CliError::Internal(_) => 1,
            CliError::NoAcceptableFamily(_) => 3,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::BadInput(message) | CliError::Internal(message) | CliError::NoAcceptableFamily(message) => f.write_str(message),
        }
    }
}

pub type CliResult<T> = Result<T, CliError>;

/// A user-supplied token for an error message, cut to 80 characters with "…".
pub fn clip(text: &str) -> String {
    const LIMIT: usize = 80;
    match text.char_indices().nth(LIMIT) {
        Some((cut, _)) => format!("{}…", &text[..cut]),
        None => text.to_string(),
    }
}
