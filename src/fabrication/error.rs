//! What makes a fabrication plan impossible: a parameter out of range, or a strip that cannot be
//! checked or laid out (named by its index and name).
use std::fmt;

/// A fabrication input that cannot be used. Every variant names the offending parameter or strip.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum FabricationError {
    /// A parameter (material constant, thickness, stock size, overlap, gap) is not finite or out of
    /// range; `name` is the parameter, `message` what is wrong with it.
    InvalidParameter { name: &'static str, message: String },
    /// Strip `strip` (called `name`) cannot be checked or cut: fewer than 2 points, a non-finite
    /// point, a zero-length segment, a ruling along the centre line, mismatched boundaries.
    InvalidStrip { strip: usize, name: String, message: String },
    /// A piece of strip `strip` does not fit on the stock even after shortening the pieces (the
    /// strip is wider, or bends more in its plane, than the stock board).
    PieceDoesNotFit { piece: String, size: [f64; 2], stock: [f64; 2] },
    /// No strips were given.
    NoStrips,
}

impl FabricationError {
    pub(crate) fn parameter(name: &'static str, message: impl Into<String>) -> FabricationError {
        FabricationError::InvalidParameter { name, message: message.into() }
    }
}

impl fmt::Display for FabricationError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FabricationError::InvalidParameter { name, message } => write!(f, "parameter `{name}`: {message}"),
            FabricationError::InvalidStrip { strip, name, message } => {
                write!(f, "strip {strip} (`{}`): {message}", crate::input::clip(name))
            }
            FabricationError::PieceDoesNotFit { piece, size, stock } => write!(
                f,
                "piece {} ({:.3} m × {:.3} m) does not fit on the stock ({:.3} m × {:.3} m): use wider or longer stock",
                crate::input::clip(piece),
                size[0],
                size[1],
                stock[0],
                stock[1]
            ),
            FabricationError::NoStrips => write!(f, "no strips to fabricate"),
        }
    }
}

impl std::error::Error for FabricationError {}
