//! Memory: a case whose frames would not fit gets a limit verdict before
//! anything is allocated, and a run holds the frames of the cases in flight
//! only, never of the whole run (each case's are released once its report
//! files are written). Peak RSS is read from the kernel's accounting of the
//! rastercheck process itself (`wait4`).

use std::path::Path;

use crate::common::cli::{read_json, text, workspace};

/// A triangle over most of a `size`² canvas with depth and `attributes`
/// attributes per vertex, at `samples` samples per pixel.
fn big_case(name: &str, size: u32, samples: u32, attributes: usize) -> String {
    let values = |v: usize| {
        (0..attributes)
            .map(|k| (k + v).to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    let s = size - 1;
    let aa = if samples > 1 {
        format!(r#", "effects": {{"antialias": {{"samples": {samples}}}}}"#)
    } else {
        String::new()
    };
    format!(
        r#"{{"name": "{name}", "canvas": {{"width": {size}, "height": {size}}},
  "primitives": [{{"triangle": [
    {{"position": [1, 1], "z": 0.5, "attributes": [{}]}},
    {{"position": [{s}, 2], "z": 0.25, "attributes": [{}]}},
    {{"position": [3, {s}], "z": 0.75, "attributes": [{}]}}]}}]{aa}}}"#,
        values(0),
        values(1),
        values(2)
    )
}

const SMALL: &str = r#"{"name": "small", "canvas": {"width": 8, "height": 8},
  "primitives": [{"triangle": [[1, 1], [7, 2], [2, 7]]}]}"#;

/// The binary run in `dir`, its peak RSS held to `bound_mib`
/// (`crate::run_within`): its exit code and stdout + stderr.
fn run(dir: &Path, args: &[&str], bound_mib: f64) -> (Option<i32>, String) {
    let out = crate::run_within(dir, args, bound_mib);
    (out.status.code(), text(&out))
}

#[test]
fn a_case_whose_frames_would_not_fit_gets_a_limit_verdict() {
    // 4096² at 4 samples is 2^26 samples: within --max-samples and
    // --max-canvas-pixels, but with depth and 16 attributes each frame
    // takes 142 bytes a sample, about 9 GiB: three would be 27 GiB.
    let big = big_case("huge_frames", 4096, 4, 16);
    let dir = workspace(
        "memory-limit",
        &[("cases/a/huge.json", &big), ("cases/a/small.json", SMALL)],
    );
    // Nothing of the 27 GiB is allocated.
    let (code, log) = run(&dir, &["run", "cases", "--report", "report"], 200.0);
    assert_eq!(code, Some(2), "{log}");
    assert!(
        log.contains("over the limit of 4096 MiB per case (raise it with --max-case-memory)"),
        "{log}"
    );
    let report = read_json(&dir.join("report/report.json"));
    let cases = report["cases"].as_array().unwrap();
    let status = |id: &str| {
        let case = cases.iter().find(|c| c["id"] == id).unwrap();
        (
            case["status"].as_str().unwrap().to_owned(),
            case["results"][0]["verdict"].clone(),
        )
    };
    assert_eq!(status("a/huge").0, "limit-exceeded");
    assert_eq!(status("a/small"), ("ran".to_owned(), "pass".into()));
    assert_eq!(report["limits"]["max_case_memory"], 4u64 << 30);

    // The limit is a flag: a lower one catches a smaller case, and the
    // message names the flag.
    let (code, log) = run(
        &dir,
        &["run", "cases/a/small.json", "--max-case-memory", "100"],
        crate::RSS_BOUND_MIB,
    );
    assert_eq!(code, Some(2), "{log}");
    assert!(log.contains("--max-case-memory"), "{log}");

    // `bless` and `show` draw with the reference too, and check first.
    for args in [
        &["bless", "cases/a/huge.json"][..],
        &["show", "cases/a/huge.json", "--out", "shown"][..],
    ] {
        let (code, log) = run(&dir, args, 200.0);
        assert_eq!(code, Some(2), "{args:?}: {log}");
        assert!(log.contains("--max-case-memory"), "{args:?}: {log}");
    }
}

#[test]
fn a_run_holds_the_frames_of_the_cases_in_flight_only() {
    // Six cases of 1024² with depth and 8 attributes: each frame takes
    // 78 bytes a pixel, 78 MiB; the reference's and production's together
    // 156 MiB a case. A run that kept every case's frames to its end would
    // peak near 1 GiB; one case at a time stays near one case's worth.
    let cases: Vec<(String, String)> = (0..6)
        .map(|k| {
            (
                format!("cases/big/frame_{k}.json"),
                big_case(&format!("frame_{k}"), 1024, 1, 8),
            )
        })
        .collect();
    let files: Vec<(&str, &str)> = cases
        .iter()
        .map(|(p, c)| (p.as_str(), c.as_str()))
        .collect();
    let dir = workspace("memory-streaming", &files);
    // Frames kept past their case would go over the bound: 1064 MiB.
    let (code, log) = run(
        &dir,
        &["run", "cases", "--threads", "1", "--report", "report"],
        450.0,
    );
    // No golden files here: missing ones are reported, not failed.
    assert_eq!(code, Some(0), "{log}");
    let report = read_json(&dir.join("report/report.json"));
    assert_eq!(report["totals"]["verdicts"][0]["pass"], 6, "{log}");
}
