//! Answers and requests in bounded memory (issue 36, findings 2 and 3): a
//! right answer for a 4096² case (192 MB of JSON, under every default
//! limit) and the request of a 2048² case at 16 time samples (the sample
//! limit; 540 MB of JSON) each go through under a 1 GiB address-space cap
//! (`prlimit --as`), the run and its report whole; and one budget,
//! `--max-case-memory`, counts an external program's answer line beside
//! the frames, so a case over it is a limit verdict with the figure while
//! the run goes on. Before the fix the answer was parsed into a
//! `serde_json::Value` with `arbitrary_precision` (each number a heap
//! string: 4.2 GB for this answer) and the request was built three times
//! (nested vectors, a `Value`, text: 9.1 GB); both aborted under a 4 GiB
//! cap, and the run's report was lost. Peak RSS is `wait4`'s, as for every
//! run here (`common::cli::run_measured`).

use std::path::Path;

use crate::common::cli::{case_entry, read_json, run_measured, text, workspace};

/// One address-space cap for both runs: 1 GiB.
const CAP_BYTES: u64 = 1 << 30;

/// A 4096² canvas under one triangle that covers every pixel centre.
const ANSWER_4096: &str = r#"{"name": "answer4096", "canvas": {"width": 4096, "height": 4096},
  "primitives": [{"triangle": [[0, 0], [8192, 0], [0, 8192]]}]}"#;

/// An 8² canvas the same way: a small case the same program answers
/// right, run after the big one.
const FULL_8: &str = r#"{"name": "full8", "canvas": {"width": 8, "height": 8},
  "primitives": [{"triangle": [[0, 0], [16, 0], [0, 16]]}]}"#;

/// A 2048² canvas at 16 time samples: 2^26 sample tests, the sample
/// limit. Its one triangle, a moving sliver near a corner, covers no pixel
/// centre at any instant, so an empty answer is right and the reference
/// is quick; the request still carries every pixel's 16 instants.
const MOTION_2048: &str = r#"{"name": "motion2048", "canvas": {"width": 2048, "height": 2048},
  "effects": {"motion_blur": {"samples": 16}},
  "primitives": [{"triangle": [{"from": [0.125, 0.125], "to": [0.25, 0.125]},
                               [0.25, 0.125], [0.125, 0.25]]}]}"#;

/// `tests/faults/programs/external_big.py MODE` as a persistent program.
fn big_program(mode: &str) -> String {
    let program =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/faults/programs/external_big.py");
    format!("external-persistent:{} {mode}", program.display())
}

/// `run cases -r external_big.py MODE --threads 1 --report report` and
/// `extra`, run in `dir` under `prlimit --as=CAP_BYTES` (the same process:
/// prlimit execs it), its peak RSS held to [`BOUND_MIB`] and its exit
/// status to 0: its report and what it printed.
fn run_capped(dir: &Path, mode: &str, extra: &[&str]) -> (serde_json::Value, String) {
    let program = big_program(mode);
    let mut args = vec![
        "run",
        "cases",
        "-r",
        &program,
        "--threads",
        "1",
        "--report",
        "report",
    ];
    args.extend(extra);
    let mut command = std::process::Command::new("prlimit");
    command
        .arg(format!("--as={CAP_BYTES}"))
        .arg(env!("CARGO_BIN_EXE_rastercheck"))
        .args(&args)
        .current_dir(dir);
    let m = run_measured(&mut command, std::time::Duration::from_secs(600));
    crate::common::cli::assert_peak_rss(&format!("{args:?}"), &m, BOUND_MIB);
    let log = text(&m.output);
    assert_eq!(m.output.status.code(), Some(0), "{log}");
    (read_json(&dir.join("report/report.json")), log)
}

/// The verdict of case `id`'s only candidate, or its status when it has none.
fn verdict(report: &serde_json::Value, id: &str) -> String {
    let case = case_entry(report, id).unwrap_or_else(|| panic!("no case {id}"));
    match case["results"][0]["verdict"].as_str() {
        Some(v) => v.to_owned(),
        None => case["status"].as_str().unwrap_or("?").to_owned(),
    }
}

#[test]
fn a_right_answer_for_a_4096_square_case_is_judged_under_a_gibibyte() {
    let dir = workspace(
        "bounded-answer",
        &[
            ("cases/big/answer4096.json", ANSWER_4096),
            ("cases/small/full8.json", FULL_8),
        ],
    );
    let (report, log) = run_capped(&dir, "full", &[]);
    assert_eq!(verdict(&report, "big/answer4096"), "pass", "{log}");
    assert_eq!(verdict(&report, "small/full8"), "pass", "{log}");
}

#[test]
fn a_moving_2048_square_request_at_16_instants_is_streamed_under_a_gibibyte() {
    let dir = workspace(
        "bounded-request",
        &[("cases/big/motion2048.json", MOTION_2048)],
    );
    let (report, log) = run_capped(&dir, "motion", &["--case-timeout", "600"]);
    assert_eq!(verdict(&report, "big/motion2048"), "pass", "{log}");
}

#[test]
fn an_answer_line_counts_in_the_one_memory_budget() {
    // An 8² case's frames take a few KiB; a persistent program may answer
    // with a line of up to its output limit (256 MiB by default), held as
    // text while it is read. Under a budget of 100 MiB the case is over
    // the limit, with the figure, before anything is sent; the run goes on
    // and the report is whole.
    let dir = workspace("bounded-budget", &[("cases/small/full8.json", FULL_8)]);
    let program = big_program("full");
    let out = crate::run_within(
        &dir,
        &[
            "run",
            "cases",
            "-r",
            &program,
            "--max-case-memory",
            "104857600",
            "--report",
            "report",
        ],
        crate::RSS_BOUND_MIB,
    );
    let log = text(&out);
    assert_eq!(out.status.code(), Some(2), "{log}");
    assert!(
        log.contains("its frames and answers would take about 257 MiB")
            && log.contains("and up to 256 MiB of answer lines")
            && log.contains("over the limit of 100 MiB per case (raise it with --max-case-memory)"),
        "{log}"
    );
    let report = read_json(&dir.join("report/report.json"));
    assert_eq!(verdict(&report, "small/full8"), "limit-exceeded", "{log}");
    // With the budget raised, the same case is judged.
    let out = crate::run_within(
        &dir,
        &["run", "cases", "-r", &program, "--report", "report2"],
        crate::RSS_BOUND_MIB,
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
}

/// The peak RSS either big run stays under: measured (see the table in
/// `main.rs`) with room, and a quarter of what the same runs took before.
const BOUND_MIB: f64 = 900.0;
