//! A run's report folder written: `report.json` alone before the run, then
//! each case's files and the summaries (JUnit, plots, markdown, HTML).

use std::path::{Path, PathBuf};

use super::files::write_file;
use super::json::Report;
use super::{case_files, html, junit, plots, summary};
use crate::harness::runner::CaseOutcome;

/// Writes `report.json` alone (used before a run starts, so that an
/// interrupted run leaves a report saying what did not run).
pub fn write_json(dir: &Path, report: &mut Report) -> Result<PathBuf, String> {
    report.tally();
    write_file(&dir.join("report.json"), report.to_json().as_bytes())
}

/// Writes every output for a finished run whose outcomes still hold their
/// frames: each case's files ([`case_files::CaseWriter`]), then the
/// summaries ([`write_summaries`]). `run` writes each case's files as it
/// finishes instead, and only the summaries at the end.
pub fn write_all(
    dir: &Path,
    report: &mut Report,
    outcomes: &[CaseOutcome],
) -> Result<Vec<PathBuf>, String> {
    let foils: Vec<bool> = report.rasterizers.iter().map(|r| r.foil).collect();
    let writer = case_files::CaseWriter::new(dir, &foils);
    for (entry, outcome) in report.cases.iter_mut().zip(outcomes) {
        *entry = writer.write(outcome);
    }
    writer.finish()?;
    write_summaries(dir, report)
}

/// Writes the files that summarise the run, from the report alone:
/// `report.json`, `junit.xml`, the plots, `summary.md` and `index.html`
/// (the last two show the plots).
pub fn write_summaries(dir: &Path, report: &mut Report) -> Result<Vec<PathBuf>, String> {
    let mut written = vec![
        write_json(dir, report)?,
        write_file(&dir.join("junit.xml"), junit::render(report).as_bytes())?,
    ];
    written.extend(plots::write(dir, report)?);
    written.push(write_file(
        &dir.join("summary.md"),
        summary::render(report).as_bytes(),
    )?);
    written.push(write_file(
        &dir.join("index.html"),
        html::render(report).as_bytes(),
    )?);
    Ok(written)
}
