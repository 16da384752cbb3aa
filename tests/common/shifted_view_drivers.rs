//! Antialiased screen-space scenes beyond the device's largest viewport,
//! drawn by shifted passes (SPEC.md §16.9): every pass must be clipped at
//! the one rectangle the adapter reports (`Rasterizer::screen_viewport`),
//! which the judge restates the case clipped at. The adapters move the
//! viewport with each pass's shift (`adapters/gpu/stream.rs`), so that in
//! the case's coordinates every pass is clipped at the target.
//!
//! The foil is what the adapters did before: each pass the scene moved by
//! its slot's shift while the viewport stayed at the target, so that pass
//! s was clipped at the target moved by minus its shift. It is built here
//! on the same driver, with no switch in the adapter: for each sample slot,
//! the case without antialiasing and moved by the slot's shift (exact:
//! the shifts lie on the driver's grid), drawn by the candidate through
//! its fixed viewport at the target, its frame written into that slot.
//! Judged with the candidate's own declarations, it must fail.
#![allow(dead_code)]

use dashu_ratio::RBig;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{
    Capabilities, PixelCentre, RasterError, Rasterizer, ScreenViewport, Snapping, YDirection,
};
use rastercheck::scene::{
    ClipXy, ClipZ, FillRule, InterpolateFrom, LineRule, LineT, Number, Pattern, PointBounds,
    PointClip, Scene,
};

use super::{case, report};

/// Bundled antialiased polygons (16 standard samples, which no bundled
/// driver multisamples: shifted passes) whose vertices lie about 32 700 px
/// off their 24 px canvas, past every bundled device's largest viewport.
pub const SHIFTED_PAST_THE_VIEWPORT: &[&str] = &[
    "hard/poly_far_zigzag_b8_even_odd_standard16",
    "hard/poly_far_zigzag_b8_nonzero_standard16",
];

/// Each of [`SHIFTED_PAST_THE_VIEWPORT`] is clipped (the candidate reports
/// a viewport for it) and judged `pass`; the same candidate drawing each
/// pass through a viewport that stays while the scene moves is caught.
pub fn assert_passes_clipped_at_one_rectangle(candidate: &dyn Rasterizer) {
    let mut failures = Vec::new();
    for id in SHIFTED_PAST_THE_VIEWPORT {
        let scene = case(id);
        let reference = oracle::run_reference(&scene);
        let viewport = candidate.screen_viewport(&scene, &reference.plan);
        assert!(
            viewport.is_some(),
            "{id}: reports no viewport, clips nothing"
        );
        let run = judge::run_candidate(&scene, &reference, candidate);
        if run.verdict != Verdict::Pass {
            failures.push(report(id, &reference, &run));
        }
        let foil = FixedViewportPasses(candidate);
        let wrong = judge::run_candidate(&scene, &reference, &foil);
        eprintln!("{}", report(id, &reference, &wrong));
        if !matches!(wrong.verdict, Verdict::Fail(_)) {
            failures.push(format!(
                "{id}: passes drawn through a viewport that stays while the scene moves \
                 are not caught: {:?}",
                wrong.verdict
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The candidate drawing an antialiased scene as the adapters did before:
/// per sample slot, the scene moved by the slot's shift drawn through the
/// candidate's viewport at the target. Declares what the candidate does.
struct FixedViewportPasses<'a>(&'a dyn Rasterizer);

/// `scene` moved by `shift` pixels (x right, y down), without
/// antialiasing.
fn moved(scene: &Scene, shift: &[RBig; 2]) -> Scene {
    let mut moved = scene.clone();
    moved.effects.antialias = None;
    for primitive in &mut moved.primitives {
        for v in primitive.vertices_mut() {
            v.x = Number::from_rbig(v.x.as_rbig() + &shift[0]);
            v.y = Number::from_rbig(v.y.as_rbig() + &shift[1]);
        }
    }
    moved
}

impl Rasterizer for FixedViewportPasses<'_> {
    fn name(&self) -> &str {
        "fixed-viewport-passes"
    }
    fn capabilities(&self) -> Capabilities {
        self.0.capabilities()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let aa = plan.antialias.as_ref().expect("an antialiased case");
        let unit = RBig::from(1u64 << aa.position_bits);
        let n = aa.offsets.len();
        let mut frame = Frame::for_plan(scene.canvas.width, scene.canvas.height, plan);
        for (k, offset) in aa.offsets.iter().enumerate() {
            // The shift that brings slot k's offset onto the pixel centre.
            let shift = offset.map(|o| RBig::from(1u8) / RBig::from(2u8) - RBig::from(o) / &unit);
            let pass = moved(scene, &shift);
            let pass_frame = self.0.rasterize(&pass, &Plan::for_scene(&pass))?;
            for p in 0..frame.pixel_count() {
                frame.coverage[p * n + k] = pass_frame.coverage[p];
                frame.last[p * n + k] = pass_frame.last[p];
            }
        }
        frame.resolve();
        Ok(frame)
    }
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        self.0.fixed_fill_rule()
    }
    fn no_tie_rule(&self) -> bool {
        self.0.no_tie_rule()
    }
    fn diamond_exit_latitude(&self) -> bool {
        self.0.diamond_exit_latitude()
    }
    fn fixed_line_parameter(&self, rule: LineRule) -> Option<LineT> {
        self.0.fixed_line_parameter(rule)
    }
    fn rectangle_border_no_tie_rule(&self) -> bool {
        self.0.rectangle_border_no_tie_rule()
    }
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        self.0.fixed_clip_rules()
    }
    fn screen_viewport(&self, scene: &Scene, plan: &Plan) -> Option<ScreenViewport> {
        self.0.screen_viewport(scene, plan)
    }
    fn fixed_subpixel_bits(&self) -> Option<u32> {
        self.0.fixed_subpixel_bits()
    }
    fn fixed_snapping(&self) -> Option<Snapping> {
        self.0.fixed_snapping()
    }
    fn fixed_sample_pattern(&self) -> Option<Pattern> {
        self.0.fixed_sample_pattern()
    }
    fn fixed_y_direction(&self) -> Option<YDirection> {
        self.0.fixed_y_direction()
    }
    fn fixed_pixel_centre(&self) -> Option<PixelCentre> {
        self.0.fixed_pixel_centre()
    }
    fn fixed_interpolate_from(&self) -> Option<InterpolateFrom> {
        self.0.fixed_interpolate_from()
    }
    fn fixed_point_clip(&self) -> Option<PointClip> {
        self.0.fixed_point_clip()
    }
    fn fixed_point_bounds(&self) -> Option<PointBounds> {
        self.0.fixed_point_bounds()
    }
}
