//! `run --repeat N` (SPEC.md §6.6): every case drawn N times by each
//! candidate, and a candidate whose frames differ between repetitions is
//! FLAKY on the case. Through the binary, as a user runs it:
//!
//! - The foil is a real program that is not deterministic
//!   (`tests/clients/flaky.py`: exact point sampling, but the second time
//!   it is asked for a scene it leaves out one fragment). Under
//!   `--repeat 3` each case it draws is FLAKY, with its three outcomes
//!   (PASS, FAIL, PASS) and the difference (coverage, the pixel, one
//!   sample) in report.json, the console, the summary, JUnit and the
//!   case's page, and the run fails. The same program without its fault
//!   (`--steady`) is judged under `--repeat 3` exactly as under
//!   `--repeat 1`.
//! - Production, deterministic, gives the same verdicts on every bundled
//!   case under `--repeat 3` as under `--repeat 1`, none flaky.

mod common;

use std::path::{Path, PathBuf};

use common::cli::{rastercheck, read_json, scratch, text, verdicts};
use serde_json::Value;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs `-r NAME=external-persistent:flaky.py FLAGS` over the fan cases
/// (a handful, each drawn by the client) with `--repeat N`: exit code,
/// what was printed, the report folder.
fn run_client(tag: &str, flags: &str, repeat: &str) -> (Option<i32>, String, PathBuf) {
    let dir = scratch(&format!("repeat-{tag}"));
    let state = dir.join("state");
    std::fs::create_dir_all(&state).unwrap();
    let spec = format!(
        "flaky=external-persistent:python3 {} --state {} {flags}",
        root().join("tests/clients/flaky.py").display(),
        state.display()
    );
    let report = dir.join("report");
    let out = rastercheck(
        &root(),
        &[
            "run",
            "cases/triangles",
            "--filter",
            "triangles/fan_*",
            "-r",
            &spec,
            "--repeat",
            repeat,
            "--report",
            &report.display().to_string(),
        ],
    );
    (out.status.code(), text(&out), report)
}

fn results(report: &Path) -> Vec<Value> {
    let json = read_json(&report.join("report.json"));
    json["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let mut r = c["results"][0].clone();
            r["id"] = c["id"].clone();
            r["page"] = c["page"].clone();
            r
        })
        .collect()
}

#[test]
fn a_rasterizer_that_draws_a_case_differently_the_second_time_is_flaky() {
    let (code, printed, report) = run_client("foil", "", "3");
    assert_eq!(code, Some(1), "a flaky result fails the run:\n{printed}");
    let results = results(&report);
    let flaky: Vec<&Value> = results.iter().filter(|r| r["verdict"] == "flaky").collect();
    let drawn = results
        .iter()
        .filter(|r| r["verdict"] != "unsupported")
        .count();
    assert!(drawn >= 3, "the client draws the fan cases:\n{printed}");
    assert_eq!(
        flaky.len(),
        drawn,
        "every case it drew is flaky:\n{printed}"
    );
    for r in &flaky {
        let id = r["id"].as_str().unwrap();
        let outcomes: Vec<&str> = r["flaky"]["outcomes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|o| o["verdict"].as_str().unwrap())
            .collect();
        assert_eq!(outcomes, ["PASS", "FAIL", "PASS"], "{id}: {r}");
        // Only repetition 2 differs, by one fragment: its sample's
        // coverage and last primitive.
        let differences = r["flaky"]["differences"].as_array().unwrap();
        let channels: Vec<&str> = differences
            .iter()
            .map(|d| d["channel"].as_str().unwrap())
            .collect();
        assert_eq!(channels, ["coverage", "last"], "{id}: {r}");
        for d in differences {
            assert_eq!(d["repetition"], 2, "{id}: {d}");
            assert_eq!(d["count"], 1, "{id}: one fragment left out: {d}");
            assert!(d["first"]["x"].is_u64() && d["first"]["sample"] == 0, "{d}");
            assert_eq!(d["first"], differences[0]["first"], "{id}: {d}");
        }
        assert_eq!(
            differences[0]["values"],
            serde_json::json!([1.0, 0.0]),
            "{id}: covered once, then not: {r}"
        );
        let reason = r["reasons"][0].as_str().unwrap();
        assert!(
            reason.starts_with("flaky: 3 repetitions: PASS, FAIL (")
                && reason.contains("coverage differs in repetition 2 from the first at pixel (")
                && reason.ends_with("(and 1 more differences)"),
            "{id}: {reason}"
        );
        // The console names it, with every repetition's outcome.
        assert!(
            printed
                .lines()
                .any(|l| l.starts_with("FLAKY") && l.contains(id)),
            "{id}:\n{printed}"
        );
        // Its page shows the repetitions and the difference.
        let page = std::fs::read_to_string(report.join(r["page"].as_str().unwrap())).unwrap();
        assert!(
            page.contains("repetition 2: FAIL") && page.contains("coverage differs"),
            "{id}'s page"
        );
    }
    assert!(printed.contains("        repetition 2: FAIL"), "{printed}");
    let summary = printed
        .lines()
        .find(|l| l.starts_with("flaky:"))
        .unwrap_or_else(|| panic!("no summary line:\n{printed}"));
    assert!(
        summary.contains(&format!(", {} flaky over 3 repetitions", flaky.len())),
        "{summary}"
    );
    let json = read_json(&report.join("report.json"));
    assert_eq!(json["totals"]["verdicts"][0]["flaky"], flaky.len());
    let junit = std::fs::read_to_string(report.join("junit.xml")).unwrap();
    assert_eq!(
        junit.matches("<failure message=\"flaky: ").count(),
        flaky.len(),
        "{junit}"
    );
    let md = std::fs::read_to_string(report.join("summary.md")).unwrap();
    assert!(md.contains("| flaky |"), "{md}");
}

#[test]
fn a_deterministic_program_is_judged_the_same_under_repeat() {
    let (once_code, once_printed, once) = run_client("steady-1", "--steady", "1");
    let (code, printed, thrice) = run_client("steady-3", "--steady", "3");
    assert_eq!(code, once_code, "{printed}\n{once_printed}");
    let (a, b) = (
        verdicts(&read_json(&once.join("report.json"))),
        verdicts(&read_json(&thrice.join("report.json"))),
    );
    assert_eq!(a, b);
    assert!(a.iter().any(|(_, v, _)| v == "pass"), "{a:?}");
    assert!(!printed.contains("FLAKY"), "{printed}");
    assert!(
        printed.contains(", 0 flaky over 3 repetitions"),
        "{printed}"
    );
}

/// Production is deterministic: over every bundled case, `--repeat 3`
/// gives the verdicts `--repeat 1` gives, and no case is flaky.
#[test]
fn production_gives_the_same_verdicts_on_every_repetition() {
    let dir = scratch("repeat-production");
    let run = |repeat: &str| {
        let report = dir.join(format!("report-{repeat}"));
        let out = rastercheck(
            &root(),
            &[
                "run",
                "cases",
                "-q",
                "--repeat",
                repeat,
                "--report",
                &report.display().to_string(),
            ],
        );
        (
            out.status.code(),
            text(&out),
            read_json(&report.join("report.json")),
        )
    };
    let (once_code, _, once) = run("1");
    let (code, printed, thrice) = run("3");
    assert_eq!(code, once_code, "{printed}");
    assert!(!printed.contains("FLAKY"), "{printed}");
    assert!(
        printed.contains("production: ") && printed.contains(", 0 flaky over 3 repetitions"),
        "{printed}"
    );
    let (a, b) = (verdicts(&once), verdicts(&thrice));
    assert!(a.len() > 400, "{} cases", a.len());
    assert_eq!(a, b);
}

#[test]
fn a_repeat_count_out_of_range_is_bad_usage() {
    for bad in ["0", "101", "x"] {
        let out = rastercheck(&root(), &["run", "cases/triangles", "--repeat", bad]);
        assert_eq!(out.status.code(), Some(2), "--repeat {bad}: {}", text(&out));
        assert!(text(&out).contains("repetitions"), "{}", text(&out));
    }
}
