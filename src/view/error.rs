//! What makes a scene impossible to show: an element with a non-finite point, a triangle
//! addressing a missing vertex, a strip of mismatched boundaries or an unknown family.
use std::fmt;

/// A scene element that cannot be drawn; every variant names the element.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum ViewError {
    /// The surface: a non-finite vertex or a triangle addressing a missing vertex.
    InvalidSurface { message: String },
    /// Level curve `curve`: a non-finite point.
    InvalidCurve { curve: usize, message: String },
    /// Strip `strip` (called `name`): fewer than 2 rulings, boundaries or unrolling of different
    /// lengths, a non-finite point, an unknown family, a non-finite utilisation.
    InvalidStrip { strip: usize, name: String, message: String },
}

impl fmt::Display for ViewError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ViewError::InvalidSurface { message } => write!(f, "surface: {message}"),
            ViewError::InvalidCurve { curve, message } => write!(f, "level curve {curve}: {message}"),
            ViewError::InvalidStrip { strip, name, message } => write!(f, "strip {strip} (`{}`): {message}", crate::input::clip(name)),
        }
    }
}

impl std::error::Error for ViewError {}
