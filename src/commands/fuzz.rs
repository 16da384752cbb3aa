//! `rastercheck fuzz`: search random and adversarial scenes for a failure
//! of one rasterizer, shrink it, and write it as a case file.

use super::console::outln;
use std::path::PathBuf;

use clap::Args;

use super::{rasterizer_named, Exit};
use crate::explore::fuzz;

#[derive(Args)]
pub struct FuzzArgs {
    /// The rasterizer to search for failures of.
    #[arg(long = "rasterizer", short = 'r')]
    pub rasterizer: String,
    /// Scenes to try.
    #[arg(long, default_value_t = 1000)]
    pub cases: u64,
    /// Seed of the scenes (default: from the clock; printed either way).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Folder for the shrunk case files.
    #[arg(long, value_name = "DIR", default_value = crate::explore::fuzz::default_out().to_str())]
    pub out: PathBuf,
    /// Only this family: triangles, lines, meshes, polygons, antialias or
    /// motion (default: each in turn).
    #[arg(long)]
    pub family: Option<String>,
    /// Only failures of this check count: coverage, holes, overdraw,
    /// watertight (holes or overdraw), lines, antialias, time,
    /// interpolation or error.
    #[arg(long)]
    pub check: Option<String>,
    /// Keep searching until this many failures are shrunk and written.
    #[arg(long, default_value_t = 1)]
    pub max_failures: usize,
}

/// `rastercheck fuzz`: search, shrink, write the failures as case files.
pub fn fuzz(args: FuzzArgs) -> Exit {
    let candidate = match rasterizer_named(&args.rasterizer) {
        Ok(candidate) => candidate,
        Err(exit) => return exit,
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
            eprintln!("error: unknown family {f:?}; known: {}", known.join(", "));
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
    let seed = args.seed.unwrap_or_else(fuzz::clock_seed);
    let mut command = format!("rastercheck fuzz -r '{}' --seed {seed}", args.rasterizer);
    if let Some(f) = &args.family {
        command += &format!(" --family {f}");
    }
    if let Some(c) = &args.check {
        command += &format!(" --check {c}");
    }
    outln!(
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
