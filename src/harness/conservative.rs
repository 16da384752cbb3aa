//! A conservative case's candidate (SPEC.md §19): refused unsent when it
//! draws no such case (or not this mode, or not the flag asked for), and
//! otherwise judged pixel by pixel against the reference's three classes.

use std::time::Duration;

use super::judge::{CandidateRun, Verdict};
use super::profile::OwnConventions;
use crate::frame::Frame;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::reference::conservative::ConservativeClasses;
use crate::scene::Scene;

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

/// A conservative candidate's frame judged against the oracle's classes
/// (SPEC.md §19.5).
pub fn judge(
    _scene: &Scene,
    classes: &Result<ConservativeClasses, RasterError>,
    frame: Frame,
    name: String,
    elapsed: Duration,
) -> CandidateRun {
    let verdict = match classes {
        Err(RasterError::Unsupported(why)) => Verdict::Unsupported(why.clone()),
        Err(RasterError::Failed(why)) => Verdict::Error(why.clone()),
        Ok(_) => Verdict::Error("the conservative verdict is not built yet".to_owned()),
    };
    CandidateRun {
        rasterizer: name,
        verdict,
        metrics: None,
        method: frame.method,
        frame: Some(frame),
        elapsed,
        judged: OwnConventions::default(),
    }
}
