//! One candidate on one case: its frame judged against the reference's
//! answer (under the conventions it declares it follows), as a [`Verdict`]
//! with metrics, and a one-line summary of them.

use std::time::{Duration, Instant};

use super::flaky::Flaky;
use super::oracle::{catch_oracle_run, primitive_areas, run_reference_planned, ReferenceRun};
use super::panics::pass_on_deadline;
use super::profile::OwnConventions;
use crate::frame::Frame;
use crate::metrics::{self, Metrics};
use crate::rasterizer::{RasterError, Rasterizer, Snapping};
use crate::reference::conservative::ConservativeClasses;
use crate::reference::{self, DiamondLine, TieSet};
use crate::scene::{Conservative, LineRule, Primitive, Scene};

/// How a candidate did on a case.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    Pass,
    Fail(Vec<String>),
    Unsupported(String),
    /// The rasterizer broke (crashed, or returned an error).
    Error(String),
    /// Its repetitions of the case (`run --repeat N`) drew different
    /// frames: a failure, whatever each repetition's verdict was.
    Flaky(Box<Flaky>),
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
            Verdict::Flaky(_) => "flaky",
        }
    }

    pub fn label(&self) -> &'static str {
        match self {
            Verdict::Pass => "PASS",
            Verdict::Fail(_) => "FAIL",
            Verdict::Unsupported(_) => "UNSUPPORTED",
            Verdict::Error(_) => "ERROR",
            Verdict::Flaky(_) => "FLAKY",
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
    /// The conventions of its own it was judged under where they are not
    /// the case's: a fill rule ([`Rasterizer::fixed_fill_rule`]), clip
    /// conventions ([`Rasterizer::fixed_clip_rules`]), subpixel bits
    /// ([`Rasterizer::fixed_subpixel_bits`], SPEC.md §3.2); none when it
    /// was judged as the case states.
    pub judged: OwnConventions,
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
            judged: OwnConventions::default(),
        }
    }
}

pub fn run_candidate(
    scene: &Scene,
    reference: &ReferenceRun,
    candidate: &dyn Rasterizer,
) -> CandidateRun {
    let started = Instant::now();
    let refused = candidate
        .capabilities()
        .refuses(scene)
        .or_else(|| super::conservative::refusal(scene, candidate));
    if let Some(why) = refused {
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
    // space, its clip conventions; its snapping, sample positions, y
    // direction or pixel centre) is judged under the ones it follows,
    // against the reference drawn under them.
    let own = OwnConventions::of(candidate, scene).with_viewport(candidate, scene, &reference.plan);
    if own.any() || own.no_tie_rule || own.line_latitude || own.rectangle_border_ties {
        if let Some(why) = own.cannot_judge(scene) {
            return CandidateRun::without_frame(name, Verdict::Unsupported(why), elapsed);
        }
        let under = own.restate(scene);
        // Restating changes rules only, and what the plan reads only when
        // it moves the samples (another pattern) or may stop a vertex
        // (truncation): then the restated case is planned anew.
        let plan = if own.sample_pattern.is_some() || own.snapping == Some(Snapping::Truncate) {
            crate::plan::Plan::for_scene(&under)
        } else {
            reference.plan.clone()
        };
        // With no tie rule the oracle also gives its tie set (SPEC.md
        // §3.1.1); its failure is the reference's, as below.
        // With no tie rule on rectangle lines' borders (§4.3.1), only the
        // ties every primitive holding them on an edge is such a line's.
        let ties = match (own.no_tie_rule || own.rectangle_border_ties) && plan.motion.is_none() {
            true => Some(
                std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    let set = reference::tie_set(&under, &plan);
                    match own.no_tie_rule {
                        true => set,
                        false => set.only_on(|primitive| {
                            matches!(
                                under.primitives.get(primitive),
                                Some(Primitive::Line(l)) if l.rule == LineRule::Rectangle
                            )
                        }),
                    }
                }))
                .map_err(|panic| pass_on_deadline(panic, "panicked")),
            ),
            false => None,
        };
        // Under the latitude for diamond-exit lines (SPEC.md §4.2.1) the
        // oracle also gives each line's own fragments, drawn as restated.
        let lines = match own.line_latitude {
            true => std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                reference::diamond_lines(&under, &plan)
            }))
            .map_err(|panic| pass_on_deadline(panic, "panicked")),
            false => Ok(None),
        };
        // A case clipped at a viewport: its pieces' values are the whole
        // triangles' (SPEC.md §16.9).
        let whole = own.whole_values(scene);
        let restated = match own.any() {
            true => Some(catch_oracle_run(|| {
                let mut run = run_reference_planned(&under, plan.clone());
                if let Some((whole, pieces)) = &whole {
                    let allowed = run.depth_allowed.as_mut();
                    reference::take_whole_values(&mut run.frame, allowed, whole, pieces, &plan);
                }
                run
            })),
            false => None,
        };
        let magnitudes = whole.as_ref().map(|(whole, _)| whole);
        let mut run = match (restated, ties.transpose(), lines) {
            (Some(Err(why)), _, _) | (_, Err(why), _) | (_, _, Err(why)) => {
                let why = format!(
                    "the reference under {} it follows failed: {why}",
                    own.describe()
                );
                CandidateRun::without_frame(name, Verdict::Error(why), elapsed)
            }
            (Some(Ok(restated)), Ok(ties), Ok(lines)) => {
                let under = bounds_met_by(under, &restated);
                let oracle = Oracle {
                    ties: ties.as_ref(),
                    lines: lines.as_deref(),
                    conservative: super::conservative::judged_under(&under, candidate),
                    magnitudes,
                };
                judge(&under, &restated, frame, name, elapsed, oracle)
            }
            (None, Ok(ties), Ok(lines)) => {
                let oracle = Oracle {
                    ties: ties.as_ref(),
                    lines: lines.as_deref(),
                    conservative: super::conservative::judged_under(&under, candidate),
                    magnitudes: None,
                };
                judge(&under, reference, frame, name, elapsed, oracle)
            }
        };
        run.judged = own;
        return run;
    }
    let oracle = Oracle {
        conservative: super::conservative::judged_under(scene, candidate),
        ..Oracle::default()
    };
    judge(scene, reference, frame, name, elapsed, oracle)
}

/// What the oracle gives beyond its frame for a candidate judged under a
/// convention that restates nothing: its tie set (no tie rule, SPEC.md
/// §3.1.1) and each diamond-exit line's fragments (the latitude, §4.2.1).
#[derive(Clone, Default)]
struct Oracle<'a> {
    ties: Option<&'a TieSet>,
    lines: Option<&'a [DiamondLine]>,
    /// A conservative case: the state the candidate is judged under (the
    /// case's, restated under what it declares, SPEC.md §19.6).
    conservative: Option<Conservative>,
    /// The scene whose vertices give SPEC.md §6.3's magnitudes where the
    /// judged one's do not: a case restated clipped at a viewport, whose
    /// pieces carry no values, has them from its whole triangles (§16.9).
    magnitudes: Option<&'a Scene>,
}

/// The restated case with its antialiasing bounds (`max_coverage_error`,
/// `max_coverage_rms`, SPEC.md §14.3) raised to what the reference's own
/// exact mask under the restated conventions achieves (box-resolved), where
/// that mask breaks them: bounds written for the case's precision or sample
/// positions (an edge's RMS over 4-bit snapped vertices is not its RMS over
/// 8-bit ones) must not fail a rasterizer for its convention (SPEC.md
/// §3.2). Nothing is loosened for a candidate: its mask is still held to
/// the exact mask sample by sample, and a bound the exact mask meets is
/// kept as written.
fn bounds_met_by(mut under: Scene, reference: &ReferenceRun) -> Scene {
    let Some(Ok(areas)) = &reference.areas else {
        return under;
    };
    if reference.frame.samples == 0 || reference.time.is_some() {
        return under;
    }
    let known = metrics::Known {
        interior: reference.interior.as_deref(),
        classes: Some(areas.classes.as_slice()),
        whole_time: None,
        part_areas: None,
        depth_allowed: reference.depth_allowed.as_deref(),
        ties: None,
        latitude: None,
        magnitudes: None,
    };
    // The exact mask, box-resolved: what a rasterizer exact at these
    // conventions resolves (the reference's own resolved value is the
    // exact area, which meets every bound).
    let n = reference.frame.samples as usize;
    let mut boxed = reference.frame.clone();
    boxed.resolved = Some(
        boxed
            .coverage
            .chunks(n)
            .map(|slots| slots.iter().map(|&c| f64::from(c)).sum::<f64>() / n as f64)
            .collect(),
    );
    let own = metrics::measure_known(&under, &reference.frame, &boxed, &known);
    let Some(aa) = own.antialias else {
        return under;
    };
    let (error, rms) = metrics::antialias::bounds(
        under.expect.max_coverage_error,
        under.expect.max_coverage_rms,
        reference.frame.samples,
        false,
    );
    if error.is_some_and(|bound| aa.max_error > bound) {
        under.expect.max_coverage_error = Some(aa.max_error);
    }
    if rms.is_some_and(|bound| aa.rms_edge > bound) {
        under.expect.max_coverage_rms = Some(aa.rms_edge);
    }
    under
}

/// Judges a candidate's frame against the reference's answer.
fn judge(
    scene: &Scene,
    reference: &ReferenceRun,
    frame: Frame,
    name: String,
    elapsed: Duration,
    oracle: Oracle,
) -> CandidateRun {
    let ties = oracle.ties;
    if let Some(classes) = &reference.conservative {
        return judge_conservative(
            scene,
            classes,
            oracle.conservative.as_ref(),
            frame,
            name,
            elapsed,
        );
    }
    if let Some(why) = shape_problem(&reference.frame, &frame) {
        let why = format!("returned a frame of the wrong size or with the wrong channels: {why}");
        return CandidateRun {
            rasterizer: name,
            verdict: Verdict::Error(why),
            metrics: None,
            method: frame.method,
            frame: Some(frame),
            elapsed,
            judged: OwnConventions::default(),
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
        ties,
        latitude: oracle.lines,
        magnitudes: oracle.magnitudes,
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
    // Where it differs at samples exactly on an edge, the ties are named.
    if !failures.is_empty() && m.coverage.mismatched() > 0 && ties.is_none() && time.is_none() {
        let set = reference::tie_set(scene, &reference.plan);
        let mask = &m.coverage.mask;
        let differs = |i: usize| mask[i] != metrics::SampleDiff::Same;
        failures.extend(metrics::ties::named(&set, mask.len(), differs));
    }
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
        judged: OwnConventions::default(),
    }
}

/// A conservative candidate's frame judged against the oracle's classes
/// (SPEC.md §19.5): against `classes`, the reference's for the case, or,
/// where the candidate declares an uncertainty or properties of its own
/// (`under` differs from the case's in what the scene has), against the
/// classes under those, reported as such.
fn judge_conservative(
    scene: &Scene,
    classes: &Result<ConservativeClasses, RasterError>,
    under: Option<&Conservative>,
    frame: Frame,
    name: String,
    elapsed: Duration,
) -> CandidateRun {
    let run = |verdict: Verdict, metrics: Option<Metrics>, frame: Frame| CandidateRun {
        rasterizer: name.clone(),
        verdict,
        metrics,
        method: frame.method,
        frame: Some(frame),
        elapsed,
        judged: OwnConventions::default(),
    };
    let classes = match classes {
        Err(RasterError::Unsupported(why)) => {
            return run(Verdict::Unsupported(why.clone()), None, frame)
        }
        Err(RasterError::Failed(why)) => return run(Verdict::Error(why.clone()), None, frame),
        Ok(classes) => classes,
    };
    let case = scene
        .effects
        .conservative
        .as_ref()
        .expect("a conservative scene");
    // The case's promises hold of the case's classes, whatever the
    // candidate is judged under.
    let promises = super::conservative::broken_promises(scene, classes);
    // Classified again only where the candidate's state differs from the
    // case's in what the scene has (the test the words below use too).
    let judged = under.unwrap_or(case);
    let own;
    let classes = if judged.restates(case, scene.has_points_or_lines()) {
        own = reference::conservative::classify_under(scene, judged);
        &own
    } else {
        classes
    };
    let samples = scene.effects.antialias.as_ref().map_or(1, |aa| aa.samples);
    if let Some(why) = metrics::conservative::shape_problem(classes, &frame, samples) {
        let why = format!("returned a frame of the wrong size or with the wrong channels: {why}");
        return run(Verdict::Error(why), None, frame);
    }
    let restated = judged.restated_words(case, scene.has_points_or_lines());
    let words = match &restated {
        Some((own, stated)) => format!("{own}, its own conventions; the case states {stated}"),
        None => judged.words(),
    };
    let mut m = metrics::conservative::measure(classes, &frame, words);
    m.case_states = restated.map(|(_, stated)| stated);
    let mut failures = metrics::conservative::failures(&m);
    match super::conservative_depth::judged(scene, judged, &frame) {
        Some(Ok(depth)) => {
            failures.extend(metrics::conservative_depth::failures(&depth));
            m.depth = Some(depth);
        }
        Some(Err(why)) => failures.push(why),
        None => {}
    }
    failures.extend(promises);
    let coverage = metrics::conservative::coverage(&m, &frame);
    let metrics = Metrics {
        coverage,
        watertight: None,
        lines: None,
        channels: Vec::new(),
        antialias: None,
        time: None,
        ties: None,
        latitude: None,
        conservative: Some(m),
    };
    let verdict = if failures.is_empty() {
        Verdict::Pass
    } else {
        Verdict::Fail(failures)
    };
    run(verdict, Some(metrics), frame)
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

/// A one-line summary of a candidate's metrics.
pub fn describe(run: &CandidateRun) -> String {
    let Some(m) = &run.metrics else {
        return match &run.verdict {
            Verdict::Unsupported(why) | Verdict::Error(why) => why.clone(),
            Verdict::Flaky(flaky) => flaky.summary(),
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
