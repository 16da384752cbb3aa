//! The `scene_reference_vs_production` target: production against the
//! reference on a scene drawn from a tape of choices.

use crate::explore::fuzz::case_json::case_json;
use crate::explore::fuzz::family::scene_from_tape;
use crate::explore::fuzz::judge::{evaluate, Outcome};
use crate::production::Production;

/// What the target's panic message starts with, so that a test can tell a
/// finding from any other crash.
pub const FOUND_BY_SCENE_TARGET: &str = "production differs from the reference";

/// Draws a scene from `tape` and judges production on it as `rastercheck
/// fuzz -r production` does; panics on a failure (with the scene as a case
/// file) and when the reference itself breaks.
pub fn scene_reference_vs_production(tape: &[u8]) {
    let (family, scene) = scene_from_tape(tape);
    match evaluate(&scene, &Production) {
        Outcome::Pass | Outcome::Unsupported(_) | Outcome::Invalid(_) => {}
        Outcome::Broken(why) => panic!("{why}\n{}", case_json(&scene)),
        Outcome::Fail(failure) => panic!(
            "{FOUND_BY_SCENE_TARGET} ({}, {}): {}\n{}",
            family.name(),
            failure
                .kinds
                .iter()
                .map(|k| k.name())
                .collect::<Vec<_>>()
                .join(", "),
            failure.reasons.join("; "),
            case_json(&scene)
        ),
    }
}
