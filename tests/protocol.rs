//! Protocol v2 (SPEC.md §12.7) through the binary: a real program (the
//! example rasterizer behind `tests/faults/programs/protocol_v2.py`) that
//! writes stray lines, skips an answer, answers late or with a wrong id in
//! the middle of a persistent run, one thread, so that every later request
//! goes to the same process. Every other case keeps the verdict and
//! reasons of a clean run of the same program; the faulted case is an
//! error that says why. Its hello: cases outside it are unsupported with
//! the declaration as reason, and never sent. Names: `-r NAME=COMMAND`.

mod common;

use std::path::{Path, PathBuf};

use common::cli::{rastercheck_env, read_json, scratch, text, verdicts};
use serde_json::Value;

/// Small triangle cases the example draws quickly, some passing, some
/// failing (it overdraws shared edges), in the order a one-thread run
/// sends them.
const CASES: [&str; 8] = [
    "cases/triangles/cull_ccw_mixed_windings.json",
    "cases/triangles/degenerate_collinear_cull_none.json",
    "cases/triangles/shared_edge_diagonal.json",
    "cases/triangles/shared_edge_vertical.json",
    "cases/triangles/snap_tie_b0.json",
    "cases/triangles/subpixel_no_sample_b4.json",
    "cases/triangles/unsnapped_tiny_covers.json",
    "cases/triangles/winding_cw_cull_none.json",
];

/// The case names the program sees (each file's `name`).
fn name_of(path: &str) -> String {
    read_json(&root().join(path))["name"]
        .as_str()
        .unwrap()
        .to_owned()
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn program() -> String {
    root()
        .join("tests/faults/programs/protocol_v2.py")
        .display()
        .to_string()
}

/// A persistent run of the program with `args` over `cases` on one thread,
/// in the repository (for the golden files), its report in a fresh folder.
/// The exit code, the report, what it printed, and the program's log.
fn run(
    tag: &str,
    rasterizer_prefix: &str,
    args: &str,
    cases: &[&str],
) -> (Option<i32>, Value, String, String) {
    let dir = scratch(&format!("protocol-{tag}"));
    let log = dir.join("program.log");
    let spec = format!(
        "{rasterizer_prefix}external-persistent:python3 {} {} {args}",
        program(),
        log.display()
    );
    let report = dir.join("report");
    let mut argv = vec!["run", "--threads", "1", "--report"];
    let report_text = report.display().to_string();
    argv.push(&report_text);
    argv.extend(["-r", &spec]);
    argv.extend(cases);
    let out = rastercheck_env(
        &root(),
        &argv,
        &[
            ("RASTERCHECK_EXTERNAL_TIMEOUT", "2"),
            ("PROTOCOL_LATE", "3"),
        ],
    );
    let t = text(&out);
    assert!(!t.contains("panicked"), "{t}");
    let report = read_json(&report.join("report.json"));
    assert_eq!(report["complete"], true, "{t}");
    let logged = std::fs::read_to_string(&log).unwrap_or_default();
    (out.status.code(), report, t, logged)
}

/// Runs the program clean and with `fault` on the case `CASES[at]`; every
/// other case's verdict and reasons equal the clean run's; the faulted
/// one's verdict is error with `reason` among its reasons. Exit code 1.
fn survives(fault: &str, at: usize, reason: &str) {
    let (code, clean, t, _) = run(&format!("{fault}-clean"), "", "", &CASES);
    assert_eq!(code, Some(1), "the example fails some cases: {t}");
    let clean = verdicts(&clean);
    assert!(
        clean.iter().any(|v| v.1 == "pass") && clean.iter().any(|v| v.1 == "fail"),
        "{clean:?}"
    );
    assert!(clean.iter().all(|v| v.1 != "error"), "{clean:?}");
    let bad = name_of(CASES[at]);
    let (code, faulted, t, _) = run(fault, "", &format!("{fault}={bad}"), &CASES);
    assert_eq!(code, Some(1), "{t}");
    let faulted = verdicts(&faulted);
    assert_eq!(faulted.len(), clean.len());
    for (i, (c, f)) in clean.iter().zip(&faulted).enumerate() {
        if i != at {
            assert_eq!(c, f, "case {i} changed its verdict after the fault\n{t}");
        }
    }
    let f = &faulted[at];
    assert_eq!(f.1, "error", "{f:?}\n{t}");
    assert!(f.2.contains(reason), "{f:?} lacks {reason:?}\n{t}");
}

#[test]
fn stray_lines_are_an_error_for_their_case_only() {
    survives("stray", 2, "2 stray lines on stdout");
}

#[test]
fn a_skipped_answer_is_a_timeout_for_its_case_only() {
    survives("skip", 1, "timed out after 2 s with no answer");
}

#[test]
fn a_late_answer_is_dropped_by_its_id() {
    survives("late", 3, "timed out after 2 s with no answer");
}

/// A program that hangs on a case is killed by the next case's timeout,
/// and that case is sent again to a fresh process: it is not blamed.
#[test]
fn a_hung_program_costs_its_own_case_only() {
    survives("hang", 3, "timed out after 2 s with no answer");
}

/// A flood of stray lines is bounded (1000 lines): an error for its case,
/// the process killed, the next case answered by a fresh one.
#[test]
fn a_flood_of_stray_lines_is_cut_short() {
    survives("flood", 5, "more than 1000 lines");
}

/// A hello that breaks §12.7 is refused before any case (preflight: bad
/// usage, exit code 2), naming its JSON path; no case is sent, no report
/// is written, and nothing crashes.
#[test]
fn a_malformed_hello_is_an_error() {
    let dir = scratch("protocol-bad-hello");
    let log = dir.join("program.log");
    let spec = format!(
        "external-persistent:python3 {} {} --bad-hello",
        program(),
        log.display()
    );
    let mut argv = vec!["run", "--threads", "1", "-r", &spec];
    argv.extend(&CASES[..2]);
    let out = rastercheck_env(&root(), &argv, &[]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(!t.contains("panicked"), "{t}");
    assert!(t.contains("$.hello.capabilities.primitives[1]"), "{t}");
    let log = std::fs::read_to_string(&log).unwrap_or_default();
    assert!(!log.contains("case "), "{log}");
}

#[test]
fn an_answer_with_a_wrong_id_is_never_used() {
    survives("wrongid", 4, "1 stray line on stdout");
}

/// A program whose hello declares no lines gets lines cases as
/// unsupported, with the declaration, and never receives them; its
/// triangles are judged as usual. `-r NAME=COMMAND` names it in the report.
#[test]
fn a_declared_capability_refuses_cases_unsent_and_names_are_kept() {
    let line_case = "cases/lines/rectangle_worked_example.json";
    let cases = [CASES[0], CASES[2], line_case];
    let (code, report, t, log) = run("hello", "lava=", "--no-lines", &cases);
    assert_eq!(code, Some(1), "{t}");
    let v = verdicts(&report);
    let line = v.iter().find(|v| v.0.starts_with("lines/")).unwrap();
    assert_eq!(line.1, "unsupported", "{line:?}");
    assert!(line.2.contains("declares no lines"), "{line:?}");
    let line_name = name_of(line_case);
    assert!(
        !log.contains(&line_name),
        "the program was sent {line_name}:\n{log}"
    );
    assert!(log.contains(&name_of(CASES[0])), "{log}");
    // The name given, everywhere the report names the candidate.
    assert_eq!(report["rasterizers"][0]["name"], "lava", "{report}");
    for case in report["cases"].as_array().unwrap() {
        assert_eq!(case["results"][0]["rasterizer"], "lava");
    }
    assert!(t.contains("lava"), "{t}");
    assert!(!t.contains("external-persistent:"), "{t}");
}

/// Version 1 (no hello, no ids) still works: the same verdicts as v2.
#[test]
fn a_v1_program_is_judged_as_before() {
    let (code, v1, t, _) = run("v1", "", "--v1", &CASES[..3]);
    assert_eq!(code, Some(1), "{t}");
    let (_, v2, _, _) = run("v2", "", "", &CASES[..3]);
    assert_eq!(verdicts(&v1), verdicts(&v2));
}

/// A name that is empty, has whitespace, repeats another `-r` or is a
/// bundled rasterizer's is bad usage (exit 2), said before anything runs.
#[test]
fn bad_names_are_refused() {
    let spec = |name: &str| format!("{name}=external-persistent:python3 {} /dev/null", program());
    let dir = scratch("protocol-names");
    for args in [
        vec![spec("")],
        vec![spec("production")],
        vec![spec("a b")],
        vec![spec("twin"), spec("twin")],
    ] {
        let mut argv = vec![
            "run".to_owned(),
            "--report".to_owned(),
            dir.join("r").display().to_string(),
        ];
        for a in &args {
            argv.push("-r".to_owned());
            argv.push(a.clone());
        }
        argv.push(CASES[0].to_owned());
        let argv: Vec<&str> = argv.iter().map(String::as_str).collect();
        let out = rastercheck_env(&root(), &argv, &[]);
        let t = text(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {t}");
        assert!(t.contains("name"), "{args:?}: {t}");
    }
}

/// `-r NAME=COMMAND` in `matrix` (the row) and `baseline` (the key it
/// records, and checks under).
#[test]
fn names_hold_in_matrix_and_baseline() {
    let dir = scratch("protocol-names-elsewhere");
    let spec = format!(
        "lava=external-persistent:python3 {} {} --persistent",
        program(),
        dir.join("log").display()
    );
    let cases = [CASES[2], CASES[7]];
    let out = rastercheck_env(
        &root(),
        &[&["matrix", "-r", &spec][..], &cases].concat(),
        &[],
    );
    let t = text(&out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    assert!(t.contains("| `lava` |"), "{t}");
    let base = dir.join("base.json").display().to_string();
    let save = [&["baseline", "save", &base, "-r", &spec][..], &cases].concat();
    let out = rastercheck_env(&root(), &save, &[]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let recorded = read_json(Path::new(&base));
    assert_eq!(
        recorded["rasterizers"],
        serde_json::json!(["lava"]),
        "{recorded}"
    );
    let check = [&["baseline", "check", &base, "-r", &spec][..], &cases].concat();
    let out = rastercheck_env(&root(), &check, &[]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    assert!(t.contains("0 regressions"), "{t}");
}

/// The name and version a program's hello declares reach report.json,
/// beside the name the run gave it; a program that says no hello (v1)
/// declares nothing.
#[test]
fn the_hello_names_the_program_in_the_report() {
    let (_, report, t, _) = run("declared", "toy=", "", &CASES[..2]);
    let info = &report["rasterizers"][0];
    assert_eq!(info["name"], "toy", "{t}");
    assert_eq!(info["declared"], "python-example 3", "{info}");
    let (_, report, t, _) = run("declared-v1", "toy=", "--v1", &CASES[..2]);
    let info = &report["rasterizers"][0];
    assert_eq!(info["name"], "toy", "{t}");
    assert!(info.get("declared").is_none(), "{info}");
}
