//! Moving scenes through the protocol (SPEC.md §12.8, version 2 only): what
//! a request of a moving scene carries beyond §12.1's (each primitive's
//! `moves`, each moving vertex's `to`, the shutter and every pixel's
//! instants in `plan.motion`), and the two forms of answer read into a
//! time-only [`Frame`]: time-sample masks (`[x, y, j]`, slot j of the
//! pixel's instants) or per-pixel time coverage (`[x, y, c]`).
//!
//! The instants are sent, not left to the program to draw: they are part
//! of the case (SPEC.md §15.3), so a program tests exactly the instants
//! production tests, and a program that gets SplitMix64 wrong cannot pass
//! for one that samples time badly. Which programs are sent moving scenes
//! at all is `hello.rs`'s and `mod.rs`'s: only those whose version 2 hello
//! declares `motion`.
//!
//! What this does not do: count the tests a program ran. The answer lists
//! covered tests only, so no sample-test efficiency (SPEC.md §15.4) is
//! reported for an external program; the frame's `sample_tests` stays
//! `None`, as the GPU adapters' time passes leave it.

use serde::ser::{Serialize, SerializeSeq, Serializer};
use serde_json::{json, Value};

use crate::frame::Frame;
use crate::plan::{MotionPlan, Plan};
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{Number, Scene, Vertex};

use super::values::{float_exact, pixel_of, whole_below, Scalar};

/// Why a moving scene is not sent to a program that has not declared
/// motion in a version 2 hello: one-shot programs, version 1 programs.
pub const NOT_DECLARED: &str =
    "moving scenes are sent only to programs that declare motion in a version 2 hello (SPEC §12.8)";

/// A moving vertex's extra fields (SPEC.md §12.8): `to`, its position at
/// shutter close, beside `x`, `y` (its `from`), as floats and, in `exact`,
/// as exact strings. `None` for a static vertex, which is sent unchanged.
pub(super) fn vertex_to(v: &Vertex) -> Option<(Value, Value)> {
    if !v.moves() {
        return None;
    }
    let [x, y] = v.end().map(float_exact);
    Some((json!({"x": x.0, "y": y.0}), json!({"x": x.1, "y": y.1})))
}

/// `plan.motion` of a moving scene's request, all but its `times`: the
/// shutter (floats, and exact strings), N, the pattern and seed, M; `times`
/// is a placeholder that [`Times`] fills as the request is written.
pub(super) fn plan_motion(plan: &Plan, motion: &MotionPlan) -> Value {
    let blur = &motion.blur;
    let [open, close] = blur
        .shutter
        .map(|end| float_exact(&Number::ratio(i64::from(end), i64::from(TIME_ONE))));
    json!({
        "shutter": [open.0, close.0],
        "samples": blur.samples,
        "pattern": blur.pattern.name(),
        "seed": blur.seed,
        "spatial_samples": plan.samples_per_pixel,
        "exact": {"shutter": [open.1, close.1]},
        "times": null,
    })
}

/// `plan.motion.times`: every pixel's instants u (row-major, p = y·width +
/// x; slot j = s·N + k, SPEC.md §15.3), which are
/// [`MotionBlur::pixel_times`](crate::scene::MotionBlur::pixel_times), the
/// ones production tests. Written one pixel at a time as the request goes
/// out: a 2048² canvas at 16 instants is half a gigabyte of text, never
/// whole in memory (issue 36).
pub(super) struct Times<'a> {
    pub(super) scene: &'a Scene,
    pub(super) plan: &'a Plan,
    pub(super) motion: &'a MotionPlan,
}

impl Serialize for Times<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let pixels = u64::from(self.scene.canvas.width) * u64::from(self.scene.canvas.height);
        let spatial = self.plan.samples_per_pixel;
        let mut seq = serializer.serialize_seq(usize::try_from(pixels).ok())?;
        for p in 0..pixels {
            seq.serialize_element(&self.motion.blur.pixel_times(p, spatial))?;
        }
        seq.end()
    }
}

/// A moving scene's answer, `$.primitives` (SPEC.md §12.8), read item by
/// item into a time-only frame. Form 1, `fragments`: a moving primitive's
/// `[x, y, j]` is one covered test (slot j < M·N of the pixel's instants),
/// a static one's `[x, y, s]` a spatial sample covered at every instant (N
/// tests); each pixel's time coverage is its covered tests over M·N. Form
/// 2, `time`: each `[x, y, c]` adds c ∈ [0, 1] to the pixel. A test or
/// pixel listed twice counts twice, as static fragments do.
pub(super) struct TimeAnswer {
    /// Form 2 (`time`), else form 1 (`fragments`).
    time_form: bool,
    moving: Vec<bool>,
    m: u32,
    n: u32,
    /// Form 1 counts covered tests in integers, divided once at the end.
    covered: Vec<u64>,
    time: Vec<f64>,
}

impl TimeAnswer {
    pub(super) fn new(scene: &Scene, plan: &Plan, time_form: bool) -> Result<TimeAnswer, String> {
        let motion = plan
            .motion
            .as_ref()
            .ok_or("a time-only frame needs a moving scene")?;
        let pixels = scene.canvas.width as usize * scene.canvas.height as usize;
        Ok(TimeAnswer {
            time_form,
            moving: motion.moving.clone(),
            m: plan.samples_per_pixel,
            n: motion.blur.samples,
            covered: if time_form {
                Vec::new()
            } else {
                vec![0; pixels]
            },
            time: vec![0.0; pixels],
        })
    }

    /// The key of the entries' arrays: `time` or `fragments`.
    pub(super) fn field(&self) -> &'static str {
        if self.time_form {
            "time"
        } else {
            "fragments"
        }
    }

    /// Item `f` of entry `p`: its first values and its length, `None` when
    /// it is not an array.
    pub(super) fn item(
        &mut self,
        p: usize,
        f: usize,
        values: Option<(&[Scalar], usize)>,
        (width, height): (u32, u32),
    ) -> Result<(), String> {
        let field = self.field();
        let moves = self.moving.get(p).copied().unwrap_or(false);
        let (m, n) = (self.m, self.n);
        let at = || format!("$.primitives[{p}].{field}[{f}]");
        let triple = values.filter(|(_, len)| *len == 3).ok_or_else(|| {
            format!(
                "{} must be [x, y, {}]",
                at(),
                match (self.time_form, moves) {
                    (true, _) => "time coverage",
                    (_, true) => "time slot",
                    (_, false) => "sample",
                }
            )
        })?;
        let triple = triple.0;
        let (x, y) = pixel_of(triple, (width, height), &at)?;
        let pixel = y as usize * width as usize + x as usize;
        if self.time_form {
            let c = triple[2]
                .as_f64()
                .filter(|c| (0.0..=1.0).contains(c))
                .ok_or_else(|| {
                    format!(
                        "{}[2]: {} is not a time coverage in [0, 1]",
                        at(),
                        triple[2]
                    )
                })?;
            self.time[pixel] += c;
        } else if moves {
            whole_below(&triple[2], m * n).ok_or_else(|| {
                format!(
                    "{}[2]: {} is not a time slot in [0, {}) (M·N of a moving primitive)",
                    at(),
                    triple[2],
                    m * n
                )
            })?;
            self.covered[pixel] += 1;
        } else {
            whole_below(&triple[2], m).ok_or_else(|| {
                format!(
                    "{}[2]: {} is not a spatial sample in [0, {m}) (a static primitive is \
                     covered at every instant)",
                    at(),
                    triple[2]
                )
            })?;
            self.covered[pixel] += u64::from(n);
        }
        Ok(())
    }

    /// The time-only frame.
    pub(super) fn finish(mut self, width: u32, height: u32) -> Frame {
        if !self.time_form {
            // One exact quotient of integers, rounded once, as production's.
            let tests = f64::from(self.m) * f64::from(self.n);
            for (t, &c) in self.time.iter_mut().zip(&self.covered) {
                *t = c as f64 / tests;
            }
        }
        Frame::time_only(width, height, self.time)
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    /// A 2×1 canvas, two spatial samples, N = 2: one moving triangle and
    /// one static one.
    pub(in crate::adapters::external) fn scene() -> Scene {
        parse_case(
            r#"{"name": "m", "canvas": {"width": 2, "height": 1},
                "effects": {"antialias": {"samples": 2},
                            "motion_blur": {"samples": 2, "shutter": [0.25, 0.75]}},
                "primitives": [
                  {"triangle": [{"from": [0, 0], "to": [1, 0]}, [2, 0], [0, 1]]},
                  {"triangle": [[0, 0], [2, 0], [0, 1]]}]}"#,
            "m.json",
            &Limits::default(),
        )
        .unwrap()
    }

    #[test]
    fn the_request_carries_instants_and_ends() {
        let scene = scene();
        let plan = Plan::for_scene(&scene);
        let motion = plan.motion.as_ref().unwrap();
        let head = plan_motion(&plan, motion);
        assert_eq!(head["shutter"], json!([0.25, 0.75]));
        assert_eq!(head["exact"]["shutter"], json!(["0.25", "0.75"]));
        assert_eq!(head["spatial_samples"], 2);
        let times = serde_json::to_value(Times {
            scene: &scene,
            plan: &plan,
            motion,
        })
        .unwrap();
        let times = times.as_array().unwrap();
        assert_eq!(times.len(), 2);
        let blur = &plan.motion.as_ref().unwrap().blur;
        assert_eq!(times[1], json!(blur.pixel_times(1, 2)));
        assert_eq!(times[1].as_array().unwrap().len(), 4);
        let moving = &scene.primitives[0].vertices()[0];
        assert_eq!(
            vertex_to(moving),
            Some((json!({"x": 1.0, "y": 0.0}), json!({"x": "1", "y": "0"})))
        );
        assert_eq!(vertex_to(&scene.primitives[1].vertices()[0]), None);
    }
}
