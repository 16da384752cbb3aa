//! Moving scenes through the external protocol (SPEC.md §12.8): the example
//! Python rasterizer, which declares motion in its version 2 hello, is sent
//! `cases/motion` and judged on time coverage; a version 1 program, a
//! one-shot one and a version 2 one that declares no motion get every
//! moving case unsupported, with the reason, and never see it. Wrong
//! clients (the whole shutter for any covered instant; the scene frozen at
//! shutter open) are caught where the example passes; time-coverage
//! answers (form 2) are judged as the masks they sum; malformed answers are
//! an error naming the JSON path, for their case only; production's own
//! counts, sent as an answer, compose to production's frame bit for bit.

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use common::cli::{rastercheck_env, read_json, scratch, text, verdicts};
use rastercheck::adapters::external;
use rastercheck::plan::Plan;
use rastercheck::production::antialias::Sampling;
use rastercheck::production::motion::Sampler;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{parse_case, Limits};
use serde_json::json;

const EXAMPLE: &str = "examples/python_rasterizer.py";

/// What a v1 program, a one-shot one, or a v2 one without `motion: true`
/// is told about a moving case.
const NOT_DECLARED: &str =
    "moving scenes are sent only to programs that declare motion in a version 2 hello (SPEC §12.8)";

/// The example's bundled failures on `cases/motion`: a sample riding an
/// edge it draws inclusively (bottom-right rule, a moving and a static
/// triangle meeting, geometry that moves less than a snap step), and the
/// static scene's shared edge. Every other case passes.
const EXAMPLE_FAILS: [&str; 4] = [
    "motion/ride_top_edge_bottom_right",
    "motion/spec_moves_as_written",
    "motion/static_and_moving_overlap",
    "motion/static_scene_with_motion_blur",
];

/// A test client around the example: the hello and answers of its first
/// argument's mode, on the case named by its third (or every case).
const CLIENT: &str = r#"
import copy, importlib.util, json, sys
mode, example = sys.argv[1], sys.argv[2]
victim = sys.argv[3] if len(sys.argv) > 3 else None
spec = importlib.util.spec_from_file_location("example", example)
example = importlib.util.module_from_spec(spec)
spec.loader.exec_module(example)

def masks_to_time(request, answer):
    # Form 2: each primitive's covered tests over M·N, per pixel.
    motion = request["plan"]["motion"]
    n, tests = motion["samples"], motion["samples"] * motion["spatial_samples"]
    out = []
    for prim, entry in zip(request["primitives"], answer["primitives"]):
        counts = {}
        for x, y, _ in entry["fragments"]:
            counts[(x, y)] = counts.get((x, y), 0) + (1 if prim["moves"] else n)
        out.append({"time": [[x, y, c / tests] for (x, y), c in sorted(counts.items())]})
    return {"primitives": out}

def answer(request):
    if "motion" not in request["plan"]:
        return example.rasterize(request)
    here = victim is None or request["case"] == victim
    if mode == "frozen" and here:
        # Every moving vertex left at shutter open: the scene never moves.
        request = copy.deepcopy(request)
        for prim in request["primitives"]:
            for v in prim.get("triangle") or prim.get("line") or []:
                v.pop("to", None)
    out = example.rasterize(request)
    if "primitives" not in out:
        return out
    n = request["plan"]["motion"]["samples"]
    m = request["plan"]["motion"]["spatial_samples"]
    if mode == "whole-shutter" and here:
        # Covered at one instant: covered at all of its sample's instants.
        for prim, entry in zip(request["primitives"], out["primitives"]):
            if prim["moves"]:
                seen = sorted({(x, y, j // n) for x, y, j in entry["fragments"]})
                entry["fragments"] = [[x, y, s * n + k] for x, y, s in seen for k in range(n)]
    if mode in ("time", "bad-time", "mixed"):
        out = masks_to_time(request, out)
    if here and mode == "bad-slot":
        out["primitives"][-1]["fragments"].append([0, 0, m * n])
    if here and mode == "bad-time":
        out["primitives"][0]["time"].append([1, 1, 1.5])
    if here and mode == "mixed":
        out["primitives"][0] = {"fragments": []}
    return out

hello = copy.deepcopy(example.HELLO)
if mode == "undeclared":
    del hello["hello"]["capabilities"]["motion"]
example.serve(hello, answer)
"#;

static RUNS: Mutex<()> = Mutex::new(());

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `rasterizer` (an `-r` argument) over `cases` (paths under the
/// repository, for the golden files); each case's id → (verdict, reasons).
fn run(tag: &str, rasterizer: &str, cases: &[&str]) -> BTreeMap<String, (String, String)> {
    // One run at a time: Python processes that start together on a loaded
    // machine may each take past a second to write their hello.
    let _turn = RUNS.lock().unwrap_or_else(|e| e.into_inner());
    let dir = scratch(&format!("external-motion-{tag}"));
    let report = dir.join("report");
    let report_text = report.display().to_string();
    let mut argv = vec!["run", "--report", &report_text, "-r", rasterizer];
    argv.extend(cases);
    let out = rastercheck_env(&root(), &argv, &[("RASTERCHECK_EXTERNAL_TIMEOUT", "60")]);
    let t = text(&out);
    assert!(!t.contains("panicked"), "{t}");
    assert!(matches!(out.status.code(), Some(0 | 1)), "{t}");
    let report = read_json(&report.join("report.json"));
    assert_eq!(report["complete"], true, "{t}");
    verdicts(&report)
        .into_iter()
        .map(|(id, verdict, why)| (id, (verdict, why)))
        .collect()
}

/// The test client written into a fresh folder, as an `-r` argument in
/// persistent mode.
fn client(mode: &str, victim: Option<&str>) -> String {
    let dir = scratch(&format!("external-motion-client-{mode}"));
    let script = dir.join("client.py");
    std::fs::write(&script, CLIENT).unwrap();
    format!(
        "{mode}=external-persistent:python3 {} {mode} {} {}",
        script.display(),
        root().join(EXAMPLE).display(),
        victim.unwrap_or("")
    )
}

fn example(args: &str) -> String {
    format!(
        "external-persistent:python3 {} --persistent{args}",
        root().join(EXAMPLE).display()
    )
}

/// The ids with `verdict`.
fn with(verdicts: &BTreeMap<String, (String, String)>, verdict: &str) -> Vec<String> {
    verdicts
        .iter()
        .filter(|(_, v)| v.0 == verdict)
        .map(|(id, _)| id.clone())
        .collect()
}

#[test]
fn the_example_draws_moving_cases_and_is_judged() {
    let verdicts = run("example", &example(""), &["cases/motion"]);
    assert_eq!(verdicts.len(), 32, "{verdicts:?}");
    assert_eq!(with(&verdicts, "unsupported"), Vec::<String>::new());
    assert_eq!(with(&verdicts, "error"), Vec::<String>::new());
    // Caught on ties it draws inclusively; everything else within bounds.
    assert_eq!(with(&verdicts, "fail"), EXAMPLE_FAILS.map(String::from));
    assert_eq!(with(&verdicts, "pass").len(), 28, "{verdicts:?}");
    let (_, why) = &verdicts["motion/ride_top_edge_bottom_right"];
    assert!(why.contains("time-coverage"), "{why}");
}

/// Cases a few of each kind: moving triangles and lines, and the static
/// scene (judged whatever the program declares).
const SOME: [&str; 4] = [
    "cases/motion/line_parallelogram_moving_w1_5.json",
    "cases/motion/static_scene_with_motion_blur.json",
    "cases/motion/translate_triangle_stratified16.json",
    "cases/motion/aa_standard4_time_stratified.json",
];

#[test]
fn moving_cases_go_only_to_a_version_2_hello_that_declares_motion() {
    let one_shot = format!("external:python3 {}", root().join(EXAMPLE).display());
    for (tag, rasterizer, says) in [
        ("v1", example(" --v1"), NOT_DECLARED.to_owned()),
        ("one-shot", one_shot, NOT_DECLARED.to_owned()),
        (
            "undeclared",
            client("undeclared", None),
            format!("(python-example 3) speaks version 2 (its hello declares no motion); {NOT_DECLARED}"),
        ),
    ] {
        let verdicts = run(tag, &rasterizer, &SOME);
        for (id, (verdict, why)) in &verdicts {
            if id == "motion/static_scene_with_motion_blur" {
                // Nothing moves: a static scene, sent and judged.
                assert_eq!(verdict, "fail", "{tag} {id}: {why}");
            } else {
                assert_eq!(verdict, "unsupported", "{tag} {id}: {why}");
                assert!(why.contains(&says), "{tag} {id}: {why}");
            }
        }
    }
}

/// Cases the example passes, on which the wrong clients are judged.
const PASSED: [&str; 5] = [
    "cases/motion/translate_triangle_stratified16.json",
    "cases/motion/rotate_triangle_stratified16.json",
    "cases/motion/line_parallelogram_moving_w1_5.json",
    "cases/motion/aa_standard4_time_stratified.json",
    "cases/motion/winding_flip_cull_ccw.json",
];

#[test]
fn a_client_that_ignores_time_is_caught_where_the_example_passes() {
    let example = run("passed", &example(""), &PASSED);
    assert_eq!(with(&example, "pass").len(), PASSED.len(), "{example:?}");
    for mode in ["whole-shutter", "frozen"] {
        let wrong = run(mode, &client(mode, None), &PASSED);
        for (id, (verdict, why)) in &wrong {
            assert_eq!(verdict, "fail", "{mode} {id}: {why}");
            assert!(why.contains("time-coverage"), "{mode} {id}: {why}");
        }
    }
}

#[test]
fn time_coverage_answers_are_judged_as_the_masks_they_sum() {
    let masks = run("masks", &example(""), &SOME);
    let time = run("time", &client("time", None), &SOME);
    assert_eq!(time.len(), masks.len());
    for (id, (verdict, why)) in &time {
        assert_eq!(verdict, &masks[id].0, "{id}: {why}");
    }
    assert_eq!(with(&time, "pass").len(), 3, "{time:?}");
}

#[test]
fn a_malformed_motion_answer_is_an_error_naming_its_path_for_its_case_only() {
    let victim = "static_and_moving_overlap";
    let cases = [
        "cases/motion/static_and_moving_overlap.json",
        "cases/motion/translate_triangle_stratified16.json",
        "cases/motion/rotate_triangle_stratified16.json",
    ];
    for (mode, says) in [
        ("bad-slot", "$.primitives[1].fragments["),
        ("bad-time", "is not a time coverage in [0, 1]"),
        (
            "mixed",
            "$.primitives: give time for every primitive or fragments for every one",
        ),
    ] {
        let verdicts = run(mode, &client(mode, Some(victim)), &cases);
        let (verdict, why) = &verdicts[&format!("motion/{victim}")];
        assert_eq!(verdict, "error", "{mode}: {why}");
        assert!(why.contains(says), "{mode}: {why}");
        assert_eq!(with(&verdicts, "pass").len(), 2, "{mode}: {verdicts:?}");
    }
    let verdicts = run(
        "bad-slot-why",
        &client("bad-slot", Some(victim)),
        &cases[..1],
    );
    let why = &verdicts[&format!("motion/{victim}")].1;
    assert!(
        why.contains("[2]: 16 is not a time slot in [0, 16)"),
        "{why}"
    );
    let verdicts = run(
        "bad-time-why",
        &client("bad-time", Some(victim)),
        &cases[..1],
    );
    assert!(verdicts[&format!("motion/{victim}")]
        .1
        .contains("$.primitives[0].time["));
}

#[test]
fn production_sent_through_the_protocol_composes_its_own_frame() {
    let dir = root().join("cases/motion");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let scene = parse_case(
            &std::fs::read_to_string(&path).unwrap(),
            &path.display().to_string(),
            &Limits::default(),
        )
        .unwrap();
        let plan = Plan::for_scene(&scene);
        let Some(motion) = &plan.motion else { continue };
        // The request lists the instants production tests.
        let request = external::request(&scene, &plan);
        let m = plan.samples_per_pixel;
        assert_eq!(request["plan"]["motion"]["spatial_samples"], json!(m));
        // Production's covered tests of every slot (static primitives
        // included), all given to one moving primitive: the frame sums
        // over primitives, so it must be production's.
        let sampler = Sampler::new(&scene, &plan, Sampling::Full).unwrap();
        let mover = motion.moving.iter().position(|&m| m).unwrap();
        let mut fragments = Vec::new();
        for y in 0..scene.canvas.height {
            for x in 0..scene.canvas.width {
                let p = (y * scene.canvas.width + x) as usize;
                assert_eq!(
                    request["plan"]["motion"]["times"][p],
                    json!(motion.blur.pixel_times(p as u64, m)),
                    "{}",
                    path.display()
                );
                for (j, &count) in sampler.slot_counts(x, y).iter().enumerate() {
                    fragments.extend((0..count).map(|_| json!([x, y, j])));
                }
            }
        }
        let mut primitives = vec![json!({"fragments": []}); scene.primitives.len()];
        primitives[mover] = json!({ "fragments": fragments });
        let answer = json!({ "primitives": primitives });
        let frame = external::frame_from_response(&answer, &scene, &plan).unwrap();
        let production = Production.rasterize(&scene, &plan).unwrap();
        assert_eq!(frame.time, production.time, "{}", path.display());
        checked += 1;
    }
    assert_eq!(checked, 31);
}

/// The request of a moving scene: `moves` on every primitive, `to` on each
/// moving vertex only, the shutter as floats and exact strings.
#[test]
fn a_moving_request_carries_moves_to_and_the_shutter() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("cases/motion/shutter_quarter_to_three_quarters.json");
    let scene = parse_case(
        &std::fs::read_to_string(&path).unwrap(),
        "s.json",
        &Limits::default(),
    )
    .unwrap();
    let plan = Plan::for_scene(&scene);
    let request = external::request(&scene, &plan);
    let motion = &request["plan"]["motion"];
    assert_eq!(motion["shutter"], json!([0.25, 0.75]));
    assert_eq!(motion["exact"]["shutter"], json!(["0.25", "0.75"]));
    assert_eq!(motion["samples"], json!(16));
    assert_eq!(motion["pattern"], json!("stratified"));
    let triangle = &request["primitives"][0];
    assert_eq!(triangle["moves"], json!(true));
    for (v, written) in triangle["triangle"]
        .as_array()
        .unwrap()
        .iter()
        .zip(scene.primitives[0].vertices())
    {
        assert_eq!(v.get("to").is_some(), written.moves(), "{v}");
        if written.moves() {
            let [x, y] = written.end().map(|n| n.to_exact_string());
            assert_eq!(v["exact"]["to"], json!({"x": x, "y": y}));
        }
    }
    // A static scene's request is version 1's, unchanged.
    let still = parse_case(
        r#"{"name": "s", "canvas": {"width": 2, "height": 2},
            "primitives": [{"triangle": [[0, 0], [2, 0], [0, 2]]}]}"#,
        "s.json",
        &Limits::default(),
    )
    .unwrap();
    let request = external::request(&still, &Plan::for_scene(&still));
    assert!(request["primitives"][0].get("moves").is_none());
    assert!(request["plan"].get("motion").is_none());
}
