//! `rastercheck diff OLD NEW`, run as a user runs it: production against a
//! deliberately broken mutant (exactly the mutant's failures listed, exit
//! 1), the same report against itself, the mutant fixed; cases added and
//! removed; metric deltas without a verdict change; every kind of state
//! change on crafted reports; bad input.

mod common;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use common::cli::{rastercheck as rastercheck_in, read_json as read, text};
use serde_json::Value;

/// A mutant that fails a handful of triangle cases (the perspective ones)
/// and passes the rest.
const MUTANT: &str = "mutant:no-perspective";

/// Runs in the repository, on its bundled cases.
fn rastercheck(args: &[&str]) -> Output {
    rastercheck_in(Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

/// `rastercheck ARGS` under a 60 s `timeout` (a hang fails, not blocks, the
/// test) and, with `cap_kib`, an address-space cap (`ulimit -v`).
fn bounded(args: &[&str], cap_kib: Option<u64>) -> Output {
    let quoted: Vec<String> = args.iter().map(|a| format!("'{a}'")).collect();
    let cap = cap_kib.map_or(String::new(), |k| format!("ulimit -v {k}; "));
    let script = format!(
        "{cap}exec timeout 60 '{}' {}",
        env!("CARGO_BIN_EXE_rastercheck"),
        quoted.join(" ")
    );
    Command::new("sh")
        .arg("-c")
        .arg(script)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("sh runs")
}

fn code(out: &Output) -> i32 {
    out.status.code().expect("exited")
}

fn scratch(name: &str) -> PathBuf {
    common::cli::scratch(&format!("diff-{name}"))
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// `run PATHS -r RASTERIZER --report DIR`; the folder.
fn run(dir: &Path, name: &str, paths: &[&str], rasterizer: &str) -> PathBuf {
    let report = dir.join(name);
    let mut args = vec!["run"];
    args.extend_from_slice(paths);
    args.extend_from_slice(&["-r", rasterizer, "-q", "--report", s(&report)]);
    let out = rastercheck(&args);
    assert!(matches!(code(&out), 0 | 1), "{}", text(&out));
    report
}

/// `diff OLD NEW --out DIR`: the exit code, what it printed, and diff.json.
fn diff(old: &Path, new: &Path, out: &Path, more: &[&str]) -> (i32, String, Value) {
    let mut args = vec!["diff", s(old), s(new), "--out", s(out)];
    args.extend_from_slice(more);
    let run = rastercheck(&args);
    let printed = text(&run);
    assert!(!printed.contains("panicked"), "{printed}");
    let json = read(&out.join("diff.json"));
    assert_eq!(json["schema"], "rastercheck-diff/1");
    (code(&run), printed, json)
}

/// The case ids of a diff.json list.
fn cases(diff: &Value, list: &str) -> BTreeSet<String> {
    diff[list]
        .as_array()
        .unwrap_or_else(|| panic!("{list} is a list"))
        .iter()
        .map(|c| c["case"].as_str().unwrap().to_owned())
        .collect()
}

/// Every list of a diff.json that names changes.
const LISTS: [&str; 8] = [
    "newly_failing",
    "no_longer_judged",
    "fixed",
    "still_failing",
    "other_changes",
    "added",
    "removed",
    "metrics",
];

fn empty_but(diff: &Value, nonempty: &[&str]) {
    for list in LISTS {
        if !nonempty.contains(&list) {
            assert_eq!(diff[list], Value::Array(vec![]), "{list} is empty");
        }
    }
}

/// The ids of a report's cases whose first result has `verdict`.
fn with_verdict(report: &Path, verdict: &str) -> BTreeSet<String> {
    read(&report.join("report.json"))["cases"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["results"][0]["verdict"] == verdict)
        .map(|c| c["id"].as_str().unwrap().to_owned())
        .collect()
}

#[test]
fn the_mutant_s_failures_are_listed_exactly_and_exit_1() {
    let dir = scratch("mutant");
    let good = run(&dir, "production", &["cases/triangles"], "production");
    let bad = run(&dir, "mutant", &["cases/triangles"], MUTANT);
    let expected = with_verdict(&bad, "fail");
    assert!(
        (1..=10).contains(&expected.len()),
        "the mutant fails a handful of cases: {expected:?}"
    );
    assert!(with_verdict(&good, "fail").is_empty());

    let (exit, printed, json) = diff(&good, &bad, &dir.join("out"), &[]);
    assert_eq!(exit, 1, "{printed}");
    assert_eq!(cases(&json, "newly_failing"), expected, "{printed}");
    for id in &expected {
        assert!(printed.contains(id.as_str()), "{printed}");
    }
    // Every metric that got worse is on one of those cases.
    let worse = cases(&json, "metrics");
    assert!(!worse.is_empty() && worse.is_subset(&expected), "{worse:?}");
    assert!(json["metrics"]
        .as_array()
        .unwrap()
        .iter()
        .all(|m| m["change"] == "worse" && m["delta"].as_f64().unwrap() > 0.0));
    empty_but(&json, &["newly_failing", "metrics"]);
    assert_eq!(json["regression"], true);
    assert!(printed.contains("each report has one"), "{printed}");
    for change in json["newly_failing"].as_array().unwrap() {
        assert_eq!(change["old"], "pass");
        assert_eq!(change["new"], "fail");
        assert_eq!(change["rasterizer"], MUTANT);
        assert_eq!(change["old_rasterizer"], "production");
    }
    let md = std::fs::read_to_string(dir.join("out/diff.md")).unwrap();
    assert!(md.contains("regression") && md.len() < 65_536, "{md}");
    let html = std::fs::read_to_string(dir.join("out/diff.html")).unwrap();
    for id in &expected {
        assert!(md.contains(id.as_str()) && html.contains(id.as_str()));
    }
    assert!(!html.contains("http"), "self-contained");

    // The same report against itself: nothing.
    let (exit, printed, json) = diff(&good, &good, &dir.join("same"), &[]);
    assert_eq!(exit, 0, "{printed}");
    empty_but(&json, &[]);
    assert_eq!(json["regression"], false);

    // The mutant fixed: the same cases, fixed, every metric better.
    let (exit, printed, json) = diff(&bad, &good, &dir.join("fixed"), &[]);
    assert_eq!(exit, 0, "{printed}");
    assert_eq!(cases(&json, "fixed"), expected);
    assert!(json["metrics"]
        .as_array()
        .unwrap()
        .iter()
        .all(|m| m["change"] == "better"));
    empty_but(&json, &["fixed", "metrics"]);
}

#[test]
fn cases_added_and_removed_are_listed_and_do_not_fail() {
    let dir = scratch("families");
    let one = run(&dir, "one", &["cases/triangles"], "production");
    let two = run(
        &dir,
        "two",
        &["cases/triangles", "cases/polygons"],
        "production",
    );
    let polygons: BTreeSet<String> = common::cli::report_ids(&two)
        .into_iter()
        .filter(|id| id.starts_with("polygons/"))
        .collect();
    assert!(!polygons.is_empty());

    let (exit, printed, json) = diff(&one, &two, &dir.join("added"), &[]);
    assert_eq!(exit, 0, "{printed}");
    assert_eq!(cases(&json, "added"), polygons);
    empty_but(&json, &["added"]);
    assert_eq!(json["counts"]["compared_cases"], 77);

    let (exit, printed, json) = diff(&two, &one, &dir.join("removed"), &[]);
    assert_eq!(exit, 0, "{printed}");
    assert_eq!(cases(&json, "removed"), polygons);
    empty_but(&json, &["removed"]);
}

/// A production report of the triangle cases, as JSON to edit.
fn triangles_report(dir: &Path) -> Value {
    read(&run(dir, "base", &["cases/triangles"], "production").join("report.json"))
}

fn write(dir: &Path, name: &str, report: &Value) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, serde_json::to_string_pretty(report).unwrap()).unwrap();
    path
}

/// The index of the first passing case with an interpolated channel.
fn case_with_channel(report: &Value) -> usize {
    report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .position(|c| {
            let r = &c["results"][0];
            r["verdict"] == "pass" && r["metrics"]["channels"][0]["max_abs"].as_f64() > Some(0.0)
        })
        .expect("a passing case with interpolation error")
}

#[test]
fn a_worse_metric_without_a_verdict_change_is_a_regression() {
    let dir = scratch("metric");
    let old = triangles_report(&dir);
    let old_file = write(&dir, "old.json", &old);
    let k = case_with_channel(&old);
    let id = old["cases"][k]["id"].as_str().unwrap().to_owned();
    let channel = old["cases"][k]["results"][0]["metrics"]["channels"][0].clone();
    let max_abs = channel["max_abs"].as_f64().unwrap();
    let set = |factor: f64, time: f64| {
        let mut new = old.clone();
        let r = &mut new["cases"][k]["results"][0];
        r["metrics"]["channels"][0]["max_abs"] = (max_abs * factor).into();
        r["time_ms"] = time.into();
        new
    };

    // Twice the error, still a pass: a regression, on that metric alone.
    let worse = write(&dir, "worse.json", &set(2.0, 0.0));
    let (exit, printed, json) = diff(&old_file, &worse, &dir.join("worse"), &[]);
    assert_eq!(exit, 1, "{printed}");
    empty_but(&json, &["metrics"]);
    let metrics = json["metrics"].as_array().unwrap();
    assert_eq!(metrics.len(), 1, "{metrics:?}");
    assert_eq!(metrics[0]["case"], id.as_str());
    assert_eq!(
        metrics[0]["metric"],
        format!("{}.max_abs", channel["channel"].as_str().unwrap())
    );
    assert_eq!(metrics[0]["change"], "worse");
    assert_eq!(json["counts"]["regressed_results"], 1);
    assert!(printed.contains(&id), "{printed}");

    // Half the error: better, no regression.
    let better = write(&dir, "better.json", &set(0.5, 0.0));
    let (exit, printed, json) = diff(&old_file, &better, &dir.join("better"), &[]);
    assert_eq!(exit, 0, "{printed}");
    assert_eq!(json["metrics"][0]["change"], "better");

    // Within the errors' tolerance (1 %), and a much slower run: nothing.
    let same = write(&dir, "same.json", &set(1.005, 1e6));
    let (exit, printed, json) = diff(&old_file, &same, &dir.join("same"), &[]);
    assert_eq!(exit, 0, "{printed}");
    empty_but(&json, &[]);

    // A count: one extra sample more is worse.
    let mut new = old.clone();
    new["cases"][0]["results"][0]["metrics"]["coverage"]["extra"] = 1.into();
    let extra = write(&dir, "extra.json", &new);
    let (exit, printed, json) = diff(&old_file, &extra, &dir.join("extra"), &[]);
    assert_eq!(exit, 1, "{printed}");
    assert_eq!(json["metrics"][0]["metric"], "coverage.extra");
}

#[test]
fn each_change_of_state_is_classified() {
    let dir = scratch("states");
    let old = triangles_report(&dir);
    let old_file = write(&dir, "old.json", &old);
    let id = |k: usize| old["cases"][k]["id"].as_str().unwrap().to_owned();
    let mut new = old.clone();
    // 0: pass → fail; 1: golden match → differ; 2: ran → unreadable;
    // 3: pass → unsupported; 4: pass → error.
    new["cases"][0]["results"][0]["verdict"] = "fail".into();
    new["cases"][0]["results"][0]["reasons"] = serde_json::json!(["coverage: broken"]);
    new["cases"][1]["golden"] = "differ".into();
    new["cases"][2]["status"] = "unreadable".into();
    new["cases"][2]["results"] = serde_json::json!([]);
    new["cases"][3]["results"][0]["verdict"] = "unsupported".into();
    new["cases"][4]["results"][0]["verdict"] = "error".into();
    let new_file = write(&dir, "new.json", &new);

    let (exit, printed, json) = diff(&old_file, &new_file, &dir.join("out"), &[]);
    assert_eq!(exit, 1, "{printed}");
    assert_eq!(
        cases(&json, "newly_failing"),
        BTreeSet::from([id(0), id(1), id(2), id(4)])
    );
    let golden: Vec<&Value> = json["newly_failing"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| c["check"] == "golden")
        .collect();
    assert_eq!(golden.len(), 1);
    assert_eq!(golden[0]["case"], id(1).as_str());
    assert_eq!(cases(&json, "no_longer_judged"), BTreeSet::from([id(3)]));
    assert!(printed.contains("coverage: broken"), "{printed}");
    assert_eq!(json["counts"]["regressed_results"], 5);

    // Back again: four fixed; unsupported → pass is only another change.
    let (exit, printed, json) = diff(&new_file, &old_file, &dir.join("back"), &[]);
    assert_eq!(exit, 0, "{printed}");
    assert_eq!(
        cases(&json, "fixed"),
        BTreeSet::from([id(0), id(1), id(2), id(4)])
    );
    assert_eq!(cases(&json, "other_changes"), BTreeSet::from([id(3)]));
    empty_but(&json, &["fixed", "other_changes"]);

    // Failing in both: still failing, not a regression.
    let (exit, printed, json) = diff(&new_file, &new_file, &dir.join("still"), &[]);
    assert_eq!(exit, 0, "{printed}");
    assert_eq!(
        cases(&json, "still_failing"),
        BTreeSet::from([id(0), id(1), id(2), id(4)])
    );
}

#[test]
fn rasterizers_pair_by_name_by_count_or_by_flag() {
    let dir = scratch("pair");
    let old = triangles_report(&dir);
    let old_file = write(&dir, "old.json", &old);
    // The same results under another name, and a failure.
    let renamed = serde_json::to_string(&old)
        .unwrap()
        .replace("\"production\"", "\"other\"");
    let mut new: Value = serde_json::from_str(&renamed).unwrap();
    new["cases"][0]["results"][0]["verdict"] = "fail".into();
    let new_file = write(&dir, "new.json", &new);

    let (exit, printed, json) = diff(&old_file, &new_file, &dir.join("one"), &[]);
    assert_eq!(exit, 1, "{printed}");
    assert_eq!(json["pairs"][0]["how"], "one each");
    assert!(
        printed.contains("paired rasterizer production (OLD) with other (NEW)"),
        "{printed}"
    );
    assert_eq!(json["newly_failing"].as_array().unwrap().len(), 1);

    let (exit, printed, json) = diff(
        &old_file,
        &new_file,
        &dir.join("flag"),
        &["--pair", "production=other"],
    );
    assert_eq!(exit, 1, "{printed}");
    assert_eq!(json["pairs"][0]["how"], "--pair");

    let out = rastercheck(&[
        "diff",
        s(&old_file),
        s(&new_file),
        "--pair",
        "production=nothing",
    ]);
    assert_eq!(code(&out), 2, "{}", text(&out));
    assert!(text(&out).contains("\"nothing\""), "{}", text(&out));
}

#[test]
fn reports_that_share_no_case_judge_nothing() {
    let dir = scratch("disjoint");
    let old = triangles_report(&dir);
    let old_file = write(&dir, "old.json", &old);
    let mut new = old.clone();
    for case in new["cases"].as_array_mut().unwrap() {
        case["id"] = format!("renamed/{}", case["id"].as_str().unwrap()).into();
    }
    let new_file = write(&dir, "new.json", &new);
    let (exit, printed, json) = diff(&old_file, &new_file, &dir.join("out"), &[]);
    assert_eq!(exit, 3, "{printed}");
    assert!(printed.contains("nothing was judged"), "{printed}");
    assert_eq!(json["counts"]["added"], 77);
    assert_eq!(json["counts"]["removed"], 77);
}

#[test]
fn bad_input_exits_2_naming_the_file() {
    let dir = scratch("bad");
    let good = write(&dir, "good.json", &triangles_report(&dir));
    let not_json = dir.join("not.json");
    std::fs::write(&not_json, "{ this is not json").unwrap();
    let baseline = write(
        &dir,
        "baseline.json",
        &serde_json::json!({"schema": "rastercheck-baseline/1", "results": []}),
    );
    let mut verdict = read(&good);
    verdict["cases"][3]["results"][0]["verdict"] = "maybe".into();
    let verdict = write(&dir, "verdict.json", &verdict);
    let empty_folder = dir.join("empty");
    std::fs::create_dir_all(&empty_folder).unwrap();
    let missing = dir.join("missing.json");

    for (bad, says) in [
        (&missing, "missing.json"),
        (&not_json, "not JSON"),
        (&baseline, "schema"),
        (&verdict, "cases[3].results[0].verdict"),
        (&empty_folder, "report.json"),
    ] {
        for args in [[s(bad), s(&good)], [s(&good), s(bad)]] {
            let out = rastercheck(&["diff", args[0], args[1]]);
            let printed = text(&out);
            assert_eq!(code(&out), 2, "{printed}");
            assert!(printed.contains(s(bad)), "names {bad:?}: {printed}");
            assert!(printed.contains(says), "{says}: {printed}");
            assert!(!printed.contains("panicked"), "{printed}");
        }
    }

    // A FIFO with no writer is refused, not waited on (it hung before).
    let fifo = dir.join("fifo.json");
    let made = Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    let out = bounded(&["diff", s(&fifo), s(&good)], None);
    assert_eq!(code(&out), 2, "{}", text(&out));
    assert!(
        text(&out).contains("not a regular file (a FIFO)"),
        "{}",
        text(&out)
    );

    // 64 MB of JSON that is not a report, under a 256 MiB address-space
    // cap: refused in constant memory (parsed whole first, it took 421 MB
    // and aborted under the cap).
    let big = dir.join("big.json");
    let mut numbers = String::with_capacity(64 << 20);
    numbers.push('[');
    while numbers.len() < 64 << 20 {
        numbers.push_str("0.123456789,");
    }
    numbers.push_str("0]");
    std::fs::write(&big, numbers).unwrap();
    let out = bounded(&["diff", s(&big), s(&good)], Some(256 << 10));
    assert_eq!(code(&out), 2, "{}", text(&out));
    assert!(text(&out).contains("big.json"), "{}", text(&out));
    assert!(
        text(&out).contains("expected a JSON object"),
        "{}",
        text(&out)
    );
    std::fs::remove_file(&big).unwrap();

    // An --out folder that cannot be created: before anything is read.
    let file = dir.join("a-file");
    std::fs::write(&file, "").unwrap();
    let out = rastercheck(&[
        "diff",
        s(&missing),
        s(&missing),
        "--out",
        s(&file.join("sub")),
    ]);
    assert_eq!(code(&out), 2, "{}", text(&out));
    assert!(text(&out).contains("--out"), "{}", text(&out));
}

#[test]
fn the_markdown_is_cut_to_fit_a_pull_request_comment() {
    let dir = scratch("long");
    let old = triangles_report(&dir);
    let old_file = write(&dir, "old.json", &old);
    let mut new = old.clone();
    let long_reason = "coverage: ".to_owned() + &"x|".repeat(500);
    for case in new["cases"].as_array_mut().unwrap() {
        case["results"][0]["verdict"] = "fail".into();
        case["results"][0]["reasons"] = serde_json::json!([long_reason]);
    }
    let new_file = write(&dir, "new.json", &new);
    let (exit, printed, json) = diff(&old_file, &new_file, &dir.join("out"), &[]);
    assert_eq!(exit, 1, "{printed}");
    assert_eq!(json["newly_failing"].as_array().unwrap().len(), 77);
    let md = std::fs::read_to_string(dir.join("out/diff.md")).unwrap();
    assert!(md.len() < 65_536, "{}", md.len());
    assert!(md.contains("and 27 more"), "{md}");
    // Every row of the table is one line: `|` in a reason is escaped.
    let rows = md
        .lines()
        .filter(|l| l.starts_with("| `triangles/"))
        .count();
    assert_eq!(rows, 50, "{md}");
    for row in md.lines().filter(|l| l.starts_with("| `")) {
        let cells = row.matches('|').count() - row.matches("\\|").count();
        assert_eq!(cells, 5, "four cells: {row}");
    }
    let html = std::fs::read_to_string(dir.join("out/diff.html")).unwrap();
    assert_eq!(html.matches("<tr><td>triangles/").count(), 77);
}
