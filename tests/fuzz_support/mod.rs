//! The fuzzing engine of `tests/fuzz.rs`: options, the mutator, the outcome-feedback loop and
//! the handling of findings. The targets and their seed corpora are in [`targets`].
pub mod targets;

use lamella::surfaces::SplitMix64;
use std::cell::RefCell;
use std::collections::HashSet;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Seconds per target when neither `--seconds` nor `--execs` is given (the CI run: the nine
/// targets on two threads, about 40 s).
pub const DEFAULT_SECONDS: f64 = 8.0;
/// One execution slower than this is a finding (a hang the size limits should have prevented).
pub const SLOW_SECONDS: f64 = 5.0;
/// One execution still running after this long is a hang: the watchdog reports its input and
/// ends the process.
const HANG_SECONDS: f64 = 60.0;
/// Largest input the mutator produces, in bytes.
const MAX_INPUT_BYTES: usize = 64 * 1024;
/// Most inputs kept per target (seeds and inputs with new outcomes).
const MAX_CORPUS: usize = 4096;

/// What one execution of a target found wrong, besides panicking.
pub type Verdict = Result<String, String>;

/// A fuzz target: its seed inputs, and a function that runs one input and returns its outcome
/// signature (`Ok`) or a broken invariant (`Err`, a finding).
pub struct Target {
    pub name: &'static str,
    /// Whether inputs are text (line-oriented mutations apply).
    pub text: bool,
    pub seeds: fn() -> Vec<Vec<u8>>,
    pub run: fn(&[u8]) -> Verdict,
}

/// Command-line options of the fuzz driver.
#[derive(Debug, Default)]
pub struct Options {
    pub target: Option<String>,
    pub seconds: Option<f64>,
    pub execs: Option<u64>,
    pub seed: u64,
    pub write_corpus: Option<PathBuf>,
    /// Print the outcome of every seed and regression (to judge what the corpus reaches).
    pub show_seeds: bool,
}

impl Options {
    /// Parses `--target NAME`, `--seconds S`, `--execs N`, `--seed K`, `--write-corpus DIR`,
    /// `--show-seeds` (cargo's own test flags, e.g. `--nocapture`, are ignored).
    pub fn from_args(args: impl Iterator<Item = String>) -> Result<Options, String> {
        let mut options = Options { seed: 1, ..Options::default() };
        let mut args = args.peekable();
        while let Some(flag) = args.next() {
            let mut value = || args.next().ok_or_else(|| format!("{flag} needs a value"));
            match flag.as_str() {
                "--target" => options.target = Some(value()?),
                "--seconds" => options.seconds = Some(value()?.parse().map_err(|e| format!("--seconds: {e}"))?),
                "--execs" => options.execs = Some(value()?.parse().map_err(|e| format!("--execs: {e}"))?),
                "--seed" => options.seed = value()?.parse().map_err(|e| format!("--seed: {e}"))?,
                "--write-corpus" => options.write_corpus = Some(PathBuf::from(value()?)),
                "--show-seeds" => options.show_seeds = true,
                _ => {}
            }
        }
        Ok(options)
    }
}

/// Totals of one target's run.
pub struct RunResult {
    pub executions: u64,
    pub findings: usize,
}

/// The committed crash reproducers of a target.
fn regressions(name: &str) -> Vec<Vec<u8>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/regressions").join(name);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect()).unwrap_or_default();
    files.sort();
    files.iter().filter_map(|f| std::fs::read(f).ok()).collect()
}

/// Writes the seed corpus of `target` to `dir/<target>/seed-<i>`.
pub fn write_corpus(dir: &Path, target: &Target) {
    let sub = dir.join(target.name);
    std::fs::create_dir_all(&sub).expect("corpus directory");
    for (i, seed) in (target.seeds)().iter().enumerate() {
        std::fs::write(sub.join(format!("seed-{i:03}")), seed).expect("write seed");
    }
}

/// The outcome up to its first quoted token, with its digits removed and cut to 100 characters:
/// messages that differ only in the element or token they name count as one outcome.
fn signature(outcome: &str) -> String {
    let head = outcome.split(['\'', '`', '"']).next().unwrap_or("");
    head.chars().filter(|c| !c.is_ascii_digit()).take(100).collect()
}

thread_local! {
    /// The message of the last panic on this thread, kept by [`record_panics`]'s hook.
    static LAST_PANIC: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Replaces the panic hook, once for the whole run, by one that keeps each panic's location and
/// message for the thread that panicked (targets run on several threads at once) instead of
/// printing it.
pub fn record_panics() {
    std::panic::set_hook(Box::new(|info| {
        let location = info.location().map(|l| format!(" at {}:{}", l.file(), l.line())).unwrap_or_default();
        let payload = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        LAST_PANIC.with(|last| *last.borrow_mut() = Some(format!("panic{location}: {payload}")));
    }));
}

/// Runs `target` as `options` say: the regressions and seeds first, then mutations until the
/// time or execution budget is used up.
pub fn run_target(target: &Target, options: &Options) -> RunResult {
    let started = Instant::now();
    let budget = match (options.seconds, options.execs) {
        (Some(s), _) => Some(Duration::from_secs_f64(s)),
        (None, Some(_)) => None,
        (None, None) => Some(Duration::from_secs_f64(DEFAULT_SECONDS)),
    };
    let mut rng = SplitMix64::new(options.seed ^ fnv(target.name.as_bytes()));
    let mut corpus: Vec<Vec<u8>> = Vec::new();
    let mut seen: HashSet<String> = HashSet::new();
    let mut findings: Vec<(Vec<u8>, String)> = Vec::new();
    let mut executions: u64 = 0;
    let current: Arc<Mutex<(Option<Instant>, Vec<u8>)>> = Arc::new(Mutex::new((None, Vec::new())));
    let watched = Arc::clone(&current);
    let name = target.name;
    std::thread::spawn(move || loop {
        std::thread::sleep(Duration::from_millis(500));
        let state = watched.lock().unwrap_or_else(|e| e.into_inner());
        if let (Some(since), input) = &*state {
            let seconds = since.elapsed().as_secs_f64();
            if seconds > HANG_SECONDS {
                report_finding(name, input, &format!("hang: still running after {seconds:.0} s"));
                println!("0 passed, 1 failed");
                std::process::exit(1);
            }
        }
    });
    let mut queue = regressions(target.name).into_iter().chain((target.seeds)());
    loop {
        let (input, fixed) = match queue.next() {
            Some(input) => (input, true),
            None => {
                let done = match budget {
                    Some(budget) => started.elapsed() >= budget,
                    None => executions >= options.execs.unwrap_or(0),
                };
                if done || corpus.is_empty() {
                    break;
                }
                (mutate(&corpus, target.text, &mut rng), false)
            }
        };
        let one = Instant::now();
        *current.lock().unwrap_or_else(|e| e.into_inner()) = (Some(one), input.clone());
        let outcome = catch_unwind(AssertUnwindSafe(|| (target.run)(&input)));
        current.lock().unwrap_or_else(|e| e.into_inner()).0 = None;
        let seconds = one.elapsed().as_secs_f64();
        executions += 1;
        if fixed && options.show_seeds {
            println!("seed of {}: {:?}", target.name, outcome.as_ref().map_err(|_| "panic"));
        }
        let finding = match outcome {
            Err(_) => Some(LAST_PANIC.with(|last| last.borrow_mut().take()).unwrap_or_else(|| "panic".into())),
            Ok(Err(broken)) => Some(format!("invariant: {broken}")),
            Ok(Ok(_)) if seconds > SLOW_SECONDS => Some(format!("slow: {seconds:.1} s")),
            Ok(Ok(outcome)) => {
                // Every seed and regression stays a parent, even when its outcome repeats another's.
                if (seen.insert(signature(&outcome)) || fixed) && corpus.len() < MAX_CORPUS {
                    corpus.push(input.clone());
                }
                None
            }
        };
        if let Some(what) = finding {
            if findings.len() < 20 {
                report_finding(target.name, &input, &what);
            }
            findings.push((input, what));
        }
    }
    let rate = executions as f64 / started.elapsed().as_secs_f64().max(1e-9);
    println!(
        "fuzz {:<10} {executions:>10} executions ({rate:.0}/s), {} outcomes, corpus {}, {} findings",
        target.name,
        seen.len(),
        corpus.len(),
        findings.len()
    );
    RunResult { executions, findings: findings.len() }
}

/// Writes a finding's input under `target/fuzz-findings/<target>/` and describes it.
fn report_finding(name: &str, input: &[u8], what: &str) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/fuzz-findings").join(name);
    let path = dir.join(format!("{:016x}", fnv(input)));
    let saved = std::fs::create_dir_all(&dir).and_then(|()| std::fs::write(&path, input));
    let preview: String = String::from_utf8_lossy(&input[..input.len().min(200)]).escape_debug().collect();
    println!("FINDING in {name}: {what}");
    match saved {
        Ok(()) => println!("  input ({} bytes) saved to {}: \"{preview}\"", input.len(), path.display()),
        Err(e) => println!("  input ({} bytes) not saved ({e}): \"{preview}\"", input.len()),
    }
}

/// FNV-1a hash (stable across runs, for file names and per-target seeds).
fn fnv(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3))
}

/// Numbers that break naive readers: overflow, underflow, subnormals, signs, non-finite values,
/// index limits.
const EXTREME_NUMBERS: &[&str] = &[
    "0", "-0", "1", "-1", "2", "3", "1e300", "-1e300", "1e308", "1.8e308", "1e-320", "5e-324", "1e-300", "inf", "-inf", "nan", "NaN",
    "4294967295", "4294967296", "-4294967296", "18446744073709551615", "18446744073709551616", "9223372036854775807",
    "-9223372036854775808", "2147483647", "0.5", "1e100", "1e101", "65536", "1e-9", "99999999999999999999999",
];

fn below(rng: &mut SplitMix64, n: usize) -> usize {
    if n == 0 {
        0
    } else {
        (rng.next_u64() % n as u64) as usize
    }
}

/// A mutant of a random corpus entry: one to four stacked mutations.
fn mutate(corpus: &[Vec<u8>], text: bool, rng: &mut SplitMix64) -> Vec<u8> {
    let mut data = corpus[below(rng, corpus.len())].clone();
    for _ in 0..1 + below(rng, 4) {
        let kinds = if text { 12 } else { 8 };
        match below(rng, kinds) {
            0 if !data.is_empty() => {
                let i = below(rng, data.len());
                data[i] ^= 1 << below(rng, 8);
            }
            1 if !data.is_empty() => {
                let i = below(rng, data.len());
                data[i] = [0u8, 0xff, 0x7f, 0x80, 0x01, b'\n', b' ', b'-', b'.', b'e', b'/', b'"', b'[', b']', b',', b'9'][below(rng, 16)];
            }
            2 if !data.is_empty() => {
                let start = below(rng, data.len());
                let end = (start + 1 + below(rng, 16)).min(data.len());
                data.drain(start..end);
            }
            3 => {
                let at = below(rng, data.len() + 1);
                let bytes: Vec<u8> = (0..1 + below(rng, 8)).map(|_| rng.next_u64() as u8).collect();
                data.splice(at..at, bytes);
            }
            4 if !data.is_empty() => {
                // Duplicate a chunk in place (repeated structure).
                let start = below(rng, data.len());
                let end = (start + 1 + below(rng, 64)).min(data.len());
                let chunk = data[start..end].to_vec();
                let at = below(rng, data.len() + 1);
                data.splice(at..at, chunk);
            }
            5 => {
                // Splice: the head of this input and the tail of another.
                let other = &corpus[below(rng, corpus.len())];
                let cut = below(rng, data.len() + 1);
                let from = below(rng, other.len() + 1);
                data.truncate(cut);
                data.extend_from_slice(&other[from..]);
            }
            6 if data.len() >= 8 => {
                // Overwrite 8 bytes with an extreme little-endian value (binary layouts).
                let at = below(rng, data.len() - 7);
                let value: u64 = match below(rng, 6) {
                    0 => u64::MAX,
                    1 => 0,
                    2 => 1u64 << 40,
                    3 => f64::MIN_POSITIVE.to_bits() >> 4,
                    4 => 1e300f64.to_bits(),
                    _ => f64::NAN.to_bits(),
                };
                data[at..at + 8].copy_from_slice(&value.to_le_bytes());
            }
            7 if data.len() >= 4 => {
                let at = below(rng, data.len() - 3);
                let value = [u32::MAX, 0, 1, 1 << 31][below(rng, 4)];
                data[at..at + 4].copy_from_slice(&value.to_le_bytes());
            }
            8 => replace_number(&mut data, rng),
            9 => edit_lines(&mut data, rng),
            10 => {
                // A long token: readers must clip what they quote.
                let at = below(rng, data.len() + 1);
                let token = vec![b'x'; 1 + below(rng, 2000)];
                data.splice(at..at, token);
            }
            _ => replace_number(&mut data, rng),
        }
    }
    data.truncate(MAX_INPUT_BYTES);
    data
}

/// Replaces one run of number characters by an extreme number.
fn replace_number(data: &mut Vec<u8>, rng: &mut SplitMix64) {
    let is_number = |b: u8| b.is_ascii_digit() || b == b'.' || b == b'-' || b == b'e' || b == b'+';
    let starts: Vec<usize> = (0..data.len()).filter(|&i| is_number(data[i]) && (i == 0 || !is_number(data[i - 1]))).collect();
    if starts.is_empty() {
        return;
    }
    let start = starts[below(rng, starts.len())];
    let end = (start..data.len()).find(|&i| !is_number(data[i])).unwrap_or(data.len());
    let number = EXTREME_NUMBERS[below(rng, EXTREME_NUMBERS.len())].as_bytes().to_vec();
    data.splice(start..end, number);
}

/// Deletes, duplicates or swaps whole lines.
fn edit_lines(data: &mut Vec<u8>, rng: &mut SplitMix64) {
    let mut lines: Vec<Vec<u8>> = data.split(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    if lines.is_empty() {
        return;
    }
    let i = below(rng, lines.len());
    match below(rng, 3) {
        0 => {
            lines.remove(i);
        }
        1 => {
            let line = lines[i].clone();
            let copies = 1 + below(rng, 50);
            for _ in 0..copies {
                lines.insert(i, line.clone());
            }
        }
        _ => {
            let j = below(rng, lines.len());
            lines.swap(i, j);
        }
    }
    *data = lines.join(&b'\n');
}
