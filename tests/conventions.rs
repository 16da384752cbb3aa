//! Fill rules a rasterizer cannot choose (SPEC.md §3.1): a case under
//! another rule is judged against the reference drawn under the
//! rasterizer's own, and every report says so, apart from the verdicts.
//! Through the binary, with a real program (`tests/clients/area8.py`, exact
//! point sampling) that follows one rule whatever the case states and
//! declares it in its hello's `conventions`.
//!
//! - Following bottom-right and declaring it, it passes every triangle
//!   case, and the ones stated under another rule are named as judged
//!   under its own.
//! - Declaring a rule it does not follow is caught: the cases are judged
//!   under the declared rule, and its ties fall the other way.

mod common;

use std::path::PathBuf;

use common::cli::{case_entry, rastercheck, read_json, scratch, text};
use serde_json::Value;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the client with `flags` over `cases/triangles`; the report, and
/// what was printed.
fn run(tag: &str, flags: &str) -> (Value, String) {
    let dir = scratch(&format!("conventions-{tag}"));
    let client = root().join("tests/clients/area8.py");
    let spec = format!(
        "own=external-persistent:python3 {} {flags}",
        client.display()
    );
    let report = dir.join("report");
    let report_arg = report.display().to_string();
    let out = rastercheck(
        &root(),
        &[
            "run",
            "cases/triangles",
            "-r",
            &spec,
            "--report",
            &report_arg,
        ],
    );
    (read_json(&report.join("report.json")), text(&out))
}

fn summary(printed: &str) -> &str {
    printed
        .lines()
        .find(|l| l.starts_with("own:"))
        .unwrap_or_else(|| panic!("no summary line in:\n{printed}"))
}

#[test]
fn a_declared_fill_rule_is_judged_and_named_apart() {
    let (report, printed) = run("declared", "--rule bottom-right");
    assert_eq!(
        summary(&printed),
        "own: 77 passed, 0 failed, 0 unsupported, 0 errors; 75 judged under its own conventions \
         instead of the case's, each line naming which (SPEC.md §3, §16)",
        "{printed}"
    );
    let mut judged = 0;
    for case in report["cases"].as_array().unwrap() {
        let stated = case["rules"]["fill_rule"].as_str().unwrap();
        let result = &case["results"][0];
        match stated {
            "bottom-right" => assert!(result.get("judged_fill_rule").is_none(), "{case}"),
            _ => {
                assert_eq!(result["judged_fill_rule"], "bottom-right", "{}", case["id"]);
                judged += 1;
            }
        }
    }
    assert_eq!(judged, 75);
    assert_eq!(report["totals"]["verdicts"][0]["own_rule"], 75);
    assert!(
        printed.contains("(judged under its own bottom-right rule; the case states top-left)"),
        "{printed}"
    );
}

#[test]
fn a_rule_declared_but_not_followed_is_caught() {
    for (tag, flags) in [
        (
            "draws-bottom-right",
            "--rule bottom-right --declare top-left",
        ),
        ("draws-top-left", "--rule top-left --declare bottom-right"),
    ] {
        let (report, printed) = run(tag, flags);
        assert!(
            summary(&printed).starts_with("own: 16 passed, 61 failed,"),
            "{flags}: {printed}"
        );
        // The shared-edge cases with samples on their shared edges, whose
        // ties the rule decides, fail (`shared_edge_fractions_offgrid` has
        // none on it).
        for case in report["cases"].as_array().unwrap() {
            let id = case["id"].as_str().unwrap();
            if id.starts_with("triangles/shared_edge_") && !id.ends_with("_offgrid") {
                assert_eq!(case["results"][0]["verdict"], "fail", "{flags}: {id}");
            }
        }
    }
}

#[test]
fn an_unknown_convention_is_an_error_naming_its_path() {
    let dir = scratch("conventions-bad-hello");
    let program = dir.join("bad_hello.py");
    std::fs::write(
        &program,
        "import json, sys\n\
         print(json.dumps({'hello': {'protocol': 2, 'conventions': {'fill_rule': 'sideways'}}}), flush=True)\n\
         for line in sys.stdin:\n    pass\n",
    )
    .unwrap();
    let spec = format!("bad=external-persistent:python3 {}", program.display());
    let case = root().join("cases/triangles/shared_edge_diagonal.json");
    let out = rastercheck(&dir, &["run", &case.display().to_string(), "-r", &spec]);
    let printed = text(&out);
    // Refused before any case: bad usage (SPEC.md §12.7).
    assert_eq!(out.status.code(), Some(2), "{printed}");
    assert!(
        printed.contains("$.hello.conventions.fill_rule is \"sideways\"; known: top-left"),
        "{printed}"
    );
}

/// Judged under `all-edges` (here a profile's, SPEC.md §13), a polygon case
/// cannot be judged at all: the rule is not defined for polygons (§14.1).
/// It is unsupported with that reason, never judged under another rule;
/// its triangle cases are judged under all-edges, and named so.
#[test]
fn polygons_under_an_all_edges_rule_are_unsupported_not_judged_otherwise() {
    let dir = scratch("conventions-all-edges");
    let profile = dir.join("profile.json");
    std::fs::write(
        &profile,
        r#"{"schema": "rastercheck-profile/1", "rasterizer": "js", "fill_rule": "all-edges"}"#,
    )
    .unwrap();
    let script = root().join("examples/js/rasterizer.js");
    let spec = format!("js=external-persistent:node {}", script.display());
    let report = dir.join("report");
    let out = rastercheck(
        &root(),
        &[
            "run",
            "cases/polygons/concave_arrow.json",
            "cases/triangles/shared_edge_diagonal.json",
            "-r",
            &spec,
            "--profile",
            &profile.display().to_string(),
            "--report",
            &report.display().to_string(),
        ],
    );
    let printed = text(&out);
    let report = read_json(&report.join("report.json"));
    let result = |id: &str| {
        case_entry(&report, id)
            .map(|c| c["results"][0].clone())
            .unwrap_or_else(|| panic!("{id}: {printed}"))
    };
    let polygon = result("polygons/concave_arrow");
    assert_eq!(polygon["verdict"], "unsupported", "{printed}");
    assert!(
        polygon["reasons"][0]
            .as_str()
            .unwrap()
            .contains("all-edges is not defined for polygons"),
        "{polygon}"
    );
    let triangles = result("triangles/shared_edge_diagonal");
    assert_eq!(triangles["judged_fill_rule"], "all-edges", "{triangles}");
}

/// `fuzz --profile` (SPEC.md §13) judges the rasterizer under the
/// profile's fill rule, and the cases it writes state that rule, so that a
/// plain `run` reproduces them. The flipped-ties mutant profiles as
/// bottom-right on probe's meshes; fuzzed under that rule it is still
/// caught, on a lone triangle whose sample lies on its right edge, which
/// bottom-right gives it and the mutant leaves out.
#[test]
fn fuzz_with_a_profile_judges_under_its_rule_and_writes_cases_stating_it() {
    let dir = scratch("conventions-fuzz-profile");
    let profile = dir.join("flipped.json");
    let out = rastercheck(
        &dir,
        &[
            "probe",
            "-r",
            "mutant:flipped-ties",
            "--out",
            &profile.display().to_string(),
        ],
    );
    assert!(out.status.success(), "{}", text(&out));
    assert_eq!(read_json(&profile)["fill_rule"], "bottom-right");
    let found = dir.join("found");
    let args = [
        "fuzz",
        "-r",
        "mutant:flipped-ties",
        "--family",
        "triangles",
        "--seed",
        "7",
        "--cases",
        "200",
        "--profile",
        &profile.display().to_string(),
        "--out",
        &found.display().to_string(),
    ];
    let out = rastercheck(&dir, &args);
    let printed = text(&out);
    assert_eq!(out.status.code(), Some(1), "{printed}");
    let written: Vec<_> = std::fs::read_dir(&found)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(written.len(), 1, "{printed}");
    let case = read_json(&written[0]);
    assert_eq!(case["rules"]["fill_rule"], "bottom-right", "{case}");
    assert!(
        case["description"].as_str().unwrap().contains("--profile"),
        "{case}"
    );
    let out = rastercheck(
        &dir,
        &[
            "run",
            &written[0].display().to_string(),
            "-r",
            "mutant:flipped-ties",
            "-r",
            "production",
        ],
    );
    let printed = text(&out);
    assert!(
        printed.contains("mutant:flipped-ties: 0 passed, 1 failed"),
        "{printed}"
    );
    assert!(
        printed.contains("production: 1 passed, 0 failed"),
        "{printed}"
    );

    // A profile of another rasterizer is bad usage.
    let out = rastercheck(
        &dir,
        &[
            "fuzz",
            "-r",
            "production",
            "--cases",
            "1",
            "--profile",
            &profile.display().to_string(),
        ],
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("is a profile of mutant:flipped-ties, not of production"));
}

/// Production declaring one fill rule whatever a case states, as a driver
/// does, and drawing under it (`follows`) or under the case's own (a
/// rasterizer whose declaration is wrong).
struct Declares {
    rule: rastercheck::scene::FillRule,
    follows: bool,
}

impl rastercheck::rasterizer::Rasterizer for Declares {
    fn name(&self) -> &str {
        "declares"
    }
    fn capabilities(&self) -> rastercheck::rasterizer::Capabilities {
        rastercheck::production::Production.capabilities()
    }
    fn rasterize(
        &self,
        scene: &rastercheck::scene::Scene,
        plan: &rastercheck::plan::Plan,
    ) -> Result<rastercheck::frame::Frame, rastercheck::rasterizer::RasterError> {
        let drawn = if self.follows {
            scene.with_fill_rule(self.rule)
        } else {
            scene.clone()
        };
        rastercheck::production::Production.rasterize(&drawn, plan)
    }
    fn fixed_fill_rule(&self) -> Option<rastercheck::scene::FillRule> {
        Some(self.rule)
    }
}

/// `expect.time_coverage` pins, like `samples_covered`, describe the
/// case's own rule: a moving case judged under a rasterizer's own rule is
/// held to the reference under that rule, not to pins the rule breaks.
/// (Before, every driver failed one of `motion/ride_top_edge_*` on the
/// pins alone: "the case pins 0".) A rasterizer that does not follow the
/// rule it declares still fails.
#[test]
fn time_coverage_pins_follow_the_case_not_a_declared_rule() {
    use rastercheck::harness::judge::{run_candidate, Verdict};
    use rastercheck::harness::{discover, load, oracle};
    use rastercheck::scene::{FillRule, Limits};
    for (id, rule) in [
        ("motion/ride_top_edge_bottom_right", FillRule::TopLeft),
        ("motion/ride_top_edge_top_left", FillRule::BottomRight),
    ] {
        let file = discover::case_file(&root().join("cases").join(format!("{id}.json")));
        let scene = load::load(&file, &Limits::default()).unwrap();
        let reference = oracle::run_reference(&scene);
        let run = run_candidate(
            &scene,
            &reference,
            &Declares {
                rule,
                follows: true,
            },
        );
        assert_eq!(run.verdict, Verdict::Pass, "{id} under its own {rule}");
        assert_eq!(run.judged.fill_rule, Some(rule));
        let run = run_candidate(
            &scene,
            &reference,
            &Declares {
                rule,
                follows: false,
            },
        );
        assert!(
            matches!(run.verdict, Verdict::Fail(_)),
            "{id}: drawn under the case's rule while declaring {rule}: {:?}",
            run.verdict
        );
    }
}
