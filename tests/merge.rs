//! `rastercheck merge OUT REPORT...` run as a user runs it: the four shards
//! of the bundled suite merged give the unsharded run's verdicts, metrics
//! and totals (and `diff` finds nothing between them); runs of other
//! rasterizers, or of one rasterizer on two machines, become one report
//! with a row each; every disagreement (a shard twice or missing, a case in
//! two shards, two files behind one id, another tool version, a run twice
//! on one host) is an error naming it, exit 2, and nothing is written.

mod common;

use std::path::{Path, PathBuf};

use common::cli::{rastercheck_env, read_json, scratch, text};
use serde_json::Value;

fn repository() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `run` in the repository on `host`, its report into `report`: the exit code.
fn run_on(host: &str, report: &Path, args: &[&str]) -> i32 {
    let report_arg = report.display().to_string();
    let mut all = vec!["run"];
    all.extend_from_slice(args);
    all.extend(["-q", "--report", &report_arg]);
    let out = rastercheck_env(&repository(), &all, &[("RASTERCHECK_HOST", host)]);
    let t = text(&out);
    assert!(!t.contains("panicked"), "{t}");
    out.status.code().unwrap_or(-1)
}

/// `merge out reports...`: the exit code and what it printed.
fn merge(out: &Path, reports: &[&Path]) -> (i32, String) {
    let mut args = vec!["merge".to_owned(), out.display().to_string()];
    args.extend(reports.iter().map(|r| r.display().to_string()));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let run = rastercheck_env(&repository(), &args, &[("RASTERCHECK_HOST", "merger")]);
    let t = text(&run);
    assert!(!t.contains("panicked"), "{t}");
    (run.status.code().unwrap_or(-1), t)
}

/// A report without what differs between two runs of the same verdicts:
/// timings, the command line, the machine, the shard and the sources.
fn judged(report: &Value) -> Value {
    fn strip(v: &mut Value) {
        match v {
            Value::Object(map) => {
                map.retain(|k, _| {
                    !k.ends_with("_ms")
                        && !["command", "machine", "shard", "sources"].contains(&k.as_str())
                });
                map.values_mut().for_each(strip);
            }
            Value::Array(items) => items.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v = report.clone();
    strip(&mut v);
    v
}

fn rows(report: &Value) -> Vec<String> {
    report["rasterizers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["name"].as_str().unwrap().to_owned())
        .collect()
}

/// Every file the report names (pages, pictures, error maps) is in its folder.
fn assert_files_present(dir: &Path) {
    let report = read_json(&dir.join("report.json"));
    let mut named = 0;
    for case in report["cases"].as_array().unwrap() {
        let files = case["results"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|r| r["files"].as_array().cloned().unwrap_or_default());
        for file in case["page"]
            .as_str()
            .map(Value::from)
            .into_iter()
            .chain(files)
        {
            let file = file.as_str().unwrap();
            assert!(dir.join(file).is_file(), "{} names {file}", dir.display());
            named += 1;
        }
    }
    assert!(named > 0, "the report names no file: nothing was copied");
}

#[test]
fn four_shards_merged_are_the_unsharded_run() {
    let out = scratch("merge-shards");
    let whole = out.join("whole");
    assert_eq!(run_on("one", &whole, &["cases", "-r", "production"]), 0);
    let mut shards = Vec::new();
    for k in 1..=4 {
        let dir = out.join(format!("shard{k}"));
        let shard = format!("{k}/4");
        let code = run_on(
            &format!("runner-{k}"),
            &dir,
            &["cases", "-r", "production", "--shard", &shard],
        );
        assert_eq!(code, 0);
        shards.push(dir);
    }
    let merged = out.join("merged");
    // Given in any order, the shards go back into the suite's order.
    let given: Vec<&Path> = shards.iter().rev().map(PathBuf::as_path).collect();
    let (code, printed) = merge(&merged, &given);
    assert_eq!(code, 0, "{printed}");
    let (a, b) = (
        read_json(&whole.join("report.json")),
        read_json(&merged.join("report.json")),
    );
    assert_eq!(judged(&a), judged(&b));
    assert!(b["totals"]["cases"].as_u64().unwrap() > 400);
    assert_eq!(b["sources"].as_array().unwrap().len(), 4);
    // The sources in shard order, each naming the machine it ran on.
    assert_eq!(b["sources"][0]["machine"]["host"], "runner-1");
    assert_eq!(b["sources"][3]["shard"], "4/4");
    assert_eq!(b["machine"]["host"], "merger");
    assert!(a["cases"][0]["hash"]
        .as_str()
        .unwrap()
        .starts_with("fnv1a64:"));
    for file in ["junit.xml", "summary.md", "index.html"] {
        assert!(merged.join(file).is_file(), "{file}");
    }
    // The JUnit file counts the same tests and failures.
    let tests = |dir: &Path| {
        let junit = std::fs::read_to_string(dir.join("junit.xml")).unwrap();
        (
            junit.matches("<testcase").count(),
            junit.matches("<failure").count(),
        )
    };
    assert_eq!(tests(&whole), tests(&merged));
    // diff reads the merged report and finds nothing changed.
    let diff = rastercheck_env(
        &repository(),
        &["diff", whole.to_str().unwrap(), merged.to_str().unwrap()],
        &[],
    );
    assert_eq!(diff.status.code(), Some(0), "{}", text(&diff));
}

#[test]
fn runs_of_other_rasterizers_and_machines_become_rows() {
    let out = scratch("merge-rows");
    let (production, foil, board) = (out.join("p"), out.join("f"), out.join("b"));
    assert_eq!(
        run_on("board-a", &production, &["cases/lines", "-r", "production"]),
        0
    );
    // A foil's departures may or may not fail the run; it judged something.
    let foil_code = run_on(
        "board-a",
        &foil,
        &["cases/lines", "-r", "foil-offset-sampler"],
    );
    assert!(foil_code == 0 || foil_code == 1, "{foil_code}");
    assert_eq!(
        run_on("board-b", &board, &["cases/lines", "-r", "production"]),
        0
    );
    let merged = out.join("merged");
    let (code, printed) = merge(&merged, &[&production, &foil, &board]);
    let report = read_json(&merged.join("report.json"));
    assert_eq!(
        rows(&report),
        [
            "production on board-a",
            "foil-offset-sampler",
            "production on board-b"
        ],
        "{printed}"
    );
    let foil_report = read_json(&foil.join("report.json"));
    assert_eq!(code, foil_code, "{printed}");
    for case in report["cases"].as_array().unwrap() {
        let results = case["results"].as_array().unwrap();
        if case["status"] == "ran" {
            assert_eq!(results.len(), 3, "{}", case["id"]);
            assert_eq!(results[2]["rasterizer"], "production on board-b");
        }
    }
    // Each row's verdicts are its run's.
    let foil_verdicts: Vec<&Value> = foil_report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| &c["results"][0]["verdict"])
        .collect();
    let merged_verdicts: Vec<&Value> = report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| &c["results"][1]["verdict"])
        .collect();
    assert_eq!(foil_verdicts, merged_verdicts);
    assert_eq!(
        report["totals"]["verdicts"][1],
        foil_report["totals"]["verdicts"][0]
    );
    assert_files_present(&merged);
}

/// Asserts `merge` of `reports` exits 2 naming `said`, and writes nothing.
fn refused(tag: &str, reports: &[&Path], said: &str) {
    let out = scratch(&format!("merge-refused-{tag}"));
    let merged = out.join("merged");
    let (code, printed) = merge(&merged, reports);
    assert_eq!(code, 2, "{printed}");
    assert!(printed.contains(said), "expected {said:?} in:\n{printed}");
    assert!(!merged.join("report.json").exists(), "{printed}");
}

fn edit(from: &Path, to: &Path, change: impl Fn(&mut Value)) {
    let mut report = read_json(&from.join("report.json"));
    change(&mut report);
    std::fs::create_dir_all(to).unwrap();
    std::fs::write(to.join("report.json"), report.to_string()).unwrap();
}

#[test]
fn disagreeing_reports_are_errors_naming_what_disagrees() {
    let out = scratch("merge-conflicts");
    let s = |k: usize| out.join(format!("shard{k}"));
    for k in 1..=3 {
        let shard = format!("{k}/3");
        assert_eq!(
            run_on(
                "ci",
                &s(k),
                &["cases/lines", "-r", "production", "--shard", &shard]
            ),
            0
        );
    }
    let (s1, s2, s3) = (s(1), s(2), s(3));
    refused("missing", &[&s1, &s3], "misses shard 2/3");
    refused(
        "twice",
        &[&s1, &s2, &s3, &s2],
        "shard 2/3 of the run of production given 2 times",
    );
    // Shard 1 relabelled as shard 2: every case of it twice.
    let overlap = out.join("overlap");
    edit(&s1, &overlap, |r| {
        r["shard"] = "2/3".into();
        // Same length as shard 2, so that the cases themselves collide.
        let n = read_json(&s2.join("report.json"))["cases"]
            .as_array()
            .unwrap()
            .len();
        r["cases"].as_array_mut().unwrap().truncate(n);
    });
    let first = read_json(&s1.join("report.json"))["cases"][0]["id"]
        .as_str()
        .unwrap()
        .to_owned();
    refused(
        "overlap",
        &[&s1, &overlap, &s3],
        &format!("case {first}: in "),
    );
    // Another version of the tool.
    let newer = out.join("newer");
    edit(&s2, &newer, |r| r["tool"]["version"] = "99.0.0".into());
    refused("version", &[&s1, &newer, &s3], "different tool versions");
    // The same rasterizer twice on one host: two verdicts per case, as a
    // shard given twice.
    let (a, b) = (out.join("a"), out.join("b"));
    assert_eq!(run_on("lab", &a, &["cases/lines", "-r", "production"]), 0);
    assert_eq!(run_on("lab", &b, &["cases/lines", "-r", "production"]), 0);
    refused(
        "same-host",
        &[&a, &b],
        "shard 1/1 of the run of production given 2 times",
    );
    // One id, two case files: another machine ran an edited case.
    let edited = out.join("edited");
    edit(&b, &edited, |r| {
        r["machine"]["host"] = "elsewhere".into();
        r["cases"][3]["hash"] = "fnv1a64:0123456789abcdef".into();
    });
    let id = read_json(&b.join("report.json"))["cases"][3]["id"]
        .as_str()
        .unwrap()
        .to_owned();
    refused(
        "hash",
        &[&a, &edited],
        &format!("case {id}: different case files behind one id"),
    );
    // Not a report; the merged folder one of the inputs.
    let junk = out.join("junk");
    std::fs::create_dir_all(&junk).unwrap();
    std::fs::write(junk.join("report.json"), "{\"schema\": \"other/1\"}").unwrap();
    refused("junk", &[&a, &junk], "not a report this version reads");
    let (code, printed) = merge(&a, &[&a, &b]);
    assert_eq!(code, 2, "{printed}");
    assert!(printed.contains("would overwrite the report"), "{printed}");
}

#[test]
fn one_driver_sharded_on_two_boards_is_one_matrix_with_a_row_per_board() {
    let out = scratch("merge-boards");
    let mut reports = Vec::new();
    for board in ["board-a", "board-b"] {
        for k in 1..=2 {
            let dir = out.join(format!("{board}-{k}"));
            let shard = format!("{k}/2");
            let args = ["cases/lines", "-r", "production", "--shard", &shard];
            assert_eq!(run_on(board, &dir, &args), 0);
            reports.push(dir);
        }
    }
    let whole = out.join("whole");
    assert_eq!(
        run_on("board-a", &whole, &["cases/lines", "-r", "production"]),
        0
    );
    // Before: "shard 1/2 of the run of production given 2 times".
    let merged = out.join("merged");
    let given: Vec<&Path> = reports.iter().map(PathBuf::as_path).collect();
    let (code, printed) = merge(&merged, &given);
    assert_eq!(code, 0, "{printed}");
    let report = read_json(&merged.join("report.json"));
    assert_eq!(
        rows(&report),
        ["production on board-a", "production on board-b"],
        "{printed}"
    );
    // Each board's row holds the unsharded run's verdicts, in its order.
    let unsharded = read_json(&whole.join("report.json"));
    let ids = |r: &Value| -> Vec<Value> {
        r["cases"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c["id"].clone())
            .collect()
    };
    assert_eq!(ids(&report), ids(&unsharded));
    for row in 0..2 {
        let verdicts: Vec<&Value> = report["cases"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| &c["results"][row]["verdict"])
            .collect();
        let expected: Vec<&Value> = unsharded["cases"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| &c["results"][0]["verdict"])
            .collect();
        assert_eq!(verdicts, expected, "row {row}");
    }
    assert_eq!(report["sources"].as_array().unwrap().len(), 4);
    assert_files_present(&merged);
}
