//! Judging a candidate on one scene as `run` does: the reference's run
//! (refusing "meshes" that overlap and scenes the exact N-sample method
//! fails), the [`Kind`]s of failure in the order they are shrunk for, and
//! the samples that show each (what the shrinker crops to). Whether a
//! failing moving scene is fair is `fair.rs`'s.

use std::borrow::Cow;
use std::time::Instant;

use dashu_ratio::RBig;

use super::case_json::valid;
use super::fair::fair_time;
use super::geometry::{orient, placed, Point};
use crate::frame::Frame;
use crate::harness::judge::Verdict;
use crate::harness::oracle::ReferenceRun;
use crate::harness::profile;
use crate::harness::{judge, oracle, panics};
use crate::metrics::{Metrics, SampleDiff};
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::reference;
use crate::reference::conservative::ConservativeClasses;
use crate::scene::{FillRule, LineRule, Primitive, Scene};

/// Which check a candidate fails, in the order a scene failing several is
/// shrunk for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    /// The rasterizer broke: an error or a panic.
    Error,
    /// Interior samples of a mesh left uncovered (SPEC.md §6.2).
    Holes,
    /// Samples of a mesh covered twice (SPEC.md §6.2).
    Overdraw,
    /// A midpoint line with two pixels in one major-axis step (§6.4).
    Lines,
    /// Coverage differs from the reference's (§6.1).
    Coverage,
    /// A conservative scene's required pixel missing, forbidden pixel
    /// drawn, or fully-covered flag the classes do not allow (§19).
    Conservative,
    /// Resolved coverage against the exact areas: piglit's rule, the
    /// coverage error bounds, a resolve that is not the box resolve of the
    /// candidate's own mask (§14.3).
    Antialias,
    /// Time coverage of a moving scene against the exact values: the RMS
    /// over moving pixels, the largest error, values that are not numbers
    /// (§15.4).
    Time,
    /// Depth or an attribute beyond its bound (§6.3).
    Interpolation,
}

impl Kind {
    pub const ALL: [Kind; 9] = [
        Kind::Error,
        Kind::Holes,
        Kind::Overdraw,
        Kind::Lines,
        Kind::Coverage,
        Kind::Conservative,
        Kind::Antialias,
        Kind::Time,
        Kind::Interpolation,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::Error => "error",
            Kind::Holes => "holes",
            Kind::Overdraw => "overdraw",
            Kind::Lines => "lines",
            Kind::Coverage => "coverage",
            Kind::Conservative => "conservative",
            Kind::Antialias => "antialias",
            Kind::Time => "time",
            Kind::Interpolation => "interpolation",
        }
    }

    /// What every correct rasterizer does on a case that fails this way.
    pub(super) fn promise(self) -> &'static str {
        match self {
            Kind::Error => "draws the scene without breaking",
            Kind::Holes | Kind::Overdraw => {
                "covers every interior sample of the mesh exactly once and no sample twice"
            }
            Kind::Lines => "lights one pixel of a midpoint line per major-axis step",
            Kind::Coverage => "covers exactly the reference's samples, with the same owners",
            Kind::Conservative => {
                "draws every required pixel and no forbidden one, each fully-covered flag as the classes allow"
            }
            Kind::Antialias => {
                "resolves full pixels to exactly 1, empty ones to 0, within the coverage bounds"
            }
            Kind::Time => {
                "estimates each pixel's time coverage within the time-coverage bounds, as the sample method with the case's own instants does"
            }
            Kind::Interpolation => "interpolates depth and attributes within the bound",
        }
    }
}

/// The kinds a `--check` names: a kind, or `watertight` (holes or overdraw).
pub fn kinds_named(name: &str) -> Option<Vec<Kind>> {
    if name == "watertight" {
        return Some(vec![Kind::Holes, Kind::Overdraw]);
    }
    Kind::ALL
        .into_iter()
        .find(|k| k.name() == name)
        .map(|k| vec![k])
}

/// How a candidate fails a scene.
#[derive(Clone, Debug)]
pub struct Failure {
    /// Every check it fails, in [`Kind`] order.
    pub kinds: Vec<Kind>,
    /// The reasons `run` prints ([`crate::metrics::failures`]), or the error.
    pub reasons: Vec<String>,
    /// Per kind, the samples (sample `s` of pixel `p` at `p * N + s`, N the
    /// scene's samples per pixel) that show it.
    focus: Vec<(Kind, Vec<usize>)>,
}

impl Failure {
    /// The reasons that belong to `kind`.
    pub fn reasons_for(&self, kind: Kind) -> Vec<String> {
        let prefix: &[&str] = match kind {
            Kind::Error => &[],
            Kind::Holes | Kind::Overdraw => &["watertight:"],
            Kind::Lines => &["lines:"],
            Kind::Coverage => &["coverage:"],
            Kind::Conservative => &["conservative"],
            Kind::Antialias => &["antialias:"],
            Kind::Time => &["time:"],
            Kind::Interpolation => &["depth:", "attribute "],
        };
        let found: Vec<String> = self
            .reasons
            .iter()
            .filter(|r| prefix.is_empty() || prefix.iter().any(|p| r.starts_with(p)))
            .cloned()
            .collect();
        if found.is_empty() {
            self.reasons.clone()
        } else {
            found
        }
    }

    pub(super) fn focus(&self, kind: Kind) -> &[usize] {
        self.focus
            .iter()
            .find(|(k, _)| *k == kind)
            .map_or(&[], |(_, f)| f.as_slice())
    }
}

/// A candidate's result on one scene.
#[derive(Clone, Debug)]
pub enum Outcome {
    Pass,
    Unsupported(String),
    /// The scene is not a case worth keeping: outside the limits, or a
    /// "mesh" whose triangles overlap or have no area.
    Invalid(String),
    /// rastercheck itself broke on the scene: the reference panicked. A bug
    /// to report, not a verdict on the candidate.
    Broken(String),
    Fail(Failure),
}

/// The scene as `candidate` is judged on it: stated under the fill rule
/// (and, in clip space, the clip conventions; and at its subpixel bits
/// where the scene states more or none) it follows whatever a case
/// states, when it has them (SPEC.md §3.1, §3.2, §16; a profile's under `fuzz
/// --profile`), so that the reference, the failure's kinds and the case
/// written all state the conventions judged. `Err` when the scene cannot
/// be judged under that rule (all-edges polygons).
pub fn as_judged<'a>(
    scene: &'a Scene,
    candidate: &dyn Rasterizer,
) -> Result<Cow<'a, Scene>, String> {
    let own = profile::OwnConventions::of(candidate, scene);
    if !own.any() {
        return Ok(Cow::Borrowed(scene));
    }
    match own.cannot_judge(scene) {
        Some(why) => Err(why),
        None => Ok(Cow::Owned(own.restate(scene))),
    }
}

/// Runs the reference and `candidate` on `scene` and judges the candidate
/// as `run` does.
pub fn evaluate(scene: &Scene, candidate: &dyn Rasterizer) -> Outcome {
    let scene = &*match as_judged(scene, candidate) {
        Ok(scene) => scene,
        Err(why) => return Outcome::Unsupported(why),
    };
    if let Err(why) = valid(scene) {
        return Outcome::Invalid(why);
    }
    let reference = std::panic::catch_unwind(|| reference_run(scene));
    let reference = match reference {
        Ok(Ok(r)) => r,
        Ok(Err(why)) => return Outcome::Invalid(why),
        Err(panic) => {
            return Outcome::Broken(format!(
                "the reference panicked: {}",
                panics::panic_message(&*panic)
            ))
        }
    };
    // The exact N-sample method (the reference's mask, box-resolved) must
    // meet the case's coverage bounds: with few samples no sampler meets
    // piglit's RMS bound on some scenes, and such a scene says nothing
    // about the candidate. (A moving scene is judged on time coverage
    // only; its fairness is checked below, when a candidate fails it.)
    if scene.effects.antialias.is_some() && reference.time.is_none() {
        let mut exact = reference.frame.clone();
        exact.resolve();
        let m = crate::metrics::measure_with_areas(
            scene,
            &reference.frame,
            &exact,
            reference.interior.as_deref(),
            reference
                .areas
                .as_ref()
                .and_then(|a| a.as_ref().ok())
                .map(|a| a.classes.as_slice()),
        );
        if let Some(aa) = &m.antialias {
            let broken = crate::metrics::antialias::failures(aa);
            if !broken.is_empty() {
                return Outcome::Invalid(format!(
                    "the exact {}-sample method breaks the coverage bounds: {}",
                    scene.effects.antialias.as_ref().map_or(1, |a| a.samples),
                    broken.join("; ")
                ));
            }
        }
    }
    let run = judge::run_candidate(scene, &reference, candidate);
    if let (Some(Ok(classes)), Verdict::Fail(reasons), Some(frame)) =
        (&reference.conservative, &run.verdict, &run.frame)
    {
        return Outcome::Fail(Failure {
            kinds: vec![Kind::Conservative],
            reasons: reasons.clone(),
            focus: vec![(Kind::Conservative, conservative_focus(classes, frame))],
        });
    }
    match (run.verdict, run.metrics, run.frame) {
        (Verdict::Pass, ..) => Outcome::Pass,
        (Verdict::Unsupported(why), ..) => Outcome::Unsupported(why),
        (Verdict::Error(why), ..) => Outcome::Fail(Failure {
            kinds: vec![Kind::Error],
            reasons: vec![why],
            focus: Vec::new(),
        }),
        (Verdict::Fail(reasons), Some(m), Some(frame)) => {
            let failure = classify(scene, &reference, &frame, &m, reasons);
            let broken_values = m.time.as_ref().is_some_and(|t| t.invalid_values > 0);
            if failure.kinds.contains(&Kind::Time) && !broken_values {
                if let Err(why) = fair_time(scene, &reference) {
                    return Outcome::Invalid(why);
                }
            }
            Outcome::Fail(failure)
        }
        // One draw per scene here: never flaky, but a failure if it were.
        (Verdict::Flaky(flaky), ..) => Outcome::Fail(Failure {
            kinds: vec![Kind::Error],
            reasons: vec![format!("flaky: {}", flaky.summary())],
            focus: Vec::new(),
        }),
        (Verdict::Fail(reasons), ..) => Outcome::Fail(Failure {
            kinds: vec![Kind::Error],
            reasons,
            focus: Vec::new(),
        }),
    }
}

/// The reference's frame, and the mesh interior for a mesh case (refused
/// when the scene is no longer a mesh); for a scene in which something
/// moves, the certified time coverage as `run` computes it (refused when
/// the oracle fails or breaks a pin of the case).
fn reference_run(scene: &Scene) -> Result<ReferenceRun, String> {
    let started = Instant::now();
    let plan = Plan::for_scene(scene);
    if plan.motion.is_some() {
        let run = oracle::run_reference(scene);
        match &run.time {
            Some(Err(why)) => return Err(why.clone()),
            Some(Ok(check)) if !check.broken_promises.is_empty() => {
                return Err(check.broken_promises.join("; "))
            }
            _ => return Ok(run),
        }
    }
    if scene.is_conservative() {
        let run = oracle::run_reference(scene);
        return match &run.conservative {
            Some(Err(why)) => Err(why.to_string()),
            _ => Ok(run),
        };
    }
    let frame = reference::render(scene, &plan);
    let interior = if scene.expect.watertight {
        mesh_geometry(scene)?;
        let mut interior = vec![true; scene.canvas.pixel_count()];
        for rule in FillRule::CONSISTENT {
            let counts = reference::coverage_under(scene, &plan, rule);
            if counts.iter().any(|&c| c > 1) {
                return Err(format!("mesh triangles overlap under {rule}"));
            }
            for (inside, count) in interior.iter_mut().zip(counts) {
                *inside &= count > 0;
            }
        }
        Some(interior)
    } else {
        None
    };
    let areas = oracle::area_check(scene);
    Ok(ReferenceRun {
        plan,
        frame,
        interior,
        areas,
        time: None,
        // Fuzzed scenes state no depth format.
        depth_allowed: None,
        conservative: None,
        elapsed: started.elapsed(),
    })
}

/// Refuses a "mesh" with a zero-area triangle or two triangles whose
/// interiors overlap (after snapping, exactly): such a scene no longer says
/// what a watertight rasterizer must do.
fn mesh_geometry(scene: &Scene) -> Result<(), String> {
    let bits = scene.rules.subpixel_bits;
    let triangles: Vec<[Point; 3]> = scene
        .triangles()
        .map(|(_, t)| {
            t.vertices
                .each_ref()
                .map(|v| [placed(&v.x, bits), placed(&v.y, bits)])
        })
        .collect();
    if triangles
        .iter()
        .any(|p| orient(&p[0], &p[1], &p[2]).is_eq())
    {
        return Err("a mesh triangle has no area".to_owned());
    }
    // Bounding boxes in f64, widened so that rounding can only make two
    // boxes meet that do not: a sweep over x finds the pairs to test.
    let boxes: Vec<[f64; 4]> = triangles
        .iter()
        .map(|t| {
            let xs = t.each_ref().map(|p| p[0].to_f64().value());
            let ys = t.each_ref().map(|p| p[1].to_f64().value());
            let lo = |v: [f64; 3]| v.into_iter().fold(f64::INFINITY, f64::min);
            let hi = |v: [f64; 3]| v.into_iter().fold(f64::NEG_INFINITY, f64::max);
            let pad = |v: f64| v.abs() * 1e-12 + 1e-12;
            let (x0, x1, y0, y1) = (lo(xs), hi(xs), lo(ys), hi(ys));
            [x0 - pad(x0), x1 + pad(x1), y0 - pad(y0), y1 + pad(y1)]
        })
        .collect();
    let mut order: Vec<usize> = (0..triangles.len()).collect();
    order.sort_by(|&a, &b| boxes[a][0].total_cmp(&boxes[b][0]));
    for (k, &a) in order.iter().enumerate() {
        for &b in &order[k + 1..] {
            if boxes[b][0] >= boxes[a][1] {
                break;
            }
            if boxes[b][2] >= boxes[a][3] || boxes[a][2] >= boxes[b][3] {
                continue;
            }
            if !separated(&triangles[a], &triangles[b]) {
                return Err("mesh triangles overlap".to_owned());
            }
        }
    }
    Ok(())
}

/// Whether two triangles' interiors are disjoint: some edge line of one
/// has the other on its far side, touching allowed (the separating axis
/// theorem; for convex polygons an edge normal always serves).
fn separated(t: &[Point; 3], u: &[Point; 3]) -> bool {
    let axes = (0..3)
        .map(|k| (&t[k], &t[(k + 1) % 3]))
        .chain((0..3).map(|k| (&u[k], &u[(k + 1) % 3])));
    for (a, b) in axes {
        let n = [&a[1] - &b[1], &b[0] - &a[0]];
        let project = |p: &Point| &n[0] * &p[0] + &n[1] * &p[1];
        let pt = t.each_ref().map(project);
        let pu = u.each_ref().map(project);
        let (t_lo, t_hi) = (pt.iter().min().unwrap(), pt.iter().max().unwrap());
        let (u_lo, u_hi) = (pu.iter().min().unwrap(), pu.iter().max().unwrap());
        if t_hi <= u_lo || u_hi <= t_lo {
            return true;
        }
    }
    false
}

fn classify(
    scene: &Scene,
    reference: &ReferenceRun,
    candidate: &Frame,
    m: &Metrics,
    reasons: Vec<String>,
) -> Failure {
    let r = &reference.frame;
    let n = r.sample_count();
    let mut focus: Vec<(Kind, Vec<usize>)> = Vec::new();
    if let (Some(w), Some(interior)) = (&m.watertight, &reference.interior) {
        if w.holes > 0 {
            let holes = (0..n)
                .filter(|&i| interior[i] && candidate.coverage[i] == 0)
                .collect();
            focus.push((Kind::Holes, holes));
        }
        if w.overdraw > 0 {
            let over = (0..n)
                .filter(|&i| candidate.coverage[i] > 1 && r.coverage[i] <= 1)
                .collect();
            focus.push((Kind::Overdraw, over));
        }
    }
    if m.lines.as_ref().is_some_and(|l| l.crowded_steps > 0) {
        focus.push((Kind::Lines, crowded_pixels(scene, candidate)));
    }
    let c = &m.coverage;
    if c.mismatched() > scene.expect.max_mismatched_samples
        || (c.reference_covered > 0 && c.candidate_covered == 0)
    {
        let differ = (0..n)
            .filter(|&i| !matches!(c.mask[i], SampleDiff::Same | SampleDiff::Tie))
            .collect();
        focus.push((Kind::Coverage, differ));
    }
    if let Some(aa) = &m.antialias {
        if !crate::metrics::antialias::failures(aa).is_empty() {
            let per_pixel = r.samples.max(1) as usize;
            let w = r.width as usize;
            let pixels: Vec<usize> = aa
                .first_violation
                .into_iter()
                .chain([aa.worst_pixel])
                .map(|[x, y]| (y as usize * w + x as usize) * per_pixel)
                .collect();
            focus.push((Kind::Antialias, pixels));
        }
    }
    if let Some(t) = &m.time {
        if !crate::metrics::time::failures(t).is_empty() {
            focus.push((Kind::Time, time_focus(scene, r, candidate, t)));
        }
    }
    if m.channels.iter().any(|ch| !ch.within_bounds()) {
        let mut pixels = Vec::new();
        let exact = r.depth.iter().chain(&r.attributes);
        let values = candidate.depth.iter().chain(&candidate.attributes);
        for ((exact, values), ch) in exact.zip(values).zip(&m.channels) {
            if ch.within_bounds() {
                continue;
            }
            for i in 0..n {
                let compared = r.last[i] != 0 && r.last[i] == candidate.last[i];
                let error = (values[i] - exact[i]).abs();
                if compared && (error.is_nan() || error > ch.allowed_abs) {
                    pixels.push(i);
                }
            }
        }
        pixels.sort_unstable();
        pixels.dedup();
        focus.push((Kind::Interpolation, pixels));
    }
    focus.sort_by_key(|(k, _)| *k);
    Failure {
        kinds: focus.iter().map(|(k, _)| *k).collect(),
        reasons,
        focus,
    }
}

/// The pixels whose time coverage is off by more than a bound allows
/// (more than the RMS bound, or than the largest error allowed), the
/// worst first; the worst pixel alone when no single one is. Each as its
/// first sample slot (p · M for M spatial samples), as the shrinker crops.
fn time_focus(
    scene: &Scene,
    reference: &Frame,
    candidate: &Frame,
    t: &crate::metrics::TimeMetrics,
) -> Vec<usize> {
    // A value that is not a number has an infinite error here.
    let errors = crate::metrics::time::signed_errors(reference, candidate);
    let allowed = [t.allowed_rms, t.allowed_error]
        .into_iter()
        .flatten()
        .fold(f64::INFINITY, f64::min);
    let mut pixels: Vec<usize> = (0..errors.len())
        .filter(|&p| errors[p].abs() > allowed)
        .collect();
    // Largest error first; equal ones in pixel order.
    pixels.sort_by(|&a, &b| errors[b].abs().total_cmp(&errors[a].abs()).then(a.cmp(&b)));
    if pixels.is_empty() {
        let [x, y] = t.worst_pixel;
        pixels.push((y * reference.width + x) as usize);
    }
    let per_pixel = samples_per_pixel(scene);
    pixels.into_iter().map(|p| p * per_pixel).collect()
}

/// The pixels of a conservative frame its classes do not admit: a
/// required one missing, a forbidden one drawn, or a flag not allowed.
fn conservative_focus(classes: &ConservativeClasses, candidate: &Frame) -> Vec<usize> {
    (0..classes.drawn.len())
        .filter(|&i| {
            let Some(drawn) = crate::metrics::conservative::pixel_drawn(candidate, i) else {
                return true; // partly covered (SPEC.md §19.10)
            };
            let flag = candidate
                .fully_covered
                .as_ref()
                .is_some_and(|f| f.get(i).copied().unwrap_or(false));
            !classes.drawn[i].admits(drawn)
                || classes
                    .fully_covered
                    .as_ref()
                    .is_some_and(|f| drawn && !f[i].admits(flag))
        })
        .collect()
}

/// Pixels of midpoint lines in steps where the line has more than one.
fn crowded_pixels(scene: &Scene, candidate: &Frame) -> Vec<usize> {
    let (w, h) = (candidate.width as usize, candidate.height as usize);
    let mut out = Vec::new();
    for (index, primitive) in scene.primitives.iter().enumerate() {
        let Primitive::Line(line) = primitive else {
            continue;
        };
        if line.rule != LineRule::Midpoint {
            continue;
        }
        let bits = scene.rules.subpixel_bits;
        let [a, b] = &line.vertices;
        let dx = placed(&b.x, bits) - placed(&a.x, bits);
        let dy = placed(&b.y, bits) - placed(&a.y, bits);
        let abs = |r: RBig| if r < RBig::ZERO { -r } else { r };
        let x_major = abs(dx) >= abs(dy);
        let id = index as u32 + 1;
        let (steps, across) = if x_major { (w, h) } else { (h, w) };
        for step in 0..steps {
            let drawn: Vec<usize> = (0..across)
                .map(|k| if x_major { k * w + step } else { step * w + k })
                .filter(|&i| candidate.last[i] == id)
                .collect();
            if drawn.len() > 1 {
                out.extend(drawn);
            }
        }
    }
    out.sort_unstable();
    out
}

/// Sample slots per pixel of a scene's frames.
pub(super) fn samples_per_pixel(scene: &Scene) -> usize {
    scene
        .effects
        .antialias
        .as_ref()
        .map_or(1, |a| a.samples.max(1) as usize)
}
