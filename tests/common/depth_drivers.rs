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

/// Every case in `cases/depth` is judged (none unsupported, none broken)
/// and passes.
pub fn assert_depth_cases_pass(candidate: &dyn Rasterizer) {
    let ids = bundled_ids("depth", |_| true);
    assert!(ids.len() >= 17, "cases/depth holds {} cases", ids.len());
    let mut failures = Vec::new();
    for id in &ids {
        let (reference, run) = run(&case(id), candidate);
        let line = report(id, &reference, &run);
        eprintln!("{line}");
        if run.verdict != Verdict::Pass {
            failures.push(line);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
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
    for (wrong, ids) in must_fail {
        let wronged = Wronged(candidate, wrong);
        for id in ids {
            let (reference, run) = run(&case(id), &wronged);
            let line = report(id, &reference, &run);
            eprintln!("{wrong:?}: {line}");
            if !matches!(run.verdict, Verdict::Fail(_)) {
                missed.push(format!("{wrong:?}: {line}"));
            }
        }
    }
    assert!(missed.is_empty(), "not caught:\n{}", missed.join("\n"));
}
