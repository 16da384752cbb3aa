//! `diff` and `baseline check --report` on merged reports (issue 39), run
//! as a user runs them: the two shards of a run of the DDA foil over the
//! bundled line cases merged, and the same foil run on two boards merged.
//! A baseline saved by running the cases holds the merged shards with no
//! change at all (so a report's metrics are read as a run records them),
//! catches a metric made better than reality, and catches a half run (one
//! shard) as cases that no longer run. A two-board report has no row of the
//! recorded name: `baseline check` says so, naming the report and its
//! rows, exit 2, and takes one board with `-r "ROW=RECORDED"`. `diff` pairs
//! a merged report's rows by name, and finds a verdict made worse in one
//! board's row.

mod common;

use std::path::{Path, PathBuf};
use std::process::Output;

use common::cli::{rastercheck_env, read_json, scratch, text};
use serde_json::Value;

fn repository() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `rastercheck ARGS` in the repository on host `host`.
fn on(host: &str, args: &[&str]) -> Output {
    let out = rastercheck_env(&repository(), args, &[("RASTERCHECK_HOST", host)]);
    assert!(!text(&out).contains("panicked"), "{}", text(&out));
    out
}

fn code(out: &Output) -> i32 {
    out.status.code().unwrap_or(-1)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The DDA foil over the line cases on `host`, its report into `report`
/// (with `more` arguments: a shard).
fn run_dda(host: &str, report: &Path, more: &[&str]) {
    let mut args = vec![
        "run",
        "cases/lines",
        "-r",
        "dda-f32",
        "-q",
        "--report",
        s(report),
    ];
    args.extend_from_slice(more);
    let out = on(host, &args);
    // A foil's departures are expected; it judged something.
    assert!(matches!(code(&out), 0 | 1), "{}", text(&out));
}

fn merge(out: &Path, reports: &[&Path]) {
    let mut args = vec!["merge", s(out)];
    args.extend(reports.iter().map(|r| s(r)));
    let run = on("merger", &args);
    assert!(matches!(code(&run), 0 | 1), "{}", text(&run));
}

/// `baseline check FILE --report REPORT` with `more` arguments.
fn check(file: &Path, report: &Path, more: &[&str]) -> (i32, String) {
    let mut args = vec!["baseline", "check", s(file), "--report", s(report)];
    args.extend_from_slice(more);
    let out = on("checker", &args);
    (code(&out), text(&out))
}

/// Saves a baseline of the DDA foil on the line cases, by running them.
fn save(dir: &Path) -> PathBuf {
    let file = dir.join("dda.json");
    let out = on(
        "saver",
        &["baseline", "save", s(&file), "cases/lines", "-r", "dda-f32"],
    );
    assert_eq!(code(&out), 0, "{}", text(&out));
    file
}

#[test]
fn a_baseline_holds_two_merged_shards_as_it_holds_a_run() {
    let dir = scratch("merge-checks-shards");
    let file = save(&dir);
    let (one, two, merged) = (dir.join("s1"), dir.join("s2"), dir.join("merged"));
    run_dda("runner-1", &one, &["--shard", "1/2"]);
    run_dda("runner-2", &two, &["--shard", "2/2"]);
    merge(&merged, &[&one, &two]);

    // Every metric as the run recorded it: nothing moved.
    let (c, t) = check(&file, &merged, &[]);
    assert_eq!(c, 0, "{t}");
    assert!(
        t.contains("baseline: 0 regressions, 0 improvements,"),
        "{t}"
    );
    assert!(!t.contains("NEW "), "{t}");

    // A metric recorded better than reality is caught from the report.
    let mut b = read_json(&file);
    let (k, case, value) = b["results"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
        .find_map(|(k, r)| {
            let v = r["metrics"]["coverage.mismatched"].as_f64()?;
            (v > 0.0).then(|| (k, r["case"].as_str().unwrap().to_owned(), v))
        })
        .expect("the DDA foil mismatches somewhere");
    b["results"][k]["metrics"]["coverage.mismatched"] = 0.into();
    let better = dir.join("better.json");
    std::fs::write(&better, b.to_string()).unwrap();
    let (c, t) = check(&better, &merged, &[]);
    assert_eq!(c, 1, "{t}");
    let expected = format!("REGRESSION  {case}  dda-f32  coverage.mismatched  0 → {value}");
    assert!(t.contains(&expected), "{expected:?} in\n{t}");

    // One shard alone is half the run: the other half no longer runs.
    let (c, t) = check(&file, &one, &[]);
    assert_eq!(c, 1, "{t}");
    assert!(t.contains("the case was not found"), "{t}");

    // Case paths and a report are two sources: refused.
    let out = on(
        "checker",
        &[
            "baseline",
            "check",
            s(&file),
            "cases/lines",
            "--report",
            s(&merged),
        ],
    );
    assert_eq!(code(&out), 2, "{}", text(&out));
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_two_board_report_is_checked_one_board_at_a_time_and_diffed_by_row() {
    let dir = scratch("merge-checks-boards");
    let file = save(&dir);
    let (a, b, merged) = (dir.join("a"), dir.join("b"), dir.join("merged"));
    run_dda("board-a", &a, &[]);
    run_dda("board-b", &b, &[]);
    merge(&merged, &[&a, &b]);
    let report = read_json(&merged.join("report.json"));
    let rows: Vec<&str> = report["rasterizers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["name"].as_str().unwrap())
        .collect();
    assert_eq!(rows, ["dda-f32 on board-a", "dda-f32 on board-b"]);

    // Which row is the baseline's? Neither is named dda-f32: said, exit 2.
    let (c, t) = check(&file, &merged, &[]);
    assert_eq!(c, 2, "{t}");
    let said = format!(
        "{}: no row \"dda-f32\" to hold to \"dda-f32\" (its rows: dda-f32 on board-a, dda-f32 on board-b)",
        merged.display()
    );
    assert!(t.contains(&said), "{said:?} in\n{t}");
    // A row that is not there either.
    let (c, t) = check(&file, &merged, &["-r", "dda-f32 on board-c=dda-f32"]);
    assert_eq!(c, 2, "{t}");
    // One board chosen: held as a run.
    for row in rows {
        let (c, t) = check(&file, &merged, &["-r", &format!("{row}=dda-f32")]);
        assert_eq!(c, 0, "{row}: {t}");
        assert!(
            t.contains("baseline: 0 regressions, 0 improvements,"),
            "{t}"
        );
    }

    // diff pairs the merged report's rows by name: nothing between it and
    // itself, and a verdict made worse on board b is found there.
    let out = on("differ", &["diff", s(&merged), s(&merged)]);
    assert_eq!(code(&out), 0, "{}", text(&out));
    let mut worse = report.clone();
    let (id, row) = worse["cases"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .find_map(|case| {
            let id = case["id"].as_str()?.to_owned();
            let result = case["results"]
                .as_array_mut()?
                .iter_mut()
                .find(|r| r["rasterizer"] == "dda-f32 on board-b" && r["verdict"] == "pass")?;
            result["verdict"] = Value::from("error");
            Some((id, result["rasterizer"].as_str()?.to_owned()))
        })
        .expect("a case the DDA foil passes on board b");
    let worse_dir = dir.join("worse");
    std::fs::create_dir_all(&worse_dir).unwrap();
    std::fs::write(worse_dir.join("report.json"), worse.to_string()).unwrap();
    let out = on("differ", &["diff", s(&merged), s(&worse_dir)]);
    let t = text(&out);
    assert_eq!(code(&out), 1, "{t}");
    assert!(t.contains(&id) && t.contains(&row), "{id} {row} in\n{t}");
    assert!(t.contains("1 newly failing"), "{t}");
    // A single board's report against the merged one: paired by --pair.
    let out = on(
        "differ",
        &[
            "diff",
            s(&a),
            s(&merged),
            "--pair",
            "dda-f32=dda-f32 on board-a",
        ],
    );
    assert_eq!(code(&out), 0, "{}", text(&out));
    let _ = std::fs::remove_dir_all(dir);
}
