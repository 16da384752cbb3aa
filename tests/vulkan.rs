//! The `vulkan` adapter (raw Vulkan through ash) against the exact
//! reference: on CI, Mesa's lavapipe; on a machine with a GPU, its driver
//! (`RASTERCHECK_VULKAN_DEVICE` picks one). Needs the `vulkan` feature and
//! the system packages `libvulkan1 mesa-vulkan-drivers`. Without a device
//! each test says loudly that it skipped; under `CI=true` a missing device
//! fails the test instead.
#![cfg(feature = "vulkan")]

use rastercheck::adapters::vulkan::{self, Vulkan};
use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::{PolygonFill, Primitive, Scene};

/// The adapter as `-r vulkan` makes it: native MSAA where the device has
/// the pattern, shifted passes otherwise.
const VULKAN: Vulkan = Vulkan { passes_only: false };

mod common;
use common::adapters::{
    assert_each, assert_interpolation_within_the_bound, assert_judges_at_least_85_percent,
    assert_probe_diagnosis, assert_wrong_instants_fail, bundled_ids, INTERPOLATION, TIE_CASES,
    WINDING_CASES,
};
use common::sample_drivers::{
    assert_each_probe_lights_its_slot, assert_reversed_slots_fail, probe_scene, STANDARD_4,
};
use common::{case, inline, report};

/// Whether a Vulkan device is here; says why not (SKIPPED, uncaptured),
/// and fails under CI.
fn available() -> bool {
    common::adapters::driver_here(
        "vulkan",
        vulkan::device_description(),
        "Vulkan device",
        "libvulkan1 mesa-vulkan-drivers",
    )
}

fn run(scene: &Scene) -> (oracle::ReferenceRun, judge::CandidateRun) {
    common::run(scene, &VULKAN)
}

/// probe finds a point sampler at the centre with top-left ties: the
/// sampler decision and the rule agree with what the cases show.
#[test]
fn probe_finds_a_point_sampler_with_top_left_ties() {
    if !available() {
        return;
    }
    assert_probe_diagnosis(&VULKAN, "top-left");
}

#[test]
fn matches_the_reference_on_top_left_tie_and_winding_cases() {
    if !available() {
        return;
    }
    assert_each(
        &[TIE_CASES, WINDING_CASES].concat(),
        &VULKAN,
        |_| {},
        |_, run, line, failures| {
            if run.verdict != Verdict::Pass {
                failures.push(line.to_owned());
            }
        },
    );
}

#[test]
fn interpolation_is_within_the_bound() {
    if !available() {
        return;
    }
    assert_interpolation_within_the_bound(INTERPOLATION, &VULKAN, "vulkan", |_| {});
}

/// Every bundled polygon case written for top-left (the device's own tie
/// rule) passes: stencil then cover fills each sample its winding number
/// and fill rule fill, even-odd and nonzero, holes and self-crossings.
#[test]
fn polygons_by_stencil_then_cover_match_the_reference() {
    if !available() {
        return;
    }
    let ids: Vec<String> = bundled_ids("polygons", |_| true)
        .into_iter()
        .filter(|id| case(id).rules.fill_rule.name() == "top-left")
        .collect();
    assert!(ids.len() > 20, "{ids:?}");
    let ids: Vec<&str> = ids.iter().map(String::as_str).collect();
    assert_each(
        &ids,
        &VULKAN,
        |_| {},
        |_, run, line, failures| {
            if run.verdict != Verdict::Pass {
                failures.push(line.to_owned());
            }
        },
    );
}

/// The adapter with each polygon's fill rule swapped (even-odd for
/// nonzero and back): the stencil's test is what decides, and the check
/// sees it.
struct FillSwapped;

impl Rasterizer for FillSwapped {
    fn name(&self) -> &str {
        "vulkan-fill-swapped"
    }

    fn capabilities(&self) -> Capabilities {
        VULKAN.capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut scene = scene.clone();
        for p in &mut scene.primitives {
            if let Primitive::Polygon(p) = p {
                p.fill = match p.fill {
                    PolygonFill::EvenOdd => PolygonFill::NonZero,
                    PolygonFill::NonZero => PolygonFill::EvenOdd,
                };
            }
        }
        VULKAN.rasterize(&scene, plan)
    }
}

#[test]
fn a_wrong_stencil_test_fails() {
    if !available() {
        return;
    }
    // Two overlapping squares wound the same way: winding 2 where they
    // overlap, filled by nonzero and empty under even-odd.
    let scene = inline(
        r#"{"name": "overlap", "canvas": {"width": 8, "height": 8},
            "primitives": [{"contours": [[[1, 1], [5, 1], [5, 5], [1, 5]],
                                         [[3, 3], [7, 3], [7, 7], [3, 7]]],
                            "fill": "nonzero"}]}"#,
    );
    let (reference, right) = run(&scene);
    assert_eq!(
        right.verdict,
        Verdict::Pass,
        "{}",
        report("overlap", &reference, &right)
    );
    let wrong = judge::run_candidate(&scene, &reference, &FillSwapped);
    let m = wrong.metrics.as_ref().unwrap();
    assert_eq!(
        m.coverage.missing,
        4,
        "{}",
        report("overlap", &reference, &wrong)
    );
}

/// The patterns the probes use: 8× n-rooks (no device's native pattern:
/// shifted passes) and standard 4× (`STANDARD_4`: native MSAA where the
/// device offers 4×, lavapipe among them).
const N_ROOKS_8: &str = r#"{"samples": 8, "pattern": "n-rooks", "seed": 7, "position_bits": 4}"#;

/// Each probe lights exactly its own slot, through `vulkan` (native 4×
/// where offered, shifted passes for n-rooks) and `vulkan-passes`.
#[test]
fn each_probe_lights_exactly_the_probed_slot() {
    if !available() {
        return;
    }
    let passes = Vulkan { passes_only: true };
    for (pattern, n) in [(N_ROOKS_8, 8), (STANDARD_4, 4)] {
        for candidate in [&VULKAN, &passes] {
            assert_each_probe_lights_its_slot(candidate, pattern, n);
        }
    }
}

/// lavapipe offers 4×: the standard 4× probe is multisampled natively, and
/// the declared description says which counts are.
#[test]
fn standard_4x_is_drawn_natively_where_offered() {
    if !available() {
        return;
    }
    let declared = VULKAN.declared().unwrap();
    eprintln!("{declared}");
    let passes = Vulkan { passes_only: true }.declared().unwrap();
    assert!(passes.contains("shifted passes only"), "{passes}");
    if vulkan::device_description().is_ok_and(|d| d.contains("llvmpipe")) {
        assert!(
            declared.contains("native MSAA at the standard locations (4x)"),
            "{declared}"
        );
    }
}

/// The adapter with each pixel's slots read back in reverse fails both
/// probes, so the slot order is checked, not assumed.
#[test]
fn a_readback_in_the_wrong_slot_order_fails() {
    if !available() {
        return;
    }
    for (pattern, n) in [(N_ROOKS_8, 8), (STANDARD_4, 4)] {
        assert_reversed_slots_fail(&VULKAN, pattern, &probe_scene(pattern, n));
    }
}

/// Every bundled antialiased case whose offsets lie on the device's grid
/// and whose rule is top-left is drawn, and each is listed.
#[test]
fn every_antialias_case_is_judged() {
    if !available() {
        return;
    }
    for id in bundled_ids("antialias", |_| true) {
        let scene = case(&id);
        let (reference, run) = run(&scene);
        eprintln!("{}", report(&id, &reference, &run));
        assert!(
            !matches!(run.verdict, Verdict::Error(_)),
            "{id}: {:?}",
            run.verdict
        );
        if let Verdict::Unsupported(why) = &run.verdict {
            assert!(
                why.contains("off the driver's grid") || why.contains("line"),
                "{id}: {why}"
            );
        }
    }
}

/// Moving cases by time passes: every bundled top-left moving case passes
/// its time-coverage bounds.
#[test]
fn moving_cases_by_time_passes_pass() {
    if !available() {
        return;
    }
    let ids: Vec<String> = bundled_ids("motion", |_| true)
        .into_iter()
        .filter(|id| case(id).rules.fill_rule.name() == "top-left")
        .collect();
    let ids: Vec<&str> = ids.iter().map(String::as_str).collect();
    assert_each(
        &ids,
        &VULKAN,
        |_| {},
        |_, run, line, failures| {
            if matches!(run.verdict, Verdict::Fail(_) | Verdict::Error(_)) {
                failures.push(line.to_owned());
            }
        },
    );
}

/// A wrong shutter is caught (`assert_wrong_instants_fail`).
#[test]
fn wrong_instants_fail() {
    if !available() {
        return;
    }
    assert_wrong_instants_fail(&VULKAN);
}

/// Issue 19's bar: at least 85 % of the bundled cases are judged (passed or
/// failed), and every case left unsupported says why in one of the
/// adapter's known words; none breaks.
#[test]
fn judges_at_least_85_percent_of_the_bundled_cases() {
    if !available() {
        return;
    }
    let known = [
        "midpoint rule",
        "strictLines",
        "Bresenham",
        "rectangular lines",
    ];
    assert_judges_at_least_85_percent(&VULKAN, &known);
}

#[test]
fn the_report_names_the_device_and_driver() {
    if !available() {
        return;
    }
    let declared = VULKAN.declared().expect("a device is made");
    assert!(declared.contains("Vulkan 1."), "{declared}");
    assert!(declared.contains("shifted passes"), "{declared}");
    assert!(rastercheck::registry::names().contains(&vulkan::NAME));
}

#[test]
fn clip_space_honours_the_provoking_vertex() {
    if !available() {
        return;
    }
    common::clip_drivers::assert_provoking_vertex(&VULKAN);
}

#[test]
fn clip_space_depth_is_clipped_or_clamped() {
    if !available() {
        return;
    }
    common::clip_drivers::assert_depth_clip_and_clamp(&VULKAN);
}

#[test]
fn clip_space_refuses_what_it_cannot_hand_the_driver() {
    if !available() {
        return;
    }
    common::clip_drivers::assert_clip_refusals(&VULKAN);
}

/// The device's clipping conventions (`fixed_clip_rules`) hold sample for
/// sample on scenes that separate them, and the other conventions do not.
#[test]
fn clip_space_follows_its_declared_clipping_conventions() {
    if !available() {
        return;
    }
    common::clip_drivers::assert_clip_conventions(&VULKAN);
}

#[test]
fn clip_space_viewport_places_the_scene() {
    if !available() {
        return;
    }
    common::clip_drivers::assert_viewport_placement(&VULKAN);
}

#[test]
fn clip_space_inside_the_volume_passes() {
    if !available() {
        return;
    }
    common::clip_drivers::assert_inside_the_volume_passes(&VULKAN);
}

/// The device interpolates from the positions it declares
/// (`fixed_interpolate_from`: lavapipe's unsnapped ones), and not from
/// the others.
#[test]
fn clip_space_values_come_from_the_declared_positions() {
    if !available() {
        return;
    }
    let (own, other) = common::clip_drivers::assert_values_from_declared_positions(&VULKAN);
    eprintln!("vulkan: values depart {own:e} from its own positions', {other:e} from the others'");
}

/// What the device does with points (a measurement that checks
/// nothing: `--ignored --nocapture`; SPEC.md §17.4).
#[test]
#[ignore]
fn measure_points() {
    if !available() {
        return;
    }
    common::point_drivers::measure(&VULKAN);
}

/// Points follow the point rule under the device's own fill rule in screen
/// space: every size at every subpixel centre, and overlapping points
/// with their flat values and depth.
#[test]
fn points_follow_the_rule_in_screen_space() {
    if !available() {
        return;
    }
    common::point_drivers::assert_screen_points(&VULKAN);
}

/// Clip-space points: placed by the viewport, touching its edges, the
/// depth planes under clip and clamp, w ≤ 0.
#[test]
fn points_follow_the_rule_in_clip_space() {
    if !available() {
        return;
    }
    common::point_drivers::assert_clip_points(&VULKAN);
}

#[test]
fn multisampled_points_follow_the_rule() {
    if !available() {
        return;
    }
    common::point_drivers::assert_multisampled_points(&VULKAN);
}

/// Sub-pixel sizes, sizes off the grid or out of range, and clip-space
/// squares reaching across a viewport edge off the pixel grid are refused
/// with the reason.
#[test]
fn points_the_driver_cannot_draw_exactly_are_refused() {
    if !available() {
        return;
    }
    common::point_drivers::assert_point_refusals(&VULKAN);
}

/// Clip-space squares reaching outside the viewport are cut at its side
/// (`point_bounds: viewport`, SPEC.md §17.4), and the canvas-bounded rule
/// is told apart.
#[test]
fn point_squares_are_cut_at_the_viewport() {
    if !available() {
        return;
    }
    common::point_drivers::assert_squares_cut_at_the_viewport(&VULKAN);
}

/// probe finds the point clipping the adapter declares.
#[test]
fn probe_finds_the_declared_point_clipping() {
    if !available() {
        return;
    }
    common::point_drivers::assert_probe_finds_declared_point_clipping(&VULKAN);
}

/// The point checks catch the opposite ties, snapped sizes and an
/// unsnapped centre.
#[test]
fn wrong_point_rules_are_caught() {
    if !available() {
        return;
    }
    common::point_drivers::assert_wrong_rules_are_caught(&VULKAN);
}

/// A clip-space case with points is judged under the driver's own
/// `clip_points` (guard band), and says so; one without points keeps the
/// case's.
#[test]
fn clip_points_are_judged_under_the_drivers_own() {
    common::point_drivers::assert_judged_under_own_point_clip(&VULKAN);
}

/// SPEC.md §18 on the device's own depth attachment: every bundled depth
/// case (unorm16, unorm24, float32, polygon offset with slope and clamp,
/// screen and clip space) is judged and passes (lavapipe: 17 of 17).
#[test]
fn depth_formats_and_offset_pass() {
    if !available() {
        return;
    }
    common::depth_drivers::assert_depth_cases_pass(&VULKAN);
}

/// The same device without its offset, or storing unorm depth as f32,
/// fails the cases that show it: the read-back is the attachment's.
#[test]
fn a_wrong_depth_attachment_fails() {
    if !available() {
        return;
    }
    common::depth_drivers::assert_wrong_depth_is_caught(&VULKAN);
}

/// unorm16 and float32 depth under a standard pattern the device
/// multisamples is drawn into its own multisampled depth attachment and
/// read back sample by sample (`native MSAA`), unorm24 by shifted passes
/// (its values near 1 cannot be read through a float); both pass, and the
/// native read-back is what `a_wrong_depth_attachment_fails` catches
/// without its offset.
#[test]
fn multisampled_depth_is_read_back_sample_by_sample() {
    if !available() {
        return;
    }
    for (id, method) in [
        ("depth/offset_constant_standard4", "native MSAA"),
        ("depth/offset_negative_standard4", "native MSAA"),
        ("depth/unorm24_half_way_standard4", "shifted passes"),
    ] {
        let (reference, run) = run(&case(id));
        eprintln!("{}", report(id, &reference, &run));
        assert_eq!(run.verdict, Verdict::Pass, "{id}");
        let frame = run.frame.expect("a frame");
        assert_eq!(frame.method, Some(method), "{id}");
    }
}
