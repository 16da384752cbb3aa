//! The command line: parse arguments, call the library, map outcomes to exit
//! codes (0: every case passes; 1: a case fails; 2: bad input or usage).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand};

use rastercheck::harness::baseline::{Baseline, Observed, SelectionInfo};
use rastercheck::harness::golden;
use rastercheck::report::png;
use rastercheck::scene::Limits;
use std::io::IsTerminal;

use rastercheck::harness::runner::{self, CaseOutcome, Problem, Selection};
use rastercheck::harness::suite::{self, GoldenStatus, Verdict};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::report;
use rastercheck::report::json::{CaseEntry, LimitsInfo, RasterizerInfo, Report};

/// The system allocator, counting only while `bench` measures a method's
/// peak heap (one relaxed atomic load per allocation otherwise).
#[global_allocator]
static ALLOCATOR: rastercheck::bench::memory::Counting = rastercheck::bench::memory::Counting;

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
    Run(RunArgs),
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
    /// Record accuracy metrics per case and rasterizer (`save`), or hold a
    /// run to them (`check`: exit 1 when a metric gets worse).
    #[command(subcommand)]
    Baseline(BaselineCommand),
    /// Search random and adversarial scenes for a failure of one rasterizer,
    /// shrink it to a minimal scene that fails the same check, and write it
    /// as a case file (exit 1 when one is found, 0 when none).
    Fuzz(FuzzArgs),
    /// Run the cases through several rasterizers and print a conformance
    /// matrix (rows: rasterizers, columns: case families) with findings.
    Matrix(MatrixArgs),
    /// Time and error of each method on the same seeded workloads
    /// (triangles, lines); writes BENCH.md and bench.svg beside it.
    Bench {
        /// Small workloads that run in a few seconds.
        #[arg(long)]
        quick: bool,
        /// The report to write; the chart goes beside it as bench.svg.
        #[arg(long, value_name = "FILE", default_value = "BENCH.md")]
        out: PathBuf,
    },
    /// Find a rasterizer's conventions from its rendered frames: fill
    /// rule, y direction, subpixel precision, sample position,
    /// interpolation error; write them as a profile for `run --profile`.
    Probe {
        /// The rasterizer to probe.
        #[arg(long = "rasterizer", short = 'r')]
        rasterizer: String,
        /// Write the profile (schema rastercheck-profile/1) to this file.
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
    },
}

#[derive(Args)]
struct MatrixArgs {
    /// Case files or folders (default: cases).
    paths: Vec<PathBuf>,
    /// Row; repeat for several (default: production, the foils, tiny-skia,
    /// euc, the Python example and lavapipe).
    #[arg(long = "rasterizer", short = 'r')]
    rasterizers: Vec<String>,
    /// Replace the text between `<!-- matrix:begin -->` and
    /// `<!-- matrix:end -->` in this file with the matrix.
    #[arg(long, value_name = "FILE")]
    write_readme: Option<PathBuf>,
    /// Worker threads (default: one per core). Results do not depend on it.
    #[arg(long)]
    threads: Option<usize>,
    #[command(flatten)]
    limits: LimitArgs,
}

#[derive(Args)]
struct FuzzArgs {
    /// The rasterizer to search for failures of.
    #[arg(long = "rasterizer", short = 'r')]
    rasterizer: String,
    /// Scenes to try.
    #[arg(long, default_value_t = 1000)]
    cases: u64,
    /// Seed of the scenes (default: from the clock; printed either way).
    #[arg(long)]
    seed: Option<u64>,
    /// Folder for the shrunk case files.
    #[arg(long, value_name = "DIR", default_value = rastercheck::explore::fuzz::default_out().to_str())]
    out: PathBuf,
    /// Only this family: triangles, lines, meshes, polygons, antialias or
    /// motion (default: each in turn).
    #[arg(long)]
    family: Option<String>,
    /// Only failures of this check count: coverage, holes, overdraw,
    /// watertight (holes or overdraw), lines, antialias, time,
    /// interpolation or error.
    #[arg(long)]
    check: Option<String>,
    /// Keep searching until this many failures are shrunk and written.
    #[arg(long, default_value_t = 1)]
    max_failures: usize,
}

#[derive(Subcommand)]
enum BaselineCommand {
    /// Run the cases and write their metrics to FILE (schema
    /// rastercheck-baseline/1, with its tolerances).
    Save {
        /// The baseline file to write.
        file: PathBuf,
        /// Case files or folders (default: cases).
        paths: Vec<PathBuf>,
        /// Rasterizer to record; repeat for several (default: production).
        #[arg(long = "rasterizer", short = 'r')]
        rasterizers: Vec<String>,
        #[command(flatten)]
        select: BaselineSelectArgs,
    },
    /// Re-run the cases and rasterizers of FILE and compare: exit 1 on a
    /// regression, 0 when there are only improvements or none.
    Check {
        /// The baseline file to compare with.
        file: PathBuf,
        /// Case files or folders (default: the paths the baseline was
        /// saved from).
        paths: Vec<PathBuf>,
        /// Rasterizer to check (default: every one in FILE). NAME=RECORDED
        /// runs NAME and holds it to the results recorded for RECORDED.
        #[arg(long = "rasterizer", short = 'r', value_name = "NAME[=RECORDED]")]
        rasterizers: Vec<String>,
        #[command(flatten)]
        select: BaselineSelectArgs,
    },
}

#[derive(Args)]
struct BaselineSelectArgs {
    /// Only cases whose id matches this glob, as for `run` (check: default
    /// the baseline's).
    #[arg(long)]
    filter: Option<String>,
    /// Only cases of this family (check: default the baseline's).
    #[arg(long)]
    family: Option<String>,
    /// Worker threads (default: one per core). Results do not depend on it.
    #[arg(long)]
    threads: Option<usize>,
    #[command(flatten)]
    limits: LimitArgs,
}

#[derive(Args)]
struct RunArgs {
    /// Case files or folders (default: cases). Folders named `invalid`
    /// are skipped unless named directly.
    paths: Vec<PathBuf>,
    /// Rasterizer to check; repeat for several (default: production).
    /// `rastercheck rasterizers` lists them.
    #[arg(long = "rasterizer", short = 'r')]
    rasterizers: Vec<String>,
    /// Print only failures and the summary, and no progress bar.
    #[arg(long, short = 'q')]
    quiet: bool,
    /// Write report.json, junit.xml, summary.md, index.html, images and
    /// error maps into this folder.
    #[arg(long, value_name = "DIR")]
    report: Option<PathBuf>,
    /// Only cases whose id matches this glob (`*` within a segment, `**`
    /// across segments): --filter 'triangles/fan_*'.
    #[arg(long)]
    filter: Option<String>,
    /// Only cases of this family (the first segment of the id).
    #[arg(long)]
    family: Option<String>,
    /// Run the i-th of n shards (1-based): every n-th selected case.
    #[arg(long, value_name = "I/N")]
    shard: Option<String>,
    /// Worker threads (default: one per core). Results do not depend on it.
    #[arg(long)]
    threads: Option<usize>,
    /// A profile written by `probe`: its rasterizer is judged under the
    /// fill rule it declares instead of each case's (only the fill rule
    /// is overridden). Repeat for several rasterizers.
    #[arg(long, value_name = "FILE")]
    profile: Vec<PathBuf>,
    #[command(flatten)]
    limits: LimitArgs,
}

#[derive(Args)]
struct LimitArgs {
    /// Largest canvas, in pixels.
    #[arg(long, default_value_t = Limits::default().max_canvas_pixels)]
    max_canvas_pixels: u64,
    /// Largest number of primitives in one case.
    #[arg(long, default_value_t = Limits::default().max_primitives)]
    max_primitives: usize,
    /// Largest number of sample points in one case: pixels × samples per
    /// pixel × time samples (these only when something moves).
    #[arg(long, default_value_t = Limits::default().max_samples)]
    max_samples: u64,
    /// Seconds each rasterizer (the reference, then each candidate) may
    /// spend on one case; 0 for no limit. A case over it is an error.
    #[arg(long, value_name = "SECONDS", default_value_t = default_case_timeout(), value_parser = seconds)]
    case_timeout: f64,
}

/// A number of seconds: finite and not negative.
fn seconds(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(s) if (0.0..1e9).contains(&s) => Ok(s),
        _ => Err(format!(
            "expected a number of seconds (0 for no limit), got {text:?}"
        )),
    }
}

fn default_case_timeout() -> f64 {
    Limits::default()
        .case_timeout
        .map_or(0.0, |d| d.as_secs_f64())
}

impl LimitArgs {
    fn limits(&self) -> Limits {
        let seconds = self.case_timeout;
        Limits {
            max_canvas_pixels: self.max_canvas_pixels,
            max_primitives: self.max_primitives,
            max_samples: self.max_samples,
            case_timeout: (seconds > 0.0).then(|| std::time::Duration::from_secs_f64(seconds)),
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
        Command::Run(args) => run(args),
        Command::Bless { paths, limits } => bless(paths, limits.limits()),
        Command::Show {
            case,
            out,
            rasterizer,
            scale,
            limits,
        } => show(case, out, &rasterizer, scale, limits.limits()),
        Command::Baseline(command) => baseline(command),
        Command::Fuzz(args) => fuzz(args),
        Command::Matrix(args) => matrix(args),
        Command::Probe { rasterizer, out } => probe(&rasterizer, out),
        Command::Bench { quick, out } => bench(quick, out),
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

fn run(args: RunArgs) -> u8 {
    let limits = args.limits.limits();
    let (declared, names) =
        match rastercheck::explore::probe::for_run(&args.profile, &args.rasterizers) {
            Ok(found) => found,
            Err(e) => {
                eprintln!("error: {e}");
                return BAD_INPUT;
            }
        };
    for d in &declared {
        println!("{}", d.note());
    }
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
    let shard = match args
        .shard
        .as_deref()
        .map(Selection::parse_shard)
        .transpose()
    {
        Ok(shard) => shard,
        Err(e) => {
            eprintln!("error: {e}");
            return BAD_INPUT;
        }
    };
    let selection = Selection {
        filter: args.filter.clone(),
        family: args.family.clone(),
        shard,
    };
    let (found, mut bad_input) = discover(args.paths.clone());
    let files = selection.apply(found.cases);
    if files.is_empty() {
        eprintln!(
            "error: no case files found{}",
            if selection == Selection::default() {
                ""
            } else {
                " that match the selection"
            }
        );
        return BAD_INPUT;
    }
    let foils: Vec<bool> = candidates.iter().map(|c| c.is_foil()).collect();
    let mut report = Report::new(
        std::env::args().skip(1).collect(),
        candidates
            .iter()
            .map(|c| RasterizerInfo {
                name: c.name().to_owned(),
                foil: c.is_foil(),
            })
            .collect(),
        LimitsInfo::of(&limits),
    );
    report.cases = files.iter().map(CaseEntry::not_run).collect();
    if let Some(dir) = &args.report {
        // Written first, so that a run that is killed still leaves a report
        // that lists what did not run.
        if let Err(e) = report::write_json(dir, &mut report) {
            eprintln!("error: {e}");
            return BAD_INPUT;
        }
    }

    let progress = Progress::new(files.len(), args.quiet);
    let root = PathBuf::from(".");
    let mut outcomes = rastercheck::explore::probe::run_all_with_profiles(
        &files,
        &limits,
        &mut candidates,
        &declared,
        &root,
        args.threads,
        &|_| progress.tick(),
    );
    progress.finish();
    runner::reject_duplicate_names(&mut outcomes);

    let colour = std::io::stdout().is_terminal();
    let width = files.iter().map(|c| c.id.len()).max().unwrap_or(0);
    for outcome in &outcomes {
        print_outcome(outcome, &candidates, args.quiet, colour, width);
        bad_input |= outcome
            .problem
            .as_ref()
            .is_some_and(Problem::is_input_error);
    }
    report.cases = outcomes
        .iter()
        .map(|o| CaseEntry::from_outcome(o, &foils))
        .collect();
    report.complete = true;
    report.tally();
    let t = report.totals.clone();
    let failed = t.reference_failed > 0
        || t.golden.differing > 0
        || t.verdicts.iter().any(|v| v.tally.fail + v.tally.error > 0);
    println!();
    println!(
        "{} case files, {} unreadable{}",
        t.cases,
        t.unreadable,
        if t.limit_exceeded > 0 {
            format!(", {} over the time limit", t.limit_exceeded)
        } else {
            String::new()
        }
    );
    for (candidate, v) in candidates.iter().zip(&t.verdicts) {
        let x = &v.tally;
        if candidate.is_foil() {
            println!(
                "{}: {} exact, {} departing from the reference (a foil: expected, not a failure), {} unsupported, {} errors",
                v.rasterizer, x.pass, x.foil, x.unsupported, x.error
            );
        } else {
            println!(
                "{}: {} passed, {} failed, {} unsupported, {} errors",
                v.rasterizer, x.pass, x.fail, x.unsupported, x.error
            );
        }
    }
    let g = &t.golden;
    println!(
        "golden files: {} match, {} differ, {} missing{}",
        g.matching,
        g.differing,
        g.missing,
        if g.missing > 0 {
            " (rastercheck bless writes them)"
        } else {
            ""
        }
    );
    if let Some(dir) = &args.report {
        match report::write_all(dir, &mut report, &outcomes) {
            Ok(written) => println!("report: {} ({} files)", dir.display(), written.len()),
            Err(e) => {
                eprintln!("error: writing the report: {e}");
                return BAD_INPUT;
            }
        }
    }
    if bad_input {
        BAD_INPUT
    } else if failed {
        FAIL
    } else {
        PASS
    }
}

/// One line per candidate (failures only with `quiet`), with reasons.
fn print_outcome(
    outcome: &CaseOutcome,
    candidates: &[Box<dyn Rasterizer>],
    quiet: bool,
    colour: bool,
    width: usize,
) {
    let id = &outcome.file.id;
    match &outcome.problem {
        Some(Problem::Unreadable(e)) => {
            return println!("{} {id:width$}  {e}", paint("BAD  ", RED, colour))
        }
        Some(Problem::ReferenceFailed(e)) => {
            return println!(
                "{} {id:width$}  the reference failed on this case: {e}",
                paint("ERROR", RED, colour)
            )
        }
        Some(Problem::LimitExceeded(e)) => {
            return println!("{} {id:width$}  {e}", paint("LIMIT", RED, colour))
        }
        None => {}
    }
    if let Some(GoldenStatus::Differs(why)) = &outcome.golden {
        println!(
            "{} {id:width$}  the reference no longer reproduces its golden file: {why}",
            paint("GOLDEN", RED, colour)
        );
    }
    for (result, candidate) in outcome.candidates.iter().zip(candidates) {
        let (label, tint) = match &result.verdict {
            Verdict::Pass => ("PASS", GREEN),
            Verdict::Fail(_) if candidate.is_foil() => ("FOIL", YELLOW),
            Verdict::Fail(_) => ("FAIL", RED),
            Verdict::Unsupported(_) => ("UNSUPPORTED", YELLOW),
            Verdict::Error(_) => ("ERROR", RED),
        };
        if quiet && matches!(result.verdict, Verdict::Pass) {
            continue;
        }
        println!(
            "{} {id:width$}  {}  {}",
            paint(&format!("{label:5}"), tint, colour),
            result.rasterizer,
            suite::describe(result)
        );
        if let Verdict::Fail(reasons) = &result.verdict {
            for reason in reasons {
                println!("        {reason}");
            }
        }
    }
}

const RED: &str = "31";
const GREEN: &str = "32";
const YELLOW: &str = "33";

/// ANSI colour, only on a terminal.
fn paint(text: &str, colour_code: &str, colour: bool) -> String {
    if colour {
        format!("\x1b[{colour_code}m{text}\x1b[0m")
    } else {
        text.to_owned()
    }
}

/// A progress bar on a terminal, shown once a run has lasted a second.
struct Progress {
    bar: Option<indicatif::ProgressBar>,
    started: std::time::Instant,
}

impl Progress {
    fn new(total: usize, quiet: bool) -> Progress {
        let tty = std::io::stderr().is_terminal();
        let bar = (tty && !quiet).then(|| {
            let bar = indicatif::ProgressBar::with_draw_target(
                Some(total as u64),
                indicatif::ProgressDrawTarget::hidden(),
            );
            if let Ok(style) =
                indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} cases {elapsed}")
            {
                bar.set_style(style);
            }
            bar
        });
        Progress {
            bar,
            started: std::time::Instant::now(),
        }
    }

    fn tick(&self) {
        if let Some(bar) = &self.bar {
            if bar.is_hidden() && self.started.elapsed().as_secs_f64() > 1.0 {
                bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            }
            bar.inc(1);
        }
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
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
        let reference = match rastercheck::deadline::within(limits.case_timeout, || {
            suite::run_reference(&scene)
        }) {
            Ok(reference) => reference,
            Err(exceeded) => {
                eprintln!("error: {}: the reference {exceeded}", file.path.display());
                bad_input = true;
                continue;
            }
        };
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

fn unknown_rasterizer(name: &str) -> String {
    format!(
        "unknown rasterizer {name:?}; known: {}",
        suite::rasterizer_names().join(", ")
    )
}

/// Discovers and selects the cases of a baseline run; `Err` is bad input
/// already reported.
fn baseline_cases(
    paths: Vec<PathBuf>,
    selection: &Selection,
    allow_empty: bool,
) -> Result<Vec<suite::CaseFile>, ()> {
    let (found, bad) = discover(paths);
    if bad {
        return Err(());
    }
    let files = selection.apply(found.cases);
    if files.is_empty() && !allow_empty {
        eprintln!("error: no case files found that match the selection");
        return Err(());
    }
    Ok(files)
}

fn baseline(command: BaselineCommand) -> u8 {
    match command {
        BaselineCommand::Save {
            file,
            paths,
            rasterizers,
            select,
        } => baseline_save(file, paths, rasterizers, select),
        BaselineCommand::Check {
            file,
            paths,
            rasterizers,
            select,
        } => baseline_check(file, paths, rasterizers, select),
    }
}

fn baseline_save(
    file: PathBuf,
    paths: Vec<PathBuf>,
    names: Vec<String>,
    select: BaselineSelectArgs,
) -> u8 {
    let mut names = if names.is_empty() {
        vec!["production".to_owned()]
    } else {
        names
    };
    names.sort();
    names.dedup();
    let mut candidates = Vec::new();
    for name in &names {
        match suite::rasterizer(name) {
            Some(r) => candidates.push(r),
            None => {
                eprintln!("error: {}", unknown_rasterizer(name));
                return BAD_INPUT;
            }
        }
    }
    let paths = default_paths(paths);
    let info = SelectionInfo {
        paths: paths.iter().map(|p| p.display().to_string()).collect(),
        filter: select.filter.clone(),
        family: select.family.clone(),
    };
    let Ok(files) = baseline_cases(paths, &info.selection(), false) else {
        return BAD_INPUT;
    };
    let outcomes = runner::run_all(
        &files,
        &select.limits.limits(),
        &candidates,
        &PathBuf::from("."),
        select.threads,
        &|_| {},
    );
    let foils: Vec<bool> = candidates.iter().map(|c| c.is_foil()).collect();
    let observed = Observed::from_outcomes(&outcomes, &names, &foils);
    if !observed.problems.is_empty() {
        for (case, why) in &observed.problems {
            eprintln!("error: {case}: {why}");
        }
        eprintln!(
            "error: {} not written: every case must run to be recorded",
            file.display()
        );
        return BAD_INPUT;
    }
    let baseline = Baseline::new(std::env::args().skip(1).collect(), info, &observed);
    if let Err(e) = baseline.save(&file) {
        eprintln!("error: writing the baseline: {e}");
        return BAD_INPUT;
    }
    println!(
        "baseline: recorded {} results ({} cases × {}) in {}",
        baseline.results.len(),
        files.len(),
        names.join(", "),
        file.display()
    );
    PASS
}

fn baseline_check(
    file: PathBuf,
    paths: Vec<PathBuf>,
    names: Vec<String>,
    select: BaselineSelectArgs,
) -> u8 {
    let baseline = match Baseline::load(&file) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error: {e}");
            return BAD_INPUT;
        }
    };
    let shown = file.display();
    // (name to run, name recorded under)
    let mut pairs: Vec<(String, String)> = if names.is_empty() {
        baseline
            .rasterizers
            .iter()
            .map(|n| (n.clone(), n.clone()))
            .collect()
    } else {
        names
            .iter()
            .map(|n| match n.split_once('=') {
                Some((run, recorded)) => (run.trim().to_owned(), recorded.trim().to_owned()),
                None => (n.clone(), n.clone()),
            })
            .collect()
    };
    pairs.sort_by(|a, b| a.1.cmp(&b.1));
    if let Some(w) = pairs.windows(2).find(|w| w[0].1 == w[1].1) {
        eprintln!(
            "error: {} and {} are both held to {:?}; give each recorded rasterizer once",
            w[0].0, w[1].0, w[0].1
        );
        return BAD_INPUT;
    }
    let mut candidates = Vec::new();
    for (run, recorded) in &pairs {
        if !baseline.rasterizers.contains(recorded) {
            eprintln!(
                "error: {shown}: no results recorded for rasterizer {recorded:?} (it records: {}); save a baseline for it, or hold it to a recorded one with -r {run}={}",
                baseline.rasterizers.join(", "),
                baseline.rasterizers.first().map_or("RECORDED", String::as_str)
            );
            return BAD_INPUT;
        }
        match suite::rasterizer(run) {
            Some(r) => candidates.push(r),
            None if names.is_empty() => {
                eprintln!(
                    "error: {shown}: the baseline records {}",
                    unknown_rasterizer(run)
                );
                return BAD_INPUT;
            }
            None => {
                eprintln!("error: {}", unknown_rasterizer(run));
                return BAD_INPUT;
            }
        }
    }
    let paths = if paths.is_empty() {
        baseline.selection.paths.iter().map(PathBuf::from).collect()
    } else {
        paths
    };
    let selection = Selection {
        filter: select.filter.clone().or(baseline.selection.filter.clone()),
        family: select.family.clone().or(baseline.selection.family.clone()),
        shard: None,
    };
    let Ok(files) = baseline_cases(paths, &selection, true) else {
        return BAD_INPUT;
    };
    let outcomes = runner::run_all(
        &files,
        &select.limits.limits(),
        &candidates,
        &PathBuf::from("."),
        select.threads,
        &|_| {},
    );
    let recorded: Vec<String> = pairs.iter().map(|p| p.1.clone()).collect();
    let foils: Vec<bool> = candidates.iter().map(|c| c.is_foil()).collect();
    let observed = Observed::from_outcomes(&outcomes, &recorded, &foils);
    let comparison = baseline.compare(&observed, &recorded, &selection);
    let shown_as = |recorded: &str| {
        pairs
            .iter()
            .find(|p| p.1 == recorded)
            .map_or(recorded.to_owned(), |(run, recorded)| {
                if run == recorded {
                    run.clone()
                } else {
                    format!("{run} (as {recorded})")
                }
            })
    };
    for finding in &comparison.findings {
        let mut f = finding.clone();
        f.rasterizer = shown_as(&f.rasterizer);
        println!("{f}");
    }
    for (case, rasterizer) in &comparison.new {
        println!(
            "NEW         {case}  {}  not in the baseline",
            shown_as(rasterizer)
        );
    }
    if baseline.tool.version != env!("CARGO_PKG_VERSION") {
        println!(
            "note: {shown} was saved by rastercheck {}; this is {}",
            baseline.tool.version,
            env!("CARGO_PKG_VERSION")
        );
    }
    println!("{}", comparison.summary());
    if comparison.improvements() > 0 && comparison.regressions() == 0 {
        println!("note: save the baseline again to hold future runs to the improvements");
    }
    if !observed.problems.is_empty() {
        for (case, why) in &observed.problems {
            eprintln!("error: {case}: {why}");
        }
        BAD_INPUT
    } else if comparison.regressions() > 0 {
        FAIL
    } else {
        PASS
    }
}

fn fuzz(args: FuzzArgs) -> u8 {
    use rastercheck::explore::fuzz;
    let Some(candidate) = suite::rasterizer(&args.rasterizer) else {
        eprintln!("error: {}", unknown_rasterizer(&args.rasterizer));
        return BAD_INPUT;
    };
    let family = match args
        .family
        .as_deref()
        .map(|f| (f, fuzz::Family::from_name(f)))
    {
        None => None,
        Some((_, Some(family))) => Some(family),
        Some((f, None)) => {
            let known: Vec<&str> = rastercheck::explore::fuzz::Family::ALL
                .iter()
                .map(|f| f.name())
                .collect();
            eprintln!("error: unknown family {f:?}; known: {}", known.join(", "));
            return BAD_INPUT;
        }
    };
    let check = match args.check.as_deref().map(|c| (c, fuzz::kinds_named(c))) {
        None => Vec::new(),
        Some((_, Some(kinds))) => kinds,
        Some((c, None)) => {
            let known: Vec<&str> = fuzz::Kind::ALL.iter().map(|k| k.name()).collect();
            eprintln!(
                "error: unknown check {c:?}; known: {}, watertight",
                known.join(", ")
            );
            return BAD_INPUT;
        }
    };
    if args.cases == 0 || args.max_failures == 0 {
        eprintln!("error: --cases and --max-failures must be at least 1");
        return BAD_INPUT;
    }
    let seed = args.seed.unwrap_or_else(fuzz::clock_seed);
    let mut command = format!("rastercheck fuzz -r '{}' --seed {seed}", args.rasterizer);
    if let Some(f) = &args.family {
        command += &format!(" --family {f}");
    }
    if let Some(c) = &args.check {
        command += &format!(" --check {c}");
    }
    println!(
        "fuzz: {} on {} cases{}, seed {seed} (--seed {seed} repeats this run)",
        candidate.name(),
        args.cases,
        args.family
            .as_ref()
            .map_or(String::new(), |f| format!(" of {f}"))
    );
    let options = fuzz::Options {
        seed,
        cases: args.cases,
        family,
        check,
        max_failures: args.max_failures,
        out: args.out,
        command,
    };
    let summary = match fuzz::search(candidate.as_ref(), &options, &mut |line| println!("{line}")) {
        Ok(summary) => summary,
        Err(e) => {
            eprintln!("error: {e}");
            return BAD_INPUT;
        }
    };
    println!(
        "fuzz: {} cases, {} passed, {} failed and shrunk, {} unsupported{} (seed {seed})",
        summary.cases,
        summary.passed,
        summary.found.len(),
        summary.unsupported,
        if summary.ignored > 0 {
            format!(", {} failing other checks", summary.ignored)
        } else {
            String::new()
        }
    );
    if summary.found.is_empty() {
        PASS
    } else {
        FAIL
    }
}

fn matrix(args: MatrixArgs) -> u8 {
    use rastercheck::harness::matrix;
    let names = if args.rasterizers.is_empty() {
        matrix::default_rows()
    } else {
        args.rasterizers
    };
    if let Some(name) = names.iter().find(|n| matrix::rasterizer(n).is_none()) {
        eprintln!("error: {}", unknown_rasterizer(name));
        return BAD_INPUT;
    }
    let (found, bad_input) = discover(args.paths);
    if found.cases.is_empty() {
        eprintln!("error: no case files found");
        return BAD_INPUT;
    }
    let m = matrix::build(&found.cases, &args.limits.limits(), &names, args.threads);
    print!("{}", m.to_markdown());
    if m.unreadable > 0 {
        eprintln!(
            "error: {} case files could not be read (run `rastercheck run` to see why)",
            m.unreadable
        );
    }
    if let Some(file) = &args.write_readme {
        let written = std::fs::read_to_string(file)
            .map_err(|e| e.to_string())
            .and_then(|text| matrix::replace_block(&text, &m.readme_block(&matrix::today())))
            .and_then(|text| std::fs::write(file, text).map_err(|e| e.to_string()));
        match written {
            Ok(()) => println!("\nwrote the matrix into {}", file.display()),
            Err(e) => {
                eprintln!("error: {}: {e}", file.display());
                return BAD_INPUT;
            }
        }
    }
    if bad_input || m.unreadable > 0 {
        BAD_INPUT
    } else {
        PASS
    }
}

fn probe(name: &str, out: Option<PathBuf>) -> u8 {
    let Some(candidate) = suite::rasterizer(name) else {
        eprintln!("error: {}", unknown_rasterizer(name));
        return BAD_INPUT;
    };
    let profile = match rastercheck::explore::probe::probe(candidate.as_ref()) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {e}");
            return FAIL;
        }
    };
    print!("{}", profile.describe());
    if let Some(file) = out {
        if let Err(e) = std::fs::write(&file, profile.to_json()) {
            eprintln!("error: {}: {e}", file.display());
            return BAD_INPUT;
        }
        println!("wrote {}", file.display());
    }
    PASS
}

fn bench(quick: bool, out: PathBuf) -> u8 {
    use rastercheck::bench;
    let report = bench::run(bench::Options { quick }, &mut |line| {
        println!("bench: {line}")
    });
    let svg = out.with_file_name("bench.svg");
    let written = std::fs::write(&out, report.to_markdown("bench.svg"))
        .and_then(|()| std::fs::write(&svg, report.to_svg()));
    if let Err(e) = written {
        eprintln!("error: {}: {e}", out.display());
        return BAD_INPUT;
    }
    for w in &report.workloads {
        println!("{}", w.name);
        for m in &w.methods {
            let time = m.per_item.map_or("—".to_owned(), |d| {
                format!("{:.3} µs", d.as_secs_f64() * 1e6)
            });
            let error = m
                .errors
                .map_or("—".to_owned(), |(e, of)| format!("{e}/{of}"));
            let heap = m
                .peak_heap
                .map_or("—".to_owned(), bench::memory::bytes_text);
            println!(
                "  {:<12} {time:>14} per item, error {error}, peak heap {heap}",
                m.method
            );
        }
    }
    for t in &report.targets {
        let status = match t.met {
            Some(true) => "met",
            Some(false) => "NOT met",
            None => "not measured",
        };
        println!("target: {}: {} ({status})", t.target, t.measured);
    }
    println!("wrote {} and {}", out.display(), svg.display());
    PASS
}
