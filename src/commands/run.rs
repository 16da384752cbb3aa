//! `rastercheck run`: the main job. Cases are selected and run (harness),
//! a progress bar shown while they are judged, each outcome then printed in
//! case order (console), totals printed, and the report folder written
//! (report).

use super::console::outln;
use std::io::IsTerminal;
use std::path::PathBuf;

use clap::Args;

use super::cases::{discover_list, family_hint};
use super::console::{print_outcome, Progress};
use super::exit::Exit;
use super::limits::LimitArgs;
use super::names::rasterizers_named;
use crate::harness::runner::{self, Problem, Selection};
use crate::harness::unique_names::UniqueNames;
use crate::report;
use crate::report::digest::Digest;
use crate::report::json::{CaseEntry, LimitsInfo, RasterizerInfo, Report, Totals};

#[derive(Args)]
pub struct RunArgs {
    /// Case files or folders (default: cases). Folders named `invalid`
    /// are skipped unless named directly.
    pub paths: Vec<PathBuf>,
    /// Rasterizer to check; repeat for several (default: production).
    /// `rastercheck rasterizers` lists them.
    #[arg(long = "rasterizer", short = 'r')]
    pub rasterizers: Vec<String>,
    /// Print only failures and the summary, and no progress bar.
    #[arg(long, short = 'q')]
    pub quiet: bool,
    /// Write report.json, junit.xml, summary.md, index.html, case pages,
    /// plots, images and error maps into this folder.
    #[arg(long, value_name = "DIR")]
    pub report: Option<PathBuf>,
    /// Only cases whose id matches this glob (`*` within a segment, `**`
    /// across segments): --filter 'triangles/fan_*'.
    #[arg(long)]
    pub filter: Option<String>,
    /// Only cases of this family (the first segment of the id).
    #[arg(long)]
    pub family: Option<String>,
    /// Run the i-th of n shards (1-based): every n-th selected case.
    #[arg(long, value_name = "I/N")]
    pub shard: Option<String>,
    /// Worker threads, at most 256 (default, or 0: one per core).
    /// Results do not depend on it.
    #[arg(long, value_parser = super::values::threads)]
    pub threads: Option<usize>,
    /// A profile written by `probe`: its rasterizer is judged under the
    /// fill rule it declares instead of each case's, and under the
    /// conventions (snapping, sample pattern, y, pixel centre, diamond-exit
    /// latitude) and coverage encoding it declares, if any (SPEC.md §13).
    /// Repeat for several rasterizers.
    #[arg(long, value_name = "FILE")]
    pub profile: Vec<PathBuf>,
    /// Draw each case N times with every rasterizer (the reference once),
    /// the selection in blocks so that other cases come between a case's
    /// repetitions; a rasterizer whose frames differ between them is
    /// FLAKY on the case, a failure (SPEC.md §6.6).
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = super::values::repeat)]
    pub repeat: usize,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// `rastercheck run`: every selected case through the reference and the
/// candidates, one line each, a summary, and the report folder.
/// The summary's note on the results judged under a rasterizer's own
/// conventions (fill rule, subpixel precision, sample positions, y
/// direction, pixel centre, clipping: SPEC.md §3, §16): counted among the
/// verdicts, and named apart, each result's line saying which.
fn own_rule(x: &runner::Tally) -> String {
    if x.own_rule == 0 {
        return String::new();
    }
    format!(
        "; {} judged under its own conventions instead of the case's, each line naming which (SPEC.md §3, §16)",
        x.own_rule
    )
}

/// The summary's count of flaky cases (`--repeat`): a failure, counted
/// apart; said even when none, so a repeated run shows it checked.
fn flaky(x: &runner::Tally, repeat: usize) -> String {
    if repeat <= 1 && x.flaky == 0 {
        return String::new();
    }
    format!(", {} flaky over {repeat} repetitions", x.flaky)
}

pub fn run(args: RunArgs) -> Exit {
    let limits = args.limits.limits();
    let (declared, names) = match crate::harness::profile::for_run(
        &args.profile,
        &args.rasterizers,
        crate::registry::called,
    ) {
        Ok(found) => found,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    for d in &declared {
        outln!("{}", d.note());
    }
    let candidates = match rasterizers_named(&names) {
        Ok(candidates) => crate::harness::profile::apply(candidates, &declared),
        Err(exit) => return exit,
    };
    let shard = match args
        .shard
        .as_deref()
        .map(Selection::parse_shard)
        .transpose()
    {
        Ok(shard) => shard,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    let selection = Selection {
        filter: args.filter.clone(),
        family: args.family.clone(),
        shard,
    };
    // Held compactly: a run of a million cases keeps tens of bytes a case.
    let (found, mut bad_input) = discover_list(args.paths.clone());
    let hint = args
        .family
        .as_deref()
        .and_then(|f| family_hint(f, found.cases.ids()));
    let files = selection.apply_list(found.cases);
    if files.is_empty() {
        if let Some(hint) = hint {
            eprintln!("note: {hint}");
        }
        eprintln!(
            "error: no case files found{}{}",
            if selection == Selection::default() {
                ""
            } else {
                " that match the selection"
            },
            if bad_input {
                ""
            } else {
                "; nothing was judged"
            }
        );
        // A path that does not exist is bad input; a selection (or a
        // folder) with no case in it judged nothing.
        return if bad_input {
            Exit::BadInput
        } else {
            Exit::NothingJudged
        };
    }
    let foils: Vec<bool> = candidates.iter().map(|c| c.is_foil()).collect();
    let mut report = Report::new(
        std::env::args().skip(1).collect(),
        candidates
            .iter()
            .map(|c| RasterizerInfo {
                name: c.name().to_owned(),
                foil: c.is_foil(),
                declared: None,
                api_record: None,
            })
            .collect(),
        LimitsInfo::of(&limits),
    );
    report.shard = shard.map(|(i, n)| format!("{i}/{n}"));
    // Held (locked) until the run returns.
    let mut _claimed = None;
    if let Some(dir) = &args.report {
        if let Some(file) = not_a_folder(dir) {
            eprintln!(
                "error: --report {}: {} is a file, not a folder",
                dir.display(),
                file.display()
            );
            return Exit::BadInput;
        }
        // Ours (new, empty, or marked by an earlier run) and locked for
        // the run; what an earlier run wrote there goes first, so that no
        // file in the folder can be mistaken for this run's.
        match report::folder::claim(dir) {
            Ok(folder) => _claimed = Some(folder),
            Err(e) => {
                eprintln!("error: {e}");
                return Exit::BadInput;
            }
        }
        // Written first, so that a run that is killed still leaves a report
        // that lists what did not run.
        let mut not_run = |f: &mut dyn FnMut(&CaseEntry)| {
            (0..files.len())
                .filter_map(|k| runner::Cases::case(&files, k))
                .for_each(|c| f(&CaseEntry::not_run(&c)));
            Ok(())
        };
        report.totals = Totals::of(&report.rasterizers);
        not_run(&mut |c| report.totals.add(c)).ok();
        if let Err(e) = report::write::write_json_streamed(dir, &report, &mut not_run) {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    }
    // From here on, SIGINT and SIGTERM stop the run: no new case starts,
    // external programs are killed, and the partial report is written.
    crate::stop::install();

    // Each case's report entry, made on its worker thread as it finishes
    // and taken when the case is handed over, in order: at most
    // `runner::AHEAD` are held at once.
    let entries: std::sync::Mutex<std::collections::HashMap<usize, CaseEntry>> = Default::default();
    let progress = Progress::new(files.len(), args.quiet);
    let root = PathBuf::from(".");
    // Each case's pictures, error maps and page are written as it
    // finishes, and then its frames are released.
    let writer = args
        .report
        .as_deref()
        .map(|dir| report::case_files::CaseWriter::new(dir, &foils));
    // Every entry goes to disk as its case is handed over; what stays in
    // memory is bounded: the totals, the counts per family, and the
    // entries the summary files are drawn from (`report/digest.rs`).
    let mut spool = match args.report.as_deref().map(report::spool::Spool::create) {
        Some(Ok(spool)) => Some(spool),
        Some(Err(e)) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
        None => None,
    };
    let mut digest = Digest::new(&report.rasterizers);
    // Case names already used, by hash, and by which file (names identify
    // cases in reports and baselines, so they must be unique in a run).
    let mut names = UniqueNames::for_cases(files.len());
    let name_of = |j| runner::name_in_file(&files, j, &limits);
    let colour = std::io::stdout().is_terminal();
    let width = files.ids().map(str::len).max().unwrap_or(0);
    let settings = runner::RunSettings {
        limits: &limits,
        candidates: &candidates,
        root: &root,
        threads: args.threads,
        repeat: args.repeat,
    };
    runner::run_streamed(
        &files,
        &settings,
        &|k, outcome| {
            let entry = match &writer {
                Some(writer) => writer.write(outcome),
                None => CaseEntry::from_outcome(outcome, &foils),
            };
            entries
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .insert(k, entry);
            progress.tick();
        },
        &mut |k, mut outcome| {
            let kept = entries.lock().unwrap_or_else(|e| e.into_inner()).remove(&k);
            let duplicate =
                runner::reject_duplicate_name(&mut outcome, k, &files, &mut names, &name_of);
            // A case that did not finish gets its entry now; one marked
            // since (a duplicate name) a fresh one, with the facts of its
            // scene kept.
            let entry = match kept {
                Some(kept) if duplicate => CaseEntry {
                    description: kept.description,
                    rules: kept.rules,
                    ..CaseEntry::from_outcome(&outcome, &foils)
                },
                Some(kept) => kept,
                None => CaseEntry::from_outcome(&outcome, &foils),
            };
            progress.suspend(|| print_outcome(&outcome, &candidates, args.quiet, colour, width));
            bad_input |= outcome
                .problem
                .as_ref()
                .is_some_and(Problem::is_input_error);
            if let Some(spool) = &mut spool {
                spool.push(&entry);
            }
            digest.add(&entry);
        },
    );
    progress.finish();
    for (info, candidate) in report.rasterizers.iter_mut().zip(&candidates) {
        info.declared = candidate.declared();
        info.api_record = candidate.api_record();
    }
    let stopped = crate::stop::requested();
    report.complete = stopped.is_none();
    report.totals = digest.totals.clone();
    let t = report.totals.clone();
    let failed = t.reference_failed > 0
        || t.golden.differing > 0
        || t.verdicts
            .iter()
            .any(|v| v.tally.fail + v.tally.error + v.tally.flaky > 0);
    outln!();
    outln!(
        "{} case files, {} unreadable{}",
        t.cases,
        t.unreadable,
        if t.limit_exceeded > 0 {
            format!(", {} over a limit", t.limit_exceeded)
        } else {
            String::new()
        }
    );
    for (candidate, v) in candidates.iter().zip(&t.verdicts) {
        let x = &v.tally;
        if candidate.is_foil() {
            outln!(
                "{}: {} exact, {} departing from the reference (a foil: expected, not a failure), {} unsupported, {} errors{}{}",
                v.rasterizer, x.pass, x.foil, x.unsupported, x.error, flaky(x, args.repeat), own_rule(x)
            );
        } else {
            outln!(
                "{}: {} passed, {} failed, {} unsupported, {} errors{}{}",
                v.rasterizer,
                x.pass,
                x.fail,
                x.unsupported,
                x.error,
                flaky(x, args.repeat),
                own_rule(x)
            );
        }
    }
    for (candidate, info) in candidates.iter().zip(&report.rasterizers) {
        if let Some(record) = &info.api_record {
            outln!("{}: API record: {record}", candidate.name());
        }
    }
    if let Some(signal) = stopped {
        println!(
            "stopped by {}: {} cases did not run",
            if signal == crate::stop::SIGINT {
                "SIGINT"
            } else {
                "SIGTERM"
            },
            t.not_run
        );
    }
    let g = &t.golden;
    outln!(
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
    if let (Some(dir), Some(writer), Some(spool)) = (&args.report, writer, &mut spool) {
        let written = writer.finish().and_then(|cases| {
            Ok(cases + report::write::write_streamed(dir, &mut report, spool, digest)?.len())
        });
        match written {
            Ok(n) => outln!("report: {} ({n} files)", dir.display()),
            Err(e) => {
                eprintln!("error: writing the report: {e}");
                return Exit::BadInput;
            }
        }
    }
    // Judged: a verdict other than unsupported, from some candidate.
    let judged = t
        .verdicts
        .iter()
        .any(|v| v.tally.pass + v.tally.fail + v.tally.foil + v.tally.error + v.tally.flaky > 0);
    if let Some(signal) = stopped {
        Exit::Interrupted(signal)
    } else if bad_input {
        Exit::BadInput
    } else if failed {
        Exit::Fail
    } else if !judged {
        eprintln!(
            "error: nothing was judged: every selected case is unsupported by every rasterizer ({})",
            t.verdicts
                .iter()
                .map(|v| v.rasterizer.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        );
        Exit::NothingJudged
    } else {
        Exit::Pass
    }
}

/// The file in the way of a report folder: `dir` itself, or the nearest
/// existing path above it, when that is not a folder.
fn not_a_folder(dir: &std::path::Path) -> Option<&std::path::Path> {
    dir.ancestors()
        .filter(|p| !p.as_os_str().is_empty())
        .find(|p| p.exists())
        .filter(|p| !p.is_dir())
}
