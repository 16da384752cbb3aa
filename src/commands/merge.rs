//! `rastercheck merge OUT REPORT...`: reports from the shards of one run,
//! or from the same cases on other rasterizers or machines, into one report
//! folder (SPEC.md §10.3): `report.json`, `junit.xml`, `summary.md`,
//! the plots and `index.html` written by the run's own writers, each
//! case's page and pictures copied from its report. Disagreeing reports
//! are an error naming the case, exit 2, and nothing is written.

use super::console::outln;
use std::path::{Path, PathBuf};

use clap::Args;

use super::exit::Exit;
use crate::report::files::write_file;
use crate::report::folder::claim;
use crate::report::merge::combine::MAX_ERRORS;
use crate::report::merge::{merge as combine, read_input, Input};
use crate::report::write::write_summaries;

#[derive(Args)]
pub struct MergeArgs {
    /// The merged report folder: new, empty, or one a run wrote.
    pub out: PathBuf,
    /// The reports: report.json files, or the folders holding them.
    #[arg(required = true)]
    pub reports: Vec<PathBuf>,
}

pub fn merge(args: MergeArgs) -> Exit {
    let mut inputs = Vec::new();
    let mut bad = false;
    for path in &args.reports {
        match read_input(path) {
            Ok(input) => inputs.push(input),
            Err(e) => {
                eprintln!("error: {e}");
                bad = true;
            }
        }
    }
    if bad {
        return Exit::BadInput;
    }
    if let Some(input) = inputs.iter().find(|i| holds(&args.out, &i.dir)) {
        eprintln!(
            "error: merge {}: the merged folder would overwrite the report {} it reads; choose another folder",
            args.out.display(),
            input.file.display()
        );
        return Exit::BadInput;
    }
    let merged = match combine(&inputs, std::env::args().skip(1).collect()) {
        Ok(merged) => merged,
        Err(errors) => {
            for e in errors.iter().take(MAX_ERRORS) {
                eprintln!("error: {e}");
            }
            if errors.len() > MAX_ERRORS {
                eprintln!("error: and {} more", errors.len() - MAX_ERRORS);
            }
            eprintln!("error: the reports disagree; nothing was written");
            return Exit::BadInput;
        }
    };
    let mut report = merged.report;
    let written = claim(&args.out).and_then(|_claimed| {
        for (from, to) in &merged.copies {
            let bytes = std::fs::read(from).map_err(|e| {
                format!(
                    "{}: named by its report, cannot be read: {e}",
                    from.display()
                )
            })?;
            write_file(&args.out.join(to), &bytes)?;
        }
        Ok(merged.copies.len() + write_summaries(&args.out, &mut report)?.len())
    });
    let files = match written {
        Ok(files) => files,
        Err(e) => {
            eprintln!("error: writing the merged report: {e}");
            return Exit::BadInput;
        }
    };
    print(&inputs, merged.runs, &report.totals);
    outln!("report: {} ({files} files)", args.out.display());
    exit_of(&report.totals)
}

/// Whether the folder `out` is, or holds, the folder `dir`.
fn holds(out: &Path, dir: &Path) -> bool {
    match (out.canonicalize(), dir.canonicalize()) {
        (Ok(out), Ok(dir)) => dir.starts_with(out),
        _ => false,
    }
}

fn print(inputs: &[Input], runs: usize, totals: &crate::report::json::Totals) {
    outln!(
        "merged {} reports ({runs} run{}, {} rows): {} cases",
        inputs.len(),
        if runs == 1 { "" } else { "s" },
        totals.verdicts.len(),
        totals.cases
    );
    for v in &totals.verdicts {
        let t = &v.tally;
        outln!(
            "  {}: {} pass, {} fail, {} unsupported, {} error, {} foil{}",
            v.rasterizer,
            t.pass,
            t.fail,
            t.unsupported,
            t.error,
            t.foil,
            if t.flaky > 0 {
                format!(", {} flaky", t.flaky)
            } else {
                String::new()
            }
        );
    }
}

/// The merged run's exit code, as `run` gives one (SPEC.md §9): 1 on a
/// failure, error or flaky result or a case the reference broke on, 2 on
/// an unreadable case or one over a limit, 3 when nothing was judged.
fn exit_of(t: &crate::report::json::Totals) -> Exit {
    let failed = t.reference_failed > 0
        || t.verdicts
            .iter()
            .any(|v| v.tally.fail + v.tally.error + v.tally.flaky > 0);
    let judged = t
        .verdicts
        .iter()
        .any(|v| v.tally.pass + v.tally.fail + v.tally.foil + v.tally.error + v.tally.flaky > 0);
    if t.unreadable + t.limit_exceeded > 0 {
        Exit::BadInput
    } else if failed {
        Exit::Fail
    } else if !judged {
        eprintln!("error: nothing was judged in the merged reports");
        Exit::NothingJudged
    } else {
        Exit::Pass
    }
}
