//! A method's own draw call, timed apart from its adapter: set up once
//! (the scene converted, for a driver uploaded: timed once), then in each
//! round cleared (untimed), drawn (timed: the method's own work) and read
//! back (timed apart). The frame it draws must name the same last
//! primitive at every sample as the whole call's, which was judged: the
//! draw timed is the draw judged.

use std::time::{Duration, Instant};

use super::text::time_text;
use super::timing::{median, OnPool};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Prepared, RasterError, Rasterizer};
use crate::scene::Scene;

/// One method's draw call on one workload, round by round.
pub(super) struct DrawCall<'a> {
    prepared: Box<dyn Prepared + 'a>,
    set_up: Duration,
    draws: Vec<Duration>,
    read_backs: Vec<Duration>,
    /// The first round's read-back.
    frame: Option<Frame>,
}

/// What the rounds measured, per frame.
pub(super) struct Timed {
    pub draw: Duration,
    pub set_up: Duration,
    pub read_back: Duration,
    /// Samples whose last primitive differs from the whole call's frame.
    pub owners_differ: u64,
}

impl<'a> DrawCall<'a> {
    /// `r`'s draw call for `scene`, set up; `None` when it has none or
    /// refuses the scene (then only its whole call is timed).
    pub(super) fn prepare(
        r: &'a dyn Rasterizer,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<DrawCall<'a>> {
        let started = Instant::now();
        let prepared = r.prepare(scene, plan)?.ok()?;
        Some(DrawCall {
            prepared,
            set_up: started.elapsed(),
            draws: Vec::new(),
            read_backs: Vec::new(),
            frame: None,
        })
    }

    /// One round: clear, then the draw timed (inside `pool`'s threads when
    /// given, as the whole call is), then the read-back timed.
    pub(super) fn round(&mut self, pool: Option<&OnPool>) -> Result<(), RasterError> {
        self.prepared.clear()?;
        let (drawn, elapsed) = match pool {
            Some(pool) => pool.timed_draw(self.prepared.as_mut()),
            None => {
                let started = Instant::now();
                let drawn = self.prepared.draw();
                (drawn, started.elapsed())
            }
        };
        drawn?;
        self.draws.push(elapsed);
        let started = Instant::now();
        let frame = self.prepared.read_back()?;
        self.read_backs.push(started.elapsed());
        self.frame.get_or_insert(frame);
        Ok(())
    }

    /// The medians, and the owners checked against the whole call's frame.
    pub(super) fn finish(self, whole: &Frame) -> Result<Timed, String> {
        let Some(frame) = self.frame else {
            return Err("no round drew".to_owned());
        };
        if frame.last.len() != whole.last.len() {
            return Err(format!(
                "its draw read back {} samples, the whole call {}",
                frame.last.len(),
                whole.last.len()
            ));
        }
        let owners_differ = frame
            .last
            .iter()
            .zip(&whole.last)
            .filter(|(a, b)| a != b)
            .count() as u64;
        Ok(Timed {
            draw: median(self.draws),
            set_up: self.set_up,
            read_back: median(self.read_backs),
            owners_differ,
        })
    }
}

impl Timed {
    /// The row's note: the phases timed apart, and whether the owners
    /// agree.
    pub(super) fn note(&self, method: &str) -> String {
        let agree = match self.owners_differ {
            0 => "its frame names the whole call's last primitive at every sample".to_owned(),
            n => format!(
                "**its frame differs from the whole call's on {n} samples' last primitive**"
            ),
        };
        format!(
            "the draw call alone; per frame, apart: set-up {} (once), read-back {}; {agree}{}",
            time_text(self.set_up),
            time_text(self.read_back),
            match method {
                "tiny-skia" =>
                    "; `Pixmap::fill_path` of pre-built paths, each in an opaque \
                                colour numbering its triangle",
                "euc" =>
                    "; one `Pipeline::draw` of every triangle into a `Buffer2d<u32>` of \
                          triangle numbers, no depth buffer",
                "lavapipe" | "gl" =>
                    "; from submission to the fence, into targets cleared \
                                      before, untimed",
                "production" | "production-tiled" =>
                    "; from the vertices in fixed point \
                                                      into a frame cleared before, untimed",
                _ => "",
            }
        )
    }
}
