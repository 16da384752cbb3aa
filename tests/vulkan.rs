//! The `vulkan` adapter (raw Vulkan through ash) against the exact
//! reference: on CI, Mesa's lavapipe and, in a second process of this
//! binary (`the_same_tests_pass_on_swiftshader`), Google's SwiftShader; on
//! a machine with a GPU, its driver (`RASTERCHECK_VULKAN_DEVICE` picks
//! one). Needs the `vulkan` feature and the system packages `libvulkan1
//! mesa-vulkan-drivers vulkan-validationlayers chromium`. Every test runs
//! with the Khronos validation layer and fails on any message the
//! adapter's messenger hears (its API record). Without a device, the layer
//! or SwiftShader's ICD, a test says loudly that it skipped that part;
//! under `CI=true` it fails instead.
#![cfg(feature = "vulkan")]

use std::path::PathBuf;
use std::sync::OnceLock;

use rastercheck::adapters::vulkan::{self, Vulkan};
use rastercheck::frame::Frame;
use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::{PolygonFill, Primitive, Scene};

/// The adapter as `-r vulkan` makes it: native MSAA where the device has
/// the pattern, shifted passes otherwise.
const VULKAN: Vulkan = Vulkan {
    passes_only: false,
    on: None,
};

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

/// Set in the process `the_same_tests_pass_on_swiftshader` starts: its
/// device must be SwiftShader.
const ON_SWIFTSHADER: &str = "RASTERCHECK_TESTS_ON_SWIFTSHADER";

/// SwiftShader's ICD file: `RASTERCHECK_SWIFTSHADER_ICD`, or where Debian's
/// `chromium-common` puts it.
fn swiftshader_icd() -> PathBuf {
    std::env::var_os("RASTERCHECK_SWIFTSHADER_ICD")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("/usr/lib/chromium/vk_swiftshader_icd.json"))
}

/// Asks for the Khronos validation layer once per process, before the
/// device is made; where it is not installed, each test says so (SKIPPED,
/// failing under CI) and runs unvalidated.
fn ask_for_validation() {
    static ASKED: OnceLock<Result<(), String>> = OnceLock::new();
    if let Err(why) = ASKED.get_or_init(vulkan::ask_for_validation) {
        common::adapters::skipped("Khronos validation layer", "vulkan-validationlayers", why);
    }
}

/// Whether a Vulkan device is here (with the validation layer on); says
/// why not (SKIPPED, uncaptured), and fails under CI. The guard it gives
/// fails the test where the API record is not clean when the test ends.
fn available() -> Option<CleanRecord> {
    ask_for_validation();
    let here = common::adapters::driver_here(
        "vulkan",
        vulkan::device_description(),
        "Vulkan device",
        "libvulkan1 mesa-vulkan-drivers",
    );
    if !here {
        return None;
    }
    if std::env::var_os(ON_SWIFTSHADER).is_some() {
        let description = vulkan::device_description().unwrap_or_default();
        assert!(
            description.contains("SwiftShader"),
            "{ON_SWIFTSHADER} is set and the device is {description}"
        );
    }
    Some(CleanRecord)
}

/// Asserts, when a test that drew ends without a panic of its own, that
/// the messenger heard nothing (SPEC.md §10, `api_record`). The record is
/// the process's: a message any test caused fails the tests that end
/// after it, each naming the first message.
struct CleanRecord;

impl Drop for CleanRecord {
    fn drop(&mut self) {
        if std::thread::panicking() {
            return;
        }
        let record = VULKAN.api_record().expect("the device is made");
        eprintln!("vulkan: API record: {record}");
        assert!(record.is_clean(), "vulkan: API record: {record}");
    }
}

fn run(scene: &Scene) -> (oracle::ReferenceRun, judge::CandidateRun) {
    common::run(scene, &VULKAN)
}

/// probe finds a point sampler at the centre with top-left ties: the
/// sampler decision and the rule agree with what the cases show.
#[test]
fn probe_finds_a_point_sampler_with_top_left_ties() {
    let Some(_record) = available() else {
        return;
    };
    assert_probe_diagnosis(&VULKAN, "top-left");
}

/// A screen-space scene whose triangles reach past the target, a shared
/// edge crossing its border, matches the reference sample for sample: it
/// is drawn through a viewport enclosing it (`gpu/view.rs`), and the
/// foil, drawn through the target's viewport, is caught.
#[test]
fn triangles_past_the_target_are_not_clipped() {
    let Some(_record) = available() else {
        return;
    };
    common::viewport_drivers::assert_drawn_unclipped(&VULKAN);
}

/// An antialiased polygon far past the largest viewport, drawn by shifted
/// passes, is clipped at the one rectangle the adapter reports, so that
/// it passes under the restatement (SPEC.md §16.9): each pass's viewport
/// moves with its shift. The foil, each pass through a viewport that
/// stays while the scene moves (what the adapter did before), is caught.
/// Far triangles with attributes, clipped by the driver at its viewport,
/// pass under the restatement whose pieces take their values from the
/// whole triangles (SPEC.md §16.9; `tests/data/far_values_clipped.json`,
/// found by `fuzz -r gl`); the frame fails the case judged unclipped and
/// the pieces judged without values.
#[test]
fn far_values_clipped_at_the_viewport_pass() {
    let Some(_record) = available() else {
        return;
    };
    common::viewport_drivers::assert_far_values_judged_clipped(&VULKAN);
}

#[test]
fn shifted_passes_are_clipped_at_one_rectangle() {
    let Some(_record) = available() else {
        return;
    };
    common::shifted_view_drivers::assert_passes_clipped_at_one_rectangle(&VULKAN);
}

#[test]
fn matches_the_reference_on_top_left_tie_and_winding_cases() {
    let Some(_record) = available() else {
        return;
    };
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
    let Some(_record) = available() else {
        return;
    };
    assert_interpolation_within_the_bound(INTERPOLATION, &VULKAN, "vulkan", |_| {});
}

/// Every bundled polygon case written for top-left (the device's own tie
/// rule) passes: stencil then cover fills each sample its winding number
/// and fill rule fill, even-odd and nonzero, holes and self-crossings.
#[test]
fn polygons_by_stencil_then_cover_match_the_reference() {
    let Some(_record) = available() else {
        return;
    };
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
    let Some(_record) = available() else {
        return;
    };
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
    let Some(_record) = available() else {
        return;
    };
    let passes = Vulkan {
        passes_only: true,
        on: None,
    };
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
    let Some(_record) = available() else {
        return;
    };
    let declared = VULKAN.declared().unwrap();
    eprintln!("{declared}");
    let passes = Vulkan {
        passes_only: true,
        on: None,
    }
    .declared()
    .unwrap();
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
    let Some(_record) = available() else {
        return;
    };
    for (pattern, n) in [(N_ROOKS_8, 8), (STANDARD_4, 4)] {
        assert_reversed_slots_fail(&VULKAN, pattern, &probe_scene(pattern, n));
    }
}

/// Every bundled antialiased case whose offsets lie on the device's grid
/// and whose rule is top-left is drawn, and each is listed.
#[test]
fn every_antialias_case_is_judged() {
    let Some(_record) = available() else {
        return;
    };
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
    let Some(_record) = available() else {
        return;
    };
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
    let Some(_record) = available() else {
        return;
    };
    assert_wrong_instants_fail(&VULKAN);
}

/// Issue 19's bar: at least 85 % of the bundled cases are judged (passed or
/// failed), and every case left unsupported says why in one of the
/// adapter's known words; none breaks.
#[test]
fn judges_at_least_85_percent_of_the_bundled_cases() {
    let Some(_record) = available() else {
        return;
    };
    // A device limit each: a rule no mode draws, a line mode, a width.
    let known = [
        "midpoint rule",
        "strictLines",
        "Bresenham",
        "rectangular lines",
        "(no wideLines)",
        "off the driver's grid",
    ];
    // Issue 35's bars: 85 % for lavapipe, 80 % for SwiftShader (4 bits: the
    // offsets of more antialias patterns are off its grid; no wide lines).
    if std::env::var_os(ON_SWIFTSHADER).is_some() {
        common::adapters::assert_judges_at_least(&VULKAN, &known, 0.80);
    } else {
        assert_judges_at_least_85_percent(&VULKAN, &known);
    }
}

#[test]
fn the_report_names_the_device_and_driver() {
    let Some(_record) = available() else {
        return;
    };
    let declared = VULKAN.declared().expect("a device is made");
    assert!(declared.contains("Vulkan 1."), "{declared}");
    assert!(declared.contains("shifted passes"), "{declared}");
    assert!(rastercheck::registry::names().contains(&vulkan::NAME));
}

#[test]
fn clip_space_honours_the_provoking_vertex() {
    let Some(_record) = available() else {
        return;
    };
    common::clip_drivers::assert_provoking_vertex(&VULKAN);
}

#[test]
fn clip_space_depth_is_clipped_or_clamped() {
    let Some(_record) = available() else {
        return;
    };
    common::clip_drivers::assert_depth_clip_and_clamp(&VULKAN);
}

#[test]
fn clip_space_refuses_what_it_cannot_hand_the_driver() {
    let Some(_record) = available() else {
        return;
    };
    common::clip_drivers::assert_clip_refusals(&VULKAN);
}

/// The device's clipping conventions (`fixed_clip_rules`) hold sample for
/// sample on scenes that separate them, and the other conventions do not.
#[test]
fn clip_space_follows_its_declared_clipping_conventions() {
    let Some(_record) = available() else {
        return;
    };
    common::clip_drivers::assert_clip_conventions(&VULKAN);
}

#[test]
fn clip_space_viewport_places_the_scene() {
    let Some(_record) = available() else {
        return;
    };
    common::clip_drivers::assert_viewport_placement(&VULKAN);
}

#[test]
fn clip_space_inside_the_volume_passes() {
    let Some(_record) = available() else {
        return;
    };
    common::clip_drivers::assert_inside_the_volume_passes(&VULKAN);
}

/// The device interpolates from the positions it declares
/// (`fixed_interpolate_from`: lavapipe's unsnapped ones), and not from
/// the others.
#[test]
fn clip_space_values_come_from_the_declared_positions() {
    let Some(_record) = available() else {
        return;
    };
    let (own, other) = common::clip_drivers::assert_values_from_declared_positions(&VULKAN);
    eprintln!("vulkan: values depart {own:e} from its own positions', {other:e} from the others'");
}

/// What the device does with points (a measurement that checks
/// nothing: `--ignored --nocapture`; SPEC.md §17.4).
#[test]
#[ignore]
fn measure_points() {
    let Some(_record) = available() else {
        return;
    };
    common::point_drivers::measure(&VULKAN);
}

/// Points follow the point rule under the device's own fill rule in screen
/// space: every size at every subpixel centre, and overlapping points
/// with their flat values and depth.
#[test]
fn points_follow_the_rule_in_screen_space() {
    let Some(_record) = available() else {
        return;
    };
    common::point_drivers::assert_screen_points(&VULKAN);
}

/// Clip-space points: placed by the viewport, touching its edges, the
/// depth planes under clip and clamp, w ≤ 0.
#[test]
fn points_follow_the_rule_in_clip_space() {
    let Some(_record) = available() else {
        return;
    };
    common::point_drivers::assert_clip_points(&VULKAN);
}

#[test]
fn multisampled_points_follow_the_rule() {
    let Some(_record) = available() else {
        return;
    };
    common::point_drivers::assert_multisampled_points(&VULKAN);
}

/// Sub-pixel sizes, sizes off the grid or out of range, and clip-space
/// squares reaching across a viewport edge off the pixel grid are refused
/// with the reason.
#[test]
fn points_the_driver_cannot_draw_exactly_are_refused() {
    let Some(_record) = available() else {
        return;
    };
    common::point_drivers::assert_point_refusals(&VULKAN);
}

/// Clip-space squares reaching outside the viewport are cut at its side
/// (`point_bounds: viewport`, SPEC.md §17.4), and the canvas-bounded rule
/// is told apart.
#[test]
fn point_squares_are_cut_at_the_viewport() {
    let Some(_record) = available() else {
        return;
    };
    common::point_drivers::assert_squares_cut_at_the_viewport(&VULKAN);
}

/// probe finds the point clipping the adapter declares.
#[test]
fn probe_finds_the_declared_point_clipping() {
    let Some(_record) = available() else {
        return;
    };
    common::point_drivers::assert_probe_finds_declared_point_clipping(&VULKAN);
}

/// The point checks catch the opposite ties, snapped sizes and an
/// unsnapped centre.
#[test]
fn wrong_point_rules_are_caught() {
    let Some(_record) = available() else {
        return;
    };
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
    let Some(_record) = available() else {
        return;
    };
    common::depth_drivers::assert_depth_cases_pass(&VULKAN);
}

/// The same device without its offset, or storing unorm depth as f32,
/// fails the cases that show it: the read-back is the attachment's.
#[test]
fn a_wrong_depth_attachment_fails() {
    let Some(_record) = available() else {
        return;
    };
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
    let Some(_record) = available() else {
        return;
    };
    for (id, method) in [
        ("depth/offset_constant_standard4", "native MSAA"),
        ("depth/offset_negative_standard4", "native MSAA"),
        ("depth/unorm24_half_way_standard4", "shifted passes"),
    ] {
        let (reference, run) = run(&case(id));
        eprintln!("{}", report(id, &reference, &run));
        if common::depth_drivers::format_refused(&run).is_some() {
            // A device limit (SwiftShader has no unorm24).
            continue;
        }
        assert_eq!(run.verdict, Verdict::Pass, "{id}");
        let frame = run.frame.expect("a frame");
        assert_eq!(frame.method, Some(method), "{id}");
    }
}

/// The messenger hears the Khronos validation layer: a device of its own,
/// made with the layer, given a sampler that breaks
/// `vulkan::INVALID_CALL_VUID`, has a record with that message first.
/// The real layer, no mock; the shared device's record stays clean.
#[test]
fn the_api_record_hears_a_deliberately_invalid_call() {
    let Some(_record) = available() else {
        return;
    };
    let record = match vulkan::invalid_call_record() {
        Ok(record) => record,
        Err(why) => {
            common::adapters::skipped("Khronos validation layer", "vulkan-validationlayers", &why);
            return;
        }
    };
    eprintln!("the invalid call's record: {record}");
    assert!(!record.is_clean(), "{record}");
    assert!(record.errors >= 1, "{record}");
    let first = record.first.as_deref().unwrap_or_default();
    assert!(first.contains(vulkan::INVALID_CALL_VUID), "{record}");
    assert_eq!(
        record.validated_by.as_deref(),
        Some("the Khronos validation layer")
    );
    let shown = record.to_string();
    assert!(shown.contains(" errors, "), "{shown}");
    assert!(shown.contains("undefined behaviour"), "{shown}");
}

/// A run with the layer asked for (`RASTERCHECK_VULKAN_VALIDATION=1`)
/// shows the API record on the console and in report.json's rasterizer
/// entry.
#[test]
fn a_run_reports_its_api_record() {
    let Some(_record) = available() else {
        return;
    };
    let dir = common::cli::scratch("vulkan_api_record");
    let case = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/cases/triangles/fan_16_center.json"
    );
    let report = dir.join("report");
    let out = common::cli::rastercheck_env(
        &dir,
        &[
            "run",
            case,
            "-r",
            "vulkan",
            "--report",
            report.to_str().unwrap(),
        ],
        &[("RASTERCHECK_VULKAN_VALIDATION", "1")],
    );
    let text = common::text(&out);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(
        text.contains("vulkan: API record: 0 messages (checked by the Khronos validation layer)"),
        "{text}"
    );
    let json = common::cli::read_json(&report.join("report.json"));
    let record = &json["rasterizers"][0]["api_record"];
    assert_eq!(record["errors"], 0, "{record}");
    assert_eq!(record["warnings"], 0, "{record}");
    assert_eq!(
        record["validated_by"], "the Khronos validation layer",
        "{record}"
    );
}

/// The tests of this binary that fail on SwiftShader (Debian chromium
/// 148's, 4 subpixel bits) today, each with what it showed and the named
/// departure (`docs/drivers/departures/swiftshader/`) that explains it, and
/// none hidden: `the_same_tests_pass_on_swiftshader` fails on any other
/// failure, and on any of these passing (take it off the list then).
/// docs/drivers/vulkan.md "SwiftShader" keeps the same list.
const FAILING_ON_SWIFTSHADER: &[(&str, &str)] = &[
    ("clip_space_values_come_from_the_declared_positions", "clip/interp_perspective_clipped_gb_cts departs 9.7e-3 from the snapped positions' values it declares: SwiftShader sets a clipped piece's planes up from the whole triangle's snapped vertices (departure swiftshader/clipped-piece-values-from-the-whole-triangle; the unclipped clip/spec_interpolate_snapped matches)"),
    ("depth_formats_and_offset_pass", "depth/offset_negative_standard4 (departure swiftshader/multisampled-depth-at-mirrored-x) and, in some runs, depth/offset_line_ignored (departure swiftshader/line-depth-offset-from-an-earlier-draw) fail on depth; unorm24 is left out as a device limit"),
    ("multisampled_depth_is_read_back_sample_by_sample", "depth/offset_negative_standard4: 100 samples outside the float32 depths allowed (1.17e-2 = 2 x 0.375 px x dz/dx 1/64): departure swiftshader/multisampled-depth-at-mirrored-x"),
    ("shifted_passes_are_clipped_at_one_rectangle", "hard/poly_far_zigzag_b8_*_standard16: 25 missing samples of 3392 each, along two edges through the canvas drawn from new vertices SwiftShader clips in f32, which land across a rounding boundary of its 1/16 px grid (departure swiftshader/far-meshes-clipped-in-float); the foil, each pass through a viewport that stays while the scene moves, fails too (36 missing, 12 extra)"),
    ("polygons_by_stencil_then_cover_match_the_reference", "every judged polygon case passes; polygons/circle_64_aa_stratified256 is unsupported (its offsets are off the 4-bit grid, a device limit), which the test does not allow"),
    (
        "judges_at_least_85_percent_of_the_bundled_cases",
        "79.0 % of the triangles, lines, hard, antialias, motion and polygons cases judged (279 of 353; issue 35's bar for SwiftShader is 80 %); every other one refused for a device limit (no wide lines, antialias offsets off its 4-bit grid)",
    ),
];

/// Every test of this binary again, in a process of its own on SwiftShader
/// (`VK_DRIVER_FILES` at its ICD, `RASTERCHECK_VULKAN_DEVICE=SwiftShader`),
/// with the validation layer (asked for by the tests, and turned on the
/// loader's way too, `VK_INSTANCE_LAYERS`, as a user would: the loader's
/// notice that it added the layer is no message about the calls, and once
/// marked every verdict as resting on undefined behaviour): each must pass
/// there too, but those of
/// [`FAILING_ON_SWIFTSHADER`], which must fail (each is printed with what
/// it showed). Its output is shown when it departs from that. Without
/// the ICD it says it skipped (under `CI=true`, fails).
#[test]
fn the_same_tests_pass_on_swiftshader() {
    if std::env::var_os(ON_SWIFTSHADER).is_some() {
        return;
    }
    let icd = swiftshader_icd();
    if !icd.is_file() {
        common::adapters::skipped(
            "SwiftShader Vulkan ICD",
            "chromium (chromium-common ships vk_swiftshader_icd.json; or set RASTERCHECK_SWIFTSHADER_ICD)",
            &format!("{} is not a file", icd.display()),
        );
        return;
    }
    let exe = std::env::current_exe().expect("this test binary");
    let started = std::time::Instant::now();
    let out = std::process::Command::new(exe)
        .args(["--skip", "the_same_tests_pass_on_swiftshader"])
        .env("VK_DRIVER_FILES", &icd)
        .env("RASTERCHECK_VULKAN_DEVICE", "SwiftShader")
        .env("VK_INSTANCE_LAYERS", "VK_LAYER_KHRONOS_validation")
        .env(ON_SWIFTSHADER, "1")
        .output()
        .expect("this test binary runs again");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let summary = stdout
        .lines()
        .filter(|l| l.starts_with("test result:"))
        .collect::<Vec<_>>()
        .join("\n");
    eprintln!(
        "on SwiftShader ({}), in {:.0} s: {summary}",
        icd.display(),
        started.elapsed().as_secs_f64()
    );
    let ended = |how: &str| -> Vec<&str> {
        stdout
            .lines()
            .filter_map(|l| l.strip_prefix("test ")?.strip_suffix(how))
            .collect()
    };
    let (passed, failed) = (ended(" ... ok"), ended(" ... FAILED"));
    for (name, what) in FAILING_ON_SWIFTSHADER {
        eprintln!("FAILING ON SWIFTSHADER (not yet explained): {name}: {what}");
    }
    let known = |name: &&str| FAILING_ON_SWIFTSHADER.iter().any(|(k, _)| k == name);
    let new_failures: Vec<&&str> = failed.iter().filter(|n| !known(n)).collect();
    let now_passing: Vec<&&str> = passed.iter().filter(|n| known(n)).collect();
    let tail = || {
        format!(
            "on SwiftShader:\n{stdout}\n{}",
            String::from_utf8_lossy(&out.stderr)
        )
    };
    assert!(
        new_failures.is_empty(),
        "new failures {new_failures:?}: {}",
        tail()
    );
    assert!(
        now_passing.is_empty(),
        "{now_passing:?} pass on SwiftShader now: take them off FAILING_ON_SWIFTSHADER"
    );
    assert_eq!(
        failed.len(),
        FAILING_ON_SWIFTSHADER.len(),
        "every listed test ran and failed: {}",
        tail()
    );
    assert!(passed.len() >= 20, "{}", tail());
}
