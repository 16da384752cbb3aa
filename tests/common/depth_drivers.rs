//! What the adapters with a real depth attachment (`vulkan.rs`, `gl/`)
//! are held to on SPEC.md §18's depth formats and polygon offset: every
//! bundled depth case is judged and passes, and the driver made wrong
//! (its offset dropped, its format not quantized) fails the cases that
//! show it.
#![allow(dead_code)] // each test binary uses its own part

use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::{DepthFormat, Scene};

use super::adapters::bundled_ids;
use super::{case, report, run};

/// Why a case is left unsupported for a depth format the device cannot
/// attach and copy out (a device limit, SPEC.md §18.1: SwiftShader has no
/// unorm24), if it is.
pub fn format_refused(run: &rastercheck::harness::judge::CandidateRun) -> Option<&str> {
    match &run.verdict {
        Verdict::Unsupported(why) if why.contains("the device cannot attach") => Some(why),
        _ => None,
    }
}

/// Every case in `cases/depth` is judged and passes, but one whose depth
/// format the device cannot attach (unsupported, naming the format: a
/// device limit); at least 10 are judged.
pub fn assert_depth_cases_pass(candidate: &dyn Rasterizer) {
    let ids = bundled_ids("depth", |_| true);
    assert!(ids.len() >= 17, "cases/depth holds {} cases", ids.len());
    let mut failures = Vec::new();
    let mut judged = 0;
    for id in &ids {
        let (reference, run) = run(&case(id), candidate);
        let line = report(id, &reference, &run);
        eprintln!("{line}");
        if format_refused(&run).is_some() {
            continue;
        }
        judged += 1;
        if run.verdict != Verdict::Pass {
            failures.push(line);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(judged >= 10, "only {judged} depth cases judged");
}

/// How a wrong driver is made from the real one: the scene it is handed
/// is changed, the frame judged against the case as it stands.
#[derive(Clone, Copy, Debug)]
pub enum Wrong {
    /// No polygon offset: the driver draws the scene without `depth_bias`.
    NoOffset,
    /// No quantization: a unorm scene drawn into `float32`, whose
    /// readback lies between the unorm grid's values.
    Unquantized,
}

/// The real driver, made wrong as [`Wrong`] says.
pub struct Wronged<'a>(pub &'a dyn Rasterizer, pub Wrong);

impl Rasterizer for Wronged<'_> {
    fn name(&self) -> &str {
        "wronged"
    }

    fn capabilities(&self) -> Capabilities {
        self.0.capabilities()
    }

    fn fixed_fill_rule(&self) -> Option<rastercheck::scene::FillRule> {
        self.0.fixed_fill_rule()
    }

    fn fixed_clip_rules(&self) -> Option<(rastercheck::scene::ClipXy, rastercheck::scene::ClipZ)> {
        self.0.fixed_clip_rules()
    }

    fn fixed_interpolate_from(&self) -> Option<rastercheck::scene::InterpolateFrom> {
        self.0.fixed_interpolate_from()
    }

    fn fixed_snapping(&self) -> Option<rastercheck::rasterizer::Snapping> {
        self.0.fixed_snapping()
    }

    fn fixed_sample_pattern(&self) -> Option<rastercheck::scene::Pattern> {
        self.0.fixed_sample_pattern()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut scene = scene.clone();
        match self.1 {
            Wrong::NoOffset => scene.rules.depth_bias = None,
            Wrong::Unquantized => {
                if scene.rules.depth_format.unorm_bits().is_some() {
                    scene.rules.depth_format = DepthFormat::Float32;
                }
            }
        }
        self.0.rasterize(&scene, plan)
    }
}

/// Each wrong driver fails the depth cases that show its fault: the
/// offset cases without an offset, the unorm cases whose exact depth is
/// off the grid without quantization.
pub fn assert_wrong_depth_is_caught(candidate: &dyn Rasterizer) {
    let must_fail: [(Wrong, &[&str]); 2] = [
        (
            Wrong::NoOffset,
            &[
                "depth/spec_offset_constant",
                "depth/spec_offset_slope_45",
                "depth/offset_steep",
                "depth/offset_negative",
                "depth/spec_offset_clip",
                "depth/offset_beyond_one",
                "depth/offset_constant_standard4",
                "depth/offset_negative_standard4",
                "clip/offset_steep_slope",
                "clip/offset_steep_perspective",
            ],
        ),
        (
            Wrong::Unquantized,
            &[
                "depth/spec_depth_unorm16_half_way",
                "depth/unorm16_plane",
                "depth/spec_offset_constant",
                "depth/offset_constant_standard4",
            ],
        ),
    ];
    let mut missed = Vec::new();
    let mut caught = 0;
    for (wrong, ids) in must_fail {
        let wronged = Wronged(candidate, wrong);
        for id in ids {
            // A format the device cannot attach is no fault to catch.
            let (_, real) = run(&case(id), candidate);
            if let Some(why) = format_refused(&real) {
                eprintln!("{wrong:?}: {id}: left out: {why}");
                continue;
            }
            let (reference, run) = run(&case(id), &wronged);
            let line = report(id, &reference, &run);
            eprintln!("{wrong:?}: {line}");
            if !matches!(run.verdict, Verdict::Fail(_)) {
                missed.push(format!("{wrong:?}: {line}"));
            } else {
                caught += 1;
            }
        }
    }
    assert!(missed.is_empty(), "not caught:\n{}", missed.join("\n"));
    assert!(caught >= 10, "only {caught} wrong drivers caught");
}
