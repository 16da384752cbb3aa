//! A conservative case's candidate (SPEC.md §19): refused unsent when it
//! draws no such case (or not this mode, or not the flag asked for); the
//! oracle's classes, the case's promises about them, and the state a
//! candidate is judged under. `judge.rs` judges its frame with them.

use crate::rasterizer::{RasterError, Rasterizer};
use crate::reference::conservative::{ConservativeClasses, PixelClass};
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
    match candidate.conservative_for(scene) {
        None => Some(
            "this rasterizer does not draw conservative rasterization (SPEC.md §19)".to_owned(),
        ),
        Some(support) => support
            .refuses(case)
            .or_else(|| support.refuses_depth(scene.has_depth))
            .or_else(|| scene.conservative_lines_refused(&support.restate(case))),
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
/// Asked after the candidate has drawn, though [`refusal`] restated the
/// case before: an external program declares its uncertainty in its
/// hello, read only when the program is started for its first draw
/// (`a_declared_uncertainty_is_judged_under_and_said_so` in
/// `tests/conservative_external.rs` fails when the state asked before
/// the draw is kept).
pub fn judged_under(scene: &Scene, candidate: &dyn Rasterizer) -> Option<Conservative> {
    let case = scene.effects.conservative.as_ref()?;
    Some(match candidate.conservative_for(scene) {
        Some(support) => support.restate(case),
        None => case.clone(),
    })
}
