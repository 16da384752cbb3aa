//! The example rasterizers in C and JavaScript (`examples/c`,
//! `examples/js`, docs/validating.md), judged through the binary
//! over the bundled triangle, antialiasing, polygon and motion cases, in
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
