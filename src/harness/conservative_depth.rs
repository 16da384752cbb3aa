//! A conservative case's depth judged (SPEC.md §19.9): the reference's
//! allowed depths under the state the candidate is judged under, computed
//! here (a panic of the oracle is the case's failure, never the run's),
//! and the candidate's drawn pixels measured against them.

use crate::frame::Frame;
use crate::metrics::conservative_depth::{measure, ConservativeDepthMetrics};
use crate::scene::{Conservative, Scene};

/// The depth of `frame` judged under `under`, or why the oracle could
/// not give the allowed depths; `None` for a scene without depth.
pub fn judged(
    scene: &Scene,
    under: &Conservative,
    frame: &Frame,
) -> Option<Result<ConservativeDepthMetrics, String>> {
    if !scene.has_depth {
        return None;
    }
    let allowed = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        crate::reference::conservative::depth_allowed(scene, under)
    }));
    Some(match allowed {
        Ok(Some(allowed)) => Ok(measure(&allowed, frame)),
        Ok(None) => Err("reference: the conservative depths were not computed".to_owned()),
        Err(panic) => Err(super::panics::pass_on_deadline(
            panic,
            "reference: the conservative depths failed",
        )),
    })
}
