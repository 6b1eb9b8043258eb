//! Progress of the field optimisation: a bar with iteration, energy and ETA on a terminal, plain
//! lines otherwise, every iteration under `--verbose`, nothing under `--quiet`.
use crate::args::VerbosityArgs;
use crate::console::{err_line, out_line};
use crate::error::CliResult;
use lamella::field::StepReport;
use std::io::{IsTerminal, Write};
use std::time::Instant;

/// Plain lines are printed every this many iterations.
const PLAIN_EVERY: usize = 10;
const BAR_WIDTH: usize = 30;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verbosity {
    Quiet,
    Normal,
    Verbose,
}

impl From<VerbosityArgs> for Verbosity {
    fn from(args: VerbosityArgs) -> Verbosity {
        match (args.quiet, args.verbose) {
            (true, _) => Verbosity::Quiet,
            (false, true) => Verbosity::Verbose,
            (false, false) => Verbosity::Normal,
        }
    }
}

/// Reports the iterations of one optimisation on stderr.
pub struct Progress {
    verbosity: Verbosity,
    terminal: bool,
    started: Instant,
    first_iteration: usize,
    max_iterations: usize,
    bar_drawn: bool,
}

impl Progress {
    /// Progress of iterations `first_iteration..max_iterations`.
    pub fn new(verbosity: Verbosity, first_iteration: usize, max_iterations: usize) -> Progress {
        Progress {
            verbosity,
            terminal: std::io::stderr().is_terminal(),
            started: Instant::now(),
            first_iteration,
            max_iterations,
            bar_drawn: false,
        }
    }

    /// Reports the state after an iteration.
    pub fn iteration(&mut self, r: &StepReport) {
        match self.verbosity {
            Verbosity::Quiet => {}
            Verbosity::Verbose => err_line(format_args!(
                "iteration {:5}  stage {}  E_angle {:9.3e}  E_frame {:9.3e}  E_fair {:9.3e}  E_grad {:9.3e}  total {:9.3e}  angle error max {:.3}°  singular {}",
                r.iterations,
                r.stage,
                r.energies.angle,
                r.energies.frame,
                r.energies.fair,
                r.energies.grad,
                r.energies.total,
                r.angle_error_max_degrees,
                r.singular_vertices.len()
            )),
            Verbosity::Normal if self.terminal => self.draw_bar(r),
            Verbosity::Normal => {
                if r.iterations % PLAIN_EVERY == 0 || r.converged {
                    err_line(format_args!(
                        "iteration {:5}  E_angle {:9.3e}  total {:9.3e}  angle error max {:.3}°",
                        r.iterations, r.energies.angle, r.energies.total, r.angle_error_max_degrees
                    ));
                }
            }
        }
    }

    fn draw_bar(&mut self, r: &StepReport) {
        let span = self.max_iterations.saturating_sub(self.first_iteration).max(1);
        let done = r.iterations.saturating_sub(self.first_iteration).min(span);
        let filled = if r.converged { BAR_WIDTH } else { done * BAR_WIDTH / span };
        let elapsed = self.started.elapsed().as_secs_f64();
        // The iteration cap bounds the remaining time; convergence usually comes earlier.
        let eta = if done == 0 { 0.0 } else { elapsed / done as f64 * (span - done) as f64 };
        let mut err = std::io::stderr();
        let _ = write!(
            err,
            "\r[{}{}] iteration {:5}/{}  E_angle {:9.3e}  ETA ≤ {:5.1} s ",
            "#".repeat(filled),
            ".".repeat(BAR_WIDTH - filled),
            r.iterations,
            self.max_iterations,
            r.energies.angle,
            if r.converged { 0.0 } else { eta }
        );
        let _ = err.flush();
        self.bar_drawn = true;
    }

    /// Ends the bar's line.
    pub fn finish(&mut self) {
        if self.bar_drawn {
            err_line("");
            self.bar_drawn = false;
        }
    }
}

/// A status line on stderr unless quiet.
pub fn note(verbosity: Verbosity, message: &str) {
    if verbosity != Verbosity::Quiet {
        err_line(message);
    }
}

/// A summary line on stdout unless quiet; a failed write is an error (see [`out_line`]).
pub fn summary(verbosity: Verbosity, message: &str) -> CliResult<()> {
    if verbosity != Verbosity::Quiet {
        out_line(message)?;
    }
    Ok(())
}
