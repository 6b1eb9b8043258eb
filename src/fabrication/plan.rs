//! The fabrication plan of a strip pattern: the bending check of every strip, the pieces cut
//! from stock (split with splices where a strip is longer), laid out on boards, with the yield.
use super::bending::{check_strip, validate_thickness, StripCheck};
use super::error::FabricationError;
use super::material::Material;
use super::packing::{pack, Placement};
use super::piece::{cut_piece, FlatShape};
use super::splicing::{peak, splice_intervals};
use super::strip_input::FabricationStrip;
use crate::field::Family;

/// Rounds of shortening the pieces when a cut piece's bounding box (its slanted ends, its bend in
/// the plane) is longer than the stock.
const FIT_ROUNDS: usize = 8;

/// The stock material is bought in: boards or sheets of `length × width` metres.
#[derive(Clone, Debug, PartialEq)]
pub struct Stock {
    /// Length of a board or sheet, metres.
    pub length: f64,
    /// Width of a board or sheet, metres; `None`: as wide as the widest piece (one row of pieces
    /// per board: lamellas cut from boards bought by length).
    pub width: Option<f64>,
    /// Splice overlap between consecutive pieces of a strip, metres.
    pub overlap: f64,
    /// Gap between neighbouring pieces on a board (saw kerf and margin), metres.
    pub gap: f64,
}

impl Stock {
    /// Boards of `length` metres, as wide as the widest piece, with 0.3 m splices and 10 mm gaps.
    pub fn boards(length: f64) -> Stock {
        Stock { length, width: None, overlap: 0.3, gap: 0.01 }
    }

    /// Checks every size, naming the first that is out of range: finite lengths, the board longer
    /// than two overlaps (a middle piece holds one at each end) and longer than the gap.
    pub fn validate(&self) -> Result<(), FabricationError> {
        let finite = |name: &'static str, value: f64, positive: bool| {
            if value.is_finite() && (value > 0.0 || (!positive && value == 0.0)) {
                Ok(())
            } else {
                Err(FabricationError::parameter(name, format!("must be finite and {} 0 m, got {value}", if positive { ">" } else { "≥" })))
            }
        };
        finite("stock_length", self.length, true)?;
        finite("overlap", self.overlap, false)?;
        finite("gap", self.gap, false)?;
        if let Some(width) = self.width {
            finite("stock_width", width, true)?;
        }
        if self.length <= 2.0 * self.overlap {
            return Err(FabricationError::parameter("stock_length", format!("{} m must be longer than twice the splice overlap ({} m)", self.length, self.overlap)));
        }
        if self.gap >= self.length {
            return Err(FabricationError::parameter("gap", format!("{} m must be shorter than the stock ({} m)", self.gap, self.length)));
        }
        Ok(())
    }
}

/// What to check and cut: the material, its thickness, the stock, and the strips' family (for
/// the bill of materials).
#[derive(Clone, Debug, PartialEq)]
pub struct FabricationParams {
    pub material: Material,
    /// Thickness of the strips, metres.
    pub thickness: f64,
    pub stock: Stock,
    /// θ of the strips' family in degrees, when known.
    pub theta_degrees: Option<f64>,
}

impl FabricationParams {
    /// Checks the material, thickness, stock and θ, naming the first parameter out of range.
    pub fn validate(&self) -> Result<(), FabricationError> {
        self.material.validate()?;
        validate_thickness(self.thickness)?;
        self.stock.validate()?;
        match self.theta_degrees {
            Some(theta) if !(0.0..=180.0).contains(&theta) => Err(FabricationError::parameter("theta", format!("must lie in [0°, 180°], got {theta}"))),
            _ => Ok(()),
        }
    }

}

/// The name of the family of θ (`asymptotic`, `geodesic`, `pseudo-geodesic`), `None` when θ is unknown.
pub fn family_name(theta_degrees: Option<f64>) -> Option<&'static str> {
    theta_degrees.map(|theta| match Family::from_theta(theta) {
        Family::Asymptotic => "asymptotic",
        Family::Geodesic => "geodesic",
        Family::PseudoGeodesic { .. } => "pseudo-geodesic",
        Family::ConstantSlope { .. } => "constant-slope",
    })
}

/// One piece of the plan: which strip, where along it, how it bends, where it lies.
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    /// `<strip name>-<number>`.
    pub id: String,
    /// Index of its strip.
    pub strip: usize,
    /// Its number along the strip, from 1.
    pub number: usize,
    /// Arc lengths of its ends along the strip's centre line, metres.
    pub start: f64,
    pub end: f64,
    /// The strip's width, metres.
    pub width: f64,
    /// Smallest bending radius within the piece (`None`: straight).
    pub min_bending_radius: Option<f64>,
    /// Largest twist rate within the piece, rad/m.
    pub max_twist_rate: f64,
    /// Largest utilisation within the piece.
    pub max_utilisation: f64,
    /// Indices (in [`FabricationPlan::pieces`]) of the pieces spliced to it: the previous, the next.
    pub previous: Option<usize>,
    pub next: Option<usize>,
    pub shape: FlatShape,
    pub placement: Placement,
}

impl Piece {
    /// Length of its centre line, metres.
    pub fn length(&self) -> f64 {
        self.end - self.start
    }

    /// Whether the piece is stressed beyond the allowable stress.
    pub fn is_overstressed(&self) -> bool {
        self.max_utilisation > 1.0
    }

    /// Its outline's area (shoelace), square metres.
    pub fn area(&self) -> f64 {
        let o = &self.shape.outline;
        0.5 * (0..o.len()).map(|i| {
            let (p, q) = (o[i], o[(i + 1) % o.len()]);
            p[0] * q[1] - q[0] * p[1]
        }).sum::<f64>().abs()
    }
}

/// The fabrication plan of a pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct FabricationPlan {
    pub params: FabricationParams,
    /// The strips' names, in input order.
    pub strip_names: Vec<String>,
    /// Each strip's θ in degrees (its own, else the parameters'), in input order.
    pub strip_thetas: Vec<Option<f64>>,
    /// One check per strip, in input order.
    pub checks: Vec<StripCheck>,
    /// The pieces, strip by strip, in order along each strip.
    pub pieces: Vec<Piece>,
    /// Number of boards used.
    pub boards: usize,
    /// Size of a board, metres (the width resolved when the stock left it open).
    pub board_size: [f64; 2],
}

impl FabricationPlan {
    /// The material yield: the pieces' area over the boards' area.
    pub fn material_yield(&self) -> f64 {
        let stock = self.boards as f64 * self.board_size[0] * self.board_size[1];
        if stock > 0.0 { self.pieces.iter().map(Piece::area).sum::<f64>() / stock } else { 0.0 }
    }

    /// Indices of the strips stressed beyond the allowable stress.
    pub fn overstressed_strips(&self) -> Vec<usize> {
        self.checks.iter().enumerate().filter(|(_, c)| c.is_overstressed()).map(|(i, _)| i).collect()
    }

    /// The ids of a piece's splice partners, previous first.
    pub fn splice_partners(&self, piece: &Piece) -> Vec<&str> {
        [piece.previous, piece.next].into_iter().flatten().map(|k| self.pieces[k].id.as_str()).collect()
    }
}

/// Checks, splits, and lays out `strips` (see the module docs of [`super`]).
///
/// Errors: a parameter out of range, a strip that cannot be checked (both named), a piece that
/// does not fit on the stock.
pub fn plan_fabrication(strips: &[FabricationStrip], params: &FabricationParams) -> Result<FabricationPlan, FabricationError> {
    params.validate()?;
    if strips.is_empty() {
        return Err(FabricationError::NoStrips);
    }
    for (index, strip) in strips.iter().enumerate() {
        strip.validate(index)?;
    }
    let checks: Vec<StripCheck> = strips.iter().map(|s| check_strip(s, &params.material, params.thickness)).collect();
    let stock = &params.stock;
    let mut usable = stock.length;
    let mut pieces = cut_pieces(strips, &checks, usable, stock.overlap);
    for _ in 0..FIT_ROUNDS {
        let excess = pieces.iter().map(|p| p.shape.size[0] - stock.length).fold(f64::NEG_INFINITY, f64::max);
        if excess <= 0.0 || usable - excess <= 2.0 * stock.overlap {
            break;
        }
        usable -= excess + 1e-9 * stock.length;
        pieces = cut_pieces(strips, &checks, usable, stock.overlap);
    }
    let tallest = pieces.iter().map(|p| p.shape.size[1]).fold(0.0, f64::max);
    let board_size = [stock.length, stock.width.unwrap_or(tallest)];
    if let Some(p) = pieces.iter().find(|p| p.shape.size[0] > board_size[0] || p.shape.size[1] > board_size[1]) {
        return Err(FabricationError::PieceDoesNotFit { piece: p.id.clone(), size: p.shape.size, stock: board_size });
    }
    let sizes: Vec<[f64; 2]> = pieces.iter().map(|p| p.shape.size).collect();
    let (placements, boards) = pack(&sizes, board_size, stock.gap);
    for (piece, placement) in pieces.iter_mut().zip(placements) {
        piece.placement = placement;
    }
    Ok(FabricationPlan {
        params: params.clone(),
        strip_names: strips.iter().map(|s| s.name.clone()).collect(),
        strip_thetas: strips.iter().map(|s| s.theta_degrees.or(params.theta_degrees)).collect(),
        checks,
        pieces,
        boards,
        board_size,
    })
}

/// The pieces of every strip for pieces of at most `usable` metres of centre line.
fn cut_pieces(strips: &[FabricationStrip], checks: &[StripCheck], usable: f64, overlap: f64) -> Vec<Piece> {
    let mut pieces = Vec::new();
    for (index, (strip, check)) in strips.iter().zip(checks).enumerate() {
        let s = &check.arc_length;
        let intervals = splice_intervals(s, &check.utilisation, &strip.nodes, usable, overlap);
        let unrolling = strip.unrolling();
        let width = strip.width();
        let first = pieces.len();
        let count = intervals.len();
        for (k, &[start, end]) in intervals.iter().enumerate() {
            let id = format!("{}-{}", strip.name, k + 1);
            let splices: Vec<f64> = [(k > 0).then_some(start + overlap), (k + 1 < count).then_some(end - overlap)].into_iter().flatten().collect();
            let peak = |values: &[f64]| peak(s, values, start, end);
            let (curvature, utilisation) = (peak(&check.curvature), peak(&check.utilisation));
            let text = if utilisation > 1.0 { format!("{id} ({:.0} %)", 100.0 * utilisation) } else { id.clone() };
            pieces.push(Piece {
                shape: cut_piece(&unrolling, s, [start, end], &splices, &strip.nodes, &text, width),
                id,
                strip: index,
                number: k + 1,
                start,
                end,
                width,
                min_bending_radius: (curvature > 0.0).then(|| 1.0 / curvature),
                max_twist_rate: peak(&check.twist_rate),
                max_utilisation: utilisation,
                previous: (k > 0).then(|| first + k - 1),
                next: (k + 1 < count).then(|| first + k + 1),
                placement: Placement { board: 0, position: [0.0, 0.0] },
            });
        }
    }
    pieces
}
