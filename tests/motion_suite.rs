//! Moving scenes through the real oracle (`reference::motion`) and the
//! binary: the oracle reproduces the sliding squares' hand-computed time
//! coverage exactly, the case pins hold, the motion mutants fail and an
//! honest sampler passes, and `bless`, `run --report` and `baseline` work
//! on a moving case.
//!
//! These tests need the certified time-coverage oracle: while it is a stub
//! they fail (the suite reports "the time-coverage oracle failed"), as
//! they should.

mod sliding;

mod common;

use common::{rastercheck, text};
use std::path::{Path, PathBuf};

use dashu_ratio::RBig;

use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::production::mutants::{Mutant, Mutation};
use rastercheck::reference::motion;
use rastercheck::scene::Scene;
use sliding::{Given, Slide, ONE};

/// Sliding squares of every kind the hand computation covers: integer and
/// non-stratum-aligned speeds, leftwards, antialiased, part of the shutter.
fn slides() -> Vec<Slide> {
    vec![
        Slide::new("slide"),
        Slide {
            dx: 7,
            ..Slide::new("slide_7")
        },
        Slide {
            dx: -5,
            x: [9, 13],
            ..Slide::new("slide_left")
        },
        Slide {
            antialias: Some(4),
            ..Slide::new("slide_aa4")
        },
        Slide {
            shutter: [ONE / 4, 3 * ONE / 4],
            dx: 6,
            ..Slide::new("slide_part")
        },
    ]
}

#[test]
fn the_oracle_reproduces_the_hand_computed_time_coverage_exactly() {
    for slide in slides() {
        let s = slide.scene();
        let plan = Plan::for_scene(&s);
        let certified = motion::time_coverage(&s, &plan);
        let expected = slide.exact(&plan);
        assert_eq!(certified.len(), expected.len(), "{}", slide.name);
        for (p, (got, want)) in certified.iter().zip(&expected).enumerate() {
            // Pure translation: every root is rational, so the bound is 0.
            assert_eq!(got.bound, RBig::ZERO, "{} pixel {p}", slide.name);
            assert_eq!(got.value, want.value, "{} pixel {p}", slide.name);
        }
        let r = oracle::run_reference(&s);
        let check = r.time.as_ref().unwrap().as_ref().expect("the oracle ran");
        assert!(check.broken_promises.is_empty());
        assert_eq!(r.frame.time, Some(slide.exact_f64(&plan)));
    }
}

#[test]
fn pins_hold_on_the_oracle_and_a_wrong_pin_is_caught() {
    let pinned = |value: &str| Slide {
        expect: format!(
            r#""time_coverage": [{{"pixel": [5, 1], "value": {value}}}, {{"pixel": [0, 0], "value": 0}}]"#
        ),
        ..Slide::new("slide")
    };
    let r = oracle::run_reference(&pinned("0.4375").scene());
    let check = r.time.as_ref().unwrap().as_ref().expect("the oracle ran");
    assert!(
        check.broken_promises.is_empty(),
        "{:?}",
        check.broken_promises
    );
    let r = oracle::run_reference(&pinned("0.4376").scene());
    let check = r.time.as_ref().unwrap().as_ref().expect("the oracle ran");
    assert_eq!(
        check.broken_promises.len(),
        1,
        "{:?}",
        check.broken_promises
    );
}

#[test]
fn with_the_oracle_the_motion_mutants_fail_and_an_honest_sampler_passes() {
    for slide in slides() {
        let s = slide.scene();
        let r = oracle::run_reference(&s);
        let sampler = Given("sampler", |s: &Scene, p: &Plan| slide.sampled(s, p));
        let run = judge::run_candidate(&s, &r, &sampler);
        assert_eq!(
            run.verdict,
            Verdict::Pass,
            "{}: {}",
            slide.name,
            judge::describe(&run)
        );
        let run = judge::run_candidate(&s, &r, &rastercheck::reference::Reference);
        assert_eq!(
            run.verdict,
            Verdict::Pass,
            "{}: {}",
            slide.name,
            judge::describe(&run)
        );
        for mutation in [Mutation::MotionAtOpen, Mutation::MotionHalfShutter] {
            let run = judge::run_candidate(&s, &r, &Mutant(mutation));
            match &run.verdict {
                Verdict::Fail(reasons) => assert!(
                    reasons.iter().all(|m| m.starts_with("time: ")),
                    "{} {}: {reasons:?}",
                    slide.name,
                    mutation.name()
                ),
                other => panic!("{} {}: {other:?}", slide.name, mutation.name()),
            }
        }
    }
}

fn workspace(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("motion-suite-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("cases/motion")).unwrap();
    for slide in [
        Slide::new("slide"),
        Slide {
            antialias: Some(4),
            dx: 7,
            ..Slide::new("slide_aa4")
        },
    ] {
        std::fs::write(
            dir.join(format!("cases/motion/{}.json", slide.name)),
            slide.json(),
        )
        .unwrap();
    }
    dir
}

#[test]
fn bless_run_and_report_a_moving_case() {
    let dir = workspace("cli");
    let out = rastercheck(&dir, &["bless", "cases"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let golden =
        exr::prelude::read_all_flat_layers_from_file(dir.join("reference/motion/slide.exr"))
            .expect("a golden file");
    assert_eq!(
        golden.layer_data[0]
            .attributes
            .layer_name
            .as_ref()
            .map(|n| n.to_string()),
        Some("time".to_owned())
    );
    let out = rastercheck(
        &dir,
        &[
            "run",
            "cases",
            "-r",
            "reference",
            "-r",
            "mutant:motion-at-open",
            "-r",
            "mutant:motion-half-shutter",
            "--report",
            "report",
        ],
    );
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(t.contains("golden files: 2 match, 0 differ"), "{t}");
    assert!(
        t.lines().any(|l| l.starts_with("FAIL")
            && l.split_whitespace().nth(1) == Some("motion/slide")
            && l.contains("mutant:motion-at-open")),
        "{t}"
    );
    assert!(t.contains("reference: 2 passed"), "{t}");
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report/report.json")).unwrap())
            .unwrap();
    let case = &report["cases"][0];
    assert_eq!(case["rules"]["motion_blur"]["moving"], 2);
    assert_eq!(case["results"][0]["metrics"]["time"]["max_error"], 0.0);
    assert!(
        case["results"][1]["metrics"]["time"]["rms_moving"]
            .as_f64()
            .unwrap()
            > 0.1875
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_baseline_of_a_moving_case_catches_a_worse_time_error() {
    let dir = workspace("baseline");
    let out = rastercheck(
        &dir,
        &["baseline", "save", "base.json", "cases", "-r", "reference"],
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let base: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("base.json")).unwrap()).unwrap();
    let metrics = &base["results"][0]["metrics"];
    assert_eq!(metrics["time.rms_moving"], 0, "{base}");
    let out = rastercheck(
        &dir,
        &[
            "baseline",
            "check",
            "base.json",
            "-r",
            "mutant:motion-at-open=reference",
        ],
    );
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(
        t.lines()
            .any(|l| l.starts_with("REGRESSION") && l.contains("time.rms_moving")),
        "{t}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
