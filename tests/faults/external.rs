//! Faults: external programs that flood, hang, leak or answer with hostile files.
//!
//! Each test runs the binary on a few cases against a real faulty program
//! of `tests/faults/programs/` (a flood writer, a FIFO answerer, a huge-header
//! EXR answerer, a forker whose grandchild sleeps, a hanger), in one-shot and
//! persistent mode. The programs answer the cases `a` and `b` correctly (no
//! pixel centre is covered) and misbehave on the cases named `bad…`. Each
//! test asserts that the run finishes, that `a` and `b` still pass, that
//! report.json parses with the bad case's verdict, the exit code, and that
//! no process of the program's process groups is left (the programs log
//! their group ids).

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use serde_json::Value;

use crate::common::cli::{assert_peak_rss, read_json, run_measured, text, workspace, Measured};

/// Guards against a hang only: a run that is not over by then is killed and
/// the test fails (every run here takes seconds).
const HANG_GUARD: Duration = Duration::from_secs(180);

fn program(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/faults/programs")
        .join(name)
        .display()
        .to_string()
}

/// A case whose one triangle covers no pixel centre.
fn case(name: &str) -> String {
    format!(
        r#"{{"name": "{name}", "canvas": {{"width": 4, "height": 4}},
  "primitives": [{{"triangle": [[0.1, 0.1], [0.3, 0.1], [0.1, 0.3]]}}]}}"#
    )
}

/// A workspace with cases `a`, `b` and the given bad ones, and the log file
/// the programs write to.
fn cases(name: &str, bad: &[&str]) -> (PathBuf, PathBuf) {
    let names: Vec<&str> = ["a", "b"].iter().chain(bad).copied().collect();
    let files: Vec<(String, String)> = names
        .iter()
        .map(|n| (format!("cases/{n}.json"), case(n)))
        .collect();
    let files: Vec<(&str, &str)> = files
        .iter()
        .map(|(p, c)| (p.as_str(), c.as_str()))
        .collect();
    let dir = workspace(&format!("faults-external-{name}"), &files);
    let log = dir.join("programs.log");
    (dir, log)
}

/// The rasterizer argument for `script` in one mode.
fn rasterizer(script: &str, log: &Path, persistent: bool) -> String {
    if persistent {
        format!(
            "external-persistent:python3 {} {} --persistent",
            program(script),
            log.display()
        )
    } else {
        format!("external:python3 {} {}", program(script), log.display())
    }
}

/// `run cases -r RASTERIZER --report report ARGS` in `dir`, killed (and the
/// test failed) if it is not over within the hang guard; with its peak RSS.
fn run(dir: &Path, rasterizer: &str, args: &[&str], env: &[(&str, &str)]) -> Measured {
    let mut command = Command::new(env!("CARGO_BIN_EXE_rastercheck"));
    command
        .args(["run", "cases", "--report", "report", "-r"])
        .arg(rasterizer)
        .args(args)
        .current_dir(dir);
    for (k, v) in env {
        command.env(k, v);
    }
    run_measured(&mut command, HANG_GUARD)
}

/// The report's entry for case `id`.
fn entry<'a>(report: &'a Value, id: &str) -> &'a Value {
    crate::common::cli::case_entry(report, id).unwrap_or_else(|| panic!("no case {id} in {report}"))
}

/// The one rasterizer's verdict on `id`, with its reasons joined.
fn verdict(report: &Value, id: &str) -> (String, String) {
    let result = &entry(report, id)["results"][0];
    let reasons: Vec<&str> = result["reasons"]
        .as_array()
        .map(|r| r.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default();
    (
        result["verdict"].as_str().unwrap_or("").to_owned(),
        reasons.join("; "),
    )
}

/// Checks what every fault test checks: the exit code, report.json parses
/// and is complete, `a` and `b` pass, and the bad cases' verdicts and
/// reasons. The report.
fn judged(dir: &Path, out: &Output, code: i32, bad: &[(&str, &str, &str)]) -> Value {
    let t = text(out);
    assert!(!t.contains("panicked"), "{t}");
    assert_eq!(out.status.code(), Some(code), "{t}");
    let report = read_json(&dir.join("report/report.json"));
    assert_eq!(report["complete"], true, "{t}");
    for id in ["a", "b"] {
        assert_eq!(verdict(&report, id).0, "pass", "{id}: {t}");
        assert_eq!(entry(&report, id)["status"], "ran", "{id}: {t}");
    }
    for (id, expected, reason) in bad {
        let (got, reasons) = verdict(&report, id);
        assert_eq!(&got, expected, "{id}: {reasons}\n{t}");
        assert!(
            reasons.contains(reason),
            "{id}: {reasons:?} lacks {reason:?}"
        );
    }
    report
}

/// Lines of the log starting with `word`, their number.
fn logged(log: &Path, word: &str) -> Vec<i32> {
    std::fs::read_to_string(log)
        .unwrap_or_default()
        .lines()
        .filter_map(|l| l.strip_prefix(word)?.trim().parse().ok())
        .collect()
}

/// The processes (pid) whose process group is one of `groups`.
fn members(groups: &HashSet<i32>) -> Vec<(i32, String)> {
    let mut found = Vec::new();
    for e in std::fs::read_dir("/proc").unwrap().flatten() {
        let Ok(pid) = e.file_name().to_string_lossy().parse::<i32>() else {
            continue;
        };
        let Ok(stat) = std::fs::read_to_string(format!("/proc/{pid}/stat")) else {
            continue;
        };
        // pid (comm) state ppid pgrp ...: the fields after the last ')'.
        let Some(rest) = stat.rsplit_once(')').map(|(_, r)| r) else {
            continue;
        };
        let fields: Vec<&str> = rest.split_whitespace().collect();
        if let Some(pgrp) = fields.get(2).and_then(|g| g.parse::<i32>().ok()) {
            if groups.contains(&pgrp) {
                found.push((pid, stat.trim().to_owned()));
            }
        }
    }
    found
}

/// No process of the groups the programs logged is left. A killed process
/// may take a moment to be reaped by its new parent: waited for, within the
/// hang guard.
fn assert_no_group_left(log: &Path) {
    let groups: HashSet<i32> = logged(log, "pgid ").into_iter().collect();
    assert!(!groups.is_empty(), "the programs logged no group");
    let started = Instant::now();
    loop {
        let left = members(&groups);
        if left.is_empty() {
            return;
        }
        if started.elapsed() > HANG_GUARD {
            panic!("processes of the run's groups are left: {left:?}");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

const MODES: [bool; 2] = [false, true];

#[test]
fn a_program_flooding_stdout_is_an_error_at_the_output_limit() {
    for persistent in MODES {
        let (dir, log) = cases(&format!("flood-{persistent}"), &["bad"]);
        let r = rasterizer("external_flood.py", &log, persistent);
        let env = [("RASTERCHECK_EXTERNAL_MAX_OUTPUT", "1000000")];
        let m = run(&dir, &r, &[], &env);
        let out = &m.output;
        // Measured 15 MiB. The program writes without end: the run holds
        // at most the 1 MB allowed here (256 MiB under the default limit,
        // everything without one; 388 MiB with the limit at 400 MB).
        assert_peak_rss("flood", &m, crate::RSS_BOUND_MIB);
        judged(
            &dir,
            out,
            1,
            &[("bad", "error", "more than 1000000 bytes to stdout")],
        );
        let t = text(out);
        assert!(t.contains("RASTERCHECK_EXTERNAL_MAX_OUTPUT"), "{t}");
        assert_no_group_left(&log);
    }
}

#[test]
fn a_bad_output_limit_is_an_error_naming_the_variable() {
    let (dir, log) = cases("flood-bad-limit", &[]);
    let r = rasterizer("external_flood.py", &log, false);
    let m = run(
        &dir,
        &r,
        &[],
        &[("RASTERCHECK_EXTERNAL_MAX_OUTPUT", "lots")],
    );
    let out = &m.output;
    // Measured 4 MiB: refused before any case runs.
    assert_peak_rss("bad output limit", &m, crate::RSS_BOUND_MIB);
    let t = text(out);
    assert!(!t.contains("panicked"), "{t}");
    // Bad usage, said before any case runs (SPEC §9).
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("RASTERCHECK_EXTERNAL_MAX_OUTPUT=\"lots\""),
        "{t}"
    );
}

#[test]
fn an_exr_answer_that_is_a_fifo_is_refused_without_opening_it() {
    for persistent in MODES {
        let (dir, log) = cases(&format!("fifo-{persistent}"), &["bad"]);
        let r = rasterizer("external_fifo.py", &log, persistent);
        let m = run(&dir, &r, &[], &[]);
        let out = &m.output;
        // Measured 13 MiB (the python program's own peak among them).
        assert_peak_rss("EXR FIFO", &m, crate::RSS_BOUND_MIB);
        judged(&dir, out, 1, &[("bad", "error", "not a regular file")]);
        assert_no_group_left(&log);
    }
}

#[test]
fn an_exr_answer_with_a_huge_header_is_refused_before_decoding() {
    for persistent in MODES {
        let (dir, log) = cases(&format!("huge-exr-{persistent}"), &["bad"]);
        let r = rasterizer("external_huge_exr.py", &log, persistent);
        let m = run(&dir, &r, &[], &[]);
        let out = &m.output;
        // Measured 18 MiB. Decoding the 32768×32768 layer the header
        // declares would take 8 GiB (two f32 channels); it is refused from the header.
        assert_peak_rss("huge EXR answer", &m, crate::RSS_BOUND_MIB);
        judged(
            &dir,
            out,
            1,
            &[(
                "bad",
                "error",
                "32768×32768 by its header; the canvas is 4×4",
            )],
        );
        assert_no_group_left(&log);
    }
}

#[test]
fn a_golden_file_with_a_huge_header_is_refused_before_decoding() {
    let (dir, log) = cases("huge-golden", &[]);
    let golden = dir.join("reference/a.exr");
    std::fs::create_dir_all(golden.parent().unwrap()).unwrap();
    let written = Command::new("python3")
        .arg(program("external_huge_exr.py"))
        .arg("--write")
        .arg(&golden)
        .status()
        .unwrap();
    assert!(written.success());
    let r = rasterizer("external_counter.py", &log, false);
    let m = run(&dir, &r, &[], &[]);
    let out = &m.output;
    // Measured 13 MiB; the golden file's 32768×32768 layer is not decoded.
    assert_peak_rss("huge golden file", &m, crate::RSS_BOUND_MIB);
    let t = text(out);
    // The reference no longer reproduces its golden file: a failure (1).
    let report = judged(&dir, out, 1, &[]);
    assert_eq!(entry(&report, "a")["golden"], "differ", "{t}");
    let detail = entry(&report, "a")["golden_detail"].to_string();
    assert!(
        detail.contains("32768×32768") && detail.contains("not decoded"),
        "{detail}"
    );
    assert_eq!(entry(&report, "b")["golden"], "missing", "{t}");
}

#[test]
fn a_grandchild_is_killed_with_its_program_group() {
    for persistent in MODES {
        let (dir, log) = cases(&format!("forker-{persistent}"), &["bad", "bad_hang"]);
        let r = rasterizer("external_forker.py", &log, persistent);
        let env = [("RASTERCHECK_EXTERNAL_TIMEOUT", "3")];
        let m = run(&dir, &r, &[], &env);
        let out = &m.output;
        // Measured 13 MiB.
        assert_peak_rss("forker", &m, crate::RSS_BOUND_MIB);
        // "bad" answered correctly before leaving its grandchild behind.
        judged(
            &dir,
            out,
            1,
            &[
                ("bad", "pass", ""),
                ("bad_hang", "error", "timed out after 3 s"),
            ],
        );
        assert_eq!(logged(&log, "grandchild ").len(), 2, "{}", text(out));
        assert_no_group_left(&log);
    }
}

#[test]
fn a_candidate_over_the_case_timeout_is_a_limit_verdict() {
    for persistent in MODES {
        let (dir, log) = cases(&format!("hanger-{persistent}"), &["bad"]);
        let r = rasterizer("external_hanger.py", &log, persistent);
        // The program's own limit is far away: the case's deadline stops it.
        let env = [("RASTERCHECK_EXTERNAL_TIMEOUT", "900")];
        let m = run(&dir, &r, &["--case-timeout", "5"], &env);
        let out = &m.output;
        // Measured 13 MiB.
        assert_peak_rss("hanger", &m, crate::RSS_BOUND_MIB);
        let report = judged(&dir, out, 2, &[("bad", "error", "--case-timeout")]);
        assert_eq!(entry(&report, "bad")["status"], "limit-exceeded");
        assert_eq!(report["totals"]["limit_exceeded"], 1);
        let t = text(out);
        assert!(t.contains("LIMIT"), "{t}");
        assert_no_group_left(&log);
    }
}

#[test]
fn no_thread_or_file_descriptor_leaks_per_case() {
    // Every other case leaves a grandchild holding the program's pipes.
    for (persistent, count) in [(false, 60), (true, 200)] {
        let names: Vec<String> = (0..count)
            .map(|i| {
                if i % 2 == 1 {
                    format!("bad{i:03}")
                } else {
                    format!("c{i:03}")
                }
            })
            .collect();
        let bad: Vec<&str> = names.iter().map(String::as_str).collect();
        let (dir, log) = cases(&format!("counter-{persistent}"), &bad);
        let r = rasterizer("external_counter.py", &log, persistent);
        let m = run(&dir, &r, &["--threads", "1"], &[]);
        let out = &m.output;
        // Measured 13 MiB over 200 cases: nothing accumulates per case.
        assert_peak_rss("counter", &m, crate::RSS_BOUND_MIB);
        let t = text(out);
        assert_eq!(out.status.code(), Some(0), "{t}");
        // (fds, threads) of rastercheck, in the order the cases ran.
        let counts: Vec<(u32, u32)> = std::fs::read_to_string(&log)
            .unwrap()
            .lines()
            .filter_map(|l| {
                let f: Vec<&str> = l.split_whitespace().collect();
                (f.first() == Some(&"count"))
                    .then(|| (f[2].parse().unwrap(), f[3].parse().unwrap()))
            })
            .collect();
        assert_eq!(counts.len(), count + 2, "{t}");
        // After the first few cases (the pool's threads start), flat.
        let settled = counts[10];
        let last = *counts.last().unwrap();
        assert!(
            last.0 <= settled.0 && last.1 <= settled.1,
            "persistent {persistent}: (fds, threads) went from {settled:?} to {last:?}: {counts:?}"
        );
        assert_no_group_left(&log);
    }
}
