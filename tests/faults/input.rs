//! Faults: hostile case input (huge files, special files, symlink loops, duplicate keys and ids).
//!
//! Each test runs the binary on a folder holding one good case beside the
//! hostile input, and asserts that the run finishes (every child is waited
//! for with a generous limit that only guards against a hang), the good
//! case keeps its verdict, report.json parses and names each case's status,
//! and the exit code is SPEC §9's: 2 for bad input or a case over a limit.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::common::cli::{read_json, scratch, text, workspace};

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
/// that hangs fails the test instead of hanging it.
fn run_bounded(dir: &Path, args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    // Drain both pipes on threads so that a full pipe cannot block it.
    let mut out = child.stdout.take().unwrap();
    let mut err = child.stderr.take().unwrap();
    let stdout = std::thread::spawn(move || {
        let mut v = Vec::new();
        let _ = out.read_to_end(&mut v);
        v
    });
    let stderr = std::thread::spawn(move || {
        let mut v = Vec::new();
        let _ = err.read_to_end(&mut v);
        v
    });
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("rastercheck {args:?} hung (killed after 60 s)");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Output {
        status,
        stdout: stdout.join().unwrap(),
        stderr: stderr.join().unwrap(),
    }
}

/// `run cases --report rep` (plus `more`) in `dir`: it exits with `code`,
/// panics nowhere, and report.json parses. Returns the printed text and
/// the status of each case in the report, by id.
fn run_report(dir: &Path, more: &[&str], code: i32) -> (String, Vec<(String, String)>) {
    let args = [&["run", "cases", "--report", "rep"], more].concat();
    let out = run_bounded(dir, &args);
    let t = text(&out);
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
    (t, statuses)
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
    let (t, statuses) = run_report(&dir, &[], 2);
    assert_good_passes(&t, &statuses);
    assert_eq!(status_of(&statuses, "huge"), "limit-exceeded", "{t}");
    let line = t.lines().find(|l| l.contains(" huge ")).unwrap();
    assert!(line.starts_with("LIMIT"), "{t}");
    assert!(line.contains("600000000 bytes"), "{t}");
    assert!(line.contains("--max-case-bytes"), "{t}");

    // The flag moves the limit: a small good case over a tiny limit is a
    // limit verdict too, and under a raised one the same file reads.
    let dir = workspace("input-small-limit", &[("cases/good.json", GOOD)]);
    let (t, statuses) = run_report(&dir, &["--max-case-bytes", "20"], 2);
    assert_eq!(status_of(&statuses, "good"), "limit-exceeded", "{t}");
    let (t, statuses) = run_report(&dir, &["--max-case-bytes", "100000"], 0);
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
    let (t, statuses) = run_report(&dir, &[], 2);
    assert_good_passes(&t, &statuses);
    assert_eq!(status_of(&statuses, "fifo"), "unreadable", "{t}");
    assert!(t.contains("not a regular file (a FIFO)"), "{t}");
    let out = run_bounded(&dir, &["run", "cases/fifo.json", "cases/good.json"]);
    let t = text(&out);
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
#[test]
fn symlink_loops_in_the_case_tree_are_reported_once() {
    let dir = workspace("input-loop", &[("cases/a/good.json", GOOD)]);
    // A link to the case root inside it, and one to its own folder.
    std::os::unix::fs::symlink("..", dir.join("cases/a/up")).unwrap();
    std::os::unix::fs::symlink(".", dir.join("cases/a/here")).unwrap();
    let out = run_bounded(&dir, &["run", "cases", "--report", "rep"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert_eq!(t.matches("symbolic link loop").count(), 2, "{t}");
    assert!(t.contains("cases/a/up: a symbolic link loop"), "{t}");
    assert!(t.contains("cases/a/here: a symbolic link loop"), "{t}");
    assert!(
        t.lines()
            .any(|l| l.starts_with("PASS") && l.contains(" a/good ")),
        "{t}"
    );
    // The good case is run once, whatever paths lead to it.
    let report = read_json(&dir.join("rep/report.json"));
    assert_eq!(report["cases"].as_array().unwrap().len(), 1, "{t}");
}
