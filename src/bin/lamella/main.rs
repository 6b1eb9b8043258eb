//! `lamella`: the command-line front door of the crate. Without arguments it designs a θ = 60°
//! rectifying strip pattern on the built-in hall roof into `./lamella-out/`; subcommands run the
//! pipeline's steps one at a time on the same files. Exit codes: 0 success (or stdout closed by
//! its reader), 2 bad input, 1 internal failure or a failed write to stdout, 3 no acceptable
//! family (outputs written, but the strips miss θ).

mod args;
mod config;
mod console;
mod design;
mod diagnostics_csv;
mod error;
mod fabricate;
mod fabrication_files;
mod field_cmd;
mod field_files;
mod guides;
mod info;
mod mesh_input;
mod metrics;
mod net_cmd;
mod net_obj;
mod optimise_cmd;
mod output_dir;
mod progress;
mod report_json;
mod reshape_cmd;
mod reshape_trial;
mod shade_cmd;
mod slope_field;
mod start_field;
mod strip_obj;
mod strips_cmd;
mod strokes_file;
mod surface_cmd;
mod svg;
mod trace_cmd;
mod units;
mod unroll;
mod view_cmd;

use args::{Cli, Command};
use clap::Parser;
use error::{CliError, CliResult};
use std::process::ExitCode;

fn main() -> ExitCode {
    // Usage errors exit with clap's code 2 (bad input); --help and --version with 0.
    let cli = Cli::parse();
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(CliError::NoAcceptableFamily(message)) => {
            console::err_line(format!("lamella: {message}"));
            ExitCode::from(3)
        }
        Err(error) => {
            if let Some(message) = error.message() {
                console::err_line(format!("lamella: error: {message}"));
            }
            ExitCode::from(error.exit_code())
        }
    }
}

fn run(cli: &Cli) -> CliResult<()> {
    match &cli.command {
        None => design::run(&cli.design),
        Some(Command::Design(args)) => design::run(args),
        Some(Command::Info(args)) => info::run(args),
        Some(Command::Trace(args)) => trace_cmd::run(args),
        Some(Command::Field(args)) => field_cmd::run(args),
        Some(Command::Strips(args)) => strips_cmd::run(args),
        Some(Command::Unroll(args)) => unroll::run(args),
        Some(Command::Metrics(args)) => metrics::run(args),
        Some(Command::Fabricate(args)) => fabricate::run(args),
        Some(Command::Net(args)) => net_cmd::run(args),
        Some(Command::View(args)) => view_cmd::run(args),
        Some(Command::Reshape(args)) => reshape_cmd::run(args),
        Some(Command::Optimise(args)) => optimise_cmd::run(args),
        Some(Command::Shade(args)) => shade_cmd::run(args),
        Some(Command::Surface(args)) => surface_cmd::run(args),
    }
}
