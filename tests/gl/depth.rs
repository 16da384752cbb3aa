//! Depth formats and polygon offsets (SPEC.md §18) drawn into a real depth
//! attachment, and its stored values read back.

use super::GL;
use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::depth::unorm_index;
use rastercheck::scene::{DepthFormat, FillRule, Scene};

use super::available;
use super::common::adapters::assert_prepared_draws_as_rasterize;
use super::common::{case, inline, report, run};

/// Every bundled depth case is drawn and judged, not refused, and passes
/// (measured on llvmpipe, Mesa 22.3). Catches the adapter refusing an
/// attachment it should set up (a capability left false, a format or an
/// offset clamp it thinks it lacks) and any readback or state that puts a
/// sample outside the set its format and offset allow.
#[test]
fn answers_every_depth_case() {
    let Some(_record) = available() else {
        return;
    };
    assert!(GL.capabilities().depth_attachment);
    super::common::depth_drivers::assert_depth_cases_pass(&GL);
}

/// The same driver without its offset, or storing a unorm case as f32,
/// fails the cases that show it (`common::depth_drivers`).
#[test]
fn a_wrong_depth_attachment_fails() {
    let Some(_record) = available() else {
        return;
    };
    super::common::depth_drivers::assert_wrong_depth_is_caught(&GL);
}

/// An 8×8 screen-space triangle over the canvas's upper-left half at
/// constant z = 1/2, in `format`, with `bias` (`depth_bias`'s JSON, or
/// none).
fn flat_half(format: &str, bias: Option<&str>) -> Scene {
    let bias = bias.map_or(String::new(), |b| format!(r#", "depth_bias": {b}"#));
    inline(&format!(
        r#"{{"name": "flat_half", "canvas": {{"width": 8, "height": 8}},
            "rules": {{"depth_format": "{format}"{bias}}},
            "primitives": [{{"triangle": [
                {{"position": [0, 0], "z": "1/2"}},
                {{"position": [8, 0], "z": "1/2"}},
                {{"position": [0, 8], "z": "1/2"}}]}}]}}"#
    ))
}

/// The depth of every covered sample of gl's frame of `scene`.
fn covered_depths(scene: &Scene) -> Vec<f64> {
    let frame = GL
        .rasterize(scene, &Plan::for_scene(scene))
        .unwrap_or_else(|e| panic!("{}: {e}", scene.name));
    let depth = frame.depth.as_ref().expect("a depth channel");
    let values: Vec<f64> = (0..frame.coverage.len())
        .filter(|&i| frame.coverage[i] > 0)
        .map(|i| depth[i])
        .collect();
    assert!(
        values.len() > 20,
        "{}: {} covered",
        scene.name,
        values.len()
    );
    values
}

/// The readback follows the offset and lies on the format's grid: at
/// z = 1/2 with `depth_bias.constant` 4, each covered sample reads back
/// within [1/2 + 4·r_lo, 1/2 + 4·r_hi] (r's range for the format,
/// SPEC.md §18.2) widened by one grid step (unorm) or one f32 ulp
/// (float32) for the rounding, and (unorm) exactly a grid value; without
/// the offset, within one step of 1/2; and the offset raises every
/// sample. Catches a readback of the fragment's depth (no offset, off the
/// grid), an offset on the wrong side or scaled wrongly (GL's factor and
/// units swapped would give no offset on this flat plane), the wrong
/// attachment format (a finer one puts the value off the unorm grid), and
/// rows or words decoded wrongly.
#[test]
fn the_readback_follows_the_offset_on_the_grid() {
    let Some(_record) = available() else {
        return;
    };
    let p = |e: i32| 2f64.powi(e);
    for (format, bits, r) in [
        ("unorm16", Some(16), [p(-16), p(-15)]),
        ("unorm24", Some(24), [p(-24), p(-23)]),
        // e = −1 for |z| = 1/2: r ∈ [2^(e−23), 2^(e−22)].
        ("float32", None, [p(-24), p(-23)]),
    ] {
        let step = bits.map_or(p(-24), |n: u32| 1.0 / f64::from((1u32 << n) - 1));
        let plain = covered_depths(&flat_half(format, None));
        let offset = covered_depths(&flat_half(format, Some(r#"{"constant": 4}"#)));
        let (lo, hi) = (0.5 + 4.0 * r[0] - step, 0.5 + 4.0 * r[1] + step);
        let distinct = |values: &[f64]| {
            let mut v = values.to_vec();
            v.dedup();
            v
        };
        eprintln!(
            "{format}: z = 1/2 reads back {:?}; with constant 4, {:?} (allowed [{lo}, {hi}])",
            distinct(&plain),
            distinct(&offset)
        );
        for &v in plain.iter().chain(&offset) {
            if let Some(n) = bits {
                assert!(unorm_index(v, n).is_some(), "{format}: {v} is off the grid");
            }
        }
        for &v in &plain {
            assert!((v - 0.5).abs() <= step, "{format}: {v} without an offset");
        }
        for (&v, &w) in offset.iter().zip(&plain) {
            assert!((lo..=hi).contains(&v), "{format}: {v} outside [{lo}, {hi}]");
            assert!(v > w, "{format}: the offset did not raise {w} (got {v})");
        }
    }
}

/// gl with the case's depth rules dropped: it reports the fragment's
/// depth, as the adapter did before it had an attachment.
struct FragmentDepth;

/// gl with each unorm24 depth decoded from its k as a fixed-point
/// fraction, k/2^24 in f32, instead of the f32 nearest k/(2^24 − 1): what
/// an adapter that shifts the 24 bits into an f32's mantissa reports.
struct Unorm24AsFraction;

impl Rasterizer for FragmentDepth {
    fn name(&self) -> &str {
        "gl-fragment-depth"
    }
    fn capabilities(&self) -> Capabilities {
        GL.capabilities()
    }
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        GL.fixed_fill_rule()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut exact = scene.clone();
        exact.rules.depth_format = DepthFormat::Exact;
        exact.rules.depth_bias = None;
        GL.rasterize(&exact, plan)
    }
}

impl Rasterizer for Unorm24AsFraction {
    fn name(&self) -> &str {
        "gl-unorm24-as-fraction"
    }
    fn capabilities(&self) -> Capabilities {
        GL.capabilities()
    }
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        GL.fixed_fill_rule()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut frame = GL.rasterize(scene, plan)?;
        for d in frame.depth.iter_mut().flatten() {
            if let Some(k) = unorm_index(*d, 24) {
                *d = f64::from(k as f32 / 16_777_216.0);
            }
        }
        Ok(frame)
    }
}

/// The checks catch a wrong readback: the fragment's depth (no attachment)
/// fails the offset case (outside the set) and a unorm16 plane (off the
/// grid); unorm24 decoded as k/2^24 fails at z = 1/3 (off the grid: there
/// k/2^24 is no grid value's f32). Each case passes as gl reads it
/// (`answers_every_depth_case`).
#[test]
fn a_wrong_readback_is_caught() {
    let Some(_record) = available() else {
        return;
    };
    let wrong: [(&dyn Rasterizer, &str); 3] = [
        (&FragmentDepth, "depth/spec_offset_constant"),
        (&FragmentDepth, "depth/unorm16_plane"),
        (&Unorm24AsFraction, "depth/unorm24_on_grid"),
    ];
    for (candidate, id) in wrong {
        let (reference, r) = run(&case(id), candidate);
        let line = report(id, &reference, &r);
        eprintln!("{line}");
        let m = r.metrics.as_ref().expect("judged");
        let c = &m.coverage;
        assert_eq!((c.missing, c.extra, c.wrong_owner), (0, 0, 0), "{line}");
        let miss = m
            .channels
            .iter()
            .find_map(|ch| ch.depth_set.clone())
            .expect("a depth set");
        assert!(miss.off_grid + miss.outside > 0, "{line}");
        assert!(matches!(r.verdict, Verdict::Fail(_)), "{line}");
    }
}

/// The prepared path the bench times draws what `rasterize` draws with
/// a depth attachment: clear, draw and read back phase by phase, the
/// attachment cleared and the depth state set again for each draw.
#[test]
fn the_prepared_path_draws_depth_as_rasterize_does() {
    let Some(_record) = available() else {
        return;
    };
    assert_prepared_draws_as_rasterize(
        &GL,
        &[
            "depth/spec_offset_constant",
            "depth/unorm24_on_grid",
            "depth/offset_clamp_positive",
            "depth/spec_offset_clip",
        ],
    );
}

/// The depth state is put back after each scene, since every case shares
/// the context: a clip-space case (whose depth is `gl_FragCoord.z`, which
/// a polygon offset left on would move) and a screen-space one draw the
/// same frames before and after a case with a large offset and one clamped
/// in screen space.
#[test]
fn depth_state_does_not_leak_into_the_next_case() {
    let Some(_record) = available() else {
        return;
    };
    let after = ["clip/depth_clip_near", "triangles/interp_depth_z"];
    let draw = |id: &str| {
        let scene = case(id);
        GL.rasterize(&scene, &Plan::for_scene(&scene))
            .unwrap_or_else(|e| panic!("{id}: {e}"))
    };
    let before: Vec<Frame> = after.iter().map(|id| draw(id)).collect();
    for depth in ["depth/offset_beyond_one", "depth/spec_offset_clip"] {
        draw(depth);
        for (id, frame) in after.iter().zip(&before) {
            let again = draw(id);
            assert_eq!(again.depth, frame.depth, "{id} after {depth}");
            assert_eq!(again.coverage, frame.coverage, "{id} after {depth}");
        }
    }
}

/// An antialiased scene with a depth attachment is drawn by shifted
/// passes (a multisampled attachment cannot be read back exactly) and
/// judged; rectangle lines beside one are refused with the reason.
#[test]
fn antialiased_depth_is_drawn_by_shifted_passes() {
    let Some(_record) = available() else {
        return;
    };
    let mut scene = flat_half("unorm16", Some(r#"{"constant": 4}"#));
    let aa = inline(
        r#"{"name": "aa", "canvas": {"width": 8, "height": 8},
            "effects": {"antialias": {"samples": 4}},
            "primitives": [{"triangle": [[0, 0], [8, 0], [0, 8]]}]}"#,
    );
    scene.effects = aa.effects;
    let (reference, r) = run(&scene, &GL);
    let line = report("flat_half_aa", &reference, &r);
    eprintln!("{line}");
    assert_eq!(r.verdict, Verdict::Pass, "{line}");
    assert_eq!(
        r.frame.as_ref().and_then(|f| f.method),
        Some("shifted passes")
    );
    let lines = inline(
        r#"{"name": "rect", "canvas": {"width": 8, "height": 8},
            "rules": {"depth_format": "unorm16"},
            "primitives": [{"line": [{"position": [1, 1], "z": "1/4"},
                                     {"position": [7, 5], "z": "3/4"}],
                            "rule": "rectangle", "width": 2}]}"#,
    );
    match GL.rasterize(&lines, &Plan::for_scene(&lines)) {
        Err(RasterError::Unsupported(why)) => assert!(why.contains("depth attachment"), "{why}"),
        other => panic!(
            "rectangle lines with depth: {:?}",
            other.map(|f| f.covered_samples())
        ),
    }
}
