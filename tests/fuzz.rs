//! In-process fuzzing of every reader of hostile input, on stable Rust (FUZZING.md): the OBJ
//! reader, the session loaders (field, surface, net, base mesh), the command line's field CSV,
//! strokes and guides readers, and the C ABI's mesh and field creation.
//!
//! A mutation fuzzer with outcome feedback: each target starts from a seed corpus this file makes
//! from the project's own surfaces and writers (plus the committed crash reproducers in
//! `fuzz/regressions/<target>/`), mutates inputs (bit flips, byte and line edits, splices,
//! numbers replaced by extreme ones), and keeps every input whose outcome (the error message with
//! its numbers removed, or the shape of the result) was not seen before. A panic, a broken
//! invariant (checked by each target) or an input slower than [`SLOW_SECONDS`] is a finding:
//! its input is written to `target/fuzz-findings/<target>/` and the run fails.
//!
//! `cargo test --test fuzz` runs each target for a few seconds (CI); longer runs:
//! `cargo test --release --test fuzz -- --seconds 600 [--target obj] [--seed 7]` or
//! `--execs N` (deterministic for a given seed); `--write-corpus DIR` writes the seed corpus.
#![allow(dead_code)] // The command-line modules included below are only partly used here.

#[path = "../src/bin/lamella/args.rs"]
mod args;
#[path = "../src/bin/lamella/config.rs"]
mod config;
#[path = "../src/bin/lamella/console.rs"]
mod console;
#[path = "../src/bin/lamella/error.rs"]
mod error;
#[path = "../src/bin/lamella/field_files.rs"]
mod field_files;
#[path = "../src/bin/lamella/guides.rs"]
mod guides;
#[path = "../src/bin/lamella/mesh_input.rs"]
mod mesh_input;
#[path = "../src/bin/lamella/strokes_file.rs"]
mod strokes_file;

#[path = "integration/mesh_support/mod.rs"]
mod mesh_support;

mod fuzz_support;

use fuzz_support::{run_target, Options, RunResult, Target};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Targets fuzzed at the same time: each has its own seeded generator, corpus and watchdog, so a
/// target's run does not depend on which worker takes it.
const WORKERS: usize = 2;

fn main() {
    let options = match Options::from_args(std::env::args().skip(1)) {
        Ok(options) => options,
        Err(message) => {
            eprintln!("fuzz: {message}");
            std::process::exit(2);
        }
    };
    let targets = fuzz_support::targets::all();
    if let Some(dir) = &options.write_corpus {
        for target in &targets {
            fuzz_support::write_corpus(dir, target);
        }
        return;
    }
    let chosen: Vec<&Target> = targets.iter().filter(|t| options.target.as_deref().is_none_or(|name| name == t.name)).collect();
    if chosen.is_empty() {
        eprintln!("fuzz: no target named {:?}", options.target);
        std::process::exit(2);
    }
    fuzz_support::record_panics();
    let results = run_on_workers(&chosen, &options);
    let executions: u64 = results.iter().map(|r| r.executions).sum();
    let findings: usize = results.iter().map(|r| r.findings).sum();
    println!("fuzz: {executions} executions in total, {findings} findings");
    if findings > 0 {
        println!("0 passed, 1 failed");
        std::process::exit(1);
    }
}

/// Runs the targets on [`WORKERS`] threads, each taking the next target not yet taken; the
/// results come back in the targets' order.
fn run_on_workers(targets: &[&Target], options: &Options) -> Vec<RunResult> {
    let next = AtomicUsize::new(0);
    let mut results: Vec<(usize, RunResult)> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..WORKERS.min(targets.len()))
            .map(|_| {
                scope.spawn(|| {
                    let mut done = Vec::new();
                    loop {
                        let index = next.fetch_add(1, Ordering::Relaxed);
                        let Some(target) = targets.get(index) else { break done };
                        done.push((index, run_target(target, options)));
                    }
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|worker| {
                worker.join().unwrap_or_else(|_| {
                    // The panic hook keeps messages instead of printing them: say it here.
                    println!("fuzz: a worker thread panicked outside a target's execution");
                    println!("0 passed, 1 failed");
                    std::process::exit(1)
                })
            })
            .collect()
    });
    results.sort_by_key(|(index, _)| *index);
    results.into_iter().map(|(_, result)| result).collect()
}
