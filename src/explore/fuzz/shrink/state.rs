//! The shrinker's state: the best failing scene so far, the check it must
//! keep failing, and the evaluation budget every attempt spends.

use std::time::Duration;

use crate::explore::fuzz::judge::{evaluate, Failure, Kind, Outcome};
use crate::rasterizer::Rasterizer;
use crate::scene::Scene;

/// Most candidate evaluations one shrink may spend.
pub const SHRINK_BUDGET: u64 = 20_000;

/// A shrunk counterexample.
#[derive(Clone, Debug)]
pub struct Shrunk {
    pub scene: Scene,
    pub failure: Failure,
    /// Candidate evaluations spent.
    pub evaluations: u64,
    /// Rounds of passes, the last of which made no progress.
    pub rounds: u32,
    pub elapsed: Duration,
}

/// One proposed change to a scene; `false` when it would change nothing.
pub(super) type Edit = Box<dyn Fn(&mut Scene) -> bool>;

pub(super) struct Shrinker<'a> {
    pub(super) candidate: &'a dyn Rasterizer,
    pub(super) kind: Kind,
    pub(super) best: Scene,
    pub(super) failure: Failure,
    pub(super) evaluations: u64,
}

impl Shrinker<'_> {
    pub(super) fn exhausted(&self) -> bool {
        self.evaluations >= SHRINK_BUDGET
    }

    /// Keeps `scene` when it still fails the same check.
    pub(super) fn try_scene(&mut self, scene: Scene) -> bool {
        if self.exhausted() {
            return false;
        }
        self.evaluations += 1;
        match evaluate(&scene, self.candidate) {
            Outcome::Fail(f) if f.kinds.contains(&self.kind) => {
                self.best = scene;
                self.failure = f;
                true
            }
            _ => false,
        }
    }

    /// Tries each of `edits` on the current best scene in turn, keeping
    /// each that still fails.
    pub(super) fn try_each(&mut self, edits: Vec<Edit>) -> bool {
        let mut progress = false;
        for edit in edits {
            let mut scene = self.best.clone();
            if edit(&mut scene) {
                progress |= self.try_scene(scene);
            }
        }
        progress
    }
}
