//! `rastercheck baseline save|check`: record a run's accuracy metrics per
//! case and rasterizer, or hold a later run to them (exit 1 when a metric
//! gets worse).

use super::console::outln;
use std::path::PathBuf;

use clap::{Args, Subcommand};

use super::cases::default_paths;
use super::cases::discover;
use super::exit::Exit;
use super::limits::LimitArgs;
use super::names::rasterizers_named;
use super::names::unknown_rasterizer;
use crate::harness::baseline::{Baseline, Observed, SelectionInfo};
use crate::harness::discover;
use crate::harness::runner::{self, Selection};
use crate::rasterizer::Rasterizer;
use crate::registry;
use crate::report::baseline_rows;

#[derive(Subcommand)]
pub enum BaselineCommand {
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
        /// With --report, NAME is a row of the report (a rasterizer, or in a
        /// merged report of several devices "NAME on DEVICE").
        #[arg(long = "rasterizer", short = 'r', value_name = "NAME[=RECORDED]")]
        rasterizers: Vec<String>,
        /// Hold the results of this report (a report.json or its folder;
        /// one run's, or a merge of shards or devices) to FILE instead of
        /// running anything. Each recorded rasterizer is held to the row of
        /// its name; a row of another name (a device's) is chosen with
        /// -r "ROW=RECORDED".
        #[arg(long, value_name = "REPORT", conflicts_with = "paths")]
        report: Option<PathBuf>,
        #[command(flatten)]
        select: BaselineSelectArgs,
    },
}

#[derive(Args)]
pub struct BaselineSelectArgs {
    /// Only cases whose id matches this glob, as for `run` (check: default
    /// the baseline's).
    #[arg(long)]
    pub filter: Option<String>,
    /// Only cases of this family (check: default the baseline's).
    #[arg(long)]
    pub family: Option<String>,
    /// Worker threads, at most 256 (default, or 0: one per core).
    /// Results do not depend on it.
    #[arg(long, value_parser = super::values::threads)]
    pub threads: Option<usize>,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// Discovers and selects the cases of a baseline run; `Err` is the exit,
/// already reported: bad input, or no case selected (unless `allow_empty`).
fn baseline_cases(
    paths: Vec<PathBuf>,
    selection: &Selection,
    allow_empty: bool,
) -> Result<Vec<discover::CaseFile>, Exit> {
    let (found, bad) = discover(paths);
    if bad {
        return Err(Exit::BadInput);
    }
    let files = selection.apply(found.cases);
    if files.is_empty() && !allow_empty {
        eprintln!("error: no case files found that match the selection; nothing was judged");
        return Err(Exit::NothingJudged);
    }
    Ok(files)
}

/// Runs the cases and observes each candidate's metrics, recorded under
/// `names` (one per candidate, in order).
fn observe(
    files: &[discover::CaseFile],
    candidates: &[Box<dyn Rasterizer>],
    names: &[String],
    select: &BaselineSelectArgs,
) -> Observed {
    let outcomes = runner::run_all(
        files,
        &select.limits.limits(),
        candidates,
        &PathBuf::from("."),
        select.threads,
        &|_, _| {},
    );
    let foils: Vec<bool> = candidates.iter().map(|c| c.is_foil()).collect();
    Observed::from_outcomes(&outcomes, names, &foils)
}

/// `rastercheck baseline save|check`.
pub fn baseline(command: BaselineCommand) -> Exit {
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
            report,
            select,
        } => baseline_check(file, paths, rasterizers, report, select),
    }
}

fn baseline_save(
    file: PathBuf,
    paths: Vec<PathBuf>,
    names: Vec<String>,
    select: BaselineSelectArgs,
) -> Exit {
    let mut names = if names.is_empty() {
        vec!["production".to_owned()]
    } else {
        names
    };
    names.sort();
    names.dedup();
    let candidates = match rasterizers_named(&names) {
        Ok(candidates) => candidates,
        Err(exit) => return exit,
    };
    let paths = default_paths(paths);
    let info = SelectionInfo {
        paths: paths.iter().map(|p| p.display().to_string()).collect(),
        filter: select.filter.clone(),
        family: select.family.clone(),
    };
    let files = match baseline_cases(paths, &info.selection(), false) {
        Ok(files) => files,
        Err(exit) => return exit,
    };
    // Recorded under the names the candidates go by (NAME in `-r NAME=external…`).
    let names: Vec<String> = candidates.iter().map(|c| c.name().to_owned()).collect();
    let observed = observe(&files, &candidates, &names, &select);
    if !observed.problems.is_empty() {
        for (case, why) in &observed.problems {
            eprintln!("error: {case}: {why}");
        }
        eprintln!(
            "error: {} not written: every case must run to be recorded",
            file.display()
        );
        return Exit::BadInput;
    }
    let baseline = Baseline::new(std::env::args().skip(1).collect(), info, &observed);
    if let Err(e) = baseline.save(&file) {
        eprintln!("error: writing the baseline: {e}");
        return Exit::BadInput;
    }
    outln!(
        "baseline: recorded {} results ({} cases × {}) in {}",
        baseline.results.len(),
        files.len(),
        names.join(", "),
        file.display()
    );
    Exit::Pass
}

/// The baseline's cases run again, each candidate named by `pairs`
/// observed under its recorded name; and whether no case was found.
#[allow(clippy::too_many_arguments)]
fn observe_run(
    baseline: &Baseline,
    shown: &str,
    paths: Vec<PathBuf>,
    names: &[String],
    pairs: &[(String, String)],
    recorded: &[String],
    selection: &Selection,
    select: &BaselineSelectArgs,
) -> Result<(Observed, bool), Exit> {
    let mut candidates = Vec::new();
    for (run, _) in pairs {
        // First: a command that cannot be split, or a program that cannot
        // start, is said as such, not as an unknown name.
        super::names::environment_for(run).and_then(|()| super::names::startable(run))?;
        match registry::by_name(run) {
            Some(r) => candidates.push(r),
            None if names.is_empty() => {
                eprintln!(
                    "error: {shown}: the baseline records {}",
                    unknown_rasterizer(run)
                );
                return Err(Exit::BadInput);
            }
            None => {
                eprintln!("error: {}", unknown_rasterizer(run));
                return Err(Exit::BadInput);
            }
        }
    }
    let paths = if paths.is_empty() {
        baseline.selection.paths.iter().map(PathBuf::from).collect()
    } else {
        paths
    };
    // Empty is allowed: the baseline's cases that are gone are regressions.
    let files = baseline_cases(paths, selection, true)?;
    Ok((
        observe(&files, &candidates, recorded, select),
        files.is_empty(),
    ))
}

/// The rows of the report at `path` named by `pairs` (row, recorded), its
/// cases that `selection` keeps, observed under their recorded names; and
/// whether it has no such case. A row the report lacks is bad input naming
/// the report and its rows.
fn observe_report(
    path: &std::path::Path,
    pairs: &[(String, String)],
    selection: &Selection,
) -> Result<(Observed, bool), Exit> {
    let mut input = match crate::report::merge::read::read_input(path) {
        Ok(input) => input,
        Err(e) => {
            eprintln!("error: {e}");
            return Err(Exit::BadInput);
        }
    };
    let rows = baseline_rows::rows(&input.report);
    for (row, recorded) in pairs {
        if !rows.contains(row) {
            eprintln!(
                "error: {}: no row {row:?} to hold to {recorded:?} (its rows: {}); choose one with -r \"ROW={recorded}\"",
                input.file.display(),
                rows.join(", "),
            );
            return Err(Exit::BadInput);
        }
    }
    let ids: Vec<discover::CaseFile> = input
        .report
        .cases
        .iter()
        .map(|c| discover::CaseFile {
            id: c.id.clone(),
            path: Default::default(),
        })
        .collect();
    let kept: std::collections::HashSet<String> =
        selection.apply(ids).into_iter().map(|c| c.id).collect();
    input.report.cases.retain(|c| kept.contains(&c.id));
    let observed = baseline_rows::observed(&input.report, pairs);
    Ok((observed, input.report.cases.is_empty()))
}

fn baseline_check(
    file: PathBuf,
    paths: Vec<PathBuf>,
    names: Vec<String>,
    report: Option<PathBuf>,
    select: BaselineSelectArgs,
) -> Exit {
    let baseline = match Baseline::load(&file) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
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
    } else if report.is_some() {
        // Rows of a report: `ROW` or `ROW=RECORDED`.
        names
            .iter()
            .map(|n| match n.split_once('=') {
                Some((row, recorded)) => (row.trim().to_owned(), recorded.trim().to_owned()),
                None => (n.clone(), n.clone()),
            })
            .collect()
    } else {
        if let Err(exit) = super::names::check_names(&names) {
            return exit;
        }
        names
            .iter()
            .map(|n| match crate::adapters::external::split_name(n) {
                // `-r NAME=external…`: run the program, held to NAME.
                Some((name, _)) => (n.clone(), name.to_owned()),
                None => match n.split_once('=') {
                    Some((run, recorded)) => (run.trim().to_owned(), recorded.trim().to_owned()),
                    None => (n.clone(), n.clone()),
                },
            })
            .collect()
    };
    pairs.sort_by(|a, b| a.1.cmp(&b.1));
    if let Some(w) = pairs.windows(2).find(|w| w[0].1 == w[1].1) {
        eprintln!(
            "error: {} and {} are both held to {:?}; give each recorded rasterizer once",
            w[0].0, w[1].0, w[0].1
        );
        return Exit::BadInput;
    }
    for (run, recorded) in &pairs {
        if !baseline.rasterizers.contains(recorded) {
            eprintln!(
                "error: {shown}: no results recorded for rasterizer {recorded:?} (it records: {}); save a baseline for it, or hold it to a recorded one with -r {run}={}",
                baseline.rasterizers.join(", "),
                baseline.rasterizers.first().map_or("RECORDED", String::as_str)
            );
            return Exit::BadInput;
        }
    }
    let selection = Selection {
        filter: select.filter.clone().or(baseline.selection.filter.clone()),
        family: select.family.clone().or(baseline.selection.family.clone()),
        shard: None,
    };
    let recorded: Vec<String> = pairs.iter().map(|p| p.1.clone()).collect();
    let (observed, found_none) = match &report {
        Some(report) => match observe_report(report, &pairs, &selection) {
            Ok(observed) => observed,
            Err(exit) => return exit,
        },
        None => match observe_run(
            &baseline,
            &shown.to_string(),
            paths,
            &names,
            &pairs,
            &recorded,
            &selection,
            &select,
        ) {
            Ok(observed) => observed,
            Err(exit) => return exit,
        },
    };
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
        outln!("{f}");
    }
    for (case, rasterizer) in &comparison.new {
        outln!(
            "NEW         {case}  {}  not in the baseline",
            shown_as(rasterizer)
        );
    }
    if baseline.tool.version != env!("CARGO_PKG_VERSION") {
        outln!(
            "note: {shown} was saved by rastercheck {}; this is {}",
            baseline.tool.version,
            env!("CARGO_PKG_VERSION")
        );
    }
    outln!("{}", comparison.summary());
    if comparison.improvements() > 0 && comparison.regressions() == 0 {
        outln!("note: save the baseline again to hold future runs to the improvements");
    }
    if !observed.problems.is_empty() {
        for (case, why) in &observed.problems {
            eprintln!("error: {case}: {why}");
        }
        Exit::BadInput
    } else if comparison.regressions() > 0 {
        Exit::Fail
    } else if found_none && comparison.results == 0 {
        eprintln!(
            "error: no case files found that match the selection, and {shown} records none; nothing was judged"
        );
        Exit::NothingJudged
    } else {
        Exit::Pass
    }
}
