//! The command line: parse arguments, call the library, map outcomes to exit
//! codes (0: every case passes; 1: a case fails; 2: bad input or usage).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

use rastercheck::golden;
use rastercheck::report::png;
use rastercheck::scene::Limits;
use rastercheck::suite::{self, GoldenStatus, Verdict};

#[derive(Parser)]
#[command(
    name = "rastercheck",
    version,
    about = "Conformance and accuracy tests for rasterizers, against an exact reference"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run cases through rasterizers and compare them with the exact reference.
    Run {
        /// Case files or folders (default: cases). Folders named `invalid`
        /// are skipped unless named directly.
        paths: Vec<PathBuf>,
        /// Rasterizer to check; repeat for several (default: production).
        /// `rastercheck rasterizers` lists them.
        #[arg(long = "rasterizer", short = 'r')]
        rasterizers: Vec<String>,
        /// Print only failures and the summary.
        #[arg(long, short = 'q')]
        quiet: bool,
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// Rewrite the golden reference files (reference/<case>.exr) from the oracle.
    Bless {
        /// Case files or folders (default: cases).
        paths: Vec<PathBuf>,
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// Write magnified PNGs of one case: reference, candidate and difference mask.
    Show {
        /// The case file.
        case: PathBuf,
        /// Folder for the images.
        #[arg(long)]
        out: PathBuf,
        /// The candidate rasterizer (default: production).
        #[arg(long = "rasterizer", short = 'r', default_value = "production")]
        rasterizer: String,
        /// Magnification (default: about 512 pixels across).
        #[arg(long)]
        scale: Option<u32>,
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// List the rasterizers that can be named with --rasterizer.
    Rasterizers,
}

#[derive(Args)]
struct LimitArgs {
    /// Largest canvas, in pixels.
    #[arg(long, default_value_t = Limits::default().max_canvas_pixels)]
    max_canvas_pixels: u64,
    /// Largest number of primitives in one case.
    #[arg(long, default_value_t = Limits::default().max_primitives)]
    max_primitives: usize,
}

impl LimitArgs {
    fn limits(&self) -> Limits {
        Limits {
            max_canvas_pixels: self.max_canvas_pixels,
            max_primitives: self.max_primitives,
        }
    }
}

const PASS: u8 = 0;
const FAIL: u8 = 1;
const BAD_INPUT: u8 = 2;

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            let code = if e.use_stderr() { BAD_INPUT } else { PASS };
            return ExitCode::from(code);
        }
    };
    ExitCode::from(match cli.command {
        Command::Run {
            paths,
            rasterizers,
            quiet,
            limits,
        } => run(paths, rasterizers, quiet, limits.limits()),
        Command::Bless { paths, limits } => bless(paths, limits.limits()),
        Command::Show {
            case,
            out,
            rasterizer,
            scale,
            limits,
        } => show(case, out, &rasterizer, scale, limits.limits()),
        Command::Rasterizers => {
            for name in suite::rasterizer_names() {
                println!("{name}");
            }
            PASS
        }
    })
}

fn default_paths(paths: Vec<PathBuf>) -> Vec<PathBuf> {
    if paths.is_empty() {
        vec![PathBuf::from("cases")]
    } else {
        paths
    }
}

/// Discovers cases, printing what was skipped and what could not be found.
/// `None` when nothing can be run.
fn discover(paths: Vec<PathBuf>) -> (suite::Discovery, bool) {
    let found = suite::discover(&default_paths(paths));
    for dir in &found.skipped {
        println!(
            "note: skipping {} (negative tests; name it explicitly to check it)",
            dir.display()
        );
    }
    for error in &found.errors {
        eprintln!("error: {error}");
    }
    let bad = !found.errors.is_empty();
    (found, bad)
}

fn run(paths: Vec<PathBuf>, names: Vec<String>, quiet: bool, limits: Limits) -> u8 {
    let names = if names.is_empty() {
        vec!["production".to_owned()]
    } else {
        names
    };
    let mut candidates = Vec::new();
    for name in &names {
        match suite::rasterizer(name) {
            Some(r) => candidates.push(r),
            None => {
                eprintln!(
                    "error: unknown rasterizer {name:?}; known: {}",
                    suite::rasterizer_names().join(", ")
                );
                return BAD_INPUT;
            }
        }
    }
    let (found, mut bad_input) = discover(paths);
    if found.cases.is_empty() {
        eprintln!("error: no case files found");
        return BAD_INPUT;
    }
    let root = PathBuf::from(".");
    let width = found.cases.iter().map(|c| c.id.len()).max().unwrap_or(0);
    let mut tally = vec![[0usize; 4]; candidates.len()];
    let (mut bad_cases, mut golden_ok, mut golden_missing, mut golden_bad) = (0, 0, 0, 0);
    for file in &found.cases {
        let scene = match suite::load(file, &limits) {
            Ok(scene) => scene,
            Err(e) => {
                println!("BAD   {:width$}  {e}", file.id);
                bad_cases += 1;
                bad_input = true;
                continue;
            }
        };
        let reference = suite::run_reference(&scene);
        match suite::check_golden(&root, &file.id, &reference.frame) {
            GoldenStatus::Matches => golden_ok += 1,
            GoldenStatus::Missing(_) => golden_missing += 1,
            GoldenStatus::Differs(why) => {
                golden_bad += 1;
                println!(
                    "GOLDEN {:width$}  the reference no longer reproduces its golden file: {why}",
                    file.id
                );
            }
        }
        for (k, candidate) in candidates.iter().enumerate() {
            let result = suite::run_candidate(&scene, &reference, candidate.as_ref());
            let slot = match result.verdict {
                Verdict::Pass => 0,
                Verdict::Fail(_) => 1,
                Verdict::Unsupported(_) => 2,
                Verdict::Error(_) => 3,
            };
            tally[k][slot] += 1;
            if quiet && slot == 0 {
                continue;
            }
            // A foil's failure is a measured departure, not a failure.
            let label = match &result.verdict {
                Verdict::Fail(_) if candidate.is_foil() => "FOIL",
                other => other.label(),
            };
            println!(
                "{:5} {:width$}  {}  {}",
                label,
                file.id,
                result.rasterizer,
                suite::describe(&result)
            );
            if let Verdict::Fail(reasons) = &result.verdict {
                for reason in reasons {
                    println!("        {reason}");
                }
            }
        }
    }
    println!();
    println!("{} case files, {} unreadable", found.cases.len(), bad_cases);
    for (candidate, t) in candidates.iter().zip(&tally) {
        if candidate.is_foil() {
            println!(
                "{}: {} exact, {} departing from the reference (a foil: expected, not a failure), {} unsupported, {} errors",
                candidate.name(),
                t[0],
                t[1],
                t[2],
                t[3]
            );
        } else {
            println!(
                "{}: {} passed, {} failed, {} unsupported, {} errors",
                candidate.name(),
                t[0],
                t[1],
                t[2],
                t[3]
            );
        }
    }
    println!(
        "golden files: {golden_ok} match, {golden_bad} differ, {golden_missing} missing{}",
        if golden_missing > 0 {
            " (rastercheck bless writes them)"
        } else {
            ""
        }
    );
    if bad_input {
        BAD_INPUT
    } else if golden_bad > 0
        || candidates
            .iter()
            .zip(&tally)
            .any(|(c, t)| t[3] > 0 || (t[1] > 0 && !c.is_foil()))
    {
        FAIL
    } else {
        PASS
    }
}

fn bless(paths: Vec<PathBuf>, limits: Limits) -> u8 {
    let (found, mut bad_input) = discover(paths);
    let root = PathBuf::from(".");
    let mut written = 0;
    for file in &found.cases {
        let scene = match suite::load(file, &limits) {
            Ok(scene) => scene,
            Err(e) => {
                eprintln!("error: {e}");
                bad_input = true;
                continue;
            }
        };
        let reference = suite::run_reference(&scene);
        let path = golden::path_for(&root, &file.id);
        match golden::write(&reference.frame, &path) {
            Ok(()) => written += 1,
            Err(e) => {
                eprintln!("error: {e}");
                bad_input = true;
            }
        }
    }
    println!("blessed {written} golden files under reference/");
    if bad_input {
        BAD_INPUT
    } else {
        PASS
    }
}

fn show(case: PathBuf, out: PathBuf, name: &str, scale: Option<u32>, limits: Limits) -> u8 {
    let Some(candidate) = suite::rasterizer(name) else {
        eprintln!(
            "error: unknown rasterizer {name:?}; known: {}",
            suite::rasterizer_names().join(", ")
        );
        return BAD_INPUT;
    };
    let file = suite::case_file(&case);
    let scene = match suite::load(&file, &limits) {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("error: {e}");
            return BAD_INPUT;
        }
    };
    let reference = suite::run_reference(&scene);
    let result = suite::run_candidate(&scene, &reference, candidate.as_ref());
    let (Some(frame), Some(metrics)) = (&result.frame, &result.metrics) else {
        eprintln!("{}: {}", candidate.name(), suite::describe(&result));
        return FAIL;
    };
    let scale = scale.unwrap_or_else(|| png::auto_scale(frame)).clamp(1, 64);
    match png::write_comparison(
        &scene,
        &reference.frame,
        candidate.name(),
        frame,
        &metrics.coverage.mask,
        &out,
        scale,
    ) {
        Ok(paths) => {
            for p in paths {
                println!("wrote {}", p.display());
            }
            println!(
                "{} {}: {}",
                result.verdict.label(),
                candidate.name(),
                suite::describe(&result)
            );
            println!("key: magenta = missing, red = extra, yellow = wrong owner, grey = covered alike; cyan = snapped edges");
            if matches!(result.verdict, Verdict::Pass) {
                PASS
            } else {
                FAIL
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            BAD_INPUT
        }
    }
}
