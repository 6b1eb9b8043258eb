//! `lamella fabricate`: the workshop files of the strips in a strips.obj (cut.dxf, cut.svg,
//! bom.csv, utilisation.svg, report.json). Strips over 100 % utilisation are a warning (exit 0):
//! the files are written and flag them.
use crate::args::FabricateArgs;
use crate::config::DEFAULT_OUT;
use crate::console::err_line;
use crate::error::CliResult;
use crate::fabrication_files::{cli_error, overstress_warning, params, report_section, summary_line, write_files, FILES};
use crate::output_dir::OutputDir;
use crate::progress::{summary, Verbosity};
use crate::strip_obj::read_strips_obj;
use lamella::fabrication::{plan_fabrication, FabricationStrip};
use serde_json::json;
use std::path::PathBuf;

pub fn run(args: &FabricateArgs) -> CliResult<()> {
    let verbosity = Verbosity::from(args.verbosity);
    let params = params(&args.fabrication, args.theta)?;
    let shapes = read_strips_obj(&args.strips_obj)?;
    let strips: Vec<FabricationStrip> = shapes.iter().map(|s| FabricationStrip::from_boundaries(&s.name, &s.left, &s.right)).collect();
    let plan = plan_fabrication(&strips, &params).map_err(cli_error)?;
    let target = args.out.out.clone().unwrap_or_else(|| PathBuf::from(DEFAULT_OUT));
    let out = OutputDir::create(&target, args.out.force)?;
    let boundaries: Vec<(&[_], &[_])> = shapes.iter().map(|s| (s.left.as_slice(), s.right.as_slice())).collect();
    write_files(&out, &plan, &boundaries, None)?;
    let report = json!({
        "lamella_version": env!("CARGO_PKG_VERSION"),
        "strips_obj": args.strips_obj.display().to_string(),
        "fabrication": report_section(&plan),
    });
    out.write("report.json", crate::report_json::pretty(&report))?;
    out.commit()?;
    if let Some(warning) = overstress_warning(&plan) {
        if verbosity != Verbosity::Quiet {
            err_line(format!("lamella: warning: {warning}"));
        }
    }
    summary(verbosity, &format!("{}\nwrote {}/ ({FILES}, report.json)", summary_line(&plan), target.display()))
}
