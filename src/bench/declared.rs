//! The declared-blur pair: a static scene drawn by production without and
//! with `effects.motion_blur` declared, in turn in the same rounds, so that
//! the cost of the declaration is a ratio measured side by side.

use std::time::{Duration, Instant};

use super::memory;
use super::model::Measured;
use super::score::mismatched;
use super::text::time_text;
use super::timing::median;
use super::workloads::SEED;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{MotionBlur, Scene, TimePattern};

/// The row of a static scene that declares motion blur, and of the same
/// scene without, drawn in turn with it.
pub const DECLARED: &str = "production, motion blur declared";
pub const PAIRED: &str = "production, paired";

/// `s` declaring 16 stratified instants over the whole shutter, with
/// nothing moving: a static scene (SPEC.md §15.1).
fn with_motion_declared(s: &Scene) -> Scene {
    let mut declared = s.clone();
    declared.effects.motion_blur = Some(MotionBlur {
        shutter: [0, TIME_ONE],
        samples: 16,
        pattern: TimePattern::Stratified,
        seed: SEED,
    });
    declared
}

/// The same static scene, drawn by production without and with motion
/// blur declared: each round draws them in turn through the same call, in
/// the orders ABBA ABBA (BAAB BAAB in odd rounds), so that each takes every
/// place as often. A draw's time depends on where it falls: drawn right
/// after the row `production`, the same scene took 10–20% longer than that
/// row (a large frame allocated after another's is freed comes from a
/// different place in the allocator), and a plain alternation still left a
/// few percent in favour of the later place.
pub(super) struct Declared {
    scenes: [Scene; 2],
    plans: [Plan; 2],
    /// Draw times, and Plan::for_scene's: plain, then declared.
    draws: [Vec<Duration>; 2],
    planning: [Vec<Duration>; 2],
    frames: [Result<Frame, String>; 2],
}

impl Declared {
    pub(super) fn new(s: &Scene) -> Declared {
        let scenes = [s.clone(), with_motion_declared(s)];
        Declared {
            plans: [Plan::for_scene(&scenes[0]), Plan::for_scene(&scenes[1])],
            scenes,
            draws: [Vec::new(), Vec::new()],
            planning: [Vec::new(), Vec::new()],
            frames: [Err(String::new()), Err(String::new())],
        }
    }

    pub(super) fn round(&mut self, rep: usize, production: &dyn Rasterizer) {
        let order = if rep.is_multiple_of(2) {
            [0, 1, 1, 0, 0, 1, 1, 0]
        } else {
            [1, 0, 0, 1, 1, 0, 0, 1]
        };
        for (i, k) in order.into_iter().enumerate() {
            let started = Instant::now();
            let frame = production.rasterize(&self.scenes[k], &self.plans[k]);
            self.draws[k].push(started.elapsed());
            if rep == 0 && i < 2 {
                self.frames[k] = frame.map_err(|e| e.to_string());
            }
        }
        for k in [0, 1] {
            let started = Instant::now();
            let plan = Plan::for_scene(&self.scenes[k]);
            self.planning[k].push(started.elapsed());
            std::hint::black_box(plan);
        }
    }

    /// Each scene's peak heap, drawn once more outside every timing.
    pub(super) fn peaks(&self, production: &dyn Rasterizer) -> [Option<u64>; 2] {
        [0, 1].map(|k| memory::peak(|| production.rasterize(&self.scenes[k], &self.plans[k])).1)
    }

    /// The two rows.
    pub(super) fn rows(
        self,
        exact: &Frame,
        covered: u64,
        count: usize,
        peaks: [Option<u64>; 2],
    ) -> Vec<Measured> {
        let [plain_planning, declared_planning] = self.planning.map(median);
        [PAIRED, DECLARED]
            .iter()
            .zip(self.draws)
            .zip(self.frames)
            .zip(peaks)
            .enumerate()
            .map(|(k, (((name, draws), frame), peak_heap))| Measured {
                method: (*name).to_owned(),
                per_item: frame.is_ok().then(|| median(draws) / count as u32),
                timed_items: count,
                errors: frame.as_ref().ok().map(|f| (mismatched(exact, f), covered)),
                coverage_error: None,
                exact: true,
                peak_heap,
                whole_call: None,
                set_up: None,
                read_back: None,
                note: match (frame, k) {
                    (Err(why), _) => why,
                    (Ok(_), 0) => format!("production on this scene, drawn in turn with `{DECLARED}`"),
                    (Ok(_), _) => format!(
                        "this scene with effects.motion_blur declared, nothing moving: its plan has \
                         no time loop (planning, outside every timing: {} with the declaration, {} \
                         without)",
                        time_text(declared_planning),
                        time_text(plain_planning)
                    ),
                },
            })
            .collect()
    }
}
