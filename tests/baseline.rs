//! `rastercheck baseline save|check`, run as a user runs it: a foil's real
//! errors recorded and held, regressions injected and caught, a worse
//! rasterizer held to production's baseline, bad baseline files refused.

mod common;

use std::path::{Path, PathBuf};
use std::process::Output;

use common::cli::{rastercheck as rastercheck_in, read_json as read, text};
use serde_json::Value;

/// Runs in the repository, on its bundled cases.
fn rastercheck(args: &[&str]) -> Output {
    rastercheck_in(Path::new(env!("CARGO_MANIFEST_DIR")), args)
}

fn code(out: &Output) -> i32 {
    out.status.code().expect("exited")
}

/// A fresh scratch folder.
fn scratch(name: &str) -> PathBuf {
    common::cli::scratch(&format!("baseline-{name}"))
}

fn write(path: &Path, value: &Value) {
    std::fs::write(path, serde_json::to_string_pretty(value).unwrap()).unwrap();
}

/// The first result of `rasterizer` whose `metric` is above zero, as
/// (index in `results`, case id, value).
fn first_nonzero(baseline: &Value, rasterizer: &str, metric: &str) -> (usize, String, f64) {
    baseline["results"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
        .find_map(|(k, r)| {
            let v = r["metrics"][metric].as_f64()?;
            (r["rasterizer"] == rasterizer && v > 0.0)
                .then(|| (k, r["case"].as_str().unwrap().to_owned(), v))
        })
        .unwrap_or_else(|| panic!("no {rasterizer} result with {metric} > 0"))
}

/// Saves a baseline of the DDA foil on the line cases.
fn save_dda(dir: &Path) -> PathBuf {
    let file = dir.join("dda.json");
    let out = rastercheck(&[
        "baseline",
        "save",
        file.to_str().unwrap(),
        "cases/lines",
        "-r",
        "dda-f32",
    ]);
    assert_eq!(code(&out), 0, "{}", text(&out));
    file
}

#[test]
fn a_foil_is_recorded_and_holds_to_its_own_baseline() {
    let dir = scratch("foil");
    let file = save_dda(&dir);
    let b = read(&file);
    assert_eq!(b["schema"], "rastercheck-baseline/1");
    assert_eq!(b["rasterizers"], serde_json::json!(["dda-f32"]));
    assert_eq!(b["tool"]["name"], "rastercheck");
    assert!(b["command"].as_array().unwrap().iter().any(|a| a == "save"));
    assert_eq!(b["tolerance"]["counts"]["relative"], 0.0);
    assert_eq!(b["tolerance"]["errors"]["relative"], 0.01);
    // The foil has real departures, and they are recorded.
    let (_, _, mismatched) = first_nonzero(&b, "dda-f32", "coverage.mismatched");
    assert!(mismatched >= 1.0);
    let results = b["results"].as_array().unwrap();
    assert!(results.iter().any(|r| r["verdict"] == "foil"));
    let ids: Vec<&str> = results
        .iter()
        .map(|r| r["case"].as_str().unwrap())
        .collect();
    let mut sorted = ids.clone();
    sorted.sort();
    assert_eq!(ids, sorted, "results are sorted by case");

    let out = rastercheck(&["baseline", "check", file.to_str().unwrap()]);
    let t = text(&out);
    assert_eq!(code(&out), 0, "{t}");
    assert!(
        t.contains("baseline: 0 regressions, 0 improvements,"),
        "{t}"
    );
    assert!(!t.contains("REGRESSION") && !t.contains("IMPROVED"), "{t}");
}

#[test]
fn saving_is_deterministic_whatever_the_thread_count() {
    let dir = scratch("determinism");
    let (a, b) = (dir.join("a.json"), dir.join("b.json"));
    for (file, threads) in [(&a, "1"), (&b, "4")] {
        let out = rastercheck(&[
            "baseline",
            "save",
            file.to_str().unwrap(),
            "cases/lines",
            "-r",
            "dda-f32",
            "-r",
            "production",
            "--threads",
            threads,
        ]);
        assert_eq!(code(&out), 0, "{}", text(&out));
    }
    let (mut a, mut b) = (read(&a), read(&b));
    a["command"] = Value::Null;
    b["command"] = Value::Null;
    assert_eq!(a, b);
}

/// A baseline made better than reality, checked.
struct Zeroed {
    file: PathBuf,
    baseline: Value,
    case: String,
    value: f64,
    text: String,
}

/// Saves the DDA foil's baseline in scratch folder `name`, records its
/// first nonzero `metric` as 0 (better than reality) and checks it, which
/// fails (exit 1).
fn check_zeroed(name: &str, metric: &str) -> Zeroed {
    let dir = scratch(name);
    let file = save_dda(&dir);
    let mut b = read(&file);
    let (k, case, value) = first_nonzero(&b, "dda-f32", metric);
    b["results"][k]["metrics"][metric] = 0.into();
    write(&file, &b);

    let out = rastercheck(&["baseline", "check", file.to_str().unwrap()]);
    let t = text(&out);
    assert_eq!(code(&out), 1, "{t}");
    Zeroed {
        file,
        baseline: b,
        case,
        value,
        text: t,
    }
}

#[test]
fn a_count_made_better_than_reality_is_caught_as_a_regression() {
    let Zeroed {
        case,
        value,
        text: t,
        ..
    } = check_zeroed("count", "coverage.mismatched");
    let expected = format!("REGRESSION  {case}  dda-f32  coverage.mismatched  0 → {value}");
    assert!(t.contains(&expected), "{expected:?} in\n{t}");
    assert!(
        t.contains("baseline: 1 regressions, 0 improvements,"),
        "{t}"
    );
}

#[test]
fn an_interpolation_error_made_better_than_reality_is_caught() {
    let Zeroed {
        file,
        baseline: mut b,
        case,
        text: t,
        ..
    } = check_zeroed("error", "depth.max_abs");
    assert!(
        t.contains(&format!("REGRESSION  {case}  dda-f32  depth.max_abs  0 → ")),
        "{t}"
    );

    // The file states its tolerance, and a looser one lets it through.
    b["tolerance"]["errors"]["absolute"] = 1.0.into();
    write(&file, &b);
    let out = rastercheck(&["baseline", "check", file.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", text(&out));
}

#[test]
fn improvements_are_reported_and_do_not_fail() {
    let dir = scratch("improvement");
    let file = save_dda(&dir);
    let mut b = read(&file);
    let (k, case, value) = first_nonzero(&b, "dda-f32", "coverage.missing");
    let worse = value + 100.0;
    b["results"][k]["metrics"]["coverage.missing"] = (worse as u64).into();
    write(&file, &b);

    let out = rastercheck(&["baseline", "check", file.to_str().unwrap()]);
    let t = text(&out);
    assert_eq!(code(&out), 0, "{t}");
    assert!(
        t.contains(&format!(
            "IMPROVED    {case}  dda-f32  coverage.missing  {worse} → {value}"
        )),
        "{t}"
    );
    assert!(
        t.contains("baseline: 0 regressions, 1 improvements,"),
        "{t}"
    );
}

#[test]
fn a_worse_rasterizer_held_to_productions_baseline_regresses() {
    let dir = scratch("mutant");
    let file = dir.join("production.json");
    let f = file.to_str().unwrap();
    let out = rastercheck(&["baseline", "save", f, "cases/triangles"]);
    assert_eq!(code(&out), 0, "{}", text(&out));
    assert_eq!(
        read(&file)["rasterizers"],
        serde_json::json!(["production"])
    );

    let out = rastercheck(&["baseline", "check", f]);
    assert_eq!(code(&out), 0, "{}", text(&out));

    let out = rastercheck(&[
        "baseline",
        "check",
        f,
        "-r",
        "mutant:flipped-ties=production",
    ]);
    let t = text(&out);
    assert_eq!(code(&out), 1, "{t}");
    assert!(
        t.contains("mutant:flipped-ties (as production)  verdict  pass → fail"),
        "{t}"
    );
    assert!(t.contains("coverage.wrong_owner  0 → "), "{t}");

    // Without the mapping, a rasterizer the baseline does not record is
    // bad usage, not a silent pass.
    let out = rastercheck(&["baseline", "check", f, "-r", "mutant:flipped-ties"]);
    let t = text(&out);
    assert_eq!(code(&out), 2, "{t}");
    assert!(
        t.contains(f) && t.contains("-r mutant:flipped-ties=production"),
        "{t}"
    );
}

const SINGLE: &str = r#"{"name": "single", "canvas": {"width": 4, "height": 4},
  "primitives": [{"triangle": [[0, 0], [4, 0], [0, 4]]}]}"#;

#[test]
fn missing_cases_regress_and_new_cases_are_listed() {
    let dir = scratch("missing");
    std::fs::create_dir_all(dir.join("cases/a")).unwrap();
    for name in ["one", "two"] {
        std::fs::write(dir.join(format!("cases/a/{name}.json")), SINGLE).unwrap();
    }
    let out = rastercheck_in(&dir, &["baseline", "save", "base.json", "cases"]);
    assert_eq!(code(&out), 0, "{}", text(&out));

    std::fs::remove_file(dir.join("cases/a/two.json")).unwrap();
    std::fs::write(dir.join("cases/a/three.json"), SINGLE).unwrap();
    let out = rastercheck_in(&dir, &["baseline", "check", "base.json"]);
    let t = text(&out);
    assert_eq!(code(&out), 1, "{t}");
    assert!(
        t.contains("REGRESSION  a/two  production  runs  pass → no longer runs"),
        "{t}"
    );
    assert!(
        t.contains("NEW         a/three  production  not in the baseline"),
        "{t}"
    );

    // A narrower selection leaves the rest of the baseline out of scope.
    let out = rastercheck_in(
        &dir,
        &["baseline", "check", "base.json", "--filter", "a/one"],
    );
    assert_eq!(code(&out), 0, "{}", text(&out));
}

#[test]
fn bad_baseline_files_exit_2_naming_the_file() {
    let dir = scratch("bad");
    let corrupt = dir.join("corrupt.json");
    std::fs::write(
        &corrupt,
        "{\"schema\": \"rastercheck-baseline/1\", \"results\": [",
    )
    .unwrap();
    let missing = dir.join("missing.json");
    let report = dir.join("report.json");
    std::fs::write(
        &report,
        r#"{"schema": "rastercheck-report/1", "cases": []}"#,
    )
    .unwrap();
    for file in [&corrupt, &missing, &report] {
        let out = rastercheck(&["baseline", "check", file.to_str().unwrap()]);
        let t = text(&out);
        assert_eq!(code(&out), 2, "{t}");
        assert!(t.contains(file.to_str().unwrap()), "{t}");
        assert!(!t.contains("panicked"), "{t}");
    }

    let file = save_dda(&dir);
    let mut b = read(&file);
    b["rasterizers"] = serde_json::json!(["dda-f16"]);
    for r in b["results"].as_array_mut().unwrap() {
        r["rasterizer"] = "dda-f16".into();
    }
    write(&file, &b);
    let out = rastercheck(&["baseline", "check", file.to_str().unwrap()]);
    let t = text(&out);
    assert_eq!(code(&out), 2, "{t}");
    assert!(
        t.contains(file.to_str().unwrap()) && t.contains("dda-f16"),
        "{t}"
    );

    let out = rastercheck(&[
        "baseline",
        "save",
        dir.join("x.json").to_str().unwrap(),
        "-r",
        "nonesuch",
    ]);
    assert_eq!(code(&out), 2, "{}", text(&out));
    assert!(!dir.join("x.json").exists());

    // A program held to a recorded name whose command cannot be split is
    // said as such, not as an unknown rasterizer.
    let file = save_dda(&dir);
    let out = rastercheck(&[
        "baseline",
        "check",
        file.to_str().unwrap(),
        "-r",
        "external:python3 'open=dda-f32",
    ]);
    let t = text(&out);
    assert_eq!(code(&out), 2, "{t}");
    assert!(t.contains("has an unterminated ' quote"), "{t}");
    assert!(!t.contains("unknown rasterizer"), "{t}");
}

/// An antialiased triangle whose resolved coverage has error at 16
/// samples; rounding it down to quarters makes the error larger.
const ANTIALIASED: &str = r#"{"name": "aa", "canvas": {"width": 12, "height": 9},
  "primitives": [{"triangle": [[0.5, 0.25], [11.75, 1.5], [2.25, 8.5]]}],
  "effects": {"antialias": {"samples": 16}},
  "expect": {"max_coverage_error": 0.5, "max_coverage_rms": 0.2}}"#;

#[test]
fn a_worse_antialiasing_error_regresses() {
    let dir = scratch("antialias");
    std::fs::create_dir_all(dir.join("cases/aa")).unwrap();
    std::fs::write(dir.join("cases/aa/triangle.json"), ANTIALIASED).unwrap();
    let out = rastercheck_in(&dir, &["baseline", "save", "base.json", "cases"]);
    assert_eq!(code(&out), 0, "{}", text(&out));
    let b = read(&dir.join("base.json"));
    let m = &b["results"][0]["metrics"];
    assert_eq!(b["results"][0]["verdict"], "pass", "{b}");
    let (max_error, rms_edge) = (
        m["antialias.max_error"].as_f64().unwrap(),
        m["antialias.rms_edge"].as_f64().unwrap(),
    );
    assert!(max_error > 0.0 && rms_edge > 0.0, "{m}");
    assert_eq!(m["antialias.piglit_violations"], 0);

    // The same method, its resolve rounded down to quarters.
    let out = rastercheck_in(
        &dir,
        &[
            "baseline",
            "check",
            "base.json",
            "-r",
            "mutant:coarse-resolve=production",
        ],
    );
    let t = text(&out);
    assert_eq!(code(&out), 1, "{t}");
    for metric in [
        "antialias.max_error",
        "antialias.rms_edge",
        "antialias.rms_all",
    ] {
        assert!(
            t.lines().any(|l| l.starts_with("REGRESSION")
                && l.contains("mutant:coarse-resolve (as production)")
                && l.contains(&format!("{metric}  "))),
            "{metric} in\n{t}"
        );
    }
    assert!(
        t.contains(&format!("antialias.max_error  {max_error:e} → ")),
        "{t}"
    );

    // An edge RMS recorded better than it is regresses too; within the
    // error tolerance (1%) it does not.
    let mut edited = b.clone();
    edited["results"][0]["metrics"]["antialias.rms_edge"] = (rms_edge / 1.02).into();
    write(&dir.join("base.json"), &edited);
    let out = rastercheck_in(&dir, &["baseline", "check", "base.json"]);
    let t = text(&out);
    assert_eq!(code(&out), 1, "{t}");
    assert!(
        t.contains("REGRESSION  aa/triangle  production  antialias.rms_edge"),
        "{t}"
    );
    edited["results"][0]["metrics"]["antialias.rms_edge"] = (rms_edge / 1.005).into();
    write(&dir.join("base.json"), &edited);
    let out = rastercheck_in(&dir, &["baseline", "check", "base.json"]);
    assert_eq!(code(&out), 0, "{}", text(&out));
}
