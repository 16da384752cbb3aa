//! The example rasterizers in C and JavaScript (`examples/c`,
//! `examples/js`, docs/validating.md), judged through the binary
//! over the bundled triangle, antialiasing, polygon and motion cases (and
//! the C example over the clip, point and depth cases, SPEC §12.10), in
//! persistent mode with protocol v2 (moving scenes by SPEC §12.8): each hello is honoured (what a program declares it
//! does not draw is UNSUPPORTED with the declaration as reason), each
//! example gets the verdicts it was built for, and each one's planted bug
//! (`--wrong-tie`, `--truncate`, `--swap`) is caught. A missing `cc` or
//! `node` skips loudly, and fails under `CI=true` (`.ci/run` installs both).
//! The counts docs/validating.md gives are checked here (its `example-c`
//! and `example-js` blocks; `RASTERCHECK_BLESS=1` rewrites them).

mod common;

use std::path::PathBuf;
use std::process::Command;

use common::adapters::skipped;
use common::cli::{rastercheck_env, read_json, scratch, text, verdicts};
use serde_json::Value;

const FAMILIES: [&str; 4] = [
    "cases/triangles",
    "cases/antialias",
    "cases/polygons",
    "cases/motion",
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Whether `program --version` runs.
fn available(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// The C example compiled as docs/validating.md says (C99, every warning an error)
/// into a fresh folder named by `tag`; `None` (skipped) without `cc`.
fn c_example(tag: &str) -> Option<PathBuf> {
    if !available("cc") {
        skipped("C compiler", "gcc", "the C example cannot be built");
        return None;
    }
    let exe = scratch(&format!("examples-{tag}")).join("c_rasterizer");
    let mut sources: Vec<PathBuf> = std::fs::read_dir(root().join("examples/c"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "c"))
        .collect();
    sources.sort();
    let out = Command::new("cc")
        .args(["-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-o"])
        .arg(&exe)
        .args(&sources)
        .arg("-lm")
        .output()
        .unwrap();
    assert!(out.status.success(), "cc failed:\n{}", text(&out));
    Some(exe)
}

/// The JavaScript example's command with `flags`; `None` (skipped) without
/// `node`.
fn js_example(flags: &str) -> Option<String> {
    if !available("node") {
        skipped("node", "nodejs", "the JavaScript example cannot run");
        return None;
    }
    let script = root().join("examples/js/rasterizer.js");
    Some(format!("node {} {flags}", script.display()))
}

/// One case's result for the one candidate.
#[derive(Debug)]
struct Verdict {
    id: String,
    verdict: String,
    reasons: String,
}

/// A persistent run of `command` named `name` over `cases`, in the
/// repository (for the golden files), its report in a fresh folder: the
/// exit code, the verdicts, and what the binary printed.
fn run(
    tag: &str,
    name: &str,
    command: &str,
    cases: &[&str],
) -> (Option<i32>, Vec<Verdict>, String) {
    let dir = scratch(&format!("examples-run-{tag}"));
    let report = dir.join("report");
    let spec = format!("{name}=external-persistent:{command}");
    let report_text = report.display().to_string();
    let mut argv = vec!["run", "--report", &report_text, "-r", &spec];
    argv.extend(cases);
    let out = rastercheck_env(&root(), &argv, &[]);
    let t = text(&out);
    assert!(!t.contains("panicked"), "{t}");
    let report = read_json(&report.join("report.json"));
    assert_eq!(report["complete"], true, "{t}");
    let verdicts = verdicts(&report)
        .into_iter()
        .map(|(id, verdict, reasons)| Verdict {
            id,
            verdict,
            reasons,
        })
        .collect();
    (out.status.code(), verdicts, t)
}

fn count(verdicts: &[Verdict], verdict: &str) -> usize {
    verdicts.iter().filter(|v| v.verdict == verdict).count()
}

fn verdict_of<'a>(verdicts: &'a [Verdict], id: &str) -> &'a Verdict {
    verdicts
        .iter()
        .find(|v| v.id == id)
        .unwrap_or_else(|| panic!("no {id} in {verdicts:?}"))
}

/// Holds the figures in `docs/validating.md` to what a test measured:
/// the block `name` there must read `line` (one list item). With
/// `RASTERCHECK_BLESS=1` the block is rewritten instead.
fn document(name: &str, line: String) {
    static FILE: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _lock = FILE.lock().unwrap_or_else(|e| e.into_inner());
    let path = root().join("docs/validating.md");
    let text = std::fs::read_to_string(&path).unwrap();
    let content = format!("{line}\n");
    let block = rastercheck::commands::docs::blocks(&text)
        .unwrap()
        .into_iter()
        .find(|b| b.name == name)
        .unwrap_or_else(|| panic!("docs/validating.md has no {name} block"));
    if block.content == content {
        return;
    }
    if std::env::var_os("RASTERCHECK_BLESS").is_some() {
        let text = rastercheck::commands::docs::replace(&text, name, &content);
        std::fs::write(&path, text).unwrap();
        return;
    }
    panic!(
        "docs/validating.md block {name:?} is stale:\n  in the file: {}  measured:    {content}\
         `RASTERCHECK_BLESS=1 cargo test --release --test examples` rewrites it",
        block.content
    );
}

/// The counts of `v` over `families`, as the line `document` keeps.
fn counts_line(example: &str, families: &[&str], v: &[Verdict]) -> String {
    let families: Vec<String> = families.iter().map(|f| format!("`{f}`")).collect();
    format!(
        "- {example}, over {}: **{} pass, {} fail, {} unsupported**",
        families.join(", "),
        count(v, "pass"),
        count(v, "fail"),
        count(v, "unsupported")
    )
}

/// The C example is exact: it passes every triangle, antialiasing,
/// polygon, motion and parallelogram-line case, and its hello (no other
/// line rules) makes the other line cases UNSUPPORTED with the declaration
/// as reason, unsent.
#[test]
fn the_c_example_passes_every_case_it_declares() {
    let Some(exe) = c_example("c") else { return };
    let mut cases = FAMILIES.to_vec();
    cases.push("cases/lines");
    let (code, v, t) = run("c", "c", &exe.display().to_string(), &cases);
    assert_eq!(code, Some(0), "{t}");
    assert_eq!(count(&v, "fail"), 0, "{t}");
    assert_eq!(count(&v, "error"), 0, "{t}");
    // 217 passed and 56 unsupported when written; new cases only add passes
    // (or, with other line rules, unsupported).
    assert!(count(&v, "pass") >= 217, "{t}");
    assert!(count(&v, "unsupported") >= 56, "{t}");
    for u in v.iter().filter(|v| v.verdict == "unsupported") {
        assert!(u.id.starts_with("lines/"), "{u:?}");
        assert!(
            u.reasons.contains("the program (c-example 1) declares no ")
                && u.reasons
                    .contains(" lines (its hello's line_rules: [parallelogram])"),
            "{u:?}"
        );
    }
    let wide = verdict_of(&v, "antialias/line_parallelogram_w2_5_steep_standard16");
    assert_eq!(wide.verdict, "pass", "{t}");
    document("example-c", counts_line("the C example", &cases, &v));
}

/// `--wrong-tie` gives every sample on an edge to the other side: the
/// top-left meshes lose their shared edges to the wrong triangle, and a
/// sample riding a moving top edge is covered for the whole shutter, or
/// never.
#[test]
fn the_c_example_with_the_wrong_tie_rule_is_caught() {
    let Some(exe) = c_example("c-wrong-tie") else {
        return;
    };
    let command = format!("{} --wrong-tie", exe.display());
    let (code, v, t) = run("c-wrong-tie", "c", &command, &FAMILIES);
    assert_eq!(code, Some(1), "{t}");
    let diagonal = verdict_of(&v, "triangles/shared_edge_diagonal");
    assert_eq!(diagonal.verdict, "fail", "{diagonal:?}");
    assert!(diagonal.reasons.contains("wrong owner"), "{diagonal:?}");
    let riding = verdict_of(&v, "motion/ride_top_edge_top_left");
    assert_eq!(riding.verdict, "fail", "{riding:?}");
    assert!(riding.reasons.contains("time-coverage"), "{riding:?}");
    // 103 of the 208 cases it passes fail when written: every case with a
    // sample on an edge or vertex, antialiased, moving or not.
    assert!(count(&v, "fail") >= 103, "{t}");
    assert_eq!(count(&v, "error"), 0, "{t}");
}

/// The JavaScript example quantizes each primitive's exact area to 8 bits
/// and declares it (`coverage_bits: 8`, SPEC §12.9): each primitive is
/// judged within 1/255 of its exact area, and a pixel two primitives fill
/// together may sum to 256/255. It declares coverage only, so cases that
/// ask for depth and attributes are judged on coverage and say so. It
/// passes every case of these families.
#[test]
fn the_js_example_passes_every_case_judged_per_primitive() {
    let Some(command) = js_example("") else {
        return;
    };
    let (code, v, t) = run("js", "js", &command, &FAMILIES);
    assert_eq!(code, Some(0), "{t}");
    assert_eq!(
        (count(&v, "pass"), count(&v, "fail"), count(&v, "error")),
        (v.len(), 0, 0),
        "{t}"
    );
    assert_eq!(
        verdict_of(&v, "motion/rotate_triangle_stratified16").verdict,
        "pass"
    );
    // Where rounding each half of a shared pixel gives 256/255: passes
    // within the two steps the pixel allows, not as exactly 1.
    for id in [
        "antialias/abutting_fan_8_standard8",
        "antialias/abutting_square_diagonal_standard16",
        "antialias/sweep_vertical_edge_32_standard4",
        "antialias/sweep_vertical_edge_32_standard16",
    ] {
        assert_eq!(verdict_of(&v, id).verdict, "pass", "{id}: {t}");
    }
    assert!(
        t.contains("js (coverage only: depth and attributes not judged)"),
        "{t}"
    );
    // Point sampling with the tie rule: the shared edges of meshes pass.
    assert_eq!(
        verdict_of(&v, "triangles/shared_edge_diagonal").verdict,
        "pass"
    );
    document(
        "example-js",
        counts_line("the JavaScript example", &FAMILIES, &v),
    );
}

/// `--no-motion` declares no moving scenes: they are UNSUPPORTED with the
/// hello's word as reason, unsent, and the still scene of the motion
/// folder is judged as before.
#[test]
fn a_hello_without_motion_gets_no_moving_scenes() {
    let Some(exe) = c_example("c-no-motion") else {
        return;
    };
    let command = format!("{} --no-motion", exe.display());
    let (code, v, t) = run("c-no-motion", "c", &command, &["cases/motion"]);
    assert_eq!(code, Some(0), "{t}");
    let still = verdict_of(&v, "motion/static_scene_with_motion_blur");
    assert_eq!(still.verdict, "pass", "{t}");
    for u in v.iter().filter(|v| v.id != still.id) {
        assert_eq!(u.verdict, "unsupported", "{u:?}");
        assert!(u.reasons.contains("its hello's motion: false"), "{u:?}");
    }
}

/// The families of SPEC §16–§18, which the protocol carries to a program
/// whose hello declares them (§12.10).
const FAMILIES_3D: [&str; 3] = ["cases/clip", "cases/points", "cases/depth"];

/// What the C example answers for a clip-space case it cannot draw
/// exactly: its own reasons, each naming what it does not implement.
const C_CANNOT: [&str; 3] = [
    "beyond this program's 128-bit arithmetic",
    "a projected position off this program's grid",
    "polygon offset at exact coordinates is not implemented",
];

/// The C example draws clip-space triangles (clipped exactly in 128-bit
/// rationals under each case's own conventions, vertices behind the eye by
/// §16.4's homogeneous edge functions), points, and depth formats with
/// polygon offset, and is judged as a built-in is: it fails nothing. What
/// it leaves unsupported is a line rule its hello does not declare, or
/// what it answers so itself, naming what it does not implement.
#[test]
fn the_c_example_draws_clip_space_points_and_depth_formats_exactly() {
    let Some(exe) = c_example("c-3d") else { return };
    let (code, v, t) = run("c-3d", "c", &exe.display().to_string(), &FAMILIES_3D);
    assert_eq!(code, Some(0), "{t}");
    assert_eq!(count(&v, "fail"), 0, "{t}");
    assert_eq!(count(&v, "error"), 0, "{t}");
    for u in v.iter().filter(|v| v.verdict == "unsupported") {
        assert!(
            C_CANNOT.iter().any(|why| u.reasons.contains(why))
                || u.reasons
                    .contains("the program (c-example 1) declares no diamond-exit lines"),
            "{u:?}"
        );
    }
    let family = |prefix: &str| {
        v.iter()
            .filter(|r| r.id.starts_with(prefix) && r.verdict == "pass")
            .count()
    };
    // When written: clip 81 of 81, points 51 of 51, depth 20 of 21 (the
    // 21st has a diamond-exit line, which the hello does not declare).
    assert!(family("clip/") >= 81, "{t}");
    assert!(family("points/") >= 51, "{t}");
    assert!(family("depth/") >= 20, "{t}");
    assert_eq!(
        verdict_of(&v, "depth/offset_line_ignored").verdict,
        "unsupported",
        "{t}"
    );
    for id in [
        "clip/spec_clip_then_snap",
        "clip/spec_guard_band",
        "clip/spec_near_per_sample",
        "clip/spec_w_crossing",
        "clip/offset_steep_perspective",
        "points/spec_clip_pop",
        "points/spec_bounds_viewport",
        "depth/spec_offset_slope_45",
        "depth/spec_depth_unorm16_half_way",
    ] {
        assert_eq!(verdict_of(&v, id).verdict, "pass", "{id}: {t}");
    }
    document(
        "example-c-3d",
        counts_line("the C example", &FAMILIES_3D, &v),
    );
}

/// `--ignore-offset` declares polygon offset and draws every depth without
/// it: each offset case whose offset moves a stored depth fails by its
/// depth, and the cases without an offset still pass.
#[test]
fn the_c_example_ignoring_polygon_offset_is_caught() {
    let Some(exe) = c_example("c-ignore-offset") else {
        return;
    };
    let command = format!("{} --ignore-offset", exe.display());
    let (code, v, t) = run("c-ignore-offset", "c", &command, &["cases/depth"]);
    assert_eq!(code, Some(1), "{t}");
    for id in [
        "depth/offset_steep",
        "depth/spec_offset_constant",
        "depth/spec_offset_slope_45",
    ] {
        let caught = verdict_of(&v, id);
        assert_eq!(caught.verdict, "fail", "{caught:?}");
        assert!(caught.reasons.contains("depth"), "{caught:?}");
    }
    assert_eq!(
        verdict_of(&v, "depth/spec_depth_float32").verdict,
        "pass",
        "{t}"
    );
    // Declaring no offset instead (--no-offset) makes those cases
    // unsupported, unsent, with the declaration as reason.
    let command = format!("{} --no-offset", exe.display());
    let (_, v, t) = run(
        "c-no-offset",
        "c",
        &command,
        &["cases/depth/offset_steep.json"],
    );
    let refused = verdict_of(&v, "depth/offset_steep");
    assert_eq!(refused.verdict, "unsupported", "{t}");
    assert!(
        refused
            .reasons
            .contains("its hello's polygon_offset: false"),
        "{refused:?}"
    );
}

/// `--fixed-clip` clips every case against all six planes before the
/// divide and declares so (`conventions.clip_xy` and `clip_z`,
/// SPEC §12.10): the cases stating other conventions are judged under its
/// own and pass, reported so; `--fixed-clip-undeclared` draws the same
/// without declaring it, and those cases fail.
#[test]
fn declared_clip_conventions_are_judged_as_conventions() {
    let Some(exe) = c_example("c-fixed-clip") else {
        return;
    };
    let command = format!("{} --fixed-clip", exe.display());
    let (code, v, t) = run("c-fixed-clip", "c", &command, &["cases/clip"]);
    assert_eq!(code, Some(0), "{t}");
    assert_eq!(count(&v, "pass"), v.len(), "{t}");
    let own = verdict_of(&v, "clip/spec_guard_band");
    assert!(t.contains("judged under its own clipping"), "{t}");
    assert_eq!(own.verdict, "pass", "{own:?}");
    let command = format!("{} --fixed-clip-undeclared", exe.display());
    let (code, v, t) = run("c-fixed-clip-undeclared", "c", &command, &["cases/clip"]);
    assert_eq!(code, Some(1), "{t}");
    // 22 of the 81 cases failed when written.
    assert!(count(&v, "fail") >= 10, "{t}");
    assert_eq!(
        verdict_of(&v, "clip/spec_guard_band").verdict,
        "fail",
        "{t}"
    );
}

/// A client that logs the name of every case it is sent and answers each
/// `unsupported`; with `hello` it declares version 2 and the three
/// screen-space primitives, nothing of SPEC §12.10.
const COUNTING_CLIENT: &str = r#"
import json, sys
log = open(sys.argv[1], "a")
if len(sys.argv) > 2 and sys.argv[2] == "hello":
    print(json.dumps({"hello": {"protocol": 2, "name": "flat", "capabilities":
                     {"primitives": ["triangles", "lines", "polygons"]}}}), flush=True)
for line in sys.stdin:
    request = json.loads(line)
    if request.get("bye"):
        break
    log.write(request["case"] + "\n")
    log.flush()
    answer = {"unsupported": "counting only"}
    if "id" in request:
        answer["id"] = request["id"]
    print(json.dumps(answer), flush=True)
"#;

/// A program that declares no clip space, points or depth formats (a
/// version 2 hello without them, or no hello at all) is sent no case of
/// those families that needs them: each is unsupported with the missing
/// declaration as reason, and the program's own log of requests holds
/// none of them.
#[test]
fn a_program_that_declares_no_clip_space_is_sent_none() {
    if !available("python3") {
        skipped("python3", "python3", "the counting client cannot run");
        return;
    }
    for (tag, flag, reason) in [
        ("count-hello", "hello", "the program (flat) declares no "),
        ("count-v1", "", "this program wrote none"),
    ] {
        let dir = scratch(&format!("examples-{tag}"));
        let script = dir.join("client.py");
        std::fs::write(&script, COUNTING_CLIENT).unwrap();
        let log = dir.join("sent.log");
        let command = format!("python3 {} {} {flag}", script.display(), log.display());
        let (_, v, t) = run(tag, "flat", &command, &FAMILIES_3D);
        assert_eq!(v.len(), count(&v, "unsupported"), "{t}");
        let sent = std::fs::read_to_string(&log).unwrap_or_default();
        let sent: Vec<&str> = sent.lines().collect();
        let refused: Vec<&Verdict> = v
            .iter()
            .filter(|r| !r.reasons.contains("counting only"))
            .collect();
        // Every clip and point case is refused, unsent.
        for r in &v {
            if r.id.starts_with("clip/") || r.id.starts_with("points/") {
                assert!(r.reasons.contains(reason), "{r:?}");
                let name = r.id.rsplit('/').next().unwrap();
                assert!(!sent.contains(&name), "{name} was sent: {sent:?}");
            }
        }
        // What was sent is what was not refused, one request each.
        assert_eq!(sent.len() + refused.len(), v.len(), "{t}");
        assert!(refused.len() >= 153, "{refused:?}");
    }
}

/// The verdict on the case `id` of the JavaScript example as it is (which
/// must pass) and with `flag` (its planted bug), and what the second run
/// printed; `None` (skipped) without `node`.
fn js_with_and_without(flag: &str, id: &str) -> Option<(Verdict, String)> {
    let case = format!("cases/{id}.json");
    let flag_tag = flag.replace(' ', "");
    let right = js_example("")?;
    let (_, v, t) = run(&format!("js-right{flag_tag}"), "js", &right, &[&case]);
    assert_eq!(verdict_of(&v, id).verdict, "pass", "{t}");
    let wrong = js_example(flag).unwrap();
    let (_, mut v, t) = run(&format!("js{flag_tag}"), "js", &wrong, &[&case]);
    let at = v.iter().position(|v| v.id == id).unwrap();
    Some((v.swap_remove(at), t))
}

/// `--truncate` floors area·255. Under its declared 8 bits that is within
/// one step of each primitive's area, which SPEC §12.9 allows (libraries
/// truncate or round). Declaring no quantization (`--no-coverage-bits`),
/// two polygons sharing an edge leave every pixel along it at 254/255,
/// where the union is full: piglit's rule catches it.
#[test]
fn the_js_example_truncating_coverage_is_caught_where_undeclared() {
    let id = "polygons/shared_edge_polygons_aa_standard4";
    let Some((f, t)) = js_with_and_without("--truncate --no-coverage-bits", id) else {
        return;
    };
    assert_eq!(f.verdict, "fail", "{t}");
    assert!(f.reasons.contains("full or empty pixels"), "{f:?}");
    let Some((f, t)) = js_with_and_without("--truncate", id) else {
        return;
    };
    assert_eq!(f.verdict, "pass", "{t}");
}

/// `--swap` trades coverage between primitives 2k and 2k+1 wherever both
/// touch a pixel: the pixel sums stay right, each primitive is wrong. Here
/// two triangles overlap: the sums pass, and each primitive, judged on its
/// own (SPEC §12.9), fails.
#[test]
fn the_js_example_swapping_coverage_between_primitives_is_caught() {
    let id = "antialias/count_standard_16";
    let Some((f, t)) = js_with_and_without("--swap", id) else {
        return;
    };
    assert_eq!(f.verdict, "fail", "{t}");
    assert!(!f.reasons.contains("(piglit's rule)"), "{f:?}");
    assert!(
        f.reasons.contains("from the primitive's exact area"),
        "{f:?}"
    );
}

/// Requests that are not JSON, or lack what the program reads, get an
/// `error` answer (with the id when there is one), and the next request is
/// answered as usual: a bad line costs its own case only. `bye` ends it.
#[test]
fn the_examples_answer_broken_requests_with_errors_and_go_on() {
    use std::io::Write;
    use std::process::Stdio;
    let good = r#"{"id": "b#2", "canvas": {"width": 4, "height": 4},
        "rules": {"subpixel_bits": 8, "fill_rule": "top-left", "cull": "none"},
        "plan": {"samples_per_pixel": 1, "depth": false, "attributes": 0},
        "primitives": [{"triangle": [
            {"x": 0, "y": 0, "exact": {"x": "0", "y": "0"}},
            {"x": 4, "y": 0, "exact": {"x": "4", "y": "0"}},
            {"x": 0, "y": 4, "exact": {"x": "0", "y": "4"}}]}]}"#
        .replace('\n', " ");
    let input = format!(
        "not json\n\n{{\"id\": \"a#1\", \"primitives\": 7}}\n{good}\n{}\n{{\"bye\": true}}\n",
        "[".repeat(200)
    );
    let mut programs: Vec<Vec<String>> = Vec::new();
    if let Some(exe) = c_example("c-broken") {
        programs.push(vec![exe.display().to_string()]);
    }
    if let Some(command) = js_example("") {
        programs.push(command.split_whitespace().map(str::to_owned).collect());
    }
    for program in programs {
        let mut child = Command::new(&program[0])
            .args(&program[1..])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        child
            .stdin
            .take()
            .unwrap()
            .write_all(input.as_bytes())
            .unwrap();
        let out = child.wait_with_output().unwrap();
        assert!(out.status.success(), "{program:?}");
        let lines: Vec<Value> = String::from_utf8(out.stdout)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        assert_eq!(lines.len(), 5, "{program:?}: {lines:?}");
        assert_eq!(lines[0]["hello"]["protocol"], 2, "{lines:?}");
        assert!(lines[1]["error"].is_string(), "{lines:?}");
        assert_eq!(lines[2]["id"], "a#1", "{lines:?}");
        assert!(lines[2]["error"].is_string(), "{lines:?}");
        assert_eq!(lines[3]["id"], "b#2", "{lines:?}");
        // The top-left rule: the centres on the hypotenuse x + y = 4 are out.
        assert_eq!(
            lines[3]["primitives"][0]["fragments"],
            serde_json::json!([[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [0, 2]]),
            "{lines:?}"
        );
        assert!(lines[4]["error"].is_string(), "{lines:?}");
    }
}

/// probe diagnoses both examples from their frames alone (SPEC §13): each
/// point-samples single-sample scenes at the pixel centre with the case's
/// tie rule (top-left, which probe's scenes state) and keeps every
/// subpixel bit; the JavaScript one gives no values to measure.
#[test]
fn probe_diagnoses_both_examples() {
    let (Some(exe), Some(js)) = (c_example("c-probe"), js_example("")) else {
        return;
    };
    let c = format!("c=external-persistent:{}", exe.display());
    let js = format!("js=external-persistent:{js}");
    for (tag, spec, values) in [("c", &c, true), ("js", &js, false)] {
        let out_file = scratch(&format!("examples-probe-{tag}")).join("profile.json");
        let out = rastercheck_env(
            &root(),
            &[
                "probe",
                "-r",
                spec,
                "--out",
                &out_file.display().to_string(),
            ],
            &[],
        );
        assert!(out.status.success(), "{}", text(&out));
        let p = read_json(&out_file);
        assert_eq!(p["rasterizer"], tag);
        assert_eq!(p["sampler"], "point", "{p}");
        assert_eq!(p["fill_rule"], "top-left", "{p}");
        assert_eq!(p["fill_rule_consistent"], true, "{p}");
        assert_eq!(p["subpixel"], "exact", "{p}");
        assert_eq!(p["sample_position"], "centre", "{p}");
        assert_eq!(p["y_down"], true, "{p}");
        let printed = text(&out);
        assert_eq!(printed.contains("nothing to compare"), !values, "{printed}");
    }
}
