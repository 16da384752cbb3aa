//! A conservative case's candidate (SPEC.md §19): refused unsent when it
//! draws no such case (or not this mode, or not the flag asked for), and
//! otherwise judged pixel by pixel against the reference's three classes.

use std::time::Duration;

use super::judge::{CandidateRun, Verdict};
use super::profile::OwnConventions;
use crate::frame::Frame;
use crate::metrics::{self, Metrics};
use crate::rasterizer::{RasterError, Rasterizer};
use crate::reference::{self, conservative::ConservativeClasses, conservative::PixelClass};
use crate::scene::{Conservative, Scene};

/// Why `candidate` is not asked to draw conservative `scene`, if it is
/// not: this version does not judge the scene (`Scene::conservative_unjudged`),
/// or the candidate declares no conservative rasterization, or not this
/// mode or flag. `None` for a scene that is not conservative.
pub fn refusal(scene: &Scene, candidate: &dyn Rasterizer) -> Option<String> {
    let case = scene.effects.conservative.as_ref()?;
    if let Some(why) = scene.conservative_unjudged() {
        return Some(why);
    }
    match candidate.conservative() {
        None => Some(
            "this rasterizer does not draw conservative rasterization (SPEC.md §19)".to_owned(),
        ),
        Some(support) => support.refuses(case),
    }
}

/// The oracle's classes of a conservative scene, or why there are none:
/// `Err(Unsupported)` for a scene this version does not judge, or a
/// panic's text.
pub fn oracle_classes(scene: &Scene) -> Result<ConservativeClasses, RasterError> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        crate::reference::conservative::classify(scene)
    }))
    .unwrap_or_else(|panic| {
        Err(RasterError::Failed(super::panics::pass_on_deadline(
            panic,
            "reference: the conservative classes failed",
        )))
    })
}

/// The promises of `expect.conservative` (SPEC.md §19) the reference's
/// classes break; each fails every candidate.
pub fn broken_promises(scene: &Scene, classes: &ConservativeClasses) -> Vec<String> {
    let Some(promise) = &scene.expect.conservative else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let counts = [
        (
            "required",
            promise.required,
            classes.count(PixelClass::Required),
        ),
        (
            "allowed",
            promise.allowed,
            classes.count(PixelClass::Allowed),
        ),
        (
            "fully_covered",
            promise.fully_covered,
            classes.fully_covered.as_ref().map_or(0, |f| {
                f.iter()
                    .zip(&classes.drawn)
                    .filter(|(f, d)| **f == PixelClass::Required && **d != PixelClass::Forbidden)
                    .count()
            }),
        ),
    ];
    for (key, pinned, found) in counts {
        if let Some(pinned) = pinned {
            if pinned != found as u64 {
                out.push(format!(
                    "reference: {found} pixels are {key} but the case's expect.conservative.{key} is {pinned}"
                ));
            }
        }
    }
    let sets = [
        (
            "required_pixels",
            &promise.required_pixels,
            PixelClass::Required,
        ),
        (
            "allowed_pixels",
            &promise.allowed_pixels,
            PixelClass::Allowed,
        ),
    ];
    for (key, pinned, class) in sets {
        let Some(pinned) = pinned else { continue };
        let width = classes.width as usize;
        let mut found: Vec<[u32; 2]> = (0..classes.drawn.len())
            .filter(|&i| classes.drawn[i] == class)
            .map(|i| [(i % width) as u32, (i / width) as u32])
            .collect();
        let mut pinned = pinned.clone();
        found.sort_by_key(|[x, y]| (*y, *x));
        pinned.sort_by_key(|[x, y]| (*y, *x));
        if found != pinned {
            out.push(format!(
                "reference: its {} pixels are {found:?} but the case's expect.conservative.{key} is {pinned:?}",
                class.name()
            ));
        }
    }
    out
}

/// The conservative state `candidate` is judged under: the case's,
/// restated under what it declares it cannot choose (SPEC.md §19.6).
pub fn judged_under(scene: &Scene, candidate: &dyn Rasterizer) -> Option<Conservative> {
    let case = scene.effects.conservative.as_ref()?;
    Some(match candidate.conservative() {
        Some(support) => support.restate(case),
        None => case.clone(),
    })
}

/// A conservative candidate's frame judged against the oracle's classes
/// (SPEC.md §19.5): against `classes`, the reference's for the case, or,
/// where the candidate declares an uncertainty or properties of its own
/// (`under` differs from the case's), against the classes under those,
/// reported as such.
pub fn judge(
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
    let promises = broken_promises(scene, classes);
    let own;
    let (judged, classes) = match under {
        Some(under) if under != case => {
            own = reference::conservative::classify_under(scene, under);
            (under, &own)
        }
        _ => (case, classes),
    };
    if let Some(why) = metrics::conservative::shape_problem(classes, &frame) {
        let why = format!("returned a frame of the wrong size or with the wrong channels: {why}");
        return run(Verdict::Error(why), None, frame);
    }
    let mut words = judged.words();
    if judged != case {
        words.push_str(&format!(
            ", its own conventions; the case states {}",
            case.words()
        ));
    }
    let m = metrics::conservative::measure(classes, &frame, words);
    let mut failures = metrics::conservative::failures(&m);
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
