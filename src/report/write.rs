//! A run's report folder written: `report.json` alone before the run, then
//! each case's files and the summaries (JUnit, plots, markdown, HTML),
//! from a report in memory (`write_summaries`, as `merge` writes) or from
//! case entries on disk (`write_streamed`, as `run` writes, in bounded
//! memory).

use std::io::Write;
use std::path::{Path, PathBuf};

use super::digest::Digest;
use super::families::{families_of, FamilyCount};
use super::files::{write_file, write_file_with};
use super::json::{Cases, Report};
use super::spool::Spool;
use super::{case_files, html, junit, plots, summary};
use crate::harness::runner::CaseOutcome;

/// Writes `report.json` alone (used before a run starts, so that an
/// interrupted run leaves a report saying what did not run).
pub fn write_json(dir: &Path, report: &mut Report) -> Result<PathBuf, String> {
    report.tally();
    write_file(&dir.join("report.json"), report.to_json().as_bytes())
}

/// Writes `report.json` for `head` (its cases are not read: its totals
/// must already count the cases) with the cases `cases` hands over, one
/// at a time: the same bytes [`Report::to_json`] gives with those cases in
/// it.
pub fn write_json_streamed(
    dir: &Path,
    head: &Report,
    cases: &mut Cases,
) -> Result<PathBuf, String> {
    let mut head = head.clone();
    head.cases = Vec::new();
    let text = head.to_json();
    let open = text
        .strip_suffix("\"cases\": []\n}")
        .expect("the cases come last in a report");
    write_file_with(&dir.join("report.json"), &mut |out| {
        let mut failed: Option<String> = None;
        let mut first = true;
        let mut put = |out: &mut dyn Write, bytes: &[u8]| {
            if failed.is_none() {
                if let Err(e) = out.write_all(bytes) {
                    failed = Some(format!("report.json: {e}"));
                }
            }
        };
        put(out, open.as_bytes());
        put(out, b"\"cases\": [");
        cases(&mut |entry| {
            let text = serde_json::to_string_pretty(entry).expect("a case entry serializes");
            put(out, if first { b"\n" } else { b",\n" });
            first = false;
            // A string in JSON holds no raw line break: each line of the
            // entry is a line of the array, indented one level deeper.
            for (k, line) in text.split('\n').enumerate() {
                if k > 0 {
                    put(out, b"\n");
                }
                put(out, b"    ");
                put(out, line.as_bytes());
            }
        })?;
        put(out, if first { b"]\n}" } else { b"\n  ]\n}" });
        failed.map_or(Ok(()), Err)
    })
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
    let families = families_of(&report.cases, report.rasterizers.len());
    written.extend(drawn(dir, report, &families)?);
    Ok(written)
}

/// Writes the files that summarise a run whose case entries are in
/// `spool`, counted and digested in `digest`: `report.json` and
/// `junit.xml` from every entry, read back one at a time; the plots,
/// `summary.md` and `index.html` from the digest's entries (all of them
/// for a run of up to `digest::LISTED` cases). `head` is the report
/// without its cases.
pub fn write_streamed(
    dir: &Path,
    head: &mut Report,
    spool: &mut Spool,
    digest: Digest,
) -> Result<Vec<PathBuf>, String> {
    head.totals = digest.totals.clone();
    head.cases = Vec::new();
    let mut written = vec![write_json_streamed(dir, head, &mut |f| spool.each(f))?];
    written.push(write_file_with(&dir.join("junit.xml"), &mut |out| {
        junit::write(out, head, digest.testcases, &mut |f| spool.each(f))
    })?);
    head.cases = digest.cases;
    let drawn = drawn(dir, head, &digest.families);
    head.cases = Vec::new();
    written.extend(drawn?);
    Ok(written)
}

/// The plots, `summary.md` and `index.html`, from `report`'s entries and
/// the count of every family.
fn drawn(dir: &Path, report: &Report, families: &[FamilyCount]) -> Result<Vec<PathBuf>, String> {
    let mut written = plots::write(dir, report)?;
    written.push(write_file(
        &dir.join("summary.md"),
        summary::render(report).as_bytes(),
    )?);
    written.push(write_file(
        &dir.join("index.html"),
        html::render(report, families).as_bytes(),
    )?);
    Ok(written)
}
