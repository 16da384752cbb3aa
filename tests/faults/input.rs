//! Faults: hostile case input (huge files, special files, symlink loops, duplicate keys and ids).
//!
//! Each test runs the binary on a folder holding one good case beside the
//! hostile input, and asserts that the run finishes (every child is waited
//! for with a generous limit that only guards against a hang), the good
//! case keeps its verdict, report.json parses and names each case's status,
//! and the exit code is SPEC §9's: 2 for bad input or a case over a limit.

use std::path::Path;
use std::process::Command;
use std::time::Duration;

use crate::common::cli::{assert_peak_rss, read_json, run_measured, text, workspace, Measured};

/// A small case that production passes.
const GOOD: &str = r#"{"name": "good", "canvas": {"width": 4, "height": 4},
    "primitives": [{"triangle": [[0, 0], [4, 0], [0, 4]]}]}"#;

/// A case named `name` with `seed` as its antialiasing seed.
fn seeded(name: &str, seed: &str) -> String {
    format!(
        r#"{{"name": "{name}", "canvas": {{"width": 4, "height": 4}},
        "effects": {{"antialias": {{"samples": 4, "pattern": "random", "seed": {seed}}}}},
        "primitives": [{{"triangle": [[0, 0], [4, 0], [0, 4]]}}]}}"#
    )
}

/// Runs rastercheck in `dir` with `args`, killing it after a minute: a run
/// that hangs fails the test instead of hanging it. With its peak RSS.
fn run_bounded(dir: &Path, args: &[&str]) -> Measured {
    let mut command = Command::new(env!("CARGO_BIN_EXE_rastercheck"));
    command.args(args).current_dir(dir);
    run_measured(&mut command, Duration::from_secs(60))
}

/// `run cases --report rep` (plus `more`) in `dir`: it exits with `code`,
/// panics nowhere, and report.json parses. Returns the printed text and
/// the status of each case in the report, by id.
fn run_report(dir: &Path, more: &[&str], code: i32) -> (String, Vec<(String, String)>, Measured) {
    let args = [&["run", "cases", "--report", "rep"], more].concat();
    let run = run_bounded(dir, &args);
    let out = &run.output;
    let t = text(out);
    assert!(!t.contains("panicked"), "{t}");
    assert_eq!(out.status.code(), Some(code), "{t}");
    let report = read_json(&dir.join("rep/report.json"));
    assert_eq!(report["complete"], true, "{t}");
    let statuses = report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            (
                c["id"].as_str().unwrap().to_owned(),
                c["status"].as_str().unwrap().to_owned(),
            )
        })
        .collect();
    (t, statuses, run)
}

/// The good case ran and production passed it.
fn assert_good_passes(t: &str, statuses: &[(String, String)]) {
    assert!(
        statuses.contains(&("good".to_owned(), "ran".to_owned())),
        "{statuses:?}\n{t}"
    );
    assert!(
        t.lines()
            .any(|l| l.starts_with("PASS") && l.contains(" good ")),
        "{t}"
    );
}

fn status_of<'s>(statuses: &'s [(String, String)], id: &str) -> &'s str {
    statuses
        .iter()
        .find(|(i, _)| i == id)
        .map(|(_, s)| s.as_str())
        .unwrap_or_else(|| panic!("no case {id} in {statuses:?}"))
}

#[test]
fn a_huge_case_file_is_a_limit_verdict_read_from_its_size() {
    let dir = workspace("input-huge", &[("cases/good.json", GOOD)]);
    // Sparse: 600 MB long, no disk used. Reading it whole would hold about
    // 20 GB; the size is judged from the metadata before a byte is read.
    let huge = std::fs::File::create(dir.join("cases/huge.json")).unwrap();
    huge.set_len(600_000_000).unwrap();
    drop(huge);
    let (t, statuses, run) = run_report(&dir, &[], 2);
    // Measured 6 MiB. Reading the 600 MB file would hold 600 MB, and
    // parsing it about 20 GB: it is judged from its size unread.
    assert_peak_rss("huge case file", &run, crate::RSS_BOUND_MIB);
    assert_good_passes(&t, &statuses);
    assert_eq!(status_of(&statuses, "huge"), "limit-exceeded", "{t}");
    let line = t.lines().find(|l| l.contains(" huge ")).unwrap();
    assert!(line.starts_with("LIMIT"), "{t}");
    assert!(line.contains("600000000 bytes"), "{t}");
    assert!(line.contains("--max-case-bytes"), "{t}");

    // The flag moves the limit: a small good case over a tiny limit is a
    // limit verdict too, and under a raised one the same file reads.
    let dir = workspace("input-small-limit", &[("cases/good.json", GOOD)]);
    let (t, statuses, run) = run_report(&dir, &["--max-case-bytes", "20"], 2);
    assert_peak_rss("tiny --max-case-bytes", &run, crate::RSS_BOUND_MIB);
    assert_eq!(status_of(&statuses, "good"), "limit-exceeded", "{t}");
    let (t, statuses, run) = run_report(&dir, &["--max-case-bytes", "100000"], 0);
    assert_peak_rss("raised --max-case-bytes", &run, crate::RSS_BOUND_MIB);
    assert_good_passes(&t, &statuses);
}

#[cfg(unix)]
#[test]
fn a_fifo_case_is_refused_and_the_run_goes_on() {
    let dir = workspace("input-fifo", &[("cases/good.json", GOOD)]);
    let fifo = dir.join("cases/fifo.json");
    let made = Command::new("mkfifo").arg(&fifo).status().expect("mkfifo");
    assert!(made.success());
    // Found by walking the folder, and named on the command line.
    let (t, statuses, run) = run_report(&dir, &[], 2);
    // Measured 6 MiB.
    assert_peak_rss("FIFO case", &run, crate::RSS_BOUND_MIB);
    assert_good_passes(&t, &statuses);
    assert_eq!(status_of(&statuses, "fifo"), "unreadable", "{t}");
    assert!(t.contains("not a regular file (a FIFO)"), "{t}");
    let run = run_bounded(&dir, &["run", "cases/fifo.json", "cases/good.json"]);
    let out = &run.output;
    assert_peak_rss("FIFO case named", &run, crate::RSS_BOUND_MIB);
    let t = text(out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("cases/fifo.json: $: not a regular file (a FIFO)"),
        "{t}"
    );
    assert!(
        t.lines()
            .any(|l| l.starts_with("PASS") && l.contains(" good ")),
        "{t}"
    );
}

#[cfg(unix)]
/// `a/good` passed, and the report in `rep/` holds one case.
fn good_passed_once(dir: &std::path::Path, t: &str) {
    assert!(
        t.lines()
            .any(|l| l.starts_with("PASS") && l.contains(" a/good ")),
        "{t}"
    );
    let report = read_json(&dir.join("rep/report.json"));
    assert_eq!(report["cases"].as_array().unwrap().len(), 1, "{t}");
}

#[test]
fn symlink_loops_in_the_case_tree_are_reported_once() {
    let dir = workspace("input-loop", &[("cases/a/good.json", GOOD)]);
    // A link to the case root inside it, and one to its own folder.
    std::os::unix::fs::symlink("..", dir.join("cases/a/up")).unwrap();
    std::os::unix::fs::symlink(".", dir.join("cases/a/here")).unwrap();
    let run = run_bounded(&dir, &["run", "cases", "--report", "rep"]);
    let out = &run.output;
    // Measured 6 MiB: each loop is walked once.
    assert_peak_rss("symlink loops", &run, crate::RSS_BOUND_MIB);
    let t = text(out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert_eq!(t.matches("symbolic link loop").count(), 2, "{t}");
    assert!(t.contains("cases/a/up: a symbolic link loop"), "{t}");
    assert!(t.contains("cases/a/here: a symbolic link loop"), "{t}");
    // The good case is run once, whatever paths lead to it.
    good_passed_once(&dir, &t);
}

#[test]
fn one_id_is_one_case() {
    let dir = workspace(
        "input-ids",
        &[
            ("cases/a/good.json", GOOD),
            ("other/cases/a/good.json", GOOD),
        ],
    );
    // The same file through two paths is one case, and passes.
    let run = run_bounded(&dir, &["run", "cases", "./cases", "cases/a/good.json"]);
    let out = &run.output;
    // Measured 7 MiB.
    assert_peak_rss("one file by two paths", &run, crate::RSS_BOUND_MIB);
    let t = text(out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    assert_eq!(t.matches(" a/good ").count(), 1, "{t}");
    // Two different files with one id: an error naming both, exit 2, and
    // the first is still run and judged.
    let run = run_bounded(&dir, &["run", "cases", "other/cases", "--report", "rep"]);
    let out = &run.output;
    assert_peak_rss("two files with one id", &run, crate::RSS_BOUND_MIB);
    let t = text(out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("two different files have the case id \"a/good\": cases/a/good.json and other/cases/a/good.json"),
        "{t}"
    );
    good_passed_once(&dir, &t);
}

#[test]
fn hostile_values_are_named_by_path_and_cut_when_echoed() {
    let long_key = "k".repeat(5_000_000);
    let long_rule = "x".repeat(5_000_000);
    let dup = r#"{"name": "dup", "canvas": {"width": 4, "height": 4}, "canvas": {"width": 4, "height": 4},
        "primitives": [{"triangle": [[0, 0], [4, 0], [0, 4]]}]}"#;
    let key = format!(
        r#"{{"name": "key", "canvas": {{"width": 4, "height": 4, "{long_key}": 1}},
        "primitives": [{{"triangle": [[0, 0], [4, 0], [0, 4]]}}]}}"#
    );
    let rule = format!(
        r#"{{"name": "rule", "canvas": {{"width": 4, "height": 4}}, "rules": {{"fill_rule": "{long_rule}"}},
        "primitives": [{{"triangle": [[0, 0], [4, 0], [0, 4]]}}]}}"#
    );
    let number = format!(
        r#"{{"name": "number", "canvas": {{"width": 4, "height": 4}},
        "primitives": [{{"triangle": [[0, 0], [4, 0], [0, "{long_rule}"]]}}]}}"#
    );
    let plus = r#"{"name": "plus", "canvas": {"width": 4, "height": 4},
        "primitives": [{"triangle": [[0, 0], ["+4", 0], [0, 4]]}]}"#;
    let dir = workspace(
        "input-echo",
        &[
            ("cases/good.json", GOOD),
            ("cases/dup.json", dup),
            ("cases/key.json", &key),
            ("cases/rule.json", &rule),
            ("cases/number.json", &number),
            ("cases/plus.json", plus),
            (
                "cases/seed_max.json",
                &seeded("seed_max", "18446744073709551615"),
            ),
            (
                "cases/seed_over.json",
                &seeded("seed_over", "18446744073709551616"),
            ),
        ],
    );
    let (t, statuses, run) = run_report(&dir, &[], 2);
    // Measured 35 MiB on 2 cores: three 5 MB values read and parsed
    // (each file is under --max-case-bytes), more at once on more cores.
    assert_peak_rss("hostile values", &run, 128.0);
    assert_good_passes(&t, &statuses);
    for id in ["dup", "key", "rule", "number", "plus", "seed_over"] {
        assert_eq!(status_of(&statuses, id), "unreadable", "{id}\n{t}");
    }
    assert_eq!(status_of(&statuses, "seed_max"), "ran", "{t}");
    let line = |id: &str| {
        t.lines()
            .find(|l| l.split_whitespace().nth(1) == Some(id))
            .unwrap_or_else(|| panic!("no line for {id}\n{t}"))
    };
    assert!(
        line("dup").contains("$.canvas: a key repeated in one object"),
        "{t}"
    );
    assert!(
        line("plus").contains("$.primitives[0].triangle[1][0]: \"+4\""),
        "{t}"
    );
    assert!(
        line("seed_over").contains("$.effects.antialias.seed"),
        "{t}"
    );
    for id in ["key", "rule", "number"] {
        let l = line(id);
        assert!(
            l.contains("… (5000000 characters)"),
            "{id}: {}",
            &l[..l.len().min(400)]
        );
        assert!(
            l.len() < 600,
            "{id} echoes {} bytes: {}…",
            l.len(),
            &l[..400]
        );
    }
    assert!(t.len() < 10_000, "the run printed {} bytes", t.len());
}
