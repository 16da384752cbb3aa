//! Helpers the driver tests (`gl.rs`, `lavapipe.rs`) share: the bundled case
//! ids of a family, and the sweeps every driver runs over bundled cases
//! (each case held to a check, values within the bound, every triangle case
//! for the record, refusing what it cannot express, the prepared path
//! drawing what the whole call draws). Whether a driver is installed, and
//! its own conventions, stay in its test file.

use std::path::Path;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::{CandidateRun, Verdict};
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::{time::limits::TIME_ONE, Scene};

use super::{case, differences, inline, report, run};

/// Tie cases (samples exactly on edges, shared edges, fan centres) written
/// for top-left, that every driver is held to; each driver adds its own.
pub const TIE_CASES: &[&str] = &[
    "triangles/fill_rule_top_left",
    "triangles/fan_16_center",
    "triangles/fan_16_center_ccw",
    "triangles/fan_16_center_snap_tie",
    "triangles/fan_16_square_ring",
    "triangles/fan_64_center",
    "triangles/shared_edge_diagonal",
    "triangles/shared_edge_antidiagonal",
    "triangles/shared_edge_horizontal",
    "triangles/shared_edge_vertical",
    "triangles/shared_edge_steep",
    "triangles/shared_edge_mixed_windings",
    "triangles/shared_edge_fractions_offgrid",
];

/// Winding cases under each cull: culled triangles draw nothing, kept ones
/// match.
pub const WINDING_CASES: &[&str] = &[
    "triangles/winding_cw_cull_cw",
    "triangles/winding_cw_cull_ccw",
    "triangles/winding_ccw_cull_cw",
    "triangles/winding_ccw_cull_ccw",
    "triangles/cull_cw_mixed_windings",
    "triangles/cull_ccw_mixed_windings",
];

/// Interpolation cases: depth, linear, flat, perspective with a wide range
/// of w.
pub const INTERPOLATION: &[&str] = &[
    "triangles/interp_depth_z",
    "triangles/interp_depth_perspective_w",
    "triangles/interp_flat",
    "triangles/interp_linear",
    "triangles/interp_mixed_modes",
    "triangles/interp_perspective_extreme",
    "triangles/interp_perspective_fan",
    "triangles/interp_perspective_w_range",
];

/// A driver test that cannot run because the driver is missing: under
/// `CI=true` that fails the test (CI installs every driver, `.ci/run`);
/// elsewhere it says SKIPPED on the test's stderr, written straight to the
/// file descriptor so that the test harness's capture does not hide it.
pub fn skipped(what: &str, install: &str, why: &str) {
    use std::io::Write;
    let ci = std::env::var("CI").is_ok_and(|v| v == "true");
    assert!(!ci, "CI=true and no {what} (install {install}): {why}");
    let _ = writeln!(
        std::io::stderr(),
        "SKIPPED: no {what} (install {install}): {why}"
    );
}

/// Whether the driver `described` names is here: says which (on the
/// test's stderr, as `NAME adapter: DESCRIPTION`), or why not ([`skipped`],
/// which fails under CI).
pub fn driver_here(
    name: &str,
    described: Result<String, String>,
    what: &str,
    install: &str,
) -> bool {
    match described {
        Ok(description) => {
            eprintln!("{name} adapter: {description}");
            true
        }
        Err(why) => {
            skipped(what, install, &why);
            false
        }
    }
}

/// probe's diagnosis of a GPU driver: point-sampled at the pixel centre,
/// ties by `rule` explaining every tie sample (Vulkan's top-left;
/// llvmpipe's GL bottom-left in y-down terms), y down, and the subpixel
/// bits Vulkan allows (at least 4, and at most D3D11's 8 of the drivers
/// rastercheck knows; lavapipe's 8 is asserted in `tests/probe.rs`).
pub fn assert_probe_diagnosis(candidate: &dyn Rasterizer, rule: &str) {
    use rastercheck::explore::probe::{self, SamplerKind};
    let p = probe::probe(candidate).unwrap_or_else(|e| panic!("{}: {e}", candidate.name()));
    eprintln!("{}", p.describe());
    assert_eq!(p.sampler, SamplerKind::Point, "{}", p.sampler_evidence);
    assert_eq!(p.fill_rule.as_deref(), Some(rule));
    assert!(p.fill_rule_consistent);
    assert_eq!(p.sample_position, "centre");
    assert_eq!(p.y_down, Some(true));
    assert!(
        p.subpixel_bits.is_some_and(|b| (4..=8).contains(&b)),
        "{}",
        p.subpixel
    );
    // What the adapter declares (SPEC.md §3.2) is what probe measures.
    let declared = p.declared_snapping.as_deref().unwrap_or("declares nothing");
    assert!(
        declared.ends_with("(agrees)"),
        "{}: {declared}",
        candidate.name()
    );
}

/// The ids (`family/stem`) of the bundled cases of `family` whose file stem
/// `keep` accepts, sorted.
pub fn bundled_ids(family: &str, keep: impl Fn(&str) -> bool) -> Vec<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("cases")
        .join(family);
    let mut ids: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            let stem = name.strip_suffix(".json")?;
            keep(stem).then(|| format!("{family}/{stem}"))
        })
        .collect();
    ids.sort();
    ids
}

/// Runs `candidate` on each bundled case of `ids` (changed by `adjust`
/// first) and prints its line; `check` gets the case id, the run and that
/// line and adds what fails to the list, which must stay empty.
pub fn assert_each(
    ids: &[&str],
    candidate: &dyn Rasterizer,
    adjust: impl Fn(&mut Scene),
    mut check: impl FnMut(&str, &CandidateRun, &str, &mut Vec<String>),
) {
    let mut failures = Vec::new();
    for id in ids {
        let mut scene = case(id);
        adjust(&mut scene);
        let (reference, run) = run(&scene, candidate);
        let line = report(id, &reference, &run);
        eprintln!("{line}");
        check(id, &run, &line, &mut failures);
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Each interpolation case of `ids` passes, every channel compared on some
/// sample and within its bound (each channel's errors printed); `name` is
/// the driver's, for the message when it draws no frame.
pub fn assert_interpolation_within_the_bound(
    ids: &[&str],
    candidate: &dyn Rasterizer,
    name: &str,
    adjust: impl Fn(&mut Scene),
) {
    assert_each(ids, candidate, adjust, |id, run, line, failures| {
        let m = run
            .metrics
            .as_ref()
            .unwrap_or_else(|| panic!("{name} drew a frame"));
        assert!(!m.channels.is_empty(), "{id}: no channel was compared");
        for c in &m.channels {
            assert!(c.samples > 0, "{id}: {} compared on no sample", c.channel);
            eprintln!(
                "        {}: max {:.3e} ({:.1} ulp), rms {:.3e}, bound {:.3e}",
                c.channel, c.max_abs, c.max_ulp, c.rms, c.allowed_abs
            );
            if !c.within_bounds() {
                failures.push(format!("{id}: {} max {:e}", c.channel, c.max_abs));
            }
        }
        if run.verdict != Verdict::Pass {
            failures.push(line.to_owned());
        }
    });
}

/// A line is `unsupported`, never passed; a case of unsnapped coordinates
/// is judged at the rasterizer's own subpixel bits.
pub fn assert_refuses_lines_and_judges_unsnapped(candidate: &dyn Rasterizer) {
    let line = inline(
        r#"{"name": "l", "canvas": {"width": 8, "height": 8},
            "primitives": [{"line": [[0.5, 0.5], [7.5, 3.5]]}]}"#,
    );
    assert!(matches!(
        run(&line, candidate).1.verdict,
        Verdict::Unsupported(_)
    ));
    // Unsnapped geometry is drawn on the driver's grid and judged at its
    // bits (SPEC.md §3.2), and named so.
    let scene = case("triangles/unsnapped_dyadic_edges");
    let r = run(&scene, candidate).1;
    assert!(
        !matches!(r.verdict, Verdict::Unsupported(_) | Verdict::Error(_)),
        "{:?}",
        r.verdict
    );
    assert_eq!(r.judged.subpixel_bits, candidate.fixed_subpixel_bits());
    assert!(r.judged.subpixel_bits.is_some());
}

/// Every triangle case once, for the record: each verdict printed, the
/// driver's departures listed rather than hidden; only an error fails
/// (`name broke`).
pub fn record_every_triangle_case(candidate: &dyn Rasterizer, name: &str) {
    let mut errors = Vec::new();
    for id in &bundled_ids("triangles", |_| true) {
        let scene = case(id);
        let (reference, run) = run(&scene, candidate);
        eprintln!("{}", report(id, &reference, &run));
        if let Verdict::Error(why) = &run.verdict {
            errors.push(format!("{id}: {why}"));
        }
    }
    assert!(errors.is_empty(), "{name} broke: {}", errors.join("\n"));
}

/// An 8×8 case `pair` under fill rule `rule`, of `primitives` (the JSON of
/// the primitives array's items), that covers each of its 64 samples once.
pub fn square_of(rule: &str, primitives: &str) -> Scene {
    inline(&format!(
        r#"{{"name": "pair", "canvas": {{"width": 8, "height": 8}},
            "rules": {{"fill_rule": "{rule}"}},
            "primitives": [{primitives}],
            "expect": {{"watertight": true, "samples_covered": 64}}}}"#
    ))
}

/// The case `pair` makes passes under the driver's own rule `own`; under
/// `other` it is judged under `own` (SPEC.md §3.1) and passes, while held
/// to `other`, 8 tie samples change hands and none is missing or extra:
/// the driver does follow `own`.
pub fn assert_eight_ties_change_hands(
    candidate: &dyn Rasterizer,
    pair: impl Fn(&str) -> Scene,
    own: &str,
    other: &str,
) {
    let (_, r) = run(&pair(own), candidate);
    assert_eq!(r.verdict, Verdict::Pass, "{}", judge::describe(&r));
    assert_eq!(r.judged.fill_rule, None);
    let (_, r) = run(&pair(other), candidate);
    assert_eq!(r.verdict, Verdict::Pass, "{}", judge::describe(&r));
    assert_eq!(r.judged.fill_rule.map(|r| r.name()), Some(own));
    let (_, r) = super::run_as_stated(&pair(other), candidate);
    let m = r.metrics.as_ref().unwrap();
    assert_eq!(
        (m.coverage.wrong_owner, m.coverage.missing, m.coverage.extra),
        (8, 0, 0),
        "{}",
        judge::describe(&r)
    );
}

/// The bench's triangle workload at a test's size: 200 random right
/// triangles of legs 50 on a 256² canvas, many of them overlapping.
pub fn bench_like_scene() -> Scene {
    rastercheck::bench::triangle_scene(256, 50, 200, rastercheck::bench::SEED)
}

/// Where `got` departs from `expected`, named `what`: the first samples
/// whose count or owner differ, or the value channels that differ; empty
/// where the frames are equal.
pub fn frame_departures(what: &str, expected: &Frame, got: &Frame) -> Vec<String> {
    if (got.width, got.height, got.samples) != (expected.width, expected.height, expected.samples) {
        return vec![format!(
            "{what}: {}×{}×{} instead of {}×{}×{}",
            got.width, got.height, got.samples, expected.width, expected.height, expected.samples
        )];
    }
    let mut departures: Vec<String> = differences(expected, got, "prepared")
        .into_iter()
        .map(|d| format!("{what}: {d}"))
        .collect();
    if got.depth != expected.depth {
        departures.push(format!("{what}: the depth differs"));
    }
    if got.attributes != expected.attributes {
        departures.push(format!("{what}: the attributes differ"));
    }
    if got.resolved != expected.resolved {
        departures.push(format!("{what}: the resolved coverage differs"));
    }
    departures
}

/// `candidate`'s prepared path (`Rasterizer::prepare`) draws what its
/// whole call draws, on each bundled case of `ids` and on
/// [`bench_like_scene`]: prepare → clear → draw → read back gives
/// `rasterize`'s frame; a second draw without a clear doubles every
/// coverage count and keeps the owners and values (the draw draws into the
/// targets as they stand: a draw that cleared them would give the frame
/// once, one that drew nothing would give it unchanged); and clear → draw
/// gives the frame again (the clear empties every target). Each scene must
/// draw something, and some sample must be covered twice, so that the
/// counts are tested beyond 0 and 1.
pub fn assert_prepared_draws_as_rasterize(candidate: &dyn Rasterizer, ids: &[&str]) {
    let mut scenes: Vec<(&str, Scene)> = ids.iter().map(|&id| (id, case(id))).collect();
    scenes.push(("bench triangles", bench_like_scene()));
    let mut failures = Vec::new();
    let mut overlapped = false;
    for (id, scene) in &scenes {
        let plan = Plan::for_scene(scene);
        let whole = candidate
            .rasterize(scene, &plan)
            .unwrap_or_else(|e| panic!("{id}: rasterize: {e}"));
        assert!(whole.covered_samples() > 0, "{id}: rasterize drew nothing");
        overlapped |= whole.coverage.iter().any(|&c| c > 1);
        let mut doubled = whole.clone();
        doubled.coverage.iter_mut().for_each(|c| *c *= 2);
        if doubled.resolved.is_some() {
            doubled.resolve();
        }

        let mut prepared = candidate
            .prepare(scene, &plan)
            .unwrap_or_else(|| panic!("{id}: prepare covers no scene"))
            .unwrap_or_else(|e| panic!("{id}: prepare: {e}"));
        let mut read = |draws: usize, clear: bool| {
            if clear {
                prepared
                    .clear()
                    .unwrap_or_else(|e| panic!("{id}: clear: {e}"));
            }
            for _ in 0..draws {
                prepared
                    .draw()
                    .unwrap_or_else(|e| panic!("{id}: draw: {e}"));
            }
            prepared
                .read_back()
                .unwrap_or_else(|e| panic!("{id}: read_back: {e}"))
        };
        let once = read(1, true);
        let twice = read(1, false);
        let again = read(1, true);
        let departures = [
            frame_departures("clear, draw", &whole, &once),
            frame_departures("clear, draw, draw", &doubled, &twice),
            frame_departures("clear, draw, draw, clear, draw", &whole, &again),
        ]
        .concat();
        eprintln!(
            "{:<5} {id}: {} samples covered, prepared path {}",
            if departures.is_empty() {
                "PASS"
            } else {
                "FAIL"
            },
            whole.covered_samples(),
            if departures.is_empty() {
                "equal"
            } else {
                "departs"
            }
        );
        failures.extend(departures.into_iter().map(|d| format!("{id}: {d}")));
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(overlapped, "no scene covers a sample twice");
}

/// A driver with each pixel's sample slots read back in reverse: a probe
/// on each sample then lights the wrong slot, so the slot order a driver's
/// read-back gives is checked, not assumed.
pub struct SlotsReversed<'a>(pub &'a dyn Rasterizer);

impl Rasterizer for SlotsReversed<'_> {
    fn name(&self) -> &str {
        "slots-reversed"
    }

    fn capabilities(&self) -> Capabilities {
        self.0.capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut frame = self.0.rasterize(scene, plan)?;
        let n = frame.samples as usize;
        frame.coverage.chunks_mut(n).for_each(<[u16]>::reverse);
        frame.last.chunks_mut(n).for_each(<[u32]>::reverse);
        Ok(frame)
    }
}

/// A driver drawing every moving scene over the whole shutter [0, 1],
/// whatever the case's shutter: its instants are wrong.
struct WholeShutter<'a>(&'a dyn Rasterizer);

impl Rasterizer for WholeShutter<'_> {
    fn name(&self) -> &str {
        "whole-shutter"
    }

    fn capabilities(&self) -> Capabilities {
        self.0.capabilities()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut plan = plan.clone();
        if let Some(motion) = &mut plan.motion {
            motion.blur.shutter = [0, TIME_ONE];
        }
        self.0.rasterize(scene, &plan)
    }
}

/// The time checks catch wrong instants: a case whose shutter closes while
/// the triangle still moves passes through `candidate`, and fails drawn
/// over the whole shutter.
pub fn assert_wrong_instants_fail(candidate: &dyn Rasterizer) {
    let id = "motion/shutter_quarter_to_three_quarters";
    let scene = case(id);
    let reference = oracle::run_reference(&scene);
    let right = judge::run_candidate(&scene, &reference, candidate);
    assert_eq!(
        right.verdict,
        Verdict::Pass,
        "{}",
        report(id, &reference, &right)
    );
    let wrong = judge::run_candidate(&scene, &reference, &WholeShutter(candidate));
    eprintln!("{}", report(id, &reference, &wrong));
    assert!(matches!(wrong.verdict, Verdict::Fail(_)), "{id}");
}

/// Issue 19's bar: `candidate` judges (passes or fails) at least 85 % of
/// the bundled cases; every case it leaves unsupported says why in one of
/// the `known` words; none breaks.
pub fn assert_judges_at_least_85_percent(candidate: &dyn Rasterizer, known: &[&str]) {
    assert_judges_at_least(candidate, known, 0.85);
}

/// [`assert_judges_at_least_85_percent`] with another bar (issue 35's for
/// SwiftShader, a 4-bit device without wide lines: 80 %).
pub fn assert_judges_at_least(candidate: &dyn Rasterizer, known: &[&str], bar: f64) {
    let families = [
        "triangles",
        "lines",
        "hard",
        "antialias",
        "motion",
        "polygons",
    ];
    let mut ids: Vec<String> = families
        .iter()
        .flat_map(|f| bundled_ids(f, |_| true))
        .collect();
    ids.push("readme".to_owned());
    let (mut judged, mut unsupported) = (0, Vec::new());
    for id in &ids {
        let (_, r) = run(&case(id), candidate);
        match &r.verdict {
            Verdict::Pass | Verdict::Fail(_) => judged += 1,
            Verdict::Unsupported(why) => unsupported.push(format!("{id}: {why}")),
            Verdict::Error(why) => panic!("{id}: {why}"),
            // One draw per case here: never flaky.
            Verdict::Flaky(f) => panic!("{id}: {}", f.summary()),
        }
    }
    for line in &unsupported {
        eprintln!("unsupported: {line}");
        assert!(known.iter().any(|k| line.contains(k)), "{line}");
    }
    let share = judged as f64 / ids.len() as f64;
    eprintln!("judged {judged} of {} ({:.1} %)", ids.len(), share * 100.0);
    assert!(share >= bar, "judged only {judged} of {}", ids.len());
}
