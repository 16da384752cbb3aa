//! Faults: exit codes (SPEC §9): nothing judged, bad environment, broken pipes, absurd flags.
//!
//! One table for every command: 0 everything judged passes, 1 something
//! failed, 2 bad input or usage, 3 nothing was judged. Each test runs the
//! binary in a fresh folder and asserts the documented code and message.

use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::Duration;

use crate::common::cli::{
    assert_no_panic, assert_peak_rss, rastercheck_env, read_json, run_measured, text, workspace,
};

const EASY: &str = r#"{"name": "easy", "canvas": {"width": 8, "height": 8},
  "primitives": [{"triangle": [[0.3, 0.2], [7.7, 1.1], [1.4, 7.3]]}]}"#;

/// [`EASY`] named `name` (case names are unique in a run).
fn easy(name: &str) -> String {
    EASY.replace("\"easy\"", &format!("{name:?}"))
}

/// `external:` running the program that answers `unsupported` to everything.
fn unsupported_everything() -> String {
    let program = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/faults/programs/exit_codes_unsupported.py");
    format!("external:python3 {}", program.display())
}

/// Runs `args` in `dir`: asserts the exit code, no panic, and a peak RSS
/// under the faults' bound (`crate::RSS_BOUND_MIB`); what it printed.
fn exits(dir: &std::path::Path, args: &[&str], code: i32) -> String {
    exits_within(dir, args, code, crate::RSS_BOUND_MIB)
}

/// [`exits`] with another bound on the peak RSS, in MiB.
fn exits_within(dir: &std::path::Path, args: &[&str], code: i32, rss_mib: f64) -> String {
    let mut command = Command::new(env!("CARGO_BIN_EXE_rastercheck"));
    command.args(args).current_dir(dir);
    let run = run_measured(&mut command, Duration::from_secs(180));
    let out = &run.output;
    let t = text(out);
    assert_no_panic(out);
    assert_eq!(out.status.code(), Some(code), "{args:?}\n{t}");
    assert_peak_rss(&format!("{args:?}"), &run, rss_mib);
    t
}

#[test]
fn a_run_where_every_case_is_unsupported_judged_nothing() {
    let dir = workspace(
        "exit-unsupported",
        &[("cases/a.json", &easy("a")), ("cases/b.json", &easy("b"))],
    );
    let none = unsupported_everything();
    let t = exits(&dir, &["run", "cases", "-r", &none, "--report", "rep"], 3);
    assert!(t.contains("nothing was judged"), "{t}");
    // The report still says what happened: every verdict unsupported.
    let report = read_json(&dir.join("rep/report.json"));
    assert_eq!(report["complete"], true, "{report}");
    assert_eq!(
        report["totals"]["verdicts"][0]["unsupported"], 2,
        "{report}"
    );
    // One candidate that judges is enough: the run passes.
    exits(&dir, &["run", "cases", "-r", &none, "-r", "production"], 0);
}

#[test]
fn a_selection_that_matches_nothing_judged_nothing_and_a_missing_path_is_bad_input() {
    let dir = workspace("exit-selection", &[("cases/tri/easy.json", EASY)]);
    let t = exits(&dir, &["run", "cases", "--filter", "nothing/*"], 3);
    assert!(
        t.contains("no case files found that match the selection; nothing was judged"),
        "{t}"
    );
    let t = exits(&dir, &["run", "cases", "--family", "lines"], 3);
    assert!(t.contains("nothing was judged"), "{t}");
    std::fs::create_dir_all(dir.join("empty")).unwrap();
    let t = exits(&dir, &["run", "empty"], 3);
    assert!(t.contains("nothing was judged"), "{t}");
    let t = exits(&dir, &["run", "no/such/folder"], 2);
    assert!(t.contains("no such file or folder"), "{t}");
    assert!(!t.contains("nothing was judged"), "{t}");
}

#[test]
fn baseline_check_with_a_filter_that_matches_nothing_judged_nothing() {
    let dir = workspace(
        "exit-baseline",
        &[
            ("cases/tri/easy.json", EASY),
            ("cases/tri/two.json", &easy("two")),
        ],
    );
    exits(&dir, &["baseline", "save", "base.json"], 0);
    exits(&dir, &["baseline", "check", "base.json"], 0);
    let t = exits(
        &dir,
        &["baseline", "check", "base.json", "--filter", "nothing/*"],
        3,
    );
    assert!(t.contains("nothing was judged"), "{t}");
    let t = exits(
        &dir,
        &["baseline", "save", "other.json", "--filter", "nothing/*"],
        3,
    );
    assert!(t.contains("nothing was judged"), "{t}");
    assert!(!dir.join("other.json").exists());
    // Cases the baseline records that are gone are regressions, not nothing.
    std::fs::remove_dir_all(dir.join("cases/tri")).unwrap();
    std::fs::create_dir_all(dir.join("cases")).unwrap();
    exits(&dir, &["baseline", "check", "base.json"], 1);
}

#[test]
fn matrix_and_fuzz_say_when_every_case_is_unsupported() {
    let dir = workspace("exit-matrix", &[("cases/tri/easy.json", EASY)]);
    let none = unsupported_everything();
    let t = exits(&dir, &["matrix", "-r", &none], 3);
    assert!(t.contains("nothing was judged"), "{t}");
    exits(&dir, &["matrix", "-r", &none, "-r", "production"], 0);
    let t = exits(
        &dir,
        &[
            "fuzz", "-r", &none, "--cases", "3", "--seed", "1", "--out", "found",
        ],
        3,
    );
    assert!(t.contains("nothing was judged"), "{t}");
    exits(
        &dir,
        &[
            "fuzz",
            "-r",
            "production",
            "--cases",
            "3",
            "--seed",
            "1",
            "--out",
            "found",
        ],
        0,
    );
}

#[test]
fn a_malformed_external_timeout_is_bad_usage_naming_the_variable_and_a_cut_value() {
    let dir = workspace("exit-timeout-env", &[("cases/easy.json", EASY)]);
    let none = unsupported_everything();
    let long = "x".repeat(5000);
    for value in ["soon", "-1", "0", long.as_str()] {
        let out = rastercheck_env(
            &dir,
            &["run", "cases", "-r", &none, "--report", "rep"],
            &[("RASTERCHECK_EXTERNAL_TIMEOUT", value)],
        );
        let t = text(&out);
        assert_no_panic(&out);
        assert_eq!(out.status.code(), Some(2), "{value:.20}: {t}");
        assert!(t.contains("RASTERCHECK_EXTERNAL_TIMEOUT="), "{t}");
        assert!(t.contains("is not a positive number of seconds"), "{t}");
        assert!(t.len() < 400, "the value is cut: {} bytes", t.len());
        // Refused before any case ran.
        assert!(!dir.join("rep").exists(), "{t}");
    }
    // A well-formed value is used, not refused.
    let out = rastercheck_env(
        &dir,
        &["run", "cases", "-r", &none, "-r", "production"],
        &[("RASTERCHECK_EXTERNAL_TIMEOUT", "5")],
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
}

#[test]
fn probing_a_rasterizer_that_cannot_start_is_bad_input_with_the_reason() {
    let dir = workspace("exit-probe", &[]);
    let t = exits(&dir, &["probe", "-r", "external:/nonexistent/program"], 2);
    assert!(t.contains("cannot start"), "{t}");
    assert!(t.contains("/nonexistent/program"), "{t}");
}

#[test]
fn thread_counts_above_the_bound_are_refused() {
    let dir = workspace("exit-threads", &[("cases/easy.json", EASY)]);
    for args in [
        &["run", "cases", "--threads", "16000"][..],
        &["run", "cases", "--threads", "257"],
        &["matrix", "--threads", "100000"],
        &["baseline", "save", "b.json", "--threads", "1000"],
    ] {
        let t = exits(&dir, args, 2);
        assert!(t.contains("256"), "{t}");
    }
    exits(&dir, &["run", "cases", "--threads", "256"], 0);
    exits(&dir, &["run", "cases", "--threads", "1"], 0);
    let help = exits(&dir, &["run", "--help"], 0);
    assert!(help.contains("at most 256"), "{help}");
}

/// A case with one small triangle on a `w`×`h` canvas.
fn big_canvas(w: u32, h: u32) -> String {
    format!(
        r#"{{"name": "big", "canvas": {{"width": {w}, "height": {h}}},
  "primitives": [{{"triangle": [[0.3, 0.2], [7.7, 1.1], [1.4, 7.3]]}}]}}"#
    )
}

#[test]
fn show_bounds_its_pictures() {
    let dir = workspace(
        "exit-show",
        &[
            ("cases/big.json", &big_canvas(1100, 1000)),
            ("cases/huge.json", &big_canvas(16384, 8192)),
        ],
    );
    // 64 would make 70400×64000 pictures (13 GB): lowered to 7, with a note.
    // Measured 492 MiB: pictures of 7700×7000 pixels (under the 2^26 bound)
    // are drawn, 206 MiB each at 4 bytes a pixel; at scale 64 they would
    // have 4.5 G pixels each.
    let t = exits_within(
        &dir,
        &["show", "cases/big.json", "--out", "shown", "--scale", "64"],
        0,
        1024.0,
    );
    assert!(t.contains("scale 7 instead"), "{t}");
    for entry in std::fs::read_dir(dir.join("shown")).unwrap() {
        let path = entry.unwrap().path();
        let (w, h) = image::image_dimensions(&path).unwrap();
        assert!(u64::from(w) * u64::from(h) <= 1 << 26, "{path:?}: {w}×{h}");
        assert_eq!((w, h), (7700, 7000), "{path:?}");
    }
    // A canvas over 2^26 pixels cannot be pictured at all: refused.
    let t = exits(
        &dir,
        &[
            "show",
            "cases/huge.json",
            "--out",
            "shown2",
            "--max-canvas-pixels",
            "1000000000",
            "--max-samples",
            "1000000000",
        ],
        2,
    );
    assert!(t.contains("more than 67108864 pixels"), "{t}");
}

#[test]
fn a_closed_stdout_ends_printing_quietly_and_the_reports_are_still_written() {
    // Enough output (over 64 KiB, a pipe's buffer) that writes must meet the
    // closed pipe: 300 cases, each line padded to a 400-character id.
    let long = format!("{}/{}", "a".repeat(200), "b".repeat(200));
    let names: Vec<String> = (0..300)
        .map(|i| format!("cases/{long}/case_{i:03}.json"))
        .collect();
    let cases: Vec<String> = (0..300).map(|i| easy(&format!("case_{i:03}"))).collect();
    let files: Vec<(&str, &str)> = names
        .iter()
        .zip(&cases)
        .map(|(n, c)| (n.as_str(), c.as_str()))
        .collect();
    let dir = workspace("exit-pipe", &files);
    let mut child = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args(["run", "cases", "--report", "rep"])
        .current_dir(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    {
        let mut stdout = BufReader::new(child.stdout.take().unwrap());
        let mut first = String::new();
        stdout.read_line(&mut first).unwrap();
        assert!(first.starts_with("PASS"), "{first}");
        // Dropped here: the read end closes, as `head -1` does.
    }
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!stderr.to_lowercase().contains("broken pipe"), "{stderr}");
    // The run's own code: every case passed.
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let report = read_json(&dir.join("rep/report.json"));
    assert_eq!(report["complete"], true);
    assert_eq!(report["cases"].as_array().unwrap().len(), 300);
    assert!(dir.join("rep/junit.xml").exists());
}
