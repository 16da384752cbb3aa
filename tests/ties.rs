//! A rasterizer with no tie rule (`fill_rule: "none"`, SPEC.md §3.1.1):
//! judged exactly off the ties, its tie samples counted apart; the
//! slope-dependent foil that needs it; and probe, which finds its ties
//! inconsistent and names the slopes.

mod common;

use std::path::Path;

use common::cli::{read_json, run_client, scratch, verdicts};
use common::{rastercheck, text};
use rastercheck::explore::probe::{self, Profile};
use rastercheck::registry;

const FOIL: &str = "foil-slope-ties";

fn cases(family: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("cases")
        .join(family)
        .display()
        .to_string()
}

/// `run` over the triangle and hard cases with the foil declared as `rule`
/// by a profile: the report, and what it printed.
fn run_declared(tag: &str, rule: &str) -> (serde_json::Value, String) {
    let dir = scratch(&format!("ties-{tag}"));
    let profile = dir.join("profile.json");
    std::fs::write(
        &profile,
        format!(r#"{{"schema": "rastercheck-profile/1", "rasterizer": "{FOIL}", "fill_rule": "{rule}"}}"#),
    )
    .unwrap();
    let report = dir.join("report");
    let out = rastercheck(
        &dir,
        &[
            "run",
            &cases("triangles"),
            &cases("hard"),
            "-r",
            FOIL,
            "--profile",
            profile.to_str().unwrap(),
            "--report",
            report.to_str().unwrap(),
        ],
    );
    (read_json(&report.join("report.json")), text(&out))
}

#[test]
fn declared_none_the_slope_foil_passes_every_case_it_draws_with_its_ties_counted() {
    let (report, shown) = run_declared("none", "none");
    let all = verdicts(&report);
    let judged: Vec<_> = all.iter().filter(|(_, v, _)| v != "unsupported").collect();
    assert!(judged.len() > 100, "{} judged", judged.len());
    let wrong: Vec<_> = judged.iter().filter(|(_, v, _)| v != "pass").collect();
    assert!(wrong.is_empty(), "{wrong:?}");
    // Its ties are counted apart, in report.json and on the console.
    let results: Vec<&serde_json::Value> = report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| &c["results"][0])
        .filter(|r| r["verdict"] == "pass")
        .collect();
    assert!(results.iter().all(|r| r["judged_fill_rule"] == "none"));
    let other_side: u64 = results
        .iter()
        .map(|r| r["ties"]["other_side"].as_u64().unwrap())
        .sum();
    let ties: u64 = results
        .iter()
        .map(|r| r["ties"]["tie_samples"].as_u64().unwrap())
        .sum();
    assert!(
        other_side > 0 && ties >= other_side,
        "{other_side} of {ties}"
    );
    assert!(shown.contains("judged off the ties: "), "{shown}");
}

#[test]
fn declared_bottom_right_the_slope_foil_fails_at_ties_and_they_are_named() {
    let (report, _) = run_declared("bottom-right", "bottom-right");
    let all = verdicts(&report);
    let steep = all
        .iter()
        .find(|(id, _, _)| id == "triangles/shared_edge_steep")
        .expect("the case ran");
    assert_eq!(steep.1, "foil", "{steep:?}");
    assert!(
        steep
            .2
            .contains("lie exactly on an edge; it differs only at ties"),
        "{steep:?}"
    );
    // Every departure is at ties alone: off them it is production.
    for (id, verdict, reasons) in all.iter().filter(|(_, v, _)| v == "foil") {
        assert!(
            reasons.contains("it differs only at ties"),
            "{id} {verdict}: {reasons}"
        );
    }
}

fn probe_of(name: &str) -> Profile {
    let r = registry::by_name(name).unwrap_or_else(|| panic!("no rasterizer {name}"));
    probe::probe(r.as_ref()).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn probe_finds_the_slope_foil_inconsistent_and_names_its_slopes() {
    let p = probe_of(FOIL);
    assert_eq!(p.fill_rule.as_deref(), Some("bottom-right"));
    assert!(!p.fill_rule_consistent);
    assert_eq!(p.tie_verdict, "inconsistent");
    let mut slopes: Vec<&str> = p.tie_slopes.iter().map(|s| s.slope.as_str()).collect();
    slopes.sort_unstable();
    assert_eq!(slopes, ["-1/3", "-2/3", "-3", "3", "3/2"]);
    assert!(p
        .tie_slopes
        .iter()
        .all(|s| s.follows.contains(&"top-left".to_owned())));
    assert!(
        p.ties_measured_on.contains("over 16 slopes"),
        "{}",
        p.ties_measured_on
    );
    assert!(p.describe().contains("inconsistent"), "{}", p.describe());
}

#[test]
fn probe_still_finds_one_rule_where_there_is_one() {
    for (name, rule) in [
        ("production", "top-left"),
        ("mutant:flipped-ties", "bottom-right"),
    ] {
        let p = probe_of(name);
        assert_eq!(p.fill_rule.as_deref(), Some(rule), "{name}");
        assert!(p.fill_rule_consistent, "{name}");
        assert_eq!(p.tie_verdict, "consistent", "{name}");
        assert!(p.tie_slopes.is_empty(), "{name}");
        assert!(p.ties_measured_on.contains("over 16 slopes"), "{name}");
    }
}

#[test]
fn a_probes_inconsistent_profile_judges_off_the_ties() {
    let dir = scratch("ties-probed");
    let profile = dir.join("probed.json");
    let out = rastercheck(
        &dir,
        &["probe", "-r", FOIL, "--out", profile.to_str().unwrap()],
    );
    assert!(out.status.success(), "{}", text(&out));
    let written = read_json(&profile);
    assert_eq!(written["tie_verdict"], "inconsistent");
    let steep =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/triangles/shared_edge_steep.json");
    let out = rastercheck(
        &dir,
        &[
            "run",
            steep.to_str().unwrap(),
            "-r",
            FOIL,
            "--profile",
            profile.to_str().unwrap(),
        ],
    );
    let shown = text(&out);
    assert_eq!(out.status.code(), Some(0), "{shown}");
    assert!(
        shown.contains("PASS") && shown.contains("judged off the ties: "),
        "{shown}"
    );
}

#[test]
fn a_program_declaring_none_in_its_hello_is_judged_off_the_ties() {
    // It follows bottom-right, and says only that it has no tie rule.
    let (report, shown) = run_client(
        "ties-hello",
        "area8.py",
        "lib",
        "--rule bottom-right --declare none",
        &[
            "cases/triangles/shared_edge_steep.json",
            "cases/triangles/shared_edge_vertical.json",
        ],
    );
    for (id, verdict, reasons) in verdicts(&report) {
        assert_eq!(verdict, "pass", "{id}: {reasons}\n{shown}");
    }
    let first = &report["cases"][0]["results"][0];
    assert_eq!(first["judged_fill_rule"], "none", "{shown}");
    assert!(
        first["ties"]["tie_samples"].as_u64().unwrap() > 0,
        "{shown}"
    );
    assert!(shown.contains("judged off the ties: "), "{shown}");
}
