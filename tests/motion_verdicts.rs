//! Verdicts on scenes in which something moves (SPEC.md §15.4), without
//! the oracle: the sliding square's exact time coverage is computed by hand
//! (tests/sliding) and handed to the suite as the oracle's answer. Within
//! the bounds a candidate passes; beyond them it fails; a pin the oracle
//! breaks fails every candidate; a broken oracle is reported, never
//! crashed on; frames of the wrong shape are errors.

mod sliding;

use dashu_ratio::RBig;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::{CandidateRun, Verdict};
use rastercheck::harness::oracle::ReferenceRun;
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::reference::motion::Certified;
use rastercheck::scene::Scene;
use sliding::{Given, Slide};

fn reference(slide: &Slide) -> (Scene, ReferenceRun) {
    let s = slide.scene();
    let r = oracle::run_reference_with(&s, |_, plan| slide.exact(plan));
    (s, r)
}

/// A candidate that returns the exact values.
fn exact_candidate(slide: &Slide) -> Given<impl Fn(&Scene, &Plan) -> Frame + '_> {
    Given("exact", shifted(slide, |_, v| v))
}

/// A candidate that returns the exact values with `change` applied.
fn shifted(slide: &Slide, change: fn(usize, f64) -> f64) -> impl Fn(&Scene, &Plan) -> Frame + '_ {
    move |s: &Scene, plan: &Plan| {
        let time = slide
            .exact_f64(plan)
            .into_iter()
            .enumerate()
            .map(|(p, v)| change(p, v))
            .collect();
        Frame::time_only(s.canvas.width, s.canvas.height, time)
    }
}

fn reasons(run: &CandidateRun) -> Vec<String> {
    match &run.verdict {
        Verdict::Fail(reasons) => reasons.clone(),
        other => panic!("{} should have failed, got {other:?}", run.rasterizer),
    }
}

#[test]
fn the_exact_time_coverage_passes() {
    let slide = Slide::new("slide");
    let (s, r) = reference(&slide);
    let check = r.time.as_ref().unwrap().as_ref().unwrap();
    assert!(check.broken_promises.is_empty());
    assert_eq!(check.max_bound, 0.0);
    // Rows 1 to 4 move; rows 0 and 5 are empty, exactly.
    let moving = check.whole.iter().filter(|w| !**w).count();
    assert_eq!(moving, 4 * 12);
    assert!(r.interior.is_none() && r.areas.is_none());
    assert_eq!((r.frame.samples, r.frame.sample_count()), (0, 0));
    let run = judge::run_candidate(&s, &r, &Given("exact", shifted(&slide, |_, v| v)));
    assert_eq!(run.verdict, Verdict::Pass, "{}", judge::describe(&run));
    let t = run.metrics.as_ref().unwrap().time.clone().unwrap();
    assert_eq!((t.max_error, t.rms_moving, t.moving_pixels), (0.0, 0.0, 48));
    // The sample metrics have nothing to compare and stay quiet, with 4×
    // antialiasing too (no resolved coverage, no mask).
    let aa = Slide {
        antialias: Some(4),
        ..Slide::new("slide_aa4")
    };
    let (s, r) = reference(&aa);
    let run = judge::run_candidate(&s, &r, &exact_candidate(&aa));
    assert_eq!(run.verdict, Verdict::Pass, "{}", judge::describe(&run));
    let m = run.metrics.as_ref().unwrap();
    assert_eq!((m.coverage.samples, m.coverage.mismatched()), (0, 0));
    assert!(m.coverage.mask.is_empty() && m.channels.is_empty());
    assert!(m.antialias.is_none() && m.watertight.is_none() && m.lines.is_none());
    assert!(m.time.is_some());
    assert!(
        judge::describe(&run).starts_with("time coverage only · time max err 0.00e0"),
        "{}",
        judge::describe(&run)
    );
}

#[test]
fn bounds_pass_within_and_fail_beyond() {
    // Every moving pixel off by 0.1 (give or take rounding): within
    // bounds of 0.1001 (the default RMS bound is 0.1875), beyond 0.0999.
    let off = |_: usize, v: f64| if v.fract() != 0.0 { v + 0.1 } else { v };
    for (expect, pass) in [
        ("", true),
        (r#""max_time_rms": 0.1001"#, true),
        (r#""max_time_rms": 0.0999"#, false),
        (r#""max_time_error": 0.1001"#, true),
        (r#""max_time_error": 0.0999"#, false),
    ] {
        let slide = Slide {
            expect: expect.to_owned(),
            ..Slide::new("slide")
        };
        let (s, r) = reference(&slide);
        let run = judge::run_candidate(&s, &r, &Given("off", shifted(&slide, off)));
        let t = run.metrics.as_ref().unwrap().time.clone().unwrap();
        assert!((t.rms_moving - 0.1).abs() < 1e-15, "{t:?}");
        assert!((t.bias_moving - 0.1).abs() < 1e-15, "{t:?}");
        assert_eq!(t.moving_pixels, 48);
        if pass {
            assert_eq!(run.verdict, Verdict::Pass, "{expect}: {:?}", run.verdict);
        } else {
            let f = reasons(&run);
            assert_eq!(f.len(), 1, "{f:?}");
            assert!(f[0].starts_with("time: "), "{f:?}");
            // The first pixel off by the most: (2, 1), exact 1/16.
            assert!(
                f[0].contains("pixel (2, 1): candidate 0.162500, exact 0.062500"),
                "{f:?}"
            );
        }
    }
}

#[test]
fn invalid_values_fail_even_within_the_bounds() {
    let slide = Slide {
        expect: r#""max_time_rms": 1000"#.to_owned(),
        ..Slide::new("slide")
    };
    let (s, r) = reference(&slide);
    let run = judge::run_candidate(
        &s,
        &r,
        &Given(
            "negative",
            shifted(&slide, |p, v| if p == 20 { -1e-9 } else { v }),
        ),
    );
    let f = reasons(&run);
    assert_eq!(f.len(), 1, "{f:?}");
    assert!(f[0].contains("first at (4, 1)"), "{f:?}");
}

#[test]
fn pins_hold_within_the_certified_bound_plus_1e_12_and_fail_beyond() {
    // Pixel (5, 1): exactly 7/16 = 0.4375.
    let pinned = |value: &str| Slide {
        expect: format!(r#""time_coverage": [{{"pixel": [5, 1], "value": {value}}}]"#),
        ..Slide::new("slide")
    };
    for (value, holds) in [
        ("0.4375", true),
        ("\"7/16\"", true),
        ("0.437500000000001", true),
        ("0.4374999999990", true),
        ("0.4375000000011", false),
        ("0.4376", false),
    ] {
        let slide = pinned(value);
        let (s, r) = reference(&slide);
        let run = judge::run_candidate(&s, &r, &exact_candidate(&slide));
        if holds {
            assert_eq!(run.verdict, Verdict::Pass, "{value}: {:?}", run.verdict);
        } else {
            let f = reasons(&run);
            assert_eq!(f.len(), 1, "{value}: {f:?}");
            assert!(
                f[0].starts_with("reference: its time coverage of pixel (5, 1) is 7/16"),
                "{f:?}"
            );
            assert!(f[0].contains("but the case pins"), "{f:?}");
        }
    }
    // The certified bound widens the slack: off by 1.5e-12 holds with a
    // bound of 2^-40 (9.1e-13), not with 0.
    let slide = pinned("0.4375000000015");
    let s = slide.scene();
    for (bound, holds) in [
        (RBig::ZERO, false),
        (rastercheck::reference::motion::max_bound(), true),
    ] {
        let r = oracle::run_reference_with(&s, |_, plan| {
            let mut values = slide.exact(plan);
            values[16 + 5].bound = bound.clone();
            values
        });
        let check = r.time.as_ref().unwrap().as_ref().unwrap();
        assert_eq!(
            check.broken_promises.is_empty(),
            holds,
            "{:?}",
            check.broken_promises
        );
        // A value with a bound is not known to be whole: pixel (5, 1) moves.
        assert!(!check.whole[16 + 5]);
        let run = judge::run_candidate(&s, &r, &exact_candidate(&slide));
        assert_eq!(
            matches!(run.verdict, Verdict::Pass),
            holds,
            "{:?}",
            run.verdict
        );
    }
}

#[test]
fn a_broken_pin_fails_every_candidate() {
    let slide = Slide {
        expect:
            r#""time_coverage": [{"pixel": [0, 0], "value": 0}, {"pixel": [2, 1], "value": 0.125}]"#
                .to_owned(),
        ..Slide::new("slide")
    };
    let (s, r) = reference(&slide);
    for candidate in [
        Given("exact", shifted(&slide, |_, v| v)),
        Given("off", shifted(&slide, |_, v| v + 0.01)),
    ] {
        let run = judge::run_candidate(&s, &r, &candidate);
        let f = reasons(&run);
        assert!(
            f.iter()
                .any(|m| m.starts_with("reference: its time coverage of pixel (2, 1) is 1/16")),
            "{f:?}"
        );
        assert!(!f.iter().any(|m| m.contains("pixel (0, 0) is")), "{f:?}");
    }
}

#[test]
fn a_broken_oracle_is_reported_on_every_candidate() {
    let slide = Slide::new("slide");
    let s = slide.scene();
    let r = oracle::run_reference_with(&s, |_, _| panic!("no roots today"));
    assert!(r.frame.time.as_ref().unwrap().iter().all(|v| v.is_nan()));
    let run = judge::run_candidate(&s, &r, &Given("exact", shifted(&slide, |_, v| v)));
    assert_eq!(
        reasons(&run),
        ["reference: the time-coverage oracle failed: no roots today"]
    );
    // A golden file is never written from it.
    let path = std::env::temp_dir()
        .join(format!("rastercheck-motion-{}", std::process::id()))
        .join("broken.exr");
    let err = rastercheck::harness::golden::write(&r.frame, &path).unwrap_err();
    assert!(err.contains("not a number"), "{err}");
    assert!(!path.exists());

    let short = oracle::run_reference_with(&s, |_, _| {
        vec![
            Certified {
                value: RBig::ONE,
                bound: RBig::ZERO,
            };
            3
        ]
    });
    let run = judge::run_candidate(&s, &short, &Given("exact", shifted(&slide, |_, v| v)));
    assert_eq!(
        reasons(&run),
        ["reference: the time-coverage oracle returned 3 values for 96 pixels"]
    );
}

type MakeFrame = Box<dyn Fn(&Scene, &Plan) -> Frame + Send + Sync>;

#[test]
fn frames_of_the_wrong_shape_are_errors() {
    let slide = Slide::new("slide");
    let (s, r) = reference(&slide);
    let cases: [(&str, MakeFrame, &str); 4] = [
        (
            "static",
            Box::new(|s: &Scene, _: &Plan| Frame::new(s.canvas.width, s.canvas.height, false, 0)),
            "needs a time coverage per pixel",
        ),
        (
            "short",
            Box::new(|_: &Scene, _: &Plan| Frame::time_only(8, 6, vec![0.0; 48])),
            "8×6 for a 16×6 canvas",
        ),
        (
            "slots",
            Box::new(|s: &Scene, _: &Plan| {
                let mut f = Frame::new(s.canvas.width, s.canvas.height, false, 0);
                f.time = Some(vec![0.0; 96]);
                f
            }),
            "judged on time coverage only",
        ),
        (
            "long",
            Box::new(|s: &Scene, _: &Plan| {
                let mut f = Frame::time_only(s.canvas.width, s.canvas.height, vec![0.0; 96]);
                f.time.as_mut().unwrap().push(0.0);
                f
            }),
            "97 time coverages for 96 pixels",
        ),
    ];
    for (name, make, why) in cases {
        let run = judge::run_candidate(&s, &r, &Given(name, make));
        match &run.verdict {
            Verdict::Error(message) => {
                assert!(
                    message.starts_with("returned a frame of the wrong size"),
                    "{message}"
                );
                assert!(message.contains(why), "{name}: {message}");
            }
            other => panic!("{name}: {other:?}"),
        }
    }
    // Time coverage for a scene in which nothing moves is wrong too.
    let still = Slide {
        dx: 0,
        ..Slide::new("still")
    };
    let s = still.scene();
    assert!(Plan::for_scene(&s).motion.is_none());
    let r = oracle::run_reference(&s);
    let run = judge::run_candidate(
        &s,
        &r,
        &Given("timed", |s: &Scene, _: &Plan| {
            Frame::time_only(s.canvas.width, s.canvas.height, vec![0.0; 96])
        }),
    );
    assert!(
        matches!(&run.verdict, Verdict::Error(m) if m.contains("time coverage for a scene in which nothing moves")),
        "{:?}",
        run.verdict
    );
}

#[test]
fn sample_expectations_on_a_moving_scene_are_named() {
    let slide = Slide::new("slide");
    let (mut s, r) = reference(&slide);
    s.expect.samples_covered = Some(12);
    s.expect.watertight = true;
    let run = judge::run_candidate(&s, &r, &Given("exact", shifted(&slide, |_, v| v)));
    let f = reasons(&run);
    assert_eq!(
        f,
        [
            "case: expect.samples_covered does not apply to a scene in which something moves (it is judged on time coverage only, SPEC.md §15.1)",
            "case: expect.watertight does not apply to a scene in which something moves (it is judged on time coverage only, SPEC.md §15.1)",
        ]
    );
}
