//! `LmlFabrication`: the workshop plan of a strip pattern: the bending and twisting check of
//! every strip for a material and thickness, the pieces cut from stock (strips longer than the
//! stock split with splice overlaps), laid out on boards, the bill of materials and the cut files.

use super::failure::Failure;
use super::guard::guarded;
use super::raw::{copy_out, handle, release, utf8, Out};
use super::status::LmlStatus;
use super::strips::LmlStrips;
use crate::fabrication::{
    bom_csv, cut_dxf, cut_svg, plan_fabrication, FabricationError, FabricationParams, FabricationPlan, FabricationStrip, Material, Piece, Stock, StripCheck,
};

/// A strip material in pascals: each finite and > 0. Fill it with `lml_material_preset` or by hand.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlMaterial {
    /// Young's modulus E, Pa.
    pub youngs_modulus: f64,
    /// Shear modulus G, Pa.
    pub shear_modulus: f64,
    /// Allowable stress, compared with the von Mises stress of bending and torsion, Pa.
    pub allowable_stress: f64,
}

/// The stock boards or sheets, in the strips' unit (metres).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlStock {
    /// Length of a board, finite, > 2 × `overlap`.
    pub length: f64,
    /// Width of a board; 0: as wide as the widest piece (one row of pieces per board).
    pub width: f64,
    /// Splice overlap between consecutive pieces of a strip, finite, ≥ 0. Default 0.3.
    pub overlap: f64,
    /// Gap between pieces on a board, finite, ≥ 0. Default 0.01.
    pub gap: f64,
}

/// The bending and twisting check of one strip (weak-axis stress E t κ / 2 from the centre
/// line's curvature, torsional shear G t τ from the twist rate of its rectifying frame,
/// utilisation √(σ² + 3 τ²) / allowable stress).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlStripCheck {
    /// Largest bending strain t κ / 2.
    pub max_strain: f64,
    /// Largest bending stress, Pa.
    pub max_bending_stress: f64,
    /// Largest torsional shear stress, Pa.
    pub max_shear_stress: f64,
    /// Largest utilisation (1 = the allowable stress).
    pub max_utilisation: f64,
    /// Centre point of the largest utilisation (index within the strip).
    pub worst_point: u64,
    /// Its arc length along the centre line.
    pub worst_arc_length: f64,
    /// Its position in space.
    pub worst_position: [f64; 3],
    /// Smallest bending radius; 0 for a straight strip.
    pub min_bending_radius: f64,
    /// Largest twist rate, rad per unit length.
    pub max_twist_rate: f64,
    /// 1 when the utilisation exceeds 1 somewhere.
    pub overstressed: u32,
}

/// One piece of the plan (a row of the bill of materials). Its id is
/// `strip_<strip>-<number>` (`lml_fabrication_piece_id`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlPiece {
    /// Index of its strip.
    pub strip: u64,
    /// Its number along the strip, from 1.
    pub number: u64,
    /// Arc lengths of its ends along the strip's centre line.
    pub start: f64,
    pub end: f64,
    /// Centre-line length (`end − start`).
    pub length: f64,
    pub width: f64,
    /// Smallest bending radius within the piece; 0 when straight.
    pub min_bending_radius: f64,
    /// Largest twist rate within the piece.
    pub max_twist_rate: f64,
    /// Largest utilisation within the piece.
    pub max_utilisation: f64,
    /// Index of the piece spliced before it, −1 for none.
    pub previous: i64,
    /// Index of the piece spliced after it, −1 for none.
    pub next: i64,
    /// Board number, from 1.
    pub board: u64,
    /// Lower-left corner of its bounding box on the board.
    pub position: [f64; 2],
    /// Size of its bounding box (along the board, across).
    pub size: [f64; 2],
}

/// Totals of a plan.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LmlFabricationSummary {
    pub strips: u64,
    pub pieces: u64,
    pub boards: u64,
    /// Size of a board (the width resolved when `LmlStock::width` was 0).
    pub board_size: [f64; 2],
    /// The pieces' area over the boards'.
    pub material_yield: f64,
    /// Number of strips over 100 % utilisation.
    pub overstressed_strips: u64,
}

/// A fabrication plan (opaque), created by `lml_fabrication_new`, released with
/// `lml_fabrication_free`. Immutable; it keeps no reference to the strips.
pub struct LmlFabrication {
    plan: FabricationPlan,
}

impl From<FabricationError> for Failure {
    /// Every fabrication error is an input out of range; the message names it.
    fn from(e: FabricationError) -> Failure {
        Failure::new(LmlStatus::InvalidArgument, e.to_string())
    }
}

/// Fills `*out` with a preset material by name: "timber" (C24: E 11 GPa, G 0.69 GPa, 24 MPa),
/// "plywood" (birch: 9.5 GPa, 0.62 GPa, 30 MPa), "steel" (S355: 210 GPa, 81 GPa, 355 MPa) or
/// "aluminium" (6082 T6: 70 GPa, 27 GPa, 250 MPa); characteristic values without safety factors.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument, unknown name).
#[no_mangle]
pub unsafe extern "C" fn lml_material_preset(name: *const std::ffi::c_char, out: *mut LmlMaterial) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): NUL-terminated `name`; writable `out`.
        let mut out = unsafe { Out::new(out, "out") }?;
        let name = unsafe { utf8(name, "name") }?;
        let m = Material::preset(name).ok_or_else(|| Failure::argument("name", format!("unknown material `{}` (timber, plywood, steel, aluminium)", crate::input::clip(name))))?;
        out.set(LmlMaterial { youngs_modulus: m.youngs_modulus, shear_modulus: m.shear_modulus, allowable_stress: m.allowable_stress });
        Ok(LmlStatus::Ok)
    })
}

/// Fills `*out` with boards of `length` (width 0: as wide as the widest piece), overlap 0.3, gap 0.01.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL `out`).
#[no_mangle]
pub unsafe extern "C" fn lml_stock_default(length: f64, out: *mut LmlStock) -> LmlStatus {
    guarded(|| {
        // SAFETY: `out` is writable by contract.
        let mut out = unsafe { Out::new(out, "out") }?;
        let s = Stock::boards(length);
        out.set(LmlStock { length: s.length, width: 0.0, overlap: s.overlap, gap: s.gap });
        Ok(LmlStatus::Ok)
    })
}

/// Checks and cuts the strips of `strips` (named `strip_<i>`, as in the CLI's files) in
/// `material` of `thickness`, from `stock`. The bill of materials gives every piece the family
/// and θ the strips were built for (`LmlStripParams::theta_degrees`).
///
/// Returns `LML_STATUS_OK` (also when strips are over 100 % utilisation: see `overstressed`),
/// or `LML_STATUS_INVALID_ARGUMENT` (NULL pointer; a material constant, the thickness or a stock
/// size not finite or out of range, the stock not longer than two overlaps, a piece that does
/// not fit the stock, no strips: the message names it). `*out` is NULL on failure.
#[no_mangle]
pub unsafe extern "C" fn lml_fabrication_new(
    strips: *const LmlStrips,
    material: *const LmlMaterial,
    thickness: f64,
    stock: *const LmlStock,
    out: *mut *mut LmlFabrication,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (all blocks): writable `out`; live `strips`; readable `material` and `stock`.
        let mut out = unsafe { Out::new(out, "out") }?;
        out.set(std::ptr::null_mut());
        let strips = unsafe { handle(strips, "strips") }?;
        let pattern = &strips.pattern;
        let m = unsafe { handle(material, "material") }?;
        let s = unsafe { handle(stock, "stock") }?;
        let width = if s.width == 0.0 { None } else { Some(s.width) };
        let params = FabricationParams {
            material: Material { name: "custom".into(), youngs_modulus: m.youngs_modulus, shear_modulus: m.shear_modulus, allowable_stress: m.allowable_stress },
            thickness,
            stock: Stock { length: s.length, width, overlap: s.overlap, gap: s.gap },
            theta_degrees: strips.theta_degrees,
        };
        let input: Vec<FabricationStrip> = pattern.strips.iter().enumerate().map(|(i, s)| FabricationStrip::from_rectifying(&format!("strip_{i}"), s)).collect();
        let plan = plan_fabrication(&input, &params)?;
        out.set_owned(LmlFabrication { plan });
        Ok(LmlStatus::Ok)
    })
}

/// Releases a plan. NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn lml_fabrication_free(fabrication: *mut LmlFabrication) {
    guarded(|| {
        // SAFETY: NULL or a live handle from lml_fabrication_new.
        unsafe { release(fabrication) };
        Ok(LmlStatus::Ok)
    });
}

/// Writes the plan's totals to `*summary`.
/// Returns `LML_STATUS_OK` or `LML_STATUS_INVALID_ARGUMENT` (NULL argument).
#[no_mangle]
pub unsafe extern "C" fn lml_fabrication_summary(fabrication: *const LmlFabrication, summary: *mut LmlFabricationSummary) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; writable `summary`.
        let plan = &unsafe { handle(fabrication, "fabrication") }?.plan;
        unsafe { Out::new(summary, "summary") }?.set(LmlFabricationSummary {
            strips: plan.checks.len() as u64,
            pieces: plan.pieces.len() as u64,
            boards: plan.boards as u64,
            board_size: plan.board_size,
            material_yield: plan.material_yield(),
            overstressed_strips: plan.overstressed_strips().len() as u64,
        });
        Ok(LmlStatus::Ok)
    })
}

impl From<&StripCheck> for LmlStripCheck {
    fn from(c: &StripCheck) -> LmlStripCheck {
        let p = c.worst_position;
        LmlStripCheck {
            max_strain: c.max_strain,
            max_bending_stress: c.max_bending_stress,
            max_shear_stress: c.max_shear_stress,
            max_utilisation: c.max_utilisation,
            worst_point: c.worst_point as u64,
            worst_arc_length: c.arc_length[c.worst_point],
            worst_position: [p.x, p.y, p.z],
            min_bending_radius: c.min_bending_radius().unwrap_or(0.0),
            max_twist_rate: c.max_twist_rate(),
            overstressed: u32::from(c.is_overstressed()),
        }
    }
}

impl From<&Piece> for LmlPiece {
    fn from(p: &Piece) -> LmlPiece {
        let index = |k: Option<usize>| k.map_or(-1, |k| k as i64);
        LmlPiece {
            strip: p.strip as u64,
            number: p.number as u64,
            start: p.start,
            end: p.end,
            length: p.length(),
            width: p.width,
            min_bending_radius: p.min_bending_radius.unwrap_or(0.0),
            max_twist_rate: p.max_twist_rate,
            max_utilisation: p.max_utilisation,
            previous: index(p.previous),
            next: index(p.next),
            board: p.placement.board as u64 + 1,
            position: p.placement.position,
            size: p.shape.size,
        }
    }
}

/// Copies one check per strip (in strip order). Two-call pattern: `*needed` is always set to
/// the strip count; if `out` is NULL or `capacity` smaller, nothing is copied and
/// `LML_STATUS_BUFFER_TOO_SMALL` is returned.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_fabrication_strip_checks(fabrication: *const LmlFabrication, out: *mut LmlStripCheck, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `out` writable for `capacity` items; writable `needed`.
        let plan = &unsafe { handle(fabrication, "fabrication") }?.plan;
        let checks: Vec<LmlStripCheck> = plan.checks.iter().map(LmlStripCheck::from).collect();
        unsafe { copy_out(&checks, out, capacity, needed, "out") }
    })
}

/// Copies the pieces, strip by strip and along each strip (the bill of materials). Two-call
/// pattern as `lml_fabrication_strip_checks`.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`.
#[no_mangle]
pub unsafe extern "C" fn lml_fabrication_pieces(fabrication: *const LmlFabrication, out: *mut LmlPiece, capacity: usize, needed: *mut usize) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): as lml_fabrication_strip_checks.
        let plan = &unsafe { handle(fabrication, "fabrication") }?.plan;
        let pieces: Vec<LmlPiece> = plan.pieces.iter().map(LmlPiece::from).collect();
        unsafe { copy_out(&pieces, out, capacity, needed, "out") }
    })
}

/// `lml_fabrication_text` kind: the id of piece `index` (`strip_<i>-<k>`).
pub const LML_FABRICATION_TEXT_PIECE_ID: u32 = 0;
/// `lml_fabrication_text` kind: cut.dxf, R12 ASCII DXF in millimetres (layers OUTLINE, LABEL,
/// MARKS, CENTRELINE, STOCK).
pub const LML_FABRICATION_TEXT_CUT_DXF: u32 = 1;
/// `lml_fabrication_text` kind: cut.svg, the same drawing as SVG in millimetres.
pub const LML_FABRICATION_TEXT_CUT_SVG: u32 = 2;
/// `lml_fabrication_text` kind: bom.csv, the bill of materials.
pub const LML_FABRICATION_TEXT_BOM_CSV: u32 = 3;

/// Writes a text output of the plan as UTF-8 with a terminating NUL, two-call pattern:
/// `*needed` receives the byte count including the NUL; if `text` is NULL or `capacity`
/// smaller, nothing is copied and `LML_STATUS_BUFFER_TOO_SMALL` is returned. `index` selects the
/// piece for `LML_FABRICATION_TEXT_PIECE_ID` and is ignored otherwise.
/// Returns `LML_STATUS_OK`, `LML_STATUS_BUFFER_TOO_SMALL` or `LML_STATUS_INVALID_ARGUMENT`
/// (NULL argument, piece index out of range, unknown `kind`).
#[no_mangle]
pub unsafe extern "C" fn lml_fabrication_text(
    fabrication: *const LmlFabrication,
    kind: u32,
    index: usize,
    text: *mut u8,
    capacity: usize,
    needed: *mut usize,
) -> LmlStatus {
    guarded(|| {
        // SAFETY (both blocks): live handle; `needed` writable, `text` NULL or `capacity` bytes.
        let plan = &unsafe { handle(fabrication, "fabrication") }?.plan;
        let mut bytes = match kind {
            LML_FABRICATION_TEXT_PIECE_ID => plan
                .pieces
                .get(index)
                .ok_or_else(|| Failure::argument("index", format!("{index} is out of range ({} pieces)", plan.pieces.len())))?
                .id
                .clone(),
            LML_FABRICATION_TEXT_CUT_DXF => cut_dxf(plan),
            LML_FABRICATION_TEXT_CUT_SVG => cut_svg(plan),
            LML_FABRICATION_TEXT_BOM_CSV => bom_csv(plan),
            _ => return Err(Failure::argument("kind", format!("{kind} is not an LML_FABRICATION_TEXT_* kind"))),
        }
        .into_bytes();
        bytes.push(0);
        unsafe { copy_out(&bytes, text, capacity, needed, "text") }
    })
}
