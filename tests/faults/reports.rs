//! Faults: reports that must stay whole (atomic writes, stale files, signals).
//!
//! - A run stopped by SIGTERM or SIGINT while an external program is in
//!   flight kills the program, starts no new case, writes the partial
//!   report (the cases that finished before the signal keep their
//!   verdicts, the others are `not-run`, `complete: false`) and exits 143
//!   or 130.
//! - A reused `--report` folder loses what an earlier run wrote there, and
//!   keeps a user's own files.
//! - Every report file is written to a temporary name and renamed, so no
//!   file is ever written in place, and no temporary file is left.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::common::cli::{read_json, scratch, text};

/// Generous: only guards the test against a hang, never times anything.
const HANG_GUARD: Duration = Duration::from_secs(120);

fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A fresh folder `name` with a `cases/` tree of `count` bundled triangle
/// cases (sorted, so their order in the run is known).
fn with_cases(name: &str, count: usize) -> (PathBuf, Vec<String>) {
    let dir = scratch(&format!("faults-reports-{name}"));
    let from = manifest().join("cases/triangles");
    let mut names: Vec<String> = std::fs::read_dir(&from)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".json"))
        .collect();
    names.sort();
    names.truncate(count);
    std::fs::create_dir_all(dir.join("cases/triangles")).unwrap();
    for n in &names {
        std::fs::copy(from.join(n), dir.join("cases/triangles").join(n)).unwrap();
    }
    let ids = names
        .iter()
        .map(|n| format!("triangles/{}", n.trim_end_matches(".json")))
        .collect();
    (dir, ids)
}

/// Every file under `dir`, recursively, as paths relative to it.
fn files_under(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_owned()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let e = e.unwrap();
            if e.file_type().unwrap().is_dir() {
                stack.push(e.path());
            } else {
                out.push(rastercheck::report::relative(dir, &e.path()));
            }
        }
    }
    out.sort();
    out
}

/// The state letter of a process (R, S, Z...), or `None` when it is gone.
fn process_state(pid: u32) -> Option<char> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    let after = stat.rsplit_once(')')?.1;
    after.trim_start().chars().next()
}

/// The peak resident set of a running process so far (VmHWM), in MiB: read
/// just before a signal ends it, since a process killed by the test is not
/// reaped through `run_measured`.
fn peak_so_far_mib(pid: u32) -> f64 {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap();
    let line = status
        .lines()
        .find(|l| l.starts_with("VmHWM:"))
        .expect("VmHWM in /proc/PID/status");
    let kib: f64 = line.split_whitespace().nth(1).unwrap().parse().unwrap();
    kib / 1024.0
}

/// Checks the run's peak RSS so far against the bound, sends it `signal`
/// (`TERM`, `INT`), and waits for it to end: its status, and how long it
/// took after the signal.
fn signal_and_wait(
    child: &mut std::process::Child,
    signal: &str,
) -> (std::process::ExitStatus, Duration) {
    let peak = peak_so_far_mib(child.id());
    assert!(
        peak < crate::RSS_BOUND_MIB,
        "peak RSS {peak:.1} MiB before the signal"
    );
    let sent = Instant::now();
    let killed = Command::new("/bin/kill")
        .args([&format!("-{signal}"), &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let mut status = None;
    wait_for("rastercheck to stop", || {
        status = child.try_wait().unwrap();
        status.is_some()
    });
    (status.unwrap(), sent.elapsed())
}

/// Polls `done` until it holds; panics after [`HANG_GUARD`].
fn wait_for(what: &str, mut done: impl FnMut() -> bool) {
    let started = Instant::now();
    while !done() {
        assert!(started.elapsed() < HANG_GUARD, "waited too long for {what}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// The run under test, killed if the test fails before it ends, and (only
/// then) the programs it started, by pid, so a failing test leaves no
/// process.
struct Cleanup {
    child: std::process::Child,
    pids: PathBuf,
}

impl Drop for Cleanup {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
        if !std::thread::panicking() {
            return;
        }
        for e in std::fs::read_dir(&self.pids)
            .into_iter()
            .flatten()
            .flatten()
        {
            if let Ok(pid) = e.file_name().to_string_lossy().parse::<u32>() {
                let _ = Command::new("/bin/kill")
                    .args(["-KILL", &pid.to_string()])
                    .stderr(Stdio::null())
                    .status();
            }
        }
    }
}

/// A command stopped by a signal while `reports_slow.py` sleeps on its
/// third case; `_cleanup` kills what is left when the test ends (kept
/// alive until then, so that it cannot make the program look gone).
struct Stopped {
    dir: PathBuf,
    ids: Vec<String>,
    pids: PathBuf,
    status: std::process::ExitStatus,
    took: Duration,
    log: String,
    sleeper: u32,
    _cleanup: Cleanup,
}

/// Runs `args` (a command over `count` cases, one thread) with `-r` the
/// program `reports_slow.py`, which answers the first 2 cases and sleeps on
/// the third; sends `signal` once it sleeps.
fn stopped_while_sleeping(tag: &str, count: usize, args: &[&str], signal: &str) -> Stopped {
    let (dir, ids) = with_cases(tag, count);
    let pids = dir.join("pids");
    std::fs::create_dir_all(&pids).unwrap();
    let program = manifest().join("tests/faults/programs/reports_slow.py");
    let rasterizer = format!(
        "external:python3 {} {} 2",
        program.display(),
        pids.display()
    );
    let log = std::fs::File::create(dir.join("log.txt")).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args(args)
        .arg("-r")
        .arg(&rasterizer)
        .current_dir(&dir)
        .env("RASTERCHECK_EXTERNAL_TIMEOUT", "600")
        .stdin(Stdio::null())
        .stdout(log.try_clone().unwrap())
        .stderr(log)
        .spawn()
        .unwrap();
    let mut run = Cleanup {
        child,
        pids: pids.clone(),
    };
    let child = &mut run.child;
    let sleeping = || -> Option<u32> {
        std::fs::read_dir(&pids).ok()?.find_map(|e| {
            let name = e.ok()?.file_name().to_string_lossy().into_owned();
            name.strip_suffix(".sleeping")?.parse().ok()
        })
    };
    wait_for("the program to sleep on the third case", || {
        sleeping().is_some() || child.try_wait().unwrap().is_some()
    });
    let sleeper = sleeping().expect("the third case's program sleeps");
    let (status, took) = signal_and_wait(child, signal);
    let log = std::fs::read_to_string(dir.join("log.txt")).unwrap();
    Stopped {
        dir,
        ids,
        pids,
        status,
        took,
        log,
        sleeper,
        _cleanup: run,
    }
}

/// `run` over 6 cases, stopped by `signal` on the third. Asserts the exit
/// code, the partial report and that the program is gone.
fn stopped_by(signal: &str, code: i32) {
    let stopped = stopped_while_sleeping(
        &format!("signal-{signal}"),
        6,
        &["run", "cases", "--report", "out", "--threads", "1"],
        signal,
    );
    let Stopped {
        dir,
        ids,
        pids,
        status,
        log,
        sleeper,
        ..
    } = &stopped;
    let (dir, ids, pids, sleeper) = (dir.as_path(), ids, pids.as_path(), *sleeper);
    assert_eq!(status.code(), Some(code), "{log}");
    assert!(!log.contains("panicked"), "{log}");
    assert!(log.contains("cases did not run"), "{log}");

    // The program it was waiting for is killed (and reaped), not orphaned.
    wait_for("the sleeping program to be gone", || {
        matches!(process_state(sleeper), None | Some('Z'))
    });
    // No case started after the signal: 3 processes in all.
    let started = std::fs::read_dir(pids)
        .unwrap()
        .filter(|e| {
            let e = e.as_ref().unwrap();
            e.file_name()
                .to_string_lossy()
                .chars()
                .all(|c| c.is_ascii_digit())
        })
        .count();
    assert_eq!(started, 3, "{log}");

    // The partial report: what ran keeps its verdict, the rest did not run.
    let out = dir.join("out");
    let report = read_json(&out.join("report.json"));
    assert_eq!(report["complete"], false, "{report}");
    let cases = report["cases"].as_array().unwrap();
    let got: Vec<(&str, &str)> = cases
        .iter()
        .map(|c| (c["id"].as_str().unwrap(), c["status"].as_str().unwrap()))
        .collect();
    let expected: Vec<(&str, &str)> = ids
        .iter()
        .enumerate()
        .map(|(k, id)| (id.as_str(), if k < 2 { "ran" } else { "not-run" }))
        .collect();
    assert_eq!(got, expected, "{log}");
    for case in &cases[..2] {
        assert_eq!(case["results"][0]["verdict"], "unsupported", "{case}");
    }
    assert_eq!(report["totals"]["not_run"], 4, "{report}");
    // Every other file is whole too, and nothing was left half-written.
    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    assert!(junit.trim_end().ends_with("</testsuites>"), "{junit}");
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(html.trim_end().ends_with("</html>"));
    assert!(html.contains("The run did not finish"));
    assert!(out.join("summary.md").is_file());
    assert_no_partial_files(&out);
}

fn assert_no_partial_files(dir: &Path) {
    let partial: Vec<String> = files_under(dir)
        .into_iter()
        .filter(|f| f.ends_with(rastercheck::report::TEMPORARY_SUFFIX))
        .collect();
    assert!(partial.is_empty(), "{partial:?}");
}

/// A case that keeps the reference busy for minutes: 4000 triangles over
/// the whole of a 1024² canvas, each tested at every pixel.
fn slow_case() -> String {
    let triangles: Vec<String> = (0..4000)
        .map(|k| {
            format!(
                r#"{{"triangle": [[{}, 0], [1024, 1024], [0, 1024]]}}"#,
                k % 7
            )
        })
        .collect();
    format!(
        r#"{{"name": "slow", "canvas": {{"width": 1024, "height": 1024}}, "primitives": [{}]}}"#,
        triangles.join(", ")
    )
}

#[test]
fn sigterm_stops_the_reference_in_the_middle_of_a_case() {
    let dir =
        crate::common::cli::workspace("signal-reference", &[("cases/a/slow.json", &slow_case())]);
    let log = std::fs::File::create(dir.join("log.txt")).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_rastercheck"))
        .args(["run", "cases", "--report", "out", "--case-timeout", "600"])
        .current_dir(&dir)
        .stdin(Stdio::null())
        .stdout(log.try_clone().unwrap())
        .stderr(log)
        .spawn()
        .unwrap();
    let mut run = Cleanup {
        child,
        pids: dir.join("pids"),
    };
    let child = &mut run.child;
    // Let the reference get going.
    std::thread::sleep(Duration::from_millis(1500));
    assert!(
        child.try_wait().unwrap().is_none(),
        "the case finished too soon to test"
    );
    let (status, took) = signal_and_wait(child, "TERM");
    let log = std::fs::read_to_string(dir.join("log.txt")).unwrap();
    assert_eq!(status.code(), Some(143), "{log}");
    assert!(
        took < Duration::from_secs(5),
        "stopped {took:?} after the signal"
    );
    let report = read_json(&dir.join("out/report.json"));
    assert_eq!(report["cases"][0]["status"], "not-run", "{report}");
    assert_eq!(report["complete"], false);
}

/// `baseline save` with `reports_slow.py`, stopped by `signal` while the
/// program sleeps on the third case: the command ends with 128 + signal and
/// the program is killed with it (before, only `run` installed the handler,
/// and the program, in a process group of its own, kept sleeping).
fn baseline_stopped_by(signal: &str, code: i32) {
    let stopped = stopped_while_sleeping(
        &format!("baseline-signal-{signal}"),
        4,
        &["baseline", "save", "base.json", "cases", "--threads", "1"],
        signal,
    );
    let log = &stopped.log;
    assert_eq!(stopped.status.code(), Some(code), "{log}");
    assert!(
        stopped.took < Duration::from_secs(5),
        "{:?}: {log}",
        stopped.took
    );
    assert!(!log.contains("panicked"), "{log}");
    wait_for("the sleeping program to be gone", || {
        matches!(process_state(stopped.sleeper), None | Some('Z'))
    });
    // No baseline half-written.
    assert!(!stopped.dir.join("base.json").exists(), "{log}");
}

#[test]
fn sigterm_to_baseline_save_kills_its_program() {
    baseline_stopped_by("TERM", 143);
}

#[test]
fn sigint_to_baseline_save_kills_its_program() {
    baseline_stopped_by("INT", 130);
}

#[test]
fn sigterm_stops_the_run_kills_the_program_and_leaves_a_partial_report() {
    stopped_by("TERM", 143);
}

#[test]
fn sigint_stops_the_run_the_same_way_with_exit_130() {
    stopped_by("INT", 130);
}

#[test]
fn a_reused_report_folder_loses_the_earlier_runs_files_and_keeps_the_users() {
    let (dir, ids) = with_cases("stale", 2);
    let out = dir.join("out");
    let stale = [
        ("junit.xml", "stale"),
        ("summary.md", "stale"),
        ("index.html", "stale"),
        ("images/triangles/gone/production.png", "stale"),
        ("exr/triangles/gone/production.exr", "stale"),
        (".report.json.99.rastercheck-partial", "{\"cases\": ["),
        // What marks the folder as an earlier run's (without it the run is
        // refused: see the next test).
        (".rastercheck-report", "an earlier run's"),
    ];
    let users = [
        ("notes.txt", "mine"),
        ("mine/report.json", "mine"),
        ("pictures/reference.png", "mine"),
    ];
    for (path, content) in stale.iter().chain(&users) {
        let path = out.join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, content).unwrap();
    }
    let run = crate::bounded_run(&dir, &["run", "cases", "--report", "out"]);
    let t = text(&run);
    assert_eq!(run.status.code(), Some(0), "{t}");
    // The earlier run's files are gone or rewritten by this run.
    for (path, _) in &stale[..3] {
        let now = std::fs::read_to_string(out.join(path)).unwrap();
        assert_ne!(now, "stale", "{path}");
    }
    assert!(!out.join("images").exists(), "{:?}", files_under(&out));
    assert!(!out.join("exr").exists(), "{:?}", files_under(&out));
    assert_no_partial_files(&out);
    // The user's own files are all there, as they were.
    for (path, content) in &users {
        assert_eq!(
            std::fs::read_to_string(out.join(path)).unwrap(),
            *content,
            "{path}"
        );
    }
    let report = read_json(&out.join("report.json"));
    assert_eq!(report["complete"], true);
    assert_eq!(report["cases"].as_array().unwrap().len(), ids.len());
}

#[test]
fn a_users_folder_with_report_like_names_is_refused_and_kept_whole() {
    // The user's own images/, pages/ and index.html, and no marker: before,
    // all three were removed or overwritten.
    let (dir, _) = with_cases("users-folder", 2);
    let out = dir.join("site");
    let users = [
        ("index.html", "my site"),
        ("images/logo.png", "my logo"),
        ("pages/about.html", "about me"),
    ];
    for (path, content) in &users {
        let path = out.join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, content).unwrap();
    }
    let run = crate::bounded_run(&dir, &["run", "cases", "--report", "site"]);
    let t = text(&run);
    assert_eq!(run.status.code(), Some(2), "{t}");
    assert!(t.contains("--report site"), "{t}");
    assert!(t.contains("no rastercheck run wrote"), "{t}");
    for (path, content) in &users {
        assert_eq!(
            std::fs::read_to_string(out.join(path)).unwrap(),
            *content,
            "{path}"
        );
    }
    assert_eq!(
        files_under(&out).len(),
        users.len(),
        "{:?}",
        files_under(&out)
    );
}

#[test]
fn report_files_are_replaced_by_a_rename_never_written_in_place() {
    // A file linked under two names: writing in place would change both,
    // a new file renamed over one name leaves the other as it was.
    let dir = scratch("faults-reports-rename");
    let path = dir.join("report.json");
    std::fs::write(&path, "old").unwrap();
    std::fs::hard_link(&path, dir.join("linked.json")).unwrap();
    rastercheck::report::write_file(&path, b"new").unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "new");
    assert_eq!(
        std::fs::read_to_string(dir.join("linked.json")).unwrap(),
        "old"
    );
    assert_eq!(files_under(&dir), ["linked.json", "report.json"]);
}

#[test]
fn a_run_with_pictures_and_error_maps_leaves_no_partial_file() {
    // A mutant fails: pictures and EXR maps are written.
    let (dir, _) = with_cases("pictures", 4);
    let run = crate::bounded_run(
        &dir,
        &[
            "run",
            "cases",
            "--report",
            "out",
            "-r",
            "production",
            "-r",
            "mutant:shrunk",
        ],
    );
    let t = text(&run);
    assert!(!t.contains("panicked"), "{t}");
    let out = dir.join("out");
    let files = files_under(&out);
    assert!(files.iter().any(|f| f.ends_with(".png")), "{files:?}\n{t}");
    assert!(files.iter().any(|f| f.ends_with(".exr")), "{files:?}\n{t}");
    assert_no_partial_files(&out);
    for f in files.iter().filter(|f| f.ends_with(".png")) {
        image::open(out.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
    }
    read_json(&out.join("report.json"));
}
