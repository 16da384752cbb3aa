//! [`shrink`]: the greedy loop over the passes (`cut.rs`, `settings.rs`,
//! `moves.rs`) until a round makes no progress or the budget is spent.

use std::time::Instant;

use super::state::{Shrinker, Shrunk};
use crate::explore::fuzz::judge::{Failure, Kind};
use crate::rasterizer::Rasterizer;
use crate::scene::Scene;

/// Shrinks `scene`, on which `candidate` fails with `failure`, to a small
/// scene that still fails the check `kind`.
pub fn shrink(scene: &Scene, failure: Failure, kind: Kind, candidate: &dyn Rasterizer) -> Shrunk {
    let started = Instant::now();
    let mut s = Shrinker {
        candidate,
        kind,
        best: scene.clone(),
        failure,
        evaluations: 0,
    };
    let mut rounds = 0;
    loop {
        rounds += 1;
        let mut progress = false;
        progress |= s.remove_primitives();
        progress |= s.crop();
        progress |= s.trim();
        progress |= s.simplify_state();
        progress |= s.simplify_antialias();
        progress |= s.simplify_motion();
        progress |= s.freeze_vertices();
        progress |= s.remove_contours_and_vertices();
        progress |= s.move_shared_vertices();
        progress |= s.move_vertices();
        progress |= s.move_ends();
        progress |= s.simplify_values();
        // Coarser snapping is tried once nothing else helps: by then the
        // vertices are as simple as they get, and often on the grid already.
        if !progress {
            progress = s.reduce_bits();
        }
        if !progress || s.exhausted() {
            break;
        }
    }
    s.restore_default_bits();
    Shrunk {
        scene: s.best,
        failure: s.failure,
        evaluations: s.evaluations,
        rounds,
        elapsed: started.elapsed(),
    }
}
