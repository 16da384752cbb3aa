//! What one case writes into the report folder as soon as it is judged,
//! while its frames are still in memory: the PNG pictures and EXR error
//! maps of its results, and its HTML page. The runner releases the frames
//! right after (`runner::run_all`), so a run holds the frames of the cases in
//! flight only, and the summary files written at the end (`report.json`,
//! `index.html`, …) need none.
//!
//! Called from the worker threads, one case at a time per thread: every
//! file of a case is its own, and the caps on pictures and pages are
//! counted atomically over the run.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use super::files::{relative, write_file};
use super::json::CaseEntry;
use super::limits::{MAX_PAGES, MAX_PICTURED, MAX_PROBLEM_PAGES};
use super::{conservative, exr, html, png};
use crate::harness::judge::Verdict;
use crate::harness::runner::CaseOutcome;

/// Writes each case's pictures, error maps and page (see the module
/// comment). Errors are kept, the first one reported by [`CaseWriter::finish`].
pub struct CaseWriter {
    dir: PathBuf,
    foils: Vec<bool>,
    pictured: AtomicUsize,
    problem_pages: AtomicUsize,
    other_pages: AtomicUsize,
    files: AtomicUsize,
    error: Mutex<Option<String>>,
}

impl CaseWriter {
    /// A writer into the report folder `dir`, for candidates that are foils
    /// or not, in the order of the run's rasterizers.
    pub fn new(dir: &Path, foils: &[bool]) -> CaseWriter {
        CaseWriter {
            dir: dir.to_owned(),
            foils: foils.to_vec(),
            pictured: AtomicUsize::new(0),
            problem_pages: AtomicUsize::new(0),
            other_pages: AtomicUsize::new(0),
            files: AtomicUsize::new(0),
            error: Mutex::new(None),
        }
    }

    /// Writes what `outcome`'s frames show, and returns the case's report
    /// entry with the files written recorded in it (paths relative to the
    /// report folder). A write that fails is remembered and the case goes
    /// without.
    pub fn write(&self, outcome: &CaseOutcome) -> CaseEntry {
        let mut entry = CaseEntry::from_outcome(outcome, &self.foils);
        if let Err(e) = self.write_frames(outcome, &mut entry) {
            self.keep(e);
        }
        let cards = html::cards_of(&entry);
        let problem = cards.iter().any(|c| c.is_problem());
        let counter = if problem {
            (&self.problem_pages, MAX_PROBLEM_PAGES)
        } else {
            (&self.other_pages, MAX_PAGES)
        };
        if !cards.is_empty() && take(counter.0, counter.1) {
            let file = html::page_file(&entry.id);
            let text = html::page(&self.dir, &entry, &cards, outcome);
            match write_file(&self.dir.join(&file), text.as_bytes()) {
                Ok(_) => {
                    self.files.fetch_add(1, Ordering::Relaxed);
                    entry.page = Some(file);
                }
                Err(e) => self.keep(e),
            }
        }
        entry
    }

    /// The PNGs of every result that is not a pass (at most
    /// [`MAX_PICTURED`] over the run) and the EXR error maps of every
    /// result with any error, recorded in the result's files.
    fn write_frames(&self, outcome: &CaseOutcome, entry: &mut CaseEntry) -> Result<(), String> {
        let (Some(scene), Some(reference)) = (&outcome.scene, &outcome.reference) else {
            return Ok(());
        };
        let id = &outcome.file.id;
        for (run, result) in outcome.candidates.iter().zip(&mut entry.results) {
            let files = &mut result.files;
            let (Some(frame), Some(metrics)) = (&run.frame, &run.metrics) else {
                continue;
            };
            let passed = matches!(run.verdict, Verdict::Pass);
            if !passed && take(&self.pictured, MAX_PICTURED) {
                let folder = self.dir.join("images").join(id);
                let paths = png::write_comparison(
                    scene,
                    &reference.frame,
                    &run.rasterizer,
                    frame,
                    &metrics.coverage.mask,
                    &folder,
                    png::auto_scale(frame),
                )?;
                for path in paths {
                    files.push(relative(&self.dir, &path));
                    self.files.fetch_add(1, Ordering::Relaxed);
                }
            }
            // A conservative case (SPEC.md §19): its three classes and the
            // candidate's pixels in one picture, when it failed or drew in
            // the allowed band.
            if let Some(m) = &metrics.conservative {
                let shows = !passed || m.band_drawn > 0;
                if shows && take(&self.pictured, MAX_PICTURED) {
                    let folder = self.dir.join("images").join(id);
                    let paths = conservative::write_picture(
                        scene,
                        &run.rasterizer,
                        m,
                        &folder,
                        png::auto_scale(frame),
                    )?;
                    for path in paths {
                        files.push(relative(&self.dir, &path));
                        self.files.fetch_add(1, Ordering::Relaxed);
                    }
                }
            }
            if exr::has_error(passed, metrics) {
                let path = self
                    .dir
                    .join("exr")
                    .join(id)
                    .join(exr::file_name(&run.rasterizer));
                let allowed = reference.depth_allowed.as_deref();
                let path = exr::write(&reference.frame, frame, allowed, &path)?;
                files.push(relative(&self.dir, &path));
                self.files.fetch_add(1, Ordering::Relaxed);
            }
        }
        Ok(())
    }

    fn keep(&self, error: String) {
        let mut kept = self.error.lock().unwrap_or_else(|e| e.into_inner());
        kept.get_or_insert(error);
    }

    /// How many files the cases wrote, or the first error.
    pub fn finish(self) -> Result<usize, String> {
        match self.error.into_inner().unwrap_or_else(|e| e.into_inner()) {
            Some(e) => Err(e),
            None => Ok(self.files.into_inner()),
        }
    }
}

/// Takes one of `cap` places, if any is left.
fn take(counter: &AtomicUsize, cap: usize) -> bool {
    counter
        .fetch_update(Ordering::Relaxed, Ordering::Relaxed, |n| {
            (n < cap).then_some(n + 1)
        })
        .is_ok()
}
