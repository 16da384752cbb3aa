//! The binary as a user runs it: exit codes, output, files written.

mod common;

use common::cli::{
    assert_no_panic, bless_cases, bless_elsewhere, rastercheck, read_json, report_ids, run_cases,
    show_failing, text, workspace,
};
use std::path::PathBuf;

const TIE_PAIR: &str = r#"{
  "name": "diagonal_pair", "canvas": {"width": 8, "height": 8},
  "primitives": [
    {"triangle": [[0, 0], [8, 0], [8, 8]]},
    {"triangle": [[0, 0], [8, 8], [0, 8]]}
  ],
  "expect": {"watertight": true}
}"#;

const SINGLE: &str = r#"{"name": "single", "canvas": {"width": 4, "height": 4},
  "primitives": [{"triangle": [[0, 0], [4, 0], [0, 4]]}]}"#;

#[test]
fn passing_cases_exit_0_with_a_line_each_and_a_summary() {
    let dir = workspace(
        "pass",
        &[
            ("cases/a/pair.json", TIE_PAIR),
            ("cases/a/single.json", SINGLE),
        ],
    );
    let t = run_cases(&dir, &[], 0);
    assert!(t.contains("PASS  a/pair"), "{t}");
    assert!(t.contains("PASS  a/single"), "{t}");
    assert!(t.contains("production: 2 passed, 0 failed"), "{t}");
}

#[test]
fn a_failing_rasterizer_exits_1_and_says_why() {
    let dir = workspace("fail", &[("cases/pair.json", TIE_PAIR)]);
    let t = run_cases(&dir, &["-r", "production", "-r", "mutant:flipped-ties"], 1);
    assert!(t.contains("FAIL  pair  mutant:flipped-ties"), "{t}");
    assert!(t.contains("8 wrong owner"), "{t}");
    assert!(t.contains("production: 1 passed"), "{t}");
}

#[test]
fn malformed_json_exits_2_naming_the_file_and_place() {
    let dir = workspace(
        "malformed",
        &[("cases/broken.json", "{\"name\": \"x\",\n \"canvas\": [1,\n")],
    );
    let out = rastercheck(&dir, &["run", "cases/broken.json"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("cases/broken.json: line 3 column 0: invalid JSON"),
        "{t}"
    );
    assert_no_panic(&out);
}

#[test]
fn bad_values_exit_2_naming_the_json_path() {
    let wrong_type = SINGLE.replace("[4, 0]", "[4, true]");
    let non_finite = SINGLE.replace("[4, 0]", "[\"inf\", 0]");
    let out_of_range = SINGLE.replace("[4, 0]", "[4, -32769]");
    for (json, path, phrase) in [
        (
            wrong_type,
            "$.primitives[0].triangle[1][1]",
            "expected a number",
        ),
        (
            non_finite,
            "$.primitives[0].triangle[1][0]",
            "is not finite",
        ),
        (
            out_of_range,
            "$.primitives[0].triangle[1][1]",
            "outside the documented range",
        ),
    ] {
        let dir = workspace("values", &[("cases/bad.json", &json)]);
        let out = rastercheck(&dir, &["run", "cases"]);
        let t = text(&out);
        assert_eq!(out.status.code(), Some(2), "{t}");
        assert!(
            t.contains(&format!("cases/bad.json: {path}: ")) && t.contains(phrase),
            "{t}"
        );
        assert_no_panic(&out);
    }
}

#[test]
fn one_bad_case_does_not_stop_the_others() {
    let dir = workspace(
        "mixed",
        &[
            ("cases/a.json", SINGLE),
            ("cases/b.json", "not json"),
            ("cases/c.json", TIE_PAIR),
        ],
    );
    // Bad input wins over a failure, and both good cases still ran.
    let t = run_cases(&dir, &["-r", "production", "-r", "mutant:flipped-ties"], 2);
    assert!(t.contains("BAD   b"), "{t}");
    assert!(t.contains("PASS  a  production"), "{t}");
    assert!(t.contains("PASS  c  production"), "{t}");
    assert!(t.contains("FAIL  c  mutant:flipped-ties"), "{t}");
    assert!(t.contains("3 case files, 1 unreadable"), "{t}");
}

#[test]
fn invalid_folders_are_skipped_unless_named() {
    let dir = workspace(
        "skip",
        &[("cases/a.json", SINGLE), ("cases/invalid/x.json", "{")],
    );
    let out = rastercheck(&dir, &["run", "cases"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    assert!(
        text(&out).contains("note: skipping cases/invalid"),
        "{}",
        text(&out)
    );
    let out = rastercheck(&dir, &["run", "cases/invalid"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
}

#[test]
fn usage_errors_exit_2() {
    let dir = workspace("usage", &[("cases/a.json", SINGLE)]);
    for args in [
        &["run", "no/such/path"][..],
        &["run", "cases", "-r", "no-such-rasterizer"],
        &["run", "--no-such-flag"],
        &["frobnicate"],
    ] {
        let out = rastercheck(&dir, args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out));
        assert_no_panic(&out);
    }
}

#[test]
fn bless_writes_golden_files_that_run_then_checks() {
    let dir = workspace("bless", &[("cases/pair.json", TIE_PAIR)]);
    bless_cases(&dir);
    assert!(dir.join("reference/pair.exr").is_file());
    let out = rastercheck(&dir, &["run", "cases"]);
    assert!(
        text(&out).contains("golden files: 1 match, 0 differ"),
        "{}",
        text(&out)
    );

    // A golden file from another case no longer matches: the run fails.
    bless_elsewhere(
        &dir,
        "bless-other",
        "pair",
        &TIE_PAIR.replace("[8, 0], [8, 8]", "[8, 0], [8, 7]"),
    );
    let t = run_cases(&dir, &[], 1);
    assert!(
        t.contains("GOLDEN pair  the reference no longer reproduces its golden file"),
        "{t}"
    );
}

#[test]
fn show_writes_three_decodable_pngs() {
    let dir = workspace("show", &[("cases/pair.json", TIE_PAIR)]);
    let (_, pictures) = show_failing(&dir, "pair", "mutant:flipped-ties", &[".png", ".diff.png"]);
    for (name, img) in pictures {
        // 8 pixels magnified 32 times, the most auto-scaling gives.
        assert_eq!(img.width(), 256, "{name}");
    }
    // The diff shows the 8 wrong-owner samples in yellow.
    let diff = image::open(dir.join("shown/mutant-flipped-ties.diff.png"))
        .unwrap()
        .to_rgb8();
    let yellow = rastercheck::report::png::WRONG_OWNER;
    let centre = |x: u32, y: u32| diff.get_pixel(x * 32 + 16, y * 32 + 10).0;
    assert_eq!(centre(3, 3), yellow);
    assert_ne!(centre(3, 4), yellow);
}

/// The report's cases with every timing removed, for comparing runs.
fn without_timings(report: &str) -> serde_json::Value {
    let mut value: serde_json::Value = serde_json::from_str(report).unwrap();
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(map) => {
                map.retain(|k, _| !k.ends_with("_ms") && k != "command");
                map.values_mut().for_each(strip);
            }
            serde_json::Value::Array(items) => items.iter_mut().for_each(strip),
            _ => {}
        }
    }
    strip(&mut value);
    value
}

fn bundled_cases() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let root = bundled_cases();
    let out = common::cli::scratch("threads");
    let mut reports = Vec::new();
    for threads in ["1", "2", "5"] {
        let dir = out.join(threads);
        let run = rastercheck(
            &root,
            &[
                "run",
                "cases",
                "-q",
                "-r",
                "production",
                "-r",
                "dda-f32",
                "--threads",
                threads,
                "--report",
                dir.to_str().unwrap(),
            ],
        );
        assert_eq!(run.status.code(), Some(0), "{}", text(&run));
        reports.push((
            std::fs::read_to_string(dir.join("report.json")).unwrap(),
            text(&run),
        ));
    }
    for (report, output) in &reports[1..] {
        assert_eq!(without_timings(report), without_timings(&reports[0].0));
        // Printed output is in the same order too (the report line names the folder).
        let body = |t: &str| {
            t.lines()
                .filter(|l| !l.starts_with("report:"))
                .collect::<Vec<_>>()
                .join("\n")
        };
        assert_eq!(body(output), body(&reports[0].1));
    }
    std::fs::remove_dir_all(out).ok();
}

#[test]
fn the_union_of_the_shards_is_the_whole_suite_each_case_once() {
    let root = bundled_cases();
    let out = common::cli::scratch("shards");
    let whole_dir = out.join("whole");
    assert_eq!(
        rastercheck(
            &root,
            &[
                "run",
                "cases",
                "-q",
                "--report",
                whole_dir.to_str().unwrap()
            ]
        )
        .status
        .code(),
        Some(0)
    );
    let mut whole = report_ids(&whole_dir);
    whole.sort();
    assert!(whole.len() > 100);
    let mut union = Vec::new();
    for i in 1..=3 {
        let dir = out.join(format!("shard{i}"));
        let shard = format!("{i}/3");
        let run = rastercheck(
            &root,
            &[
                "run",
                "cases",
                "-q",
                "--shard",
                &shard,
                "--report",
                dir.to_str().unwrap(),
            ],
        );
        assert_eq!(run.status.code(), Some(0), "{}", text(&run));
        let ids = report_ids(&dir);
        assert!(!ids.is_empty());
        union.extend(ids);
    }
    union.sort();
    assert_eq!(union, whole);
    std::fs::remove_dir_all(out).ok();
}

#[test]
fn filter_and_family_select_cases() {
    let root = bundled_cases();
    let out = common::cli::scratch("select");
    let run = rastercheck(
        &root,
        &[
            "run",
            "cases",
            "--family",
            "lines",
            "--filter",
            "**diamond*",
            "--report",
            out.to_str().unwrap(),
        ],
    );
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    let ids = report_ids(&out);
    assert!(!ids.is_empty());
    // `**` crosses segments and `diamond*` ends the id: every lines case
    // whose id has "diamond" followed by anything, `spec_diamond_…` too.
    assert!(
        ids.iter()
            .all(|id| id.starts_with("lines/") && id.contains("diamond")),
        "{ids:?}"
    );
    assert!(ids.contains(&"lines/diamond_strip".to_owned()), "{ids:?}");
    assert!(
        ids.contains(&"lines/spec_diamond_single_point".to_owned()),
        "{ids:?}"
    );
    let bad = rastercheck(&root, &["run", "cases", "--shard", "4/3"]);
    assert_eq!(bad.status.code(), Some(2), "{}", text(&bad));
    std::fs::remove_dir_all(out).ok();
}

#[test]
fn a_report_is_written_even_when_cases_are_bad_and_says_which() {
    let dir = workspace(
        "report-bad",
        &[
            ("cases/a.json", SINGLE),
            ("cases/b.json", "{ nope"),
            ("cases/c.json", TIE_PAIR),
        ],
    );
    let out = rastercheck(
        &dir,
        &[
            "run",
            "cases",
            "-r",
            "production",
            "-r",
            "mutant:flipped-ties",
            "--report",
            "rep",
        ],
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let report = read_json(&dir.join("rep/report.json"));
    assert_eq!(report["complete"], true);
    assert_eq!(report["totals"]["unreadable"], 1);
    let b = &report["cases"][1];
    assert_eq!(b["status"], "unreadable");
    assert!(
        b["error"]
            .as_str()
            .unwrap()
            .contains("cases/b.json: line 1 column 3"),
        "{b}"
    );
    assert_eq!(report["cases"][2]["results"][1]["verdict"], "fail");
    let junit = std::fs::read_to_string(dir.join("rep/junit.xml")).unwrap();
    assert!(
        junit.contains("<testcase name=\"c\" classname=\"mutant:flipped-ties.(top)\""),
        "{junit}"
    );
    assert!(
        junit.contains("<failure message=\"coverage: 8 samples differ"),
        "{junit}"
    );
    assert!(junit.contains("<error message=\"unreadable\">"), "{junit}");
    let summary = std::fs::read_to_string(dir.join("rep/summary.md")).unwrap();
    assert!(
        summary.contains("`c` **mutant:flipped-ties** fail"),
        "{summary}"
    );
    // The failing result got its pictures.
    assert!(dir
        .join("rep/images/c/mutant-flipped-ties.diff.png")
        .is_file());
}

#[test]
fn duplicate_case_names_are_bad_input_naming_both_files() {
    let dir = workspace(
        "dupes",
        &[
            ("cases/a.json", SINGLE),
            ("cases/b.json", SINGLE),
            ("cases/c.json", TIE_PAIR),
        ],
    );
    let t = run_cases(&dir, &[], 2);
    assert!(
        t.contains(
            "BAD   b  cases/b.json: $.name: the case name \"single\" is also used by cases/a.json"
        ),
        "{t}"
    );
    assert!(t.contains("PASS  a") && t.contains("PASS  c"), "{t}");
}

#[test]
fn resource_limits_are_errors_not_crashes() {
    let dir = workspace("limits", &[("cases/pair.json", TIE_PAIR)]);
    let out = rastercheck(&dir, &["run", "cases", "--max-primitives", "1"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("cases/pair.json: $.primitives: 2 primitives exceed the limit of 1"),
        "{t}"
    );
    let out = rastercheck(&dir, &["run", "cases", "--max-canvas-pixels", "63"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("cases/pair.json: $.canvas: canvas of 64 pixels exceeds the limit of 63"),
        "{t}"
    );
    // A limit of the run, not bad input: LIMIT, as the README's limits
    // paragraph says (it was BAD, unreadable, before).
    for limit in ["--max-canvas-pixels", "--max-primitives", "--max-samples"] {
        let out = rastercheck(&dir, &["run", "cases", limit, "1"]);
        let t = text(&out);
        assert_eq!(out.status.code(), Some(2), "{t}");
        assert!(t.contains("LIMIT"), "{limit}: {t}");
        assert!(!t.contains("BAD"), "{limit}: {t}");
    }
    assert_no_panic(&out);
}

/// Two triangles sharing a diagonal, 4 standard samples on the 1/16 grid,
/// in an 8×8 canvas with edges off the pixel grid.
const AA_PAIR: &str = r#"{"name": "aa_pair", "canvas": {"width": 8, "height": 8},
  "primitives": [{"triangle": [[0.5, 0.25], [7.75, 1], [7, 7.5]]},
                 {"triangle": [[0.5, 0.25], [7, 7.5], [1, 7]]}],
  "effects": {"antialias": {"samples": 4, "position_bits": 4}},
  "expect": {"max_coverage_error": 0.75, "watertight": true, "area": "1407/32"}}"#;

#[test]
fn antialiased_golden_files_bless_run_and_catch_a_changed_area() {
    let dir = workspace("bless-aa", &[("cases/aa_pair.json", AA_PAIR)]);
    bless_cases(&dir);
    let t = run_cases(&dir, &[], 0);
    assert!(t.contains("golden files: 1 match, 0 differ"), "{t}");
    assert!(t.contains("aa max err"), "{t}");

    // A golden file of the same case moved by a quarter pixel: the samples
    // and the resolved areas differ, and the run says where.
    bless_elsewhere(
        &dir,
        "bless-aa-other",
        "aa_pair",
        &AA_PAIR.replace("[1, 7]", "[1.25, 7]"),
    );
    let t = run_cases(&dir, &[], 1);
    assert!(t.contains("GOLDEN aa_pair"), "{t}");
    assert!(t.contains("resolved.f64"), "{t}");

    // The case's stated area pins the oracle's exact areas.
    std::fs::write(
        dir.join("cases/aa_pair.json"),
        AA_PAIR.replace("1407/32", "44"),
    )
    .unwrap();
    let t = run_cases(&dir, &[], 1);
    assert!(
        t.contains("reference: its pixel areas sum to 1407/32"),
        "{t}"
    );
}

#[test]
fn show_pictures_an_antialiased_case_by_its_resolved_coverage() {
    let dir = workspace("show-aa", &[("cases/aa_pair.json", AA_PAIR)]);
    let (_, pictures) = show_failing(
        &dir,
        "aa_pair",
        "mutant:shifted-samples",
        &[".png", ".diff.png", ".samples.png"],
    );
    for (name, img) in pictures {
        assert!(img.width() >= 256, "{name}");
    }
    // Pixel (0, 0) holds a sliver of the quadrilateral: a dark grey, not
    // black and not white, in the exact area's picture.
    let reference = image::open(dir.join("shown/reference.png"))
        .unwrap()
        .to_rgb8();
    let [r, g, b] = reference.get_pixel(20, 20).0;
    assert!(r == g && g == b && r > 0 && r < 128, "{:?}", [r, g, b]);
}

/// A polygon of 800 pseudo-random vertices on a 64² canvas, antialiased:
/// its edges cross each other tens of thousands of times, and the
/// reference's exact areas take a minute or more on this machine.
fn slow_case() -> String {
    let mut state: u64 = 5;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 33) % 1025
    };
    let points: Vec<String> = (0..800)
        .map(|_| format!("[{}, {}]", next() as f64 / 16.0, next() as f64 / 16.0))
        .collect();
    format!(
        r#"{{"name": "slow", "canvas": {{"width": 64, "height": 64}},
  "rules": {{"subpixel_bits": 8}},
  "effects": {{"antialias": {{"samples": 16, "pattern": "standard"}}}},
  "primitives": [{{"polygon": [{}]}}]}}"#,
        points.join(", ")
    )
}

#[test]
fn a_case_over_the_time_limit_is_an_error_and_the_others_still_run() {
    let slow = slow_case();
    let dir = workspace(
        "timeout",
        &[("cases/a.json", SINGLE), ("cases/slow.json", &slow)],
    );
    let started = std::time::Instant::now();
    let out = rastercheck(
        &dir,
        &[
            "run",
            "cases",
            "--case-timeout",
            "0.5",
            "--report",
            "report",
        ],
    );
    let elapsed = started.elapsed();
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("LIMIT slow  cases/slow.json: the reference took longer than the time limit of 0.5 s per case (raise it with --case-timeout)"),
        "{t}"
    );
    assert!(t.contains("PASS  a     production"), "{t}");
    assert!(
        t.contains("2 case files, 0 unreadable, 1 over a limit"),
        "{t}"
    );
    assert_no_panic(&out);
    let report = read_json(&dir.join("report/report.json"));
    let slow = &report["cases"][1];
    assert_eq!(slow["status"], "limit-exceeded", "{slow}");
    assert_eq!(report["totals"]["limit_exceeded"], 1);
    assert_eq!(report["limits"]["case_timeout_s"], 0.5);
    let junit = std::fs::read_to_string(dir.join("report/junit.xml")).unwrap();
    assert!(junit.contains("limit-exceeded"), "{junit}");
    assert!(junit.contains("errors=\"1\""), "{junit}");
    // The reference stopped at the limit rather than finishing and being
    // judged afterwards: uncapped, this case takes a minute or more. (A
    // loose bound: a shared machine may be slow, never 30 s slow.)
    assert!(
        elapsed < std::time::Duration::from_secs(30),
        "the run took {elapsed:?}: the reference does not poll its deadline"
    );
}

#[test]
fn a_time_limit_must_be_a_number_of_seconds() {
    let dir = workspace("timeout-usage", &[("cases/a.json", SINGLE)]);
    for bad in ["-1", "NaN", "inf", "soon"] {
        let flag = format!("--case-timeout={bad}");
        let out = rastercheck(&dir, &["run", "cases", &flag]);
        let t = text(&out);
        assert_eq!(out.status.code(), Some(2), "{bad}: {t}");
        assert!(t.contains("expected a number of seconds"), "{bad}: {t}");
    }
    let out = rastercheck(&dir, &["run", "cases", "--case-timeout", "0"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
}

#[test]
fn bench_refuses_an_out_folder_that_does_not_exist_before_it_runs() {
    let dir = workspace("bench-out", &[]);
    let out = rastercheck(&dir, &["bench", "--out", "missing/BENCH.md"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(t.contains("missing/BENCH.md"), "{t}");
    assert!(!t.contains("bench: "), "no workload ran: {t}");
    assert!(!dir.join("missing").exists());
}

/// The first line of stderr and stdout that starts with `error:`.
fn error_line(t: &str) -> &str {
    t.lines()
        .find(|l| l.starts_with("error:"))
        .unwrap_or_else(|| panic!("no error line in {t}"))
}

#[test]
fn a_mistyped_rasterizer_gets_one_suggestion_not_the_whole_list() {
    let dir = workspace("did-you-mean", &[("cases/a.json", SINGLE)]);
    for (typed, meant) in [
        ("producton", "\"production\""),
        ("foil-any-coverag", "\"foil-any-coverage\""),
        ("mutant:flipped-tie", "\"mutant:flipped-ties\""),
        (
            "mine=python3 r.py",
            "\"mine=external-persistent:python3 r.py\"",
        ),
        ("externl:python3 r.py", "\"external:python3 r.py\""),
    ] {
        let out = rastercheck(&dir, &["run", "cases", "-r", typed]);
        let t = text(&out);
        assert_eq!(out.status.code(), Some(2), "{typed}: {t}");
        let line = error_line(&t);
        assert!(
            line.contains(&format!("did you mean {meant}?")),
            "{typed}: {t}"
        );
        assert!(line.contains("`rastercheck rasterizers` lists them"), "{t}");
        assert!(!line.contains("dda-f64"), "the whole list again: {t}");
    }
    // Nothing near: no suggestion, only where the names are.
    let out = rastercheck(&dir, &["run", "cases", "-r", "qqqqqqqqqqqq"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(!t.contains("did you mean"), "{t}");
    assert!(t.contains("`rastercheck rasterizers` lists them"), "{t}");
    // The matrix reads the same names.
    let out = rastercheck(&dir, &["matrix", "cases", "-r", "producton"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(t.contains("did you mean \"production\"?"), "{t}");
}

#[test]
fn a_mistyped_family_gets_a_suggestion() {
    let dir = workspace("family-typo", &[("cases/triangles/a.json", SINGLE)]);
    let out = rastercheck(&dir, &["run", "cases", "--family", "triangls"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(3), "{t}");
    assert!(
        t.contains("no case is of family \"triangls\"; did you mean \"triangles\"?"),
        "{t}"
    );
    let out = rastercheck(&dir, &["fuzz", "--family", "triangls", "-r", "production"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(t.contains("did you mean \"triangles\"?"), "{t}");
}

#[test]
fn rasterizers_lists_each_name_with_its_kind_and_description() {
    let dir = workspace("list", &[]);
    let out = rastercheck(&dir, &["rasterizers"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    for name in rastercheck::registry::names() {
        assert!(
            t.lines().any(|l| l.split_whitespace().next() == Some(name)),
            "{name} missing from {t}"
        );
    }
    assert!(t.contains("foil-any-coverage"), "{t}");
    assert!(
        t.contains("exact reference: the exact reference rasterizer"),
        "{t}"
    );
    assert!(t.contains("mutant: "), "{t}");
    for form in [
        "external:PROGRAM",
        "external-persistent:PROGRAM",
        "NAME=external-persistent:PROGRAM",
    ] {
        assert!(t.contains(form), "{form} missing from {t}");
    }
}

#[test]
fn a_report_flag_naming_a_file_is_an_error_naming_the_flag() {
    let dir = workspace(
        "report-file",
        &[("cases/a.json", SINGLE), ("taken", "not a folder")],
    );
    for target in ["taken", "taken/inside"] {
        let out = rastercheck(&dir, &["run", "cases", "--report", target]);
        let t = text(&out);
        assert_eq!(out.status.code(), Some(2), "{t}");
        assert!(
            t.contains(&format!(
                "error: --report {target}: taken is a file, not a folder"
            )),
            "{t}"
        );
        assert_no_panic(&out);
    }
}

#[test]
fn show_labels_a_foils_failure_foil_as_run_does() {
    let dir = workspace("show-foil", &[("cases/pair.json", TIE_PAIR)]);
    let foil = "foil-any-coverage";
    let out = rastercheck(&dir, &["run", "cases", "-r", foil]);
    let run = text(&out);
    assert!(run.contains(&format!("FOIL  pair  {foil}")), "{run}");
    let shown = rastercheck(
        &dir,
        &["show", "cases/pair.json", "--out", "pictures", "-r", foil],
    );
    let t = text(&shown);
    assert!(t.contains(&format!("FOIL {foil}:")), "{t}");
    assert!(!t.contains("FAIL"), "{t}");
}
