//! Running many cases: selection (filter, family, shard), parallel execution
//! with results in a fixed order, and one outcome per case that the
//! reports are written from.
//!
//! A case's work is independent of every other's and of the thread that
//! does it, so the outcomes are identical for any thread count; only the
//! timings differ.

use std::path::Path;
use std::time::Duration;

use rayon::prelude::*;

use crate::deadline;
use crate::frame::Frame;
use crate::harness::case_list::CaseList;
use crate::harness::discover::CaseFile;
use crate::harness::flaky::{self, Flaky, Repetition};
use crate::harness::golden::GoldenStatus;
use crate::harness::judge::{CandidateRun, Verdict};
use crate::harness::oracle::ReferenceRun;
use crate::harness::unique_names::UniqueNames;
use crate::harness::{discover, golden, judge, load, oracle, panics};
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::scene::{Limits, Scene};

/// Which of the discovered cases to run.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Selection {
    /// A glob over case ids: `*` matches within a path segment, `**` across
    /// segments, `?` one character (`triangles/fan_*`, `**/*tie*`).
    pub filter: Option<String>,
    /// The first segment of the id (`triangles`, `lines`).
    pub family: Option<String>,
    /// `(i, n)`: the i-th of n shards, 1-based.
    pub shard: Option<(usize, usize)>,
}

impl Selection {
    /// Parses `i/n` with 1 ≤ i ≤ n.
    pub fn parse_shard(text: &str) -> Result<(usize, usize), String> {
        let bad = || format!("--shard takes i/n with 1 ≤ i ≤ n, such as 2/4; got {text:?}");
        let (i, n) = text.split_once('/').ok_or_else(bad)?;
        let (i, n): (usize, usize) = (
            i.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        if i == 0 || n == 0 || i > n {
            return Err(bad());
        }
        Ok((i, n))
    }

    /// The selected cases, in their original (sorted) order. Shards take
    /// every n-th case of what the filter and family leave, so the union of
    /// the shards is exactly that set, each case once, and shards stay
    /// balanced as cases are added.
    pub fn apply(&self, cases: Vec<CaseFile>) -> Vec<CaseFile> {
        let mut keeps = self.keeps();
        cases.into_iter().filter(|c| keeps(&c.id)).collect()
    }

    /// [`Selection::apply`] to a compact list.
    pub fn apply_list(&self, cases: CaseList) -> CaseList {
        if *self == Selection::default() {
            return cases;
        }
        let mut keeps = self.keeps();
        cases.retain(|list, k| keeps(list.id(k)))
    }

    /// Whether to keep each id of the selection, given in order.
    fn keeps(&self) -> impl FnMut(&str) -> bool + '_ {
        // How many ids the filter and family left so far.
        let mut left = 0usize;
        move |id| {
            let kept = self
                .family
                .as_ref()
                .is_none_or(|f| id.split('/').next() == Some(f.as_str()))
                && self.filter.as_ref().is_none_or(|g| glob_match(g, id));
            if !kept {
                return false;
            }
            left += 1;
            self.shard.is_none_or(|(i, n)| (left - 1) % n == i - 1)
        }
    }
}

/// Whether `text` matches the glob `pattern` (`*`, `**`, `?`).
pub fn glob_match(pattern: &str, text: &str) -> bool {
    fn go(p: &[u8], t: &[u8]) -> bool {
        match p.first() {
            None => t.is_empty(),
            Some(b'*') if p.get(1) == Some(&b'*') => {
                let rest = &p[2..];
                (0..=t.len()).any(|k| go(rest, &t[k..]))
            }
            Some(b'*') => {
                let rest = &p[1..];
                let segment = t.iter().position(|&c| c == b'/').unwrap_or(t.len());
                (0..=segment).any(|k| go(rest, &t[k..]))
            }
            Some(b'?') => !t.is_empty() && t[0] != b'/' && go(&p[1..], &t[1..]),
            Some(&c) => t.first() == Some(&c) && go(&p[1..], &t[1..]),
        }
    }
    go(pattern.as_bytes(), text.as_bytes())
}

/// Cases a run deals out by index: a compact [`CaseList`] or a slice of
/// [`CaseFile`]s.
pub trait Cases: Sync {
    /// How many cases there are.
    fn count(&self) -> usize;
    /// Case `k`, or `None` past the end.
    fn case(&self, k: usize) -> Option<CaseFile>;
}

impl Cases for [CaseFile] {
    fn count(&self) -> usize {
        self.len()
    }
    fn case(&self, k: usize) -> Option<CaseFile> {
        self.get(k).cloned()
    }
}

impl Cases for CaseList {
    fn count(&self) -> usize {
        self.len()
    }
    fn case(&self, k: usize) -> Option<CaseFile> {
        self.get(k).map(|(id, path)| CaseFile { id, path })
    }
}

/// Everything that happened to one case.
pub struct CaseOutcome {
    pub file: CaseFile,
    /// `None` when the file could not be read.
    pub scene: Option<Scene>,
    /// Why the case could not be read (bad input), or why the reference
    /// could not draw it.
    pub problem: Option<Problem>,
    pub reference: Option<ReferenceRun>,
    pub golden: Option<GoldenStatus>,
    pub candidates: Vec<CandidateRun>,
    /// The case file's bytes hashed (`case_hash`), when they could be read.
    pub hash: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Problem {
    /// The case file is bad input: the error names the file and JSON path.
    Unreadable(String),
    /// The reference itself broke on this case (a bug in rastercheck).
    ReferenceFailed(String),
    /// The reference took longer than the time limit per case
    /// (`--case-timeout`): an error of the run's limits, like a canvas too
    /// large, not of the case or of the rasterizers.
    LimitExceeded(String),
    /// The run was stopped (SIGINT or SIGTERM, `crate::stop`) before this
    /// case finished: it did not run, and has no verdict.
    Interrupted,
}

impl Problem {
    /// What went wrong, in a sentence that names the file (bad input and
    /// limits) or the reference's failure.
    pub fn message(&self) -> String {
        match self {
            Problem::Unreadable(e) | Problem::LimitExceeded(e) => e.clone(),
            Problem::ReferenceFailed(e) => format!("the reference failed: {e}"),
            Problem::Interrupted => "the run was stopped before this case finished".to_owned(),
        }
    }

    /// Bad input or an exceeded limit: exit code 2, not a failure of a
    /// rasterizer.
    pub fn is_input_error(&self) -> bool {
        matches!(self, Problem::Unreadable(_) | Problem::LimitExceeded(_))
    }
}

impl CaseOutcome {
    /// A case that did not run, or did not finish, because the run was
    /// stopped.
    pub fn interrupted(file: &CaseFile) -> CaseOutcome {
        CaseOutcome {
            file: file.clone(),
            scene: None,
            problem: Some(Problem::Interrupted),
            reference: None,
            golden: None,
            candidates: Vec::new(),
            hash: None,
        }
    }

    /// Gives back the memory of the case's frames once it has been judged
    /// and its pictures written: verdicts and metrics stay.
    pub fn release_frames(&mut self) {
        if let Some(reference) = &mut self.reference {
            reference.frame = Frame::released();
            reference.interior = None;
            reference.areas = None;
            reference.time = None;
        }
        for run in &mut self.candidates {
            run.frame = None;
            // The per-sample difference mask is a frame's worth too; the
            // counts stay.
            if let Some(m) = &mut run.metrics {
                m.coverage.mask = Vec::new();
            }
        }
    }

    pub fn reference_time(&self) -> Duration {
        self.reference
            .as_ref()
            .map_or(Duration::ZERO, |r| r.elapsed)
    }
}

/// Reads, draws with the reference, checks the golden file, and runs every
/// candidate. Never panics: a panic in the oracle becomes a problem.
pub fn run_case(
    file: &CaseFile,
    limits: &Limits,
    candidates: &[Box<dyn Rasterizer>],
    root: &Path,
) -> CaseOutcome {
    let mut outcome = CaseOutcome {
        file: file.clone(),
        scene: None,
        problem: None,
        reference: None,
        golden: None,
        candidates: Vec::new(),
        hash: None,
    };
    let (hash, loaded) = load::load_hashed(file, limits);
    outcome.hash = hash;
    let scene = match loaded {
        Ok(scene) => scene,
        Err(load::LoadError::Unreadable(e)) => {
            outcome.problem = Some(Problem::Unreadable(e.to_string()));
            return outcome;
        }
        Err(load::LoadError::OverLimit(e)) => {
            outcome.problem = Some(Problem::LimitExceeded(e.to_string()));
            return outcome;
        }
    };
    // The case's plan, made once here and handed down the judging path.
    let plan = Plan::for_scene(&scene);
    let answers = candidates
        .iter()
        .map(|c| c.answer_bytes())
        .fold(0, u64::saturating_add);
    if let Some(over) = over_budget(&scene, &plan, limits, candidates.len(), answers) {
        outcome.problem = Some(Problem::LimitExceeded(format!(
            "{}: {over}",
            file.path.display()
        )));
        outcome.scene = Some(scene);
        return outcome;
    }
    let limit = limits.case_timeout;
    let reference = match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        deadline::within(limit, || oracle::run_reference_planned(&scene, plan))
    })) {
        Ok(Ok(reference)) => reference,
        Ok(Err(exceeded)) => {
            outcome.problem = Some(Problem::LimitExceeded(format!(
                "{}: the reference {exceeded}",
                file.path.display()
            )));
            outcome.scene = Some(scene);
            return outcome;
        }
        Err(panic) => {
            outcome.problem = Some(Problem::ReferenceFailed(panics::panic_message(&*panic)));
            outcome.scene = Some(scene);
            return outcome;
        }
    };
    let golden_root = discover::golden_root(&file.path, root);
    outcome.golden = Some(golden::check_golden(
        &golden_root,
        &file.id,
        &reference.frame,
    ));
    // A candidate over the time limit: the case is over a limit of the run
    // (exit 2), as when the reference is; the others keep their verdicts.
    let mut over = Vec::new();
    outcome.candidates = candidates
        .iter()
        .map(|c| {
            let (run, exceeded) = run_in_time(&scene, &reference, c.as_ref(), limit);
            if let Some(exceeded) = exceeded {
                over.push(format!("{}: {} {exceeded}", file.path.display(), c.name()));
            }
            run
        })
        .collect();
    if !over.is_empty() {
        outcome.problem = Some(Problem::LimitExceeded(over.join("; ")));
    }
    outcome.reference = Some(reference);
    outcome.scene = Some(scene);
    outcome
}

/// Why a case's frames would take more memory than `--max-case-memory`
/// allows, estimated from its scene before anything is allocated: the
/// reference's frame, a working copy of it (metrics, pictures and error
/// maps are computed from pairs of frames), one frame per candidate, and a
/// byte per pixel for the mesh interior. `plan` is the scene's.
pub fn over_memory(
    scene: &Scene,
    plan: &Plan,
    limits: &Limits,
    candidates: usize,
) -> Option<String> {
    over_budget(scene, plan, limits, candidates, 0)
}

/// [`over_memory`] for candidates that also hold up to `answers` bytes of
/// answers beside their frames (`Rasterizer::answer_bytes`: an external
/// program's answer line, read into its frame as it is parsed). The one
/// budget, `--max-case-memory`, covers both (SPEC.md §8); a request is
/// written as it is serialized, and adds a constant.
pub fn over_budget(
    scene: &Scene,
    plan: &Plan,
    limits: &Limits,
    candidates: usize,
    answers: u64,
) -> Option<String> {
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let frame = Frame::estimated_bytes(w, h, plan);
    let frames = 2 + candidates as u64;
    let need = frame
        .saturating_mul(frames)
        .saturating_add(u64::from(w) * u64::from(h))
        .saturating_add(answers);
    (need > limits.max_case_memory).then(|| {
        const MIB: u64 = 1 << 20;
        let (what, answered) = if answers > 0 {
            (
                "frames and answers",
                format!(
                    ", and up to {} MiB of answer lines, each held as text while it is read (an external program's output limit)",
                    answers.div_ceil(MIB)
                ),
            )
        } else {
            ("frames", String::new())
        };
        format!(
            "its {what} would take about {} MiB ({frames} frames of {} MiB: the reference's, a working copy and one per rasterizer{answered}), over the limit of {} MiB per case (raise it with --max-case-memory)",
            need.div_ceil(MIB),
            frame.div_ceil(MIB),
            limits.max_case_memory / MIB
        )
    })
}

/// What every case of a run is run with: its limits, the candidates, the
/// folder golden files are looked up from, the threads, and how many times
/// each candidate draws each case.
#[derive(Clone, Copy)]
pub struct RunSettings<'a> {
    /// The limits on each case (`--max-*`, `--case-timeout`).
    pub limits: &'a Limits,
    /// The rasterizers judged, in order.
    pub candidates: &'a [Box<dyn Rasterizer>],
    /// The folder golden files are looked up from
    /// ([`discover::golden_root`]).
    pub root: &'a Path,
    /// How many threads draw cases; all cores when `None`.
    pub threads: Option<usize>,
    /// How many times each candidate draws each case (`run --repeat N`;
    /// 1 for once). The reference draws it once. Above 1, the selection is
    /// taken in blocks of [`ROUND_CASES`]: every case of a block is run in
    /// full (reference, golden file, the candidates' first repetition),
    /// then the candidates draw the whole block again, in the same order,
    /// once per further repetition, so that a case's repetitions have the
    /// other cases of its block between them (a selection of one case has
    /// none). A candidate whose later frame differs from its first, in any
    /// channel, gets [`Verdict::Flaky`] with every repetition's outcome and
    /// the differences; one whose repetitions agree keeps its first
    /// verdict. Pictures, error maps and the page (`done`) are written from
    /// the first repetition's frames, once the case's last repetition is
    /// compared.
    pub repeat: usize,
}

/// Runs every case once on `threads` threads (all cores when `None`),
/// calling `done` with its index in `files` as each finishes, and keeps
/// the outcomes, in the order of `files` ([`run_streamed`] with
/// `repeat` 1).
pub fn run_all(
    files: &[CaseFile],
    limits: &Limits,
    candidates: &[Box<dyn Rasterizer>],
    root: &Path,
    threads: Option<usize>,
    done: &(dyn Fn(usize, &mut CaseOutcome) + Sync),
) -> Vec<CaseOutcome> {
    let settings = RunSettings {
        limits,
        candidates,
        root,
        threads,
        repeat: 1,
    };
    let mut outcomes = Vec::with_capacity(files.len());
    run_streamed(files, &settings, done, &mut |_, o| outcomes.push(o));
    outcomes
}

/// How many cases past the oldest one not yet handed over a worker may
/// start ([`run_streamed`]): the most outcomes held waiting for their turn,
/// whatever the number of cases (a case that hangs until its time limit
/// holds the others back once this many have finished after it).
pub const AHEAD: usize = 1024;

/// Runs every case under `settings`, calling `done` with its index in
/// `files` as each finishes, on the thread that ran it: it may write what
/// it needs of the frames (pictures, error maps). Then the case's frames
/// are released ([`CaseOutcome::release_frames`]) and the outcome is
/// handed to `emit`, in the order of `files`, on the calling thread, as
/// soon as it and every case before it have finished. Cases are started in
/// order and at most [`AHEAD`] cases past the oldest one not yet handed
/// over, so a run of any number of cases holds at most that many outcomes:
/// its memory does not grow with its number of cases.
///
/// Once a stop is requested (`crate::stop`: SIGINT or SIGTERM), no new case
/// starts, and a case that finishes after the request (its external
/// programs were killed under it) is [`CaseOutcome::interrupted`] too: every
/// verdict kept is one the case earned before the signal.
pub fn run_streamed<F: Cases + ?Sized>(
    files: &F,
    settings: &RunSettings,
    done: &(dyn Fn(usize, &mut CaseOutcome) + Sync),
    emit: &mut dyn FnMut(usize, CaseOutcome),
) {
    if settings.repeat > 1 {
        return repeated(files, settings, done, emit);
    }
    let RunSettings {
        limits,
        candidates,
        root,
        threads,
        ..
    } = *settings;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build();
    let workers = pool
        .as_ref()
        .map_or_else(
            |_| rayon::current_num_threads(),
            |p| p.current_num_threads(),
        )
        .max(1);
    let next = std::sync::atomic::AtomicUsize::new(0);
    // The index of the oldest case not yet handed over, and its signal.
    let handed = std::sync::Mutex::new(0usize);
    let turn = std::sync::Condvar::new();
    let (sender, receiver) = std::sync::mpsc::channel::<(usize, CaseOutcome)>();
    let work = |sender: std::sync::mpsc::Sender<(usize, CaseOutcome)>| loop {
        let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let Some(file) = files.case(k) else {
            return;
        };
        let file = &file;
        {
            let mut oldest = handed.lock().unwrap_or_else(|e| e.into_inner());
            while k >= *oldest + AHEAD {
                oldest = turn.wait(oldest).unwrap_or_else(|e| e.into_inner());
            }
        }
        let outcome = if crate::stop::requested().is_some() {
            CaseOutcome::interrupted(file)
        } else {
            let mut outcome = run_case(file, limits, candidates, root);
            if crate::stop::requested().is_some() {
                CaseOutcome::interrupted(file)
            } else {
                done(k, &mut outcome);
                outcome.release_frames();
                outcome
            }
        };
        if sender.send((k, outcome)).is_err() {
            return;
        }
    };
    std::thread::scope(|scope| {
        let work = &work;
        scope.spawn(move || match &pool {
            Ok(pool) => pool.scope(|s| {
                for _ in 0..workers {
                    let sender = sender.clone();
                    s.spawn(move |_| work(sender));
                }
            }),
            Err(_) => work(sender.clone()),
        });
        let mut waiting: std::collections::BTreeMap<usize, CaseOutcome> = Default::default();
        let mut oldest = 0;
        for (k, outcome) in receiver {
            waiting.insert(k, outcome);
            while let Some(outcome) = waiting.remove(&oldest) {
                emit(oldest, outcome);
                oldest += 1;
                *handed.lock().unwrap_or_else(|e| e.into_inner()) = oldest;
                turn.notify_all();
            }
        }
    });
}
/// How many cases a round of a repeated run holds (`run --repeat N`): each
/// case of a block of this many is drawn once by every candidate, then the
/// block again, N times over, so that other cases' draws come between a
/// case's repetitions, as in a run, while only one block's frames are kept.
pub const ROUND_CASES: usize = 32;

/// [`run_streamed`] of `repeat` > 1, block by block.
fn repeated<F: Cases + ?Sized>(
    files: &F,
    settings: &RunSettings,
    done: &(dyn Fn(usize, &mut CaseOutcome) + Sync),
    emit: &mut dyn FnMut(usize, CaseOutcome),
) {
    let RunSettings {
        limits,
        candidates,
        root,
        threads,
        repeat,
    } = *settings;
    let stopped = || crate::stop::requested().is_some();
    // Drawn on the pool, handed over on the calling thread, a block at a
    // time.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build();
    for block in 0..files.count().div_ceil(ROUND_CASES) {
        let chunk: Vec<CaseFile> = (block * ROUND_CASES
            ..files.count().min((block + 1) * ROUND_CASES))
            .filter_map(|k| files.case(k))
            .collect();
        let work = || {
            let mut firsts: Vec<CaseOutcome> = chunk
                .par_iter()
                .map(|file| {
                    if stopped() {
                        return CaseOutcome::interrupted(file);
                    }
                    run_case(file, limits, candidates, root)
                })
                .collect();
            // Each case's candidates: every repetition's outcome, and
            // where a later frame differed from the first.
            let mut kept: Vec<Vec<Repeated>> = firsts
                .iter()
                .map(|o| o.candidates.iter().map(Repeated::first).collect())
                .collect();
            for repetition in 2..=repeat {
                let again: Vec<Option<Vec<CandidateRun>>> = firsts
                    .par_iter()
                    .map(|o| (!stopped()).then(|| redraw(o, limits, candidates)))
                    .collect();
                for ((o, reps), runs) in firsts.iter().zip(&mut kept).zip(again) {
                    for ((first, rep), run) in
                        o.candidates.iter().zip(reps).zip(runs.unwrap_or_default())
                    {
                        rep.add(first, &run, repetition);
                    }
                }
            }
            let mut outcomes = Vec::with_capacity(firsts.len());
            for (k, (mut outcome, reps)) in firsts.drain(..).zip(kept).enumerate() {
                if stopped() {
                    outcomes.push(CaseOutcome::interrupted(&outcome.file));
                    continue;
                }
                for (run, rep) in outcome.candidates.iter_mut().zip(reps) {
                    if let Some(flaky) = rep.flaky() {
                        run.verdict = Verdict::Flaky(Box::new(flaky));
                    }
                }
                done(block * ROUND_CASES + k, &mut outcome);
                outcome.release_frames();
                outcomes.push(outcome);
            }
            outcomes
        };
        let outcomes = match &pool {
            Ok(pool) => pool.install(work),
            Err(_) => work(),
        };
        for (k, outcome) in outcomes.into_iter().enumerate() {
            emit(block * ROUND_CASES + k, outcome);
        }
    }
}

/// Every candidate draws a case it already drew once again, judged against
/// the same reference (none for a case that did not run).
fn redraw(
    outcome: &CaseOutcome,
    limits: &Limits,
    candidates: &[Box<dyn Rasterizer>],
) -> Vec<CandidateRun> {
    let (Some(scene), Some(reference), None) =
        (&outcome.scene, &outcome.reference, &outcome.problem)
    else {
        return Vec::new();
    };
    candidates
        .iter()
        .map(|c| run_in_time(scene, reference, c.as_ref(), limits.case_timeout).0)
        .collect()
}

/// One candidate's run of a case within the case's time limit. Past the
/// limit, a run without a frame whose verdict is the error, and how the
/// limit was exceeded.
fn run_in_time(
    scene: &Scene,
    reference: &ReferenceRun,
    candidate: &dyn Rasterizer,
    limit: Option<Duration>,
) -> (CandidateRun, Option<deadline::Exceeded>) {
    let started = std::time::Instant::now();
    match deadline::within(limit, || judge::run_candidate(scene, reference, candidate)) {
        Ok(run) => (run, None),
        Err(exceeded) => (
            CandidateRun::without_frame(
                candidate.name().to_owned(),
                Verdict::Error(exceeded.to_string()),
                started.elapsed(),
            ),
            Some(exceeded),
        ),
    }
}

/// One candidate's repetitions of one case, as they come in.
struct Repeated {
    outcomes: Vec<Repetition>,
    differences: Vec<flaky::Difference>,
}

impl Repeated {
    fn first(run: &CandidateRun) -> Repeated {
        Repeated {
            outcomes: vec![repetition(&run.verdict, 1)],
            differences: Vec::new(),
        }
    }

    /// A later repetition, compared with the first: its frame channel by
    /// channel, and its verdict (two runs without a frame differ only
    /// there).
    fn add(&mut self, first: &CandidateRun, later: &CandidateRun, k: usize) {
        let mut found = flaky::compare(first.frame.as_ref(), later.frame.as_ref(), k);
        if found.is_empty() && first.verdict != later.verdict {
            found.push(flaky::Difference {
                repetition: k,
                channel: "verdict".to_owned(),
                first: None,
                values: None,
                count: 0,
                of: 0,
            });
        }
        self.outcomes.push(repetition(&later.verdict, k));
        self.differences.extend(found);
    }

    fn flaky(self) -> Option<Flaky> {
        (!self.differences.is_empty()).then_some(Flaky {
            outcomes: self.outcomes,
            differences: self.differences,
        })
    }
}

/// A verdict as one repetition's outcome.
fn repetition(verdict: &Verdict, k: usize) -> Repetition {
    Repetition {
        repetition: k,
        verdict: verdict.label().to_owned(),
        reasons: match verdict {
            Verdict::Pass => Vec::new(),
            Verdict::Fail(reasons) => reasons.clone(),
            Verdict::Unsupported(why) | Verdict::Error(why) => vec![why.clone()],
            Verdict::Flaky(f) => vec![f.summary()],
        },
    }
}

/// Marks every case whose `name` an earlier case already uses as bad input:
/// names identify cases in reports and baselines, so they must be unique in
/// a run. Returns the indices of those marked.
pub fn reject_duplicate_names(outcomes: &mut [CaseOutcome]) -> Vec<usize> {
    let files: Vec<CaseFile> = outcomes.iter().map(|o| o.file.clone()).collect();
    let spelled: Vec<Option<String>> = outcomes
        .iter()
        .map(|o| o.scene.as_ref().map(|s| s.name.clone()))
        .collect();
    let mut names = UniqueNames::for_cases(outcomes.len());
    let mut marked = Vec::new();
    for (k, outcome) in outcomes.iter_mut().enumerate() {
        if reject_duplicate_name(outcome, k, &files[..], &mut names, &|j| spelled[j].clone()) {
            marked.push(k);
        }
    }
    marked
}

/// [`reject_duplicate_names`] one case at a time, in order: `outcome` is
/// case `k` of `files`, and `names` the names of the cases before it, by
/// hash; `name_of` reads the name of an earlier case again, when its hash
/// meets this one's ([`name_in_file`]). Returns whether the case was marked
/// as bad input.
pub fn reject_duplicate_name<F: Cases + ?Sized>(
    outcome: &mut CaseOutcome,
    k: usize,
    files: &F,
    names: &mut UniqueNames,
    name_of: &dyn Fn(usize) -> Option<String>,
) -> bool {
    let Some(name) = outcome.scene.as_ref().map(|s| &s.name) else {
        return false;
    };
    let Some(first) = names.used_before(name, k, name_of) else {
        return false;
    };
    let path = outcome.file.path.display().to_string();
    let first = files
        .case(first)
        .map_or_else(String::new, |f| f.path.display().to_string());
    outcome.problem = Some(Problem::Unreadable(format!(
        "{path}: $.name: the case name {} is also used by {first}; case names must be unique",
        crate::scene::number::echo(name)
    )));
    outcome.reference = None;
    outcome.golden = None;
    outcome.candidates.clear();
    true
}

/// The name of case `k` of `files`, read from its file again (`None` when
/// it no longer reads).
pub fn name_in_file<F: Cases + ?Sized>(files: &F, k: usize, limits: &Limits) -> Option<String> {
    let file = files.case(k)?;
    load::load_hashed(&file, limits)
        .1
        .ok()
        .map(|scene| scene.name)
}

/// Counts of verdicts for one rasterizer.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Tally {
    pub pass: usize,
    pub fail: usize,
    pub unsupported: usize,
    pub error: usize,
    /// Cases whose repetitions drew different frames (`run --repeat`): a
    /// failure, counted apart.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub flaky: usize,
    /// Departures of a foil (counted apart from failures).
    pub foil: usize,
    /// Of all these, the results judged under the rasterizer's own fill
    /// rule, clipping or subpixel bits instead of the case's
    /// ([`crate::Rasterizer::fixed_fill_rule`], a profile,
    /// [`crate::Rasterizer::fixed_subpixel_bits`]): conventions, named
    /// apart in every summary.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub own_rule: usize,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl Tally {
    pub fn add(&mut self, verdict: &Verdict, foil: bool) {
        match verdict {
            Verdict::Pass => self.pass += 1,
            Verdict::Fail(_) if foil => self.foil += 1,
            Verdict::Fail(_) => self.fail += 1,
            Verdict::Unsupported(_) => self.unsupported += 1,
            Verdict::Error(_) => self.error += 1,
            Verdict::Flaky(_) => self.flaky += 1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ids(names: &[&str]) -> Vec<CaseFile> {
        names
            .iter()
            .map(|n| CaseFile {
                id: (*n).to_owned(),
                path: format!("cases/{n}.json").into(),
            })
            .collect()
    }

    #[test]
    fn globs_match_within_and_across_segments() {
        assert!(glob_match("triangles/fan_*", "triangles/fan_16_center"));
        assert!(!glob_match("*fan*", "triangles/fan_16_center"));
        assert!(glob_match("**fan*", "triangles/fan_16_center"));
        assert!(glob_match("**/*tie*", "lines/midpoint_tie_slope_half"));
        assert!(glob_match("lines/?iamond_strip", "lines/diamond_strip"));
        assert!(!glob_match("lines/diamond", "lines/diamond_strip"));
    }

    #[test]
    fn shards_partition_the_selection() {
        let all = ids(&["a/1", "a/2", "a/3", "b/1", "b/2", "b/3", "b/4"]);
        for n in 1..=8 {
            let mut union: Vec<String> = (1..=n)
                .flat_map(|i| {
                    Selection {
                        shard: Some((i, n)),
                        ..Default::default()
                    }
                    .apply(all.clone())
                })
                .map(|c| c.id)
                .collect();
            union.sort();
            let mut expected: Vec<String> = all.iter().map(|c| c.id.clone()).collect();
            expected.sort();
            assert_eq!(union, expected, "{n} shards");
        }
        let family = Selection {
            family: Some("b".into()),
            ..Default::default()
        }
        .apply(all);
        assert_eq!(family.len(), 4);
    }

    #[test]
    fn shard_syntax_is_checked() {
        assert_eq!(Selection::parse_shard("2/4"), Ok((2, 4)));
        for bad in ["0/4", "5/4", "2", "a/b", "1/0"] {
            assert!(Selection::parse_shard(bad).is_err(), "{bad}");
        }
    }
}
