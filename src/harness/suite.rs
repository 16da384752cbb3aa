//! Finding case files, reading them, and running them through rasterizers
//! against the reference. Both the CLI and the test harness go through here.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::deadline;
use crate::frame::Frame;
use crate::harness::golden;
use crate::metrics::{self, Metrics};
use crate::production::foils::{
    AnyCoverage, AreaSampler, DdaF32, DdaF64, FloatF32, FloatF64, OffsetSampler,
};
use crate::production::mutants::{Mutant, Mutation};
use crate::production::Production;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::reference::Reference;
use crate::scene::{parse_case, CaseError, ClipRules, FillRule, Limits, Scene};

pub use super::oracle::{
    area_check, check_areas, check_time, run_reference, run_reference_planned, run_reference_with,
    AreaCheck, ReferenceRun, TimeCheck,
};
use super::oracle::{catch_oracle_run, primitive_areas};

/// A case file and its id: its path under `cases/`, without `.json`
/// (`triangles/fan_center`).
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct CaseFile {
    pub id: String,
    pub path: PathBuf,
}

/// What a walk over the given paths found.
#[derive(Debug, Default)]
pub struct Discovery {
    pub cases: Vec<CaseFile>,
    /// `invalid/` folders passed over (they hold negative tests; name one
    /// explicitly to read it).
    pub skipped: Vec<PathBuf>,
    /// Paths that do not exist or cannot be read.
    pub errors: Vec<String>,
}

/// Finds case files under `paths`, sorted by id. Folders are walked
/// recursively, following symbolic links; folders named `invalid` inside
/// them are skipped. A folder reached again through a link is walked once,
/// and a link back to a folder being walked (a loop) is an error, reported
/// once. One file reached through several paths is one case; two
/// different files with one id are an error naming both (the first, by
/// path, is kept), since an id names a case's images, golden file and
/// baseline entry.
pub fn discover(paths: &[PathBuf]) -> Discovery {
    let mut found = Discovery::default();
    let mut walk_state = Walk::default();
    for path in paths {
        if path.is_dir() {
            walk_state.walk(path, &mut found);
        } else if path.exists() {
            // A regular file, or something the reader refuses by name.
            found.cases.push(case_file(path));
        } else {
            found
                .errors
                .push(format!("{}: no such file or folder", path.display()));
        }
    }
    found.cases.sort();
    found.cases.dedup();
    keep_each_id_once(&mut found);
    found
}

/// A file's or folder's identity: (device, inode) where there is one.
fn identity(path: &Path) -> Option<(u64, u64)> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        std::fs::metadata(path).ok().map(|m| (m.dev(), m.ino()))
    }
    #[cfg(not(unix))]
    {
        std::fs::canonicalize(path).ok().map(|p| {
            use std::hash::{Hash, Hasher};
            let mut h = std::collections::hash_map::DefaultHasher::new();
            p.hash(&mut h);
            (0, h.finish())
        })
    }
}

/// Drops a second path to the same file under one id, and turns two
/// different files with one id into an error naming both.
fn keep_each_id_once(found: &mut Discovery) {
    let mut kept: Vec<CaseFile> = Vec::with_capacity(found.cases.len());
    let mut kept_identity = None;
    for case in std::mem::take(&mut found.cases) {
        let this = identity(&case.path);
        if let Some(first) = kept.last().filter(|k| k.id == case.id) {
            if this.is_none() || this != kept_identity {
                found.errors.push(format!(
                    "two different files have the case id {:?}: {} and {} (ids name images, golden files and baseline entries; only the first is run)",
                    case.id,
                    first.path.display(),
                    case.path.display()
                ));
            }
            continue;
        }
        kept_identity = this;
        kept.push(case);
    }
    found.cases = kept;
}

/// The folders a walk has entered, by identity, and those it is inside.
#[derive(Default)]
struct Walk {
    visited: std::collections::HashSet<(u64, u64)>,
    inside: Vec<(u64, u64)>,
}

impl Walk {
    fn walk(&mut self, dir: &Path, found: &mut Discovery) {
        let Some(id) = identity(dir) else {
            return found
                .errors
                .push(format!("{}: cannot read the folder", dir.display()));
        };
        if self.inside.contains(&id) {
            return found.errors.push(format!(
                "{}: a symbolic link loop (it leads back to a folder that contains it); not followed",
                dir.display()
            ));
        }
        if !self.visited.insert(id) {
            return; // walked already through another path
        }
        let entries = match std::fs::read_dir(dir) {
            Ok(entries) => entries,
            Err(e) => return found.errors.push(format!("{}: {e}", dir.display())),
        };
        let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        paths.sort();
        self.inside.push(id);
        for path in paths {
            if path.is_dir() {
                if path.file_name().is_some_and(|n| n == "invalid") {
                    found.skipped.push(path);
                } else {
                    self.walk(&path, found);
                }
            } else if path.extension().is_some_and(|e| e == "json") {
                found.cases.push(case_file(&path));
            }
        }
        self.inside.pop();
    }
}

/// The id of a case file: its path below the nearest folder named `cases`,
/// without the extension; the path as given when there is none. The path
/// as given is searched first, then its absolute form, so that
/// `rastercheck run triangles` inside `cases/` names the same case as
/// `rastercheck run cases/triangles` beside it.
pub fn case_file(path: &Path) -> CaseFile {
    let (base, start) = cases_ancestor(path).unwrap_or((path.to_owned(), 0));
    let without_ext = base.with_extension("");
    let components: Vec<_> = without_ext.components().collect();
    let id = components[start..]
        .iter()
        .filter(|c| matches!(c, std::path::Component::Normal(_)))
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/");
    CaseFile {
        id,
        path: path.to_owned(),
    }
}

/// The folder that holds a case's golden files (`reference/` inside it,
/// SPEC.md §7): the parent of the nearest folder named `cases` above the
/// case file, so that golden files are found wherever the run starts;
/// `fallback` (the working directory) when no folder above it is named
/// `cases`.
pub fn golden_root(path: &Path, fallback: &Path) -> PathBuf {
    match cases_ancestor(path) {
        Some((base, start)) => {
            let cases: PathBuf = base.components().take(start - 1).collect();
            if cases.as_os_str().is_empty() {
                PathBuf::from(".")
            } else {
                cases
            }
        }
        None => fallback.to_owned(),
    }
}

/// The path (as given, else absolute) in which a folder above the file is
/// named `cases`, and the index of the component after the nearest one.
fn cases_ancestor(path: &Path) -> Option<(PathBuf, usize)> {
    let find = |p: &Path| {
        let components: Vec<_> = p.components().collect();
        // The file itself is no folder: only the components above it count.
        components[..components.len().saturating_sub(1)]
            .iter()
            .rposition(|c| c.as_os_str() == "cases")
            .map(|i| (p.to_owned(), i + 1))
    };
    find(path).or_else(|| std::path::absolute(path).ok().as_deref().and_then(find))
}

/// Reads and validates one case file.
pub fn load(file: &CaseFile, limits: &Limits) -> Result<Scene, CaseError> {
    load_checked(file, limits).map_err(|e| match e {
        LoadError::Unreadable(e) | LoadError::OverLimit(e) => e,
    })
}

/// Why a case file did not become a scene: bad input, or a file larger
/// than `--max-case-bytes` (a limit of the run, not a fault of the case).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum LoadError {
    Unreadable(CaseError),
    OverLimit(CaseError),
}

/// [`load`], telling a file over the size limit from bad input. Only a
/// regular file (symbolic links followed) is opened, so a FIFO or a device
/// cannot hang the run, and its size is checked before a byte is read.
pub fn load_checked(file: &CaseFile, limits: &Limits) -> Result<Scene, LoadError> {
    let text = read_case_text(&file.path, limits.max_case_bytes)?;
    parse_case(&text, &file.path.display().to_string(), limits).map_err(LoadError::Unreadable)
}

/// The text of a case file of at most `max_bytes` bytes.
fn read_case_text(path: &Path, max_bytes: u64) -> Result<String, LoadError> {
    use std::io::Read;
    let shown = path.display().to_string();
    let error = |message: String| CaseError {
        file: shown.clone(),
        location: "$".to_owned(),
        message,
    };
    let bad = |message: String| LoadError::Unreadable(error(message));
    let regular = |meta: &std::fs::Metadata| -> Result<(), LoadError> {
        if !meta.is_file() {
            return Err(bad(format!(
                "not a regular file ({}); a case must be a regular file",
                file_kind(meta)
            )));
        }
        if meta.len() > max_bytes {
            return Err(LoadError::OverLimit(error(format!(
                "the file has {} bytes, over the limit of {max_bytes} bytes per case file (raise it with --max-case-bytes)",
                meta.len()
            ))));
        }
        Ok(())
    };
    let cannot = |e: std::io::Error| bad(format!("cannot read the file: {e}"));
    // Checked before opening: opening a FIFO blocks until a writer comes.
    regular(&std::fs::metadata(path).map_err(cannot)?)?;
    let opened = std::fs::File::open(path).map_err(cannot)?;
    // And again on what was opened, in case the path changed in between.
    regular(&opened.metadata().map_err(cannot)?)?;
    let mut bytes = Vec::new();
    opened
        .take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > max_bytes {
        return Err(LoadError::OverLimit(error(format!(
            "the file grew past the limit of {max_bytes} bytes per case file while it was read (raise it with --max-case-bytes)"
        ))));
    }
    String::from_utf8(bytes).map_err(|e| bad(format!("cannot read the file: not UTF-8 text ({e})")))
}

/// What kind of file `meta` describes, in words.
fn file_kind(meta: &std::fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_block_device() || t.is_char_device() {
            return "a device";
        }
    }
    if meta.is_dir() {
        "a folder"
    } else {
        "of an unknown kind"
    }
}

/// Every rasterizer the CLI can name.
pub fn rasterizer_names() -> Vec<&'static str> {
    let mut names = vec![
        "reference",
        "production",
        "dda-f32",
        "dda-f64",
        "float-f32",
        "float-f64",
    ];
    names.extend(crate::production::foils::SAMPLER_FOILS);
    names.extend(crate::production::methods().iter().map(|m| m.name));
    names.extend(Mutation::ALL.iter().map(|m| m.name()));
    names.extend(crate::adapters::names());
    names
}

/// A rasterizer by its command-line name.
pub fn rasterizer(name: &str) -> Option<Box<dyn Rasterizer>> {
    match name {
        "reference" => Some(Box::new(Reference)),
        "production" => Some(Box::new(Production)),
        "dda-f32" => Some(Box::new(DdaF32)),
        "dda-f64" => Some(Box::new(DdaF64)),
        "float-f32" => Some(Box::new(FloatF32)),
        "float-f64" => Some(Box::new(FloatF64)),
        "foil-offset-sampler" => Some(Box::new(OffsetSampler)),
        "foil-area-sampler" => Some(Box::new(AreaSampler)),
        "foil-any-coverage" => Some(Box::new(AnyCoverage)),
        _ => crate::production::methods()
            .into_iter()
            .find(|m| m.name == name)
            .map(|m| (m.make)())
            .or_else(|| {
                Mutation::ALL
                    .into_iter()
                    .find(|m| m.name() == name)
                    .map(|m| Box::new(Mutant(m)) as Box<dyn Rasterizer>)
            })
            .or_else(|| crate::adapters::by_name(name)),
    }
}

/// How a candidate did on a case.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    Pass,
    Fail(Vec<String>),
    Unsupported(String),
    /// The rasterizer broke (crashed, or returned an error).
    Error(String),
}

impl Verdict {
    /// The name a verdict is recorded under in reports and baselines;
    /// a foil's failure is a `foil` departure.
    pub fn recorded_name(&self, foil: bool) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail(_) if foil => "foil",
            Verdict::Fail(_) => "fail",
            Verdict::Unsupported(_) => "unsupported",
            Verdict::Error(_) => "error",
        }
    }

    pub fn label(&self) -> &'static str {
        match self {
            Verdict::Pass => "PASS",
            Verdict::Fail(_) => "FAIL",
            Verdict::Unsupported(_) => "UNSUPPORTED",
            Verdict::Error(_) => "ERROR",
        }
    }
}

/// One candidate on one case.
pub struct CandidateRun {
    pub rasterizer: String,
    pub verdict: Verdict,
    pub metrics: Option<Metrics>,
    pub frame: Option<Frame>,
    pub elapsed: Duration,
    /// The frame's [`Frame::method`], kept when the frame is released.
    pub method: Option<&'static str>,
    /// The rule it was judged under, when that is not the case's: the
    /// rasterizer follows a fill rule of its own
    /// ([`Rasterizer::fixed_fill_rule`]).
    pub judged_rule: Option<FillRule>,
    /// The clip conventions it was judged under, when they are not the
    /// case's ([`Rasterizer::fixed_clip_rules`]).
    pub judged_clip: Option<ClipRules>,
}

impl CandidateRun {
    pub fn without_frame(rasterizer: String, verdict: Verdict, elapsed: Duration) -> CandidateRun {
        CandidateRun {
            rasterizer,
            verdict,
            metrics: None,
            frame: None,
            elapsed,
            method: None,
            judged_rule: None,
            judged_clip: None,
        }
    }
}

pub fn run_candidate(
    scene: &Scene,
    reference: &ReferenceRun,
    candidate: &dyn Rasterizer,
) -> CandidateRun {
    let started = Instant::now();
    if let Some(why) = candidate.capabilities().refuses(scene) {
        return CandidateRun::without_frame(
            candidate.name().to_owned(),
            Verdict::Unsupported(why),
            started.elapsed(),
        );
    }
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        candidate.rasterize(scene, &reference.plan)
    }));
    let elapsed = started.elapsed();
    let name = candidate.name().to_owned();
    let frame = match result {
        Ok(Ok(frame)) => frame,
        Ok(Err(RasterError::Unsupported(why))) => {
            return CandidateRun::without_frame(name, Verdict::Unsupported(why), elapsed)
        }
        Ok(Err(RasterError::Failed(why))) => {
            return CandidateRun::without_frame(name, Verdict::Error(why), elapsed)
        }
        Err(panic) => {
            let why = pass_on_deadline(panic, "panicked");
            return CandidateRun::without_frame(name, Verdict::Error(why), elapsed);
        }
    };
    // A rasterizer that cannot follow the case's fill rule (or, in clip
    // space, its clip conventions) is judged under the ones it follows,
    // against the reference drawn under them.
    let own = super::profile::OwnConventions::of(candidate, scene);
    if own.any() {
        if let Some(why) = own
            .fill_rule
            .and_then(|rule| super::profile::cannot_judge_under(scene, rule))
        {
            return CandidateRun::without_frame(name, Verdict::Unsupported(why), elapsed);
        }
        let under = own.restate(scene);
        // Restating changes rules only, never what the plan reads.
        let reference = catch_oracle_run(|| run_reference_planned(&under, reference.plan.clone()));
        let mut run = match reference {
            Ok(reference) => judge(&under, &reference, frame, name, elapsed),
            Err(why) => {
                let why = format!(
                    "the reference under {} it follows failed: {why}",
                    own.describe()
                );
                CandidateRun::without_frame(name, Verdict::Error(why), elapsed)
            }
        };
        run.judged_rule = own.fill_rule;
        run.judged_clip = own.clip;
        return run;
    }
    judge(scene, reference, frame, name, elapsed)
}

/// Judges a candidate's frame against the reference's answer.
fn judge(
    scene: &Scene,
    reference: &ReferenceRun,
    frame: Frame,
    name: String,
    elapsed: Duration,
) -> CandidateRun {
    if let Some(why) = shape_problem(&reference.frame, &frame) {
        let why = format!("returned a frame of the wrong size or with the wrong channels: {why}");
        return CandidateRun {
            rasterizer: name,
            verdict: Verdict::Error(why),
            metrics: None,
            method: frame.method,
            frame: Some(frame),
            elapsed,
            judged_rule: None,
            judged_clip: None,
        };
    }
    // The oracle's exact areas, computed once with the reference's frame;
    // their failure is the reference's, reported on the case.
    let (areas, broken_oracle) = match &reference.areas {
        Some(Ok(check)) => (Some(check), None),
        Some(Err(why)) => (None, Some(why.clone())),
        None => (None, None),
    };
    // Likewise the certified time coverage of a moving scene.
    let (time, broken_time_oracle) = match &reference.time {
        Some(Ok(check)) => (Some(check), None),
        Some(Err(why)) => (None, Some(why.clone())),
        None => (None, None),
    };
    // An area method that gives each primitive's coverage is judged per
    // primitive too, against areas computed here, for it alone.
    let part_areas = frame
        .parts
        .as_ref()
        .filter(|_| areas.is_some())
        .map(|_| primitive_areas(scene));
    let known = metrics::Known {
        interior: reference.interior.as_deref(),
        classes: areas.as_ref().map(|a| a.classes.as_slice()),
        whole_time: time.map(|t| t.whole.as_slice()),
        part_areas: part_areas.as_deref(),
        depth_allowed: reference.depth_allowed.as_deref(),
    };
    let m = metrics::measure_known(scene, &reference.frame, &frame, &known);
    // Without the oracle's values there is nothing to measure against: the
    // one reason is the oracle's failure.
    let mut failures = if broken_time_oracle.is_some() {
        Vec::new()
    } else {
        metrics::failures(scene, &reference.frame, &m)
    };
    if let Some(check) = &areas {
        failures.extend(check.broken_promises.iter().cloned());
    }
    failures.extend(broken_oracle);
    if let Some(check) = time {
        failures.extend(check.broken_promises.iter().cloned());
    }
    failures.extend(broken_time_oracle);
    let verdict = if failures.is_empty() {
        Verdict::Pass
    } else {
        Verdict::Fail(failures)
    };
    CandidateRun {
        rasterizer: name,
        verdict,
        metrics: Some(m),
        method: frame.method,
        frame: Some(frame),
        elapsed,
        judged_rule: None,
        judged_clip: None,
    }
}

/// Why a candidate's frame cannot be compared with the reference's, if it
/// cannot: another canvas, other samples or channels; for a scene in which
/// something moves, anything but a time-only frame (one time coverage per
/// pixel, no sample slots), and time coverage for any other scene.
pub fn shape_problem(reference: &Frame, frame: &Frame) -> Option<String> {
    if (frame.width, frame.height) != (reference.width, reference.height) {
        return Some(format!(
            "{}×{} for a {}×{} canvas",
            frame.width, frame.height, reference.width, reference.height
        ));
    }
    if reference.time.is_some() {
        let time_only = frame.samples == 0
            && frame.sample_count() == 0
            && frame.last.is_empty()
            && frame.resolved.is_none()
            && frame.depth.is_none()
            && frame.attributes.is_empty();
        return match &frame.time {
            None => Some(
                "a scene in which something moves needs a time coverage per pixel".to_owned(),
            ),
            Some(t) if t.len() != frame.pixel_count() => Some(format!(
                "{} time coverages for {} pixels",
                t.len(),
                frame.pixel_count()
            )),
            Some(_) if !time_only => Some(
                "a scene in which something moves is judged on time coverage only: its frame has no sample slots, resolved coverage, depth or attributes".to_owned(),
            ),
            Some(_) => None,
        };
    }
    if frame.time.is_some() {
        return Some("time coverage for a scene in which nothing moves".to_owned());
    }
    let samples_only_resolved = frame.samples == 0 && reference.resolved.is_some();
    // Coverage only (SPEC.md §12.9): no depth and no attributes, whatever
    // the plan asks.
    let values_not_given = samples_only_resolved
        || frame.coverage_only && frame.depth.is_none() && frame.attributes.is_empty();
    let wrong = !(frame.samples == reference.samples || samples_only_resolved)
        || frame.resolved.is_some() != reference.resolved.is_some()
        || frame
            .resolved
            .as_ref()
            .is_some_and(|r| r.len() != frame.pixel_count())
        || frame.sample_count() != frame.pixel_count() * frame.samples as usize
        || frame.attributes.len() != reference.attributes.len() && !values_not_given
        || frame.depth.is_some() != reference.depth.is_some() && !values_not_given;
    wrong.then(|| {
        format!(
            "{} for the reference's {}",
            channels(frame),
            channels(reference)
        )
    })
}

/// What a frame holds, in words, for [`shape_problem`].
fn channels(frame: &Frame) -> String {
    let mut out = format!(
        "{} samples per pixel, {} attributes",
        frame.samples,
        frame.attributes.len()
    );
    if frame.depth.is_some() {
        out.push_str(", depth");
    }
    if frame.resolved.is_some() {
        out.push_str(", resolved coverage");
    }
    out
}

/// The message a panic carried.
/// `what: message` for a caught panic; a deadline's unwinding
/// ([`deadline::Exceeded`]) is not a crash and goes on unwinding to the
/// runner that set the deadline.
pub(super) fn pass_on_deadline(panic: Box<dyn std::any::Any + Send>, what: &str) -> String {
    if deadline::is_exceeded(&*panic) {
        std::panic::resume_unwind(panic);
    }
    format!("{what}: {}", panic_message(&*panic))
}

pub fn panic_message(panic: &(dyn std::any::Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "panicked".to_owned())
}

/// Whether the reference still reproduces a case's golden file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum GoldenStatus {
    Matches,
    Missing(PathBuf),
    Differs(String),
}

pub fn check_golden(root: &Path, id: &str, frame: &Frame) -> GoldenStatus {
    let path = golden::path_for(root, id);
    if !path.exists() {
        return GoldenStatus::Missing(path);
    }
    match golden::check(frame, &path) {
        Ok(()) => GoldenStatus::Matches,
        Err(why) => GoldenStatus::Differs(why),
    }
}

/// A one-line summary of a candidate's metrics.
pub fn describe(run: &CandidateRun) -> String {
    let Some(m) = &run.metrics else {
        return match &run.verdict {
            Verdict::Unsupported(why) | Verdict::Error(why) => why.clone(),
            _ => String::new(),
        };
    };
    let c = &m.coverage;
    let mut parts = vec![if m.time.is_some() {
        "time coverage only".to_owned()
    } else if !c.has_mask() {
        "no samples (resolved coverage only)".to_owned()
    } else if c.mismatched() == 0 {
        format!(
            "coverage {}/{} samples exact",
            c.candidate_covered, c.samples
        )
    } else {
        format!(
            "coverage {} missing, {} extra, {} wrong owner of {} covered",
            c.missing, c.extra, c.wrong_owner, c.reference_covered
        )
    }];
    if let Some(w) = &m.watertight {
        parts.push(format!(
            "watertight: {} holes, {} overdraw in {} interior",
            w.holes, w.overdraw, w.interior
        ));
    }
    if let Some(l) = &m.lines {
        parts.push(format!(
            "{} midpoint lines, {} crowded steps",
            l.lines, l.crowded_steps
        ));
    }
    if let Some(aa) = &m.antialias {
        parts.push(format!(
            "aa max err {:.2e} edge rms {:.2e} (bias {:+.1e}) over {} edge pixels, {} piglit violations",
            aa.max_error, aa.rms_edge, aa.bias_edge, aa.edge_pixels, aa.piglit_violations
        ));
        if let Some(p) = &aa.primitives {
            parts.push(format!(
                "per primitive: max err {:.2e} over {} primitive-pixels, {} over the bound, {} not exact",
                p.max_error, p.judged, p.over_bound, p.exactness_violations
            ));
        }
    }
    if let Some(t) = &m.time {
        let efficiency = t
            .efficiency()
            .map(|e| format!(", sample test efficiency {:.1}%", e * 100.0))
            .unwrap_or_default();
        parts.push(format!(
            "time max err {:.2e} at ({}, {}) rms {:.2e} (bias {:+.1e}) over {} moving pixels{efficiency}",
            t.max_error, t.worst_pixel[0], t.worst_pixel[1], t.rms_moving, t.bias_moving, t.moving_pixels
        ));
    }
    if let Some(worst) = m
        .channels
        .iter()
        .max_by(|a, b| (a.max_abs / a.allowed_abs).total_cmp(&(b.max_abs / b.allowed_abs)))
    {
        let rms = m.channels.iter().map(|ch| ch.rms).fold(0.0, f64::max);
        parts.push(format!(
            "interp max {:.2e} ({:.1} ulp, {}) rms {:.1e} over {} channels",
            worst.max_abs,
            worst.max_ulp,
            worst.channel,
            rms,
            m.channels.len()
        ));
    }
    parts.join(" · ")
}
