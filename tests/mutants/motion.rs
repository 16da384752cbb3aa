//! Motion blur: the time metrics catch the motion mutants on the sliding
//! square, and an honest sampler passes it.

use crate::static_checks::DIAGONAL_PAIR;
use crate::{reasons, run, scene};
use rastercheck::harness::judge::{CandidateRun, Verdict};
use rastercheck::harness::{judge, oracle};
use rastercheck::plan::Plan;
use rastercheck::production::mutants::{Mutant, Mutation};
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, Rasterizer};
use rastercheck::scene::{Number, Scene};

// Motion blur. The oracle is not needed here: the sliding square's exact
// time coverage is computed by hand (tests/sliding), and the reference's
// run is built from it as from the oracle.

use crate::sliding::{self, Given, Slide};
use rastercheck::metrics::TimeMetrics;

/// The reference's run of a sliding square, from its exact values.
fn slide_reference(slide: &Slide) -> (Scene, oracle::ReferenceRun) {
    let s = slide.scene();
    let reference = oracle::run_reference_with(&s, |_, plan| slide.exact(plan));
    (s, reference)
}

fn time_metrics(run: &CandidateRun) -> TimeMetrics {
    run.metrics
        .as_ref()
        .and_then(|m| m.time.clone())
        .unwrap_or_else(|| panic!("{}: no time metrics: {:?}", run.rasterizer, run.verdict))
}

/// The sliding square with and without 4× antialiasing.
fn slides() -> Vec<Slide> {
    let aa = Slide {
        antialias: Some(4),
        ..Slide::new("slide_aa4")
    };
    vec![Slide::new("slide"), aa]
}

#[test]
fn only_the_motion_mutants_claim_motion_blur() {
    for mutation in Mutation::ALL {
        assert_eq!(
            Mutant(mutation).capabilities().motion_blur,
            mutation.is_motion(),
            "{}",
            mutation.name()
        );
        let others = Capabilities {
            motion_blur: false,
            ..Mutant(mutation).capabilities()
        };
        let production = Capabilities {
            motion_blur: false,
            ..Production.capabilities()
        };
        assert_eq!(others, production, "{}", mutation.name());
    }
    let s = Slide::new("slide").scene();
    let r = judge::run_candidate(
        &s,
        &slide_reference(&Slide::new("slide")).1,
        &Mutant(Mutation::FlippedTies),
    );
    assert!(
        matches!(r.verdict, Verdict::Unsupported(_)),
        "{:?}",
        r.verdict
    );
}

#[test]
fn an_honest_sampler_passes_the_sliding_square_under_every_pattern() {
    // The scene the motion mutants fail is fair: the spec's instants,
    // tested exactly, meet the default RMS bound 0.75·(M·N)^-1/2. Moving
    // 8 pixels, every centre's interval ends on a multiple of 1/16, so
    // 16 strata are exact there; moving 7, no pattern is.
    for base in slides() {
        for dx in [8, 7] {
            for pattern in [
                "random",
                "stratified",
                "jittered-xy-t",
                "stratified-shuffled",
            ] {
                let slide = Slide {
                    pattern,
                    dx,
                    ..base.clone()
                };
                let (s, reference) = slide_reference(&slide);
                let sampler = Given("sampler", |s: &Scene, p: &Plan| slide.sampled(s, p));
                let r = judge::run_candidate(&s, &reference, &sampler);
                let t = time_metrics(&r);
                let what = format!("{} dx {dx} {pattern}", slide.name);
                assert_eq!(r.verdict, Verdict::Pass, "{what}: {}", judge::describe(&r));
                assert!(t.moving_pixels > 0, "{what}: {t:?}");
                assert!(
                    t.max_error > 0.0 || dx == 8 && pattern != "random",
                    "{what}: {t:?}"
                );
                let m = slide.antialias.unwrap_or(1);
                let bound = 0.75 / f64::from(m * slide.samples).sqrt();
                assert_eq!(t.allowed_rms, Some(bound));
                // Random instants come to about half the bound, stratified
                // ones less (jittered-xy-t least well of them with 4×
                // antialiasing: each spatial sample sees one quarter of
                // the shutter).
                let share = if pattern == "random" { 0.75 } else { 0.5 };
                assert!(t.rms_moving < share * bound, "{what}: {t:?}");
                let tests = t.sample_tests.unwrap();
                assert_eq!(tests.tests, 16 * 6 * u64::from(m) * 16);
                eprintln!(
                    "{what}: rms {:.4} (bound {bound:.4}), max {:.4}, efficiency {:.3}",
                    t.rms_moving,
                    t.max_error,
                    tests.efficiency()
                );
            }
        }
    }
}

#[test]
fn time_metrics_catch_primitives_drawn_at_shutter_open() {
    for slide in slides() {
        let (s, reference) = slide_reference(&slide);
        let plan = Plan::for_scene(&s);
        let mutant = Mutant(Mutation::MotionAtOpen);
        let frame = mutant.rasterize(&s, &plan).unwrap();
        // The square where it starts: 1 inside x = 2..6, y = 1..5, else 0.
        let at_open: Vec<f64> = (0..6)
            .flat_map(|y| {
                (0..16)
                    .map(move |x| f64::from(u8::from((2..6).contains(&x) && (1..5).contains(&y))))
            })
            .collect();
        assert_eq!(frame.time.as_deref(), Some(at_open.as_slice()));
        let r = judge::run_candidate(&s, &reference, &mutant);
        let t = time_metrics(&r);
        // The expected metrics, from the exact values.
        let exact = slide.exact_f64(&plan);
        let (worst, max) = exact
            .iter()
            .zip(&at_open)
            .map(|(e, c)| (c - e).abs())
            .enumerate()
            .fold(
                (0, 0.0),
                |(wi, w), (i, e)| if e > w { (i, e) } else { (wi, w) },
            );
        assert_eq!(t.max_error, max, "{}", slide.name);
        assert_eq!(t.worst_pixel, [worst as u32 % 16, worst as u32 / 16]);
        if slide.antialias.is_none() {
            // Pixel (2, 1): its centre is inside for τ ≤ 1/16 only.
            assert_eq!(
                (t.worst_pixel, t.max_error, t.worst_exact),
                ([2, 1], 0.9375, 0.0625)
            );
        }
        let failures = reasons(&r);
        assert!(
            failures
                .iter()
                .any(|f| f.starts_with("time: time-coverage RMS")),
            "{failures:?}"
        );
        // Any primitive keeps its area at every instant: the errors cancel
        // over each row, and only the RMS sees them.
        assert!(t.bias_moving.abs() < 1e-12, "{t:?}");
        let [x, y] = t.worst_pixel;
        assert!(
            failures[0].contains(&format!("worst pixel ({x}, {y})")),
            "{failures:?}"
        );
    }
    // With a bound on the largest error, that fails too, naming the pixel.
    let slide = Slide {
        expect: "\"max_time_error\": 0.5".to_owned(),
        ..Slide::new("slide_max")
    };
    let (s, reference) = slide_reference(&slide);
    let failures = reasons(&judge::run_candidate(
        &s,
        &reference,
        &Mutant(Mutation::MotionAtOpen),
    ));
    assert!(
        failures[0].starts_with("time: max time-coverage error 9.375e-1 at pixel (2, 1): candidate 1.000000, exact 0.062500 exceeds 5.000e-1"),
        "{failures:?}"
    );
}

#[test]
fn time_metrics_catch_a_shutter_sampled_only_in_its_first_half() {
    for slide in slides() {
        let (s, reference) = slide_reference(&slide);
        let plan = Plan::for_scene(&s);
        let mutant = Mutant(Mutation::MotionHalfShutter);
        let frame = mutant.rasterize(&s, &plan).unwrap();
        if slide.antialias.is_none() {
            // Instants (2k + 1)/64, k < 16: the square's left edge at
            // 2 + (2k + 1)/8 in odd eighths, so the centre x + ½ is inside
            // when 8x − 44 < 2k + 1 < 8x − 12, never on an edge.
            let expected: Vec<f64> = (0..6)
                .flat_map(|y| {
                    (0..16i64).map(move |x| {
                        let k =
                            (0..16i64).filter(|k| 8 * x - 44 < 2 * k + 1 && 2 * k + 1 < 8 * x - 12);
                        if (1..5).contains(&y) {
                            k.count() as f64 / 16.0
                        } else {
                            0.0
                        }
                    })
                })
                .collect();
            assert_eq!(frame.time.as_deref(), Some(expected.as_slice()));
        }
        let r = judge::run_candidate(&s, &reference, &mutant);
        let t = time_metrics(&r);
        assert!(t.rms_moving > 1.25 * t.allowed_rms.unwrap(), "{t:?}");
        let failures = reasons(&r);
        assert!(
            failures
                .iter()
                .any(|f| f.starts_with("time: time-coverage RMS")),
            "{failures:?}"
        );
        if slide.antialias.is_none() {
            assert_eq!((t.max_error, t.worst_pixel), (0.4375, [5, 1]));
        }
    }
    // A shutter of [1/4, 3/4]: the mutant draws [1/4, 1/2] only.
    let slide = Slide {
        shutter: [sliding::ONE / 4, 3 * sliding::ONE / 4],
        ..Slide::new("slide_part")
    };
    let (s, reference) = slide_reference(&slide);
    let r = judge::run_candidate(&s, &reference, &Mutant(Mutation::MotionHalfShutter));
    assert!(
        reasons(&r)[0].starts_with("time: time-coverage RMS"),
        "{:?}",
        reasons(&r)
    );
    let honest = Given("sampler", |s: &Scene, p: &Plan| slide.sampled(s, p));
    assert_eq!(
        judge::run_candidate(&s, &reference, &honest).verdict,
        Verdict::Pass
    );
}

#[test]
fn motion_mutants_draw_static_scenes_as_production_does() {
    let s = scene(DIAGONAL_PAIR);
    for mutation in [Mutation::MotionAtOpen, Mutation::MotionHalfShutter] {
        assert_eq!(run(&s, &Mutant(mutation)).verdict, Verdict::Pass);
    }
}

#[test]
fn an_accumulation_buffer_over_the_whole_shutter_is_not_caught() {
    // The limit of what time metrics see: N strata midpoints shared by
    // every pixel (an accumulation buffer, which strobes) estimate each
    // pixel's mean within about 1/N per edge, well inside the RMS bound.
    // Only the half-shutter variant above is a bug they catch.
    for base in slides() {
        for dx in [8, 7] {
            let slide = Slide { dx, ..base.clone() };
            let (s, reference) = slide_reference(&slide);
            let midpoints = |_: &Scene, _: &Plan| {
                let instants: Vec<Number> = (0..16).map(|k| Number::ratio(2 * k + 1, 32)).collect();
                rastercheck::production::mutants::accumulate(&s, &instants).unwrap()
            };
            let r = judge::run_candidate(&s, &reference, &Given("accumulation", midpoints));
            let t = time_metrics(&r);
            assert_eq!(r.verdict, Verdict::Pass, "{}: {t:?}", slide.name);
            assert!(t.max_error <= 1.0 / 16.0 + 1e-12, "{}: {t:?}", slide.name);
            eprintln!(
                "{} dx {dx}: accumulation over the whole shutter: rms {:.4} (bound {:.4}), max {:.4}",
                slide.name,
                t.rms_moving,
                t.allowed_rms.unwrap(),
                t.max_error
            );
        }
    }
}
