//! Coverage-only answers and coverage judged per primitive (SPEC.md §12.9,
//! §14.3), through the binary, with a real 8-bit area rasterizer
//! (`tests/clients/area8.py`: exact areas rounded to multiples of 1/255
//! before the primitives are added, as 2D antialiasing libraries store
//! them) speaking protocol v2 in persistent mode.
//!
//! - Declaring its quantization, it passes every antialiased case it
//!   draws: its sums of rounded coverages (256/255 on a pixel two
//!   triangles share) are not false failures.
//! - Not declaring it, the same answers fail piglit's full-pixel rule on
//!   the sum: that is what the declaration changes, and nothing else.
//! - Coverage moved from one primitive to its neighbour leaves every sum
//!   right and is caught, per primitive.
//! - Without antialiasing it answers coverage only, and the cases that ask
//!   for depth and attributes are judged on coverage, saying so; without
//!   the declaration the same answers are errors that name the JSON path.

mod common;

use std::path::{Path, PathBuf};

use common::cli::{rastercheck, run_client, scratch, text};
use serde_json::Value;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the client with `flags` over `cases` (folders or files of the
/// repository), one thread; the report, and what was printed.
fn run(tag: &str, flags: &str, cases: &[&str]) -> (Value, String) {
    run_client(
        &format!("coverage-{tag}"),
        "area8.py",
        "area8",
        flags,
        cases,
    )
}

/// The client's result on each case: (case id, result object).
fn results(report: &Value) -> Vec<(String, Value)> {
    report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["id"].as_str().unwrap().to_owned(),
                c["results"][0].clone(),
            )
        })
        .collect()
}

fn verdicts(report: &Value, verdict: &str) -> Vec<String> {
    results(report)
        .into_iter()
        .filter(|(_, r)| r["verdict"] == verdict)
        .map(|(id, _)| id)
        .collect()
}

fn summary(printed: &str) -> &str {
    printed
        .lines()
        .find(|l| l.starts_with("area8:"))
        .unwrap_or_else(|| panic!("no summary line in:\n{printed}"))
}

const AA: &str = "cases/antialias";

#[test]
fn an_8_bit_area_rasterizer_is_judged_per_primitive_without_false_failures() {
    let (report, printed) = run("declared", "", &[AA]);
    assert_eq!(
        summary(&printed),
        "area8: 65 passed, 0 failed, 6 unsupported, 0 errors",
        "{printed}"
    );
    // The unsupported ones are the fill rules and primitives it declares
    // it does not do, never sent.
    for (id, r) in results(&report) {
        if r["verdict"] == "unsupported" {
            let why = r["reasons"][0].as_str().unwrap();
            assert!(why.contains("(area8 1) declares no"), "{id}: {why}");
        }
    }
    // Every judged case was judged per primitive, at its declared step.
    let (_, diagonal) = results(&report)
        .into_iter()
        .find(|(id, _)| id == "antialias/abutting_square_diagonal_standard16")
        .unwrap();
    let aa = &diagonal["metrics"]["antialias"];
    let parts = &aa["primitives"];
    assert_eq!(parts["step"].as_f64().unwrap(), 1.0 / 255.0);
    assert_eq!(
        parts["allowed_error"].as_f64().unwrap(),
        1.0 / 255.0 + 1e-9,
        "one step, and 1e-9 for the program's float arithmetic"
    );
    assert_eq!(
        (
            parts["over_bound"].as_u64(),
            parts["exactness_violations"].as_u64()
        ),
        (Some(0), Some(0))
    );
    // Its 8 diagonal pixels sum 128/255 + 128/255: full pixels within the
    // two steps they allow, not exactly 1.
    assert_eq!(aa["piglit_violations"], 0);
    assert_eq!(aa["piglit_within_quantization"], 8);
    for (id, r) in results(&report) {
        if r["verdict"] == "pass" {
            assert!(r["metrics"]["antialias"]["primitives"].is_object(), "{id}");
        }
    }
}

#[test]
fn undeclared_rounding_is_held_to_exact_full_pixels() {
    // The same answers, with no coverage_bits in the hello.
    let (report, printed) = run("undeclared", "--no-bits", &[AA]);
    assert_eq!(
        summary(&printed),
        "area8: 61 passed, 4 failed, 6 unsupported, 0 errors",
        "{printed}"
    );
    let failed = verdicts(&report, "fail");
    assert_eq!(
        failed,
        [
            "antialias/abutting_fan_8_standard8",
            "antialias/abutting_square_diagonal_standard16",
            "antialias/sweep_vertical_edge_32_standard16",
            "antialias/sweep_vertical_edge_32_standard4",
        ]
    );
    for (id, r) in results(&report) {
        if r["verdict"] == "fail" {
            let reasons = r["reasons"].to_string();
            assert!(reasons.contains("piglit's rule)"), "{id}: {reasons}");
            assert!(!reasons.contains("per primitive"), "{id}: {reasons}");
        }
    }
}

#[test]
fn coverage_moved_between_primitives_is_caught_though_every_sum_is_right() {
    let (report, printed) = run("swap", "--swap", &[AA]);
    let failed = verdicts(&report, "fail");
    assert!(failed.len() >= 20, "{printed}");
    for (id, r) in results(&report) {
        if r["verdict"] != "fail" {
            continue;
        }
        // The sums are the declared client's, which pass: only the
        // per-primitive comparison fails it.
        let reasons: Vec<&str> = r["reasons"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap())
            .collect();
        assert_eq!(reasons.len(), 1, "{id}: {reasons:?}");
        assert!(
            reasons[0].contains("from the primitive's exact area")
                && reasons[0].contains("one step of the declared quantization"),
            "{id}: {reasons:?}"
        );
        let aa = &r["metrics"]["antialias"];
        assert_eq!(aa["piglit_violations"], 0, "{id}");
        let worst = aa["primitives"]["max_error"].as_f64().unwrap();
        assert!(worst > 7.0 / 255.0, "{id}: {worst}");
    }
    // Every case with two primitives that share partly covered pixels is
    // caught; the declared client passed them all.
    assert!(failed.contains(&"antialias/abutting_square_diagonal_standard16".to_owned()));
}

#[test]
fn coverage_only_answers_are_judged_on_coverage_and_say_so() {
    let cases = [
        "cases/triangles/interp_linear.json",
        "cases/triangles/interp_depth_z.json",
        "cases/triangles/shared_edge_diagonal.json",
    ];
    let (report, printed) = run("only", "", &cases);
    assert_eq!(
        summary(&printed),
        "area8: 3 passed, 0 failed, 0 unsupported, 0 errors",
        "{printed}"
    );
    let method = "coverage only: depth and attributes not judged";
    for (id, r) in results(&report) {
        let asks_values = id != "triangles/shared_edge_diagonal";
        assert_eq!(
            r["method"].as_str() == Some(method),
            asks_values,
            "{id}: {r}"
        );
        assert_eq!(r["metrics"]["channels"], serde_json::json!([]), "{id}");
    }
    assert!(printed.contains(&format!("area8 ({method})")), "{printed}");

    // Not declared: the fragments lack the values the plan asks for.
    let (report, _) = run("not-only", "--no-coverage-only", &cases);
    for (id, r) in results(&report) {
        if id == "triangles/shared_edge_diagonal" {
            assert_eq!(r["verdict"], "pass");
            continue;
        }
        assert_eq!(r["verdict"], "error", "{id}");
        let why = r["reasons"][0].as_str().unwrap();
        assert!(
            why.contains("$.primitives[0].fragments[0] must be an array of"),
            "{id}: {why}"
        );
    }
}

#[test]
fn a_wrong_coverage_bits_is_an_error_naming_its_path() {
    let dir = scratch("coverage-bad-hello");
    let program = dir.join("bad_hello.py");
    std::fs::write(
        &program,
        "import json, sys\n\
         print(json.dumps({'hello': {'protocol': 2, 'capabilities': {'coverage_bits': 0}}}), flush=True)\n\
         for line in sys.stdin:\n    pass\n",
    )
    .unwrap();
    let spec = format!("bad=external-persistent:python3 {}", program.display());
    let case = root().join("cases/triangles/shared_edge_diagonal.json");
    let out = rastercheck(
        Path::new(&dir),
        &["run", &case.display().to_string(), "-r", &spec],
    );
    let printed = text(&out);
    // Refused before any case: bad usage (SPEC.md §12.7).
    assert_eq!(out.status.code(), Some(2), "{printed}");
    assert!(
        printed.contains("$.hello.capabilities.coverage_bits must be from 1 to 24"),
        "{printed}"
    );
}
