//! `rastercheck fuzz`: search random and adversarial scenes for a failure
//! of one rasterizer, shrink it, and write it as a case file.

use super::console::outln;
use std::path::{Path, PathBuf};

use clap::Args;

use super::exit::Exit;
use super::names::rasterizer_named;
use crate::explore::fuzz;

#[derive(Args)]
pub struct FuzzArgs {
    /// The rasterizer to search for failures of.
    #[arg(long = "rasterizer", short = 'r', required_unless_present = "corpus")]
    pub rasterizer: Option<String>,
    /// Scenes to try.
    #[arg(long, default_value_t = 1000)]
    pub cases: u64,
    /// Seed of the scenes (default: from the clock; printed either way).
    #[arg(long)]
    pub seed: Option<u64>,
    /// The number of the first case tried (as `FAIL  case N` numbers
    /// them): cases N, N + 1, … of the seed. With --family and --cases 1,
    /// one finding's case, as its case file's description gives it.
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub first_case: u64,
    /// Folder for the shrunk case files.
    #[arg(long, value_name = "DIR", default_value = crate::explore::fuzz::default_out().to_str())]
    pub out: PathBuf,
    /// Only this family: triangles, lines, meshes, polygons, antialias,
    /// motion, clip or conservative (default: each in turn).
    #[arg(long)]
    pub family: Option<String>,
    /// Only failures of this check count: coverage, holes, overdraw,
    /// watertight (holes or overdraw), lines, conservative, antialias,
    /// time, interpolation or error.
    #[arg(long)]
    pub check: Option<String>,
    /// Keep searching until this many failures are shrunk and written.
    #[arg(long, default_value_t = 1)]
    pub max_failures: usize,
    /// Judge the scene a crash input of the `scene_reference_vs_production`
    /// fuzz target draws (fuzz/artifacts/…), instead of searching; shrink
    /// and write it as a case file when the rasterizer fails it.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["cases", "seed", "first_case", "family", "max_failures"])]
    pub from_crash: Option<PathBuf>,
    /// Write the seed corpus of each fuzz target (fuzz/README.md) under
    /// DIR/<target>/, from the case files in --corpus-cases, and exit.
    #[arg(long, value_name = "DIR", conflicts_with_all = ["rasterizer", "from_crash"])]
    pub corpus: Option<PathBuf>,
    /// A profile written by `probe` for the rasterizer: it is judged under
    /// the profile's fill rule, conventions and coverage encoding, as `run
    /// --profile` judges it, and the cases written state the rule and the
    /// conventions a case can state, so that a plain `run` reproduces them.
    #[arg(long, value_name = "FILE", conflicts_with = "corpus")]
    pub profile: Option<PathBuf>,
    /// The case files --corpus seeds the case_json target with.
    #[arg(long, value_name = "DIR", default_value = "cases", requires = "corpus")]
    pub corpus_cases: PathBuf,
}

/// `rastercheck fuzz`: search, shrink, write the failures as case files.
pub fn fuzz(args: FuzzArgs) -> Exit {
    if let Some(dir) = &args.corpus {
        return write_corpus(dir, &args.corpus_cases);
    }
    let Some(rasterizer) = args.rasterizer.clone() else {
        eprintln!("error: name the rasterizer to fuzz with -r");
        return Exit::BadInput;
    };
    let candidate = match rasterizer_named(&rasterizer) {
        Ok(candidate) => candidate,
        Err(exit) => return exit,
    };
    let candidate = match &args.profile {
        None => candidate,
        Some(file) => match profiled(candidate, file) {
            Ok(candidate) => candidate,
            Err(why) => {
                eprintln!("error: {why}");
                return Exit::BadInput;
            }
        },
    };
    let family = match args
        .family
        .as_deref()
        .map(|f| (f, fuzz::Family::from_name(f)))
    {
        None => None,
        Some((_, Some(family))) => Some(family),
        Some((f, None)) => {
            let known: Vec<&str> = crate::explore::fuzz::Family::ALL
                .iter()
                .map(|f| f.name())
                .collect();
            let meant = crate::scene::case::closest(f, &known)
                .map(|m| format!("did you mean {m:?}? "))
                .unwrap_or_default();
            eprintln!(
                "error: unknown family {f:?}; {meant}known: {}",
                known.join(", ")
            );
            return Exit::BadInput;
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
            return Exit::BadInput;
        }
    };
    if args.cases == 0 || args.max_failures == 0 {
        eprintln!("error: --cases and --max-failures must be at least 1");
        return Exit::BadInput;
    }
    if let Some(file) = &args.from_crash {
        return from_crash(
            candidate.as_ref(),
            &rasterizer,
            file,
            check,
            args.out,
            &args.check,
        );
    }
    let seed = args.seed.unwrap_or_else(fuzz::clock_seed);
    // What picks the cases (seed, family, first case, number) each finding
    // adds for its own (`fuzz::reproduction`).
    let mut command = format!("rastercheck fuzz -r '{rasterizer}'");
    if let Some(c) = &args.check {
        command += &format!(" --check {c}");
    }
    if let Some(p) = &args.profile {
        command += &format!(" --profile {}", p.display());
    }
    let from = match args.first_case {
        0 => String::new(),
        n => format!(" from case {n}"),
    };
    let again = match args.first_case {
        0 => String::new(),
        n => format!(" --first-case {n}"),
    };
    outln!(
        "fuzz: {} on {} cases{}{from}, seed {seed} (--seed {seed}{again} repeats this run)",
        candidate.name(),
        args.cases,
        args.family
            .as_ref()
            .map_or(String::new(), |f| format!(" of {f}"))
    );
    let options = fuzz::Options {
        seed,
        first: args.first_case,
        cases: args.cases,
        family,
        check,
        max_failures: args.max_failures,
        out: args.out,
        command,
    };
    let summary = match fuzz::search(candidate.as_ref(), &options, &mut |line| outln!("{line}")) {
        Ok(summary) => summary,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    outln!(
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
    if !summary.found.is_empty() {
        Exit::Fail
    } else if summary.cases > 0 && summary.unsupported == summary.cases {
        eprintln!(
            "error: nothing was judged: {} unsupported every scene tried",
            candidate.name()
        );
        Exit::NothingJudged
    } else {
        Exit::Pass
    }
}

/// `--profile FILE`: the candidate judged under the profile's fill rule;
/// the profile must be the candidate's.
fn profiled(
    candidate: Box<dyn crate::rasterizer::Rasterizer>,
    file: &Path,
) -> Result<Box<dyn crate::rasterizer::Rasterizer>, String> {
    let declared = crate::harness::profile::load_declared(file)?;
    if declared.rasterizer != candidate.name() {
        return Err(format!(
            "{} is a profile of {}, not of {}",
            declared.file,
            declared.rasterizer,
            candidate.name()
        ));
    }
    Ok(Box::new(crate::harness::profile::Profiled {
        inner: candidate,
        rule: declared.fill_rule,
        conventions: declared.conventions,
        coverage: declared.coverage,
    }))
}

/// `--corpus DIR`: every fuzz target's seeds.
fn write_corpus(dir: &Path, cases: &Path) -> Exit {
    if !cases.is_dir() {
        eprintln!("error: {}: not a folder of case files", cases.display());
        return Exit::BadInput;
    }
    match fuzz::targets::write_corpus(dir, cases) {
        Ok(n) => {
            outln!(
                "fuzz: wrote {n} seed files under {}/<target>/ for {}",
                dir.display(),
                fuzz::targets::TARGETS.join(", ")
            );
            Exit::Pass
        }
        Err(e) => {
            eprintln!("error: {e}");
            Exit::BadInput
        }
    }
}

/// `--from-crash FILE`: judge, shrink and write the scene a crash input of
/// the scene target draws.
fn from_crash(
    candidate: &dyn crate::rasterizer::Rasterizer,
    rasterizer: &str,
    file: &Path,
    check: Vec<fuzz::Kind>,
    out: PathBuf,
    check_name: &Option<String>,
) -> Exit {
    let tape = match std::fs::metadata(file).and_then(|m| {
        if m.len() > 1 << 20 {
            Err(std::io::Error::other(
                "larger than 1 MiB; a crash input is not",
            ))
        } else {
            std::fs::read(file)
        }
    }) {
        Ok(tape) => tape,
        Err(e) => {
            eprintln!("error: {}: {e}", file.display());
            return Exit::BadInput;
        }
    };
    let mut command = format!(
        "rastercheck fuzz -r '{rasterizer}' --from-crash {}",
        file.display()
    );
    if let Some(c) = check_name {
        command += &format!(" --check {c}");
    }
    let options = fuzz::Options {
        seed: 0,
        first: 0,
        cases: 1,
        family: None,
        check,
        max_failures: 1,
        out,
        command,
    };
    let label = file.file_name().map_or_else(
        || file.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let summary = match fuzz::from_tape(candidate, &tape, &label, &options, &mut |line| {
        outln!("{line}")
    }) {
        Ok(summary) => summary,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    if !summary.found.is_empty() {
        Exit::Fail
    } else if summary.unsupported > 0 {
        eprintln!(
            "error: nothing was judged: {} does not support the scene",
            candidate.name()
        );
        Exit::NothingJudged
    } else {
        outln!(
            "fuzz: {} passes the scene {label} draws{}",
            candidate.name(),
            if summary.ignored > 0 {
                " on the checks asked for"
            } else {
                ""
            }
        );
        Exit::Pass
    }
}
