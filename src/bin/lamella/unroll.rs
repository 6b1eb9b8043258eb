//! `lamella unroll`: the cut sheet (unrolled.svg) of the strips in a strips.obj.
use crate::args::UnrollArgs;
use crate::config::DEFAULT_OUT;
use crate::error::CliResult;
use crate::output_dir::OutputDir;
use crate::progress::{summary, Verbosity};
use crate::strip_obj::read_strips_obj;
use crate::svg::cut_sheet::{cut_sheet_svg, CutPiece};
use lamella::strips::{unroll, Unrolling};
use std::path::PathBuf;

pub fn run(args: &UnrollArgs) -> CliResult<()> {
    let verbosity = Verbosity::from(args.verbosity);
    let shapes = read_strips_obj(&args.strips_obj)?;
    let target = args.out.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    let out = OutputDir::create(&target, args.out.force)?;
    let unrollings: Vec<Unrolling> = shapes.iter().map(|s| unroll(&s.centre(), &s.offsets())).collect();
    let pieces: Vec<CutPiece> = shapes.iter().zip(&unrollings).map(|(s, u)| CutPiece { name: s.name.clone(), unrolling: u, marks: Vec::new() }).collect();
    out.write("unrolled.svg", cut_sheet_svg(&pieces))?;
    out.commit()?;
    let total: f64 = unrollings.iter().map(|u| u.length).sum();
    summary(verbosity, &format!("{} strips, total length {total:.2} m\nwrote {}/unrolled.svg", pieces.len(), target.display()))
}
