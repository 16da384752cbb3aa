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

use serde_json::{json, Value};

use crate::frame::Frame;
use crate::plan::{MotionPlan, Plan};
use crate::scene::time::limits::TIME_ONE;
use crate::scene::{Number, Scene, Vertex};

use super::values::{float_exact, pixel_of, whole_below};

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

/// `plan.motion` of a moving scene's request: the shutter (floats, and
/// exact strings), N, the pattern and seed, M, and every pixel's instants
/// u (row-major, p = y·width + x; slot j = s·N + k, SPEC.md §15.3), which
/// are [`MotionBlur::pixel_times`](crate::scene::MotionBlur::pixel_times),
/// the ones production tests.
pub(super) fn plan_motion(scene: &Scene, plan: &Plan, motion: &MotionPlan) -> Value {
    let blur = &motion.blur;
    let spatial = plan.samples_per_pixel;
    let [open, close] = blur
        .shutter
        .map(|end| float_exact(&Number::ratio(i64::from(end), i64::from(TIME_ONE))));
    let pixels = u64::from(scene.canvas.width) * u64::from(scene.canvas.height);
    let times: Vec<Vec<u32>> = (0..pixels).map(|p| blur.pixel_times(p, spatial)).collect();
    json!({
        "shutter": [open.0, close.0],
        "samples": blur.samples,
        "pattern": blur.pattern.name(),
        "seed": blur.seed,
        "spatial_samples": spatial,
        "exact": {"shutter": [open.1, close.1]},
        "times": times,
    })
}

/// A moving scene's answer, `$.primitives` (SPEC.md §12.8), as a time-only
/// frame. Form 1, `fragments`: a moving primitive's `[x, y, j]` is one
/// covered test (slot j < M·N of the pixel's instants), a static one's
/// `[x, y, s]` a spatial sample covered at every instant (N tests); each
/// pixel's time coverage is its covered tests over M·N. Form 2, `time`:
/// each `[x, y, c]` adds c ∈ [0, 1] to the pixel. A test or pixel listed
/// twice counts twice, as static fragments do.
pub(super) fn compose(list: &[Value], scene: &Scene, plan: &Plan) -> Result<Frame, String> {
    let motion = plan
        .motion
        .as_ref()
        .ok_or("a time-only frame needs a moving scene")?;
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    let with_time = list.iter().filter(|e| e.get("time").is_some()).count();
    if with_time > 0 && with_time != list.len() {
        return Err(
            "$.primitives: give time for every primitive or fragments for every one".into(),
        );
    }
    let field = if with_time > 0 { "time" } else { "fragments" };
    let m = plan.samples_per_pixel;
    let n = motion.blur.samples;
    let tests = f64::from(m) * f64::from(n);
    // Form 1 counts covered tests in integers, divided once at the end.
    let mut covered = vec![0u64; width as usize * height as usize];
    let mut time = vec![0.0; covered.len()];
    for (p, entry) in list.iter().enumerate() {
        let items = entry
            .as_object()
            .and_then(|o| o.get(field))
            .and_then(Value::as_array)
            .ok_or_else(|| {
                format!("$.primitives[{p}] must be an object with a {field} array (SPEC §12.8)")
            })?;
        let moves = motion.moving[p];
        for (f, item) in items.iter().enumerate() {
            let at = || format!("$.primitives[{p}].{field}[{f}]");
            let triple = item.as_array().filter(|a| a.len() == 3).ok_or_else(|| {
                format!(
                    "{} must be [x, y, {}]",
                    at(),
                    match (field, moves) {
                        ("time", _) => "time coverage",
                        (_, true) => "time slot",
                        (_, false) => "sample",
                    }
                )
            })?;
            let (x, y) = pixel_of(triple, (width, height), &at)?;
            let pixel = y as usize * width as usize + x as usize;
            if field == "time" {
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
                time[pixel] += c;
            } else if moves {
                whole_below(&triple[2], m * n).ok_or_else(|| {
                    format!(
                        "{}[2]: {} is not a time slot in [0, {}) (M·N of a moving primitive)",
                        at(),
                        triple[2],
                        m * n
                    )
                })?;
                covered[pixel] += 1;
            } else {
                whole_below(&triple[2], m).ok_or_else(|| {
                    format!(
                        "{}[2]: {} is not a spatial sample in [0, {m}) (a static primitive is \
                         covered at every instant)",
                        at(),
                        triple[2]
                    )
                })?;
                covered[pixel] += u64::from(n);
            }
        }
    }
    if field == "fragments" {
        // One exact quotient of integers, rounded once, as production's.
        for (t, &c) in time.iter_mut().zip(&covered) {
            *t = c as f64 / tests;
        }
    }
    Ok(Frame::time_only(width, height, time))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{parse_case, Limits};

    /// A 2×1 canvas, two spatial samples, N = 2: one moving triangle and
    /// one static one.
    fn scene() -> Scene {
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
        let motion = plan_motion(&scene, &plan, plan.motion.as_ref().unwrap());
        assert_eq!(motion["shutter"], json!([0.25, 0.75]));
        assert_eq!(motion["exact"]["shutter"], json!(["0.25", "0.75"]));
        assert_eq!(motion["spatial_samples"], 2);
        let times = motion["times"].as_array().unwrap();
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

    #[test]
    fn masks_count_tests_and_time_adds_coverage() {
        let scene = scene();
        let plan = Plan::for_scene(&scene);
        // Pixel 0: two moving tests and one static sample (N = 2 tests):
        // 4 of M·N = 4. Pixel 1: one moving test, listed twice: 2 of 4.
        let masks = json!([
            {"fragments": [[0, 0, 0], [0, 0, 3], [1, 0, 2], [1, 0, 2]]},
            {"fragments": [[0, 0, 1]]}
        ]);
        let frame = compose(masks.as_array().unwrap(), &scene, &plan).unwrap();
        assert_eq!(frame.time, Some(vec![1.0, 0.5]));
        assert_eq!(frame.samples, 0);
        let time = json!([{"time": [[0, 0, 0.25], [1, 0, 1]]}, {"time": [[0, 0, 0.5]]}]);
        let frame = compose(time.as_array().unwrap(), &scene, &plan).unwrap();
        assert_eq!(frame.time, Some(vec![0.75, 1.0]));
        for (bad, says) in [
            (
                json!([{"fragments": [[0, 0, 4]]}, {"fragments": []}]),
                "$.primitives[0].fragments[0][2]: 4 is not a time slot in [0, 4)",
            ),
            (
                json!([{"fragments": []}, {"fragments": [[0, 0, 2]]}]),
                "$.primitives[1].fragments[0][2]: 2 is not a spatial sample in [0, 2)",
            ),
            (
                json!([{"time": [[0, 0, 1.5]]}, {"time": []}]),
                "$.primitives[0].time[0][2]: 1.5 is not a time coverage in [0, 1]",
            ),
            (
                json!([{"time": []}, {"fragments": []}]),
                "time for every primitive or fragments for every one",
            ),
            (
                json!([{"fragments": [[2, 0, 0]]}, {"fragments": []}]),
                "$.primitives[0].fragments[0]: (2, 0) is not a pixel",
            ),
            (
                json!([{"fragments": [[0, 0]]}, {"fragments": []}]),
                "$.primitives[0].fragments[0] must be [x, y, time slot]",
            ),
            (
                json!([{"coverage": []}, {"coverage": []}]),
                "$.primitives[0] must be an object with a fragments array",
            ),
        ] {
            let why = compose(bad.as_array().unwrap(), &scene, &plan).unwrap_err();
            assert!(why.contains(says), "{why}");
        }
    }
}
