//! Outputs: for people, magnified PNG images and (with `--report`) an HTML
//! page; for machines, `report.json`, `junit.xml` and `summary.md`.
//!
//! `write_all` writes the whole folder:
//!
//! ```text
//! DIR/report.json          the run, machine-readable (SPEC.md §10)
//! DIR/junit.xml            one testcase per case × rasterizer
//! DIR/summary.md           totals, failures first, worst metrics, the plots
//! DIR/plots/*.svg          accuracy charts (plots/mod.rs)
//! DIR/images/<id>/*.png    reference, candidate and difference mask, for
//!                          every result that is not a pass (antialiased
//!                          cases: resolved coverage, signed error, samples;
//!                          moving scenes: time coverage, signed error)
//! DIR/exr/<id>/<rast>.exr  signed float error maps, for every result that
//!                          is not a pass or has any nonzero error (per
//!                          sample; antialiased: resolved error per pixel;
//!                          moving: exact, candidate and error per pixel)
//! DIR/pages/<id>.html      one page per case worth a look (failures,
//!                          departures, results with some error): its
//!                          cards, pictures embedded, loaded only when opened
//! DIR/index.html           the light page for people: totals, families,
//!                          failures first, links to the case pages
//! ```
//!
//! The pictures, error maps and case page of a case are written as soon as
//! it is judged, while its frames are in memory (`case_files.rs`); the rest
//! at the end, from `report.json`'s model alone.
//!
//! Every file is written whole or not at all ([`write_file`]: a temporary
//! name, then a rename), and a run first removes what an earlier run wrote
//! there ([`remove_owned`]), never a user's own files.

pub mod case_files;
pub mod diff;
pub mod exr;
pub mod html;
pub mod json;
pub mod junit;
pub mod plots;
pub mod png;
pub mod summary;

use std::path::{Path, PathBuf};

use json::Report;

use crate::harness::runner::CaseOutcome;

/// Results that get PNG pictures, at most, over a run.
pub const MAX_PICTURED: usize = 200;

/// Case pages for failures, errors and problems, at most, over a run.
pub const MAX_PROBLEM_PAGES: usize = 1000;

/// Case pages for a foil's departures and passes with some error, at most,
/// over a run. Which cases get one is decided as cases finish, so past
/// this many the choice depends on the order threads finish in: it is
/// kept well above the bundled cases' 424 (every one of which may have
/// a pass with some error) so that their report does not.
pub const MAX_PAGES: usize = 1000;

/// What the temporary name of a file being written ends with: a file so
/// named is one rastercheck did not finish writing.
pub const TEMPORARY_SUFFIX: &str = ".rastercheck-partial";

/// The files and folders a report folder holds that rastercheck wrote;
/// nothing else in it is ever removed.
pub const OWNED_FILES: [&str; 4] = ["report.json", "junit.xml", "summary.md", "index.html"];
pub const OWNED_FOLDERS: [&str; 4] = ["images", "exr", "pages", "plots"];

/// Writes `content` to `path` whole or not at all (every report file goes
/// through here): into a temporary file in the same folder, then renamed
/// over `path`, so a run killed mid-write leaves the old file or the new
/// one, never a truncated one. Creates the folder.
pub fn write_file(path: &Path, content: &[u8]) -> Result<PathBuf, String> {
    let parent = path.parent().unwrap_or(Path::new("."));
    if !parent.as_os_str().is_empty() {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    let name = path
        .file_name()
        .ok_or_else(|| format!("{}: not a file name", path.display()))?;
    let temporary = path.with_file_name(format!(
        ".{}.{}{TEMPORARY_SUFFIX}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let written = std::fs::write(&temporary, content)
        .and_then(|()| std::fs::rename(&temporary, path))
        .map_err(|e| format!("{}: {e}", path.display()));
    if written.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    written.map(|()| path.to_owned())
}

/// Removes what an earlier run wrote into the report folder `dir`
/// ([`OWNED_FILES`], [`OWNED_FOLDERS`], and temporary files a killed run
/// left), and nothing else: a user's own files there stay. A missing folder
/// is fine.
pub fn remove_owned(dir: &Path) -> Result<(), String> {
    let entries = match std::fs::read_dir(dir) {
        Ok(entries) => entries,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(format!("{}: {e}", dir.display())),
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let path = entry.path();
        // Not followed: a link named `images` is removed, not its target.
        let Ok(kind) = entry.file_type() else {
            continue;
        };
        let removed = if OWNED_FOLDERS.contains(&name.as_str()) && kind.is_dir() {
            std::fs::remove_dir_all(&path)
        } else if !kind.is_dir()
            && (OWNED_FILES.contains(&name.as_str())
                || OWNED_FOLDERS.contains(&name.as_str())
                || name.ends_with(TEMPORARY_SUFFIX))
        {
            std::fs::remove_file(&path)
        } else {
            continue;
        };
        removed.map_err(|e| {
            format!(
                "{}: removing what an earlier run wrote: {e}",
                path.display()
            )
        })?;
    }
    Ok(())
}

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

/// Escapes text for XML and HTML content and attribute values. Control
/// characters, which XML 1.0 forbids even escaped, become `?`.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c if (c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r') => out.push('?'),
            c => out.push(c),
        }
    }
    out
}

/// `path` relative to `dir`, with forward slashes.
pub fn relative(dir: &Path, path: &Path) -> String {
    let rel = path.strip_prefix(dir).unwrap_or(path);
    rel.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}
