//! Conservative rasterization (SPEC.md §19): the exact reference on the
//! worked examples (the sets asserted here and pinned by their cases), a
//! wrong reference (a growth too large, an open square) caught by the
//! pins, and the verdict failing on a required pixel missing, a forbidden
//! pixel drawn and a wrong fully-covered flag.

use std::path::Path;

use rastercheck::frame::Frame;
use rastercheck::harness::conservative::broken_promises;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::oracle::run_reference;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::reference::conservative::{
    classify, classify_under, ConservativeClasses, PixelClass,
};
use rastercheck::reference::Reference;
use rastercheck::scene::{ConservativeSupport, Number};
use rastercheck::{parse_case, Limits, Scene};

const CASES: &str = "cases/conservative";

fn case(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(CASES)
        .join(format!("{name}.json"));
    let text = std::fs::read_to_string(&path).unwrap();
    parse_case(&text, &path.display().to_string(), &Limits::default()).unwrap()
}

fn pixels(classes: &ConservativeClasses, class: PixelClass) -> Vec<[u32; 2]> {
    let w = classes.width as usize;
    (0..classes.drawn.len())
        .filter(|&i| classes.drawn[i] == class)
        .map(|i| [(i % w) as u32, (i / w) as u32])
        .collect()
}

fn flags(classes: &ConservativeClasses, class: PixelClass) -> Vec<[u32; 2]> {
    let w = classes.width as usize;
    let f = classes.fully_covered.as_ref().unwrap();
    (0..f.len())
        .filter(|&i| f[i] == class && classes.drawn[i] != PixelClass::Forbidden)
        .map(|i| [(i % w) as u32, (i / w) as u32])
        .collect()
}

#[test]
fn every_case_keeps_its_promises_on_the_reference() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(CASES);
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_stem().unwrap().to_str().unwrap().to_owned();
        let scene = case(&name);
        assert!(scene.expect.conservative.is_some(), "{name} pins nothing");
        let classes = classify(&scene).unwrap();
        assert_eq!(
            broken_promises(&scene, &classes),
            Vec::<String>::new(),
            "{name}"
        );
        n += 1;
    }
    assert!(n >= 40, "{n} conservative cases");
}

#[test]
fn worked_example_1_corner_touch() {
    let c = classify(&case("over_corner_touch")).unwrap();
    let mut expected = Vec::new();
    for y in 0..4u32 {
        for x in 0..4u32 {
            if x + y <= 4 {
                expected.push([x, y]);
            }
        }
    }
    assert_eq!(pixels(&c, PixelClass::Required), expected);
    assert!(pixels(&c, PixelClass::Allowed).is_empty());
    assert_eq!(
        c.drawn[0],
        PixelClass::Required,
        "(0,0) touches only at (1,1)"
    );
}

#[test]
fn worked_example_2_sliver_band() {
    let c = classify(&case("over_sliver_band")).unwrap();
    assert_eq!(
        pixels(&c, PixelClass::Required),
        (1..=6).map(|x| [x, 2]).collect::<Vec<_>>()
    );
    assert_eq!(
        pixels(&c, PixelClass::Allowed),
        vec![[0, 2], [7, 2], [0, 3], [1, 3]]
    );
}

#[test]
fn worked_examples_3_and_4_underestimation() {
    let c = classify(&case("under_no_uncertainty")).unwrap();
    assert_eq!(
        pixels(&c, PixelClass::Required),
        vec![[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [0, 2]]
    );
    let c = classify(&case("under_quarter_band")).unwrap();
    let required: Vec<[u32; 2]> = (0..8u32)
        .flat_map(|y| (0..8u32).map(move |x| [x, y]))
        .filter(|&[x, y]| x >= 1 && y >= 1 && x + y <= 5)
        .collect();
    let band: Vec<[u32; 2]> = (0..8u32)
        .flat_map(|y| (0..8u32).map(move |x| [x, y]))
        .filter(|&[x, y]| x + y <= 6 && !(x >= 1 && y >= 1 && x + y <= 5))
        .collect();
    assert_eq!(pixels(&c, PixelClass::Required), required);
    assert_eq!(pixels(&c, PixelClass::Allowed), band);
}

#[test]
fn worked_examples_5_and_6_degenerate_triangles() {
    let c = classify(&case("degenerate_segment_drawn")).unwrap();
    assert_eq!(
        pixels(&c, PixelClass::Required),
        vec![[1, 1], [2, 1], [3, 1]]
    );
    let c = classify(&case("degenerate_segment_culled")).unwrap();
    assert!(c.drawn.iter().all(|&d| d == PixelClass::Forbidden));
}

#[test]
fn worked_examples_7_and_8_the_flag() {
    let c = classify(&case("flag_overestimate")).unwrap();
    assert_eq!(
        flags(&c, PixelClass::Required),
        vec![[0, 0], [1, 0], [2, 0], [0, 1], [1, 1], [0, 2]]
    );
    assert_eq!(flags(&c, PixelClass::Forbidden).len(), 13 - 6);
    // The last writer decides: the second triangle (y ≥ x) draws every
    // pixel with y ≥ x − 1 last.
    let c = classify(&case("flag_last_writer")).unwrap();
    let truth: Vec<[u32; 2]> = (0..4u32)
        .flat_map(|y| (0..4u32).map(move |x| [x, y]))
        .filter(|&[x, y]| y > x || y + 2 <= x)
        .collect();
    assert_eq!(flags(&c, PixelClass::Required), truth);
}

/// A reference that grows by twice the stated uncertainty, or tests the
/// open square (touching not counted), is caught by the cases' pins.
#[test]
fn a_wrong_reference_is_caught_by_the_pins() {
    for name in [
        "over_sliver_band",
        "over_u256_gap_beyond",
        "over_band_corner_exact",
        "under_quarter_band",
    ] {
        let scene = case(name);
        let mut wrong = scene.effects.conservative.clone().unwrap();
        let u = wrong.uncertainty.as_rbig().clone();
        wrong.uncertainty =
            Number::from_rbig(&u + &u + dashu_ratio::RBig::from_parts(1.into(), 256u32.into()));
        let classes = classify_under(&scene, &wrong);
        assert!(
            !broken_promises(&scene, &classes).is_empty(),
            "{name}: a larger growth went unseen"
        );
    }
    // The open square: a corner touch not counted.
    let scene = case("over_corner_touch");
    let mut classes = classify(&scene).unwrap();
    classes.drawn[0] = PixelClass::Forbidden;
    assert!(!broken_promises(&scene, &classes).is_empty());
}

/// Draws the reference's required pixels, then moves them by a closure.
struct Edited {
    name: &'static str,
    edit: fn(&Scene, &mut Frame),
}

impl Rasterizer for Edited {
    fn name(&self) -> &str {
        self.name
    }
    fn capabilities(&self) -> Capabilities {
        Capabilities::everything()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut frame = Reference.rasterize(scene, plan)?;
        (self.edit)(scene, &mut frame);
        Ok(frame)
    }
    fn conservative(&self) -> Option<ConservativeSupport> {
        Reference.conservative()
    }
}

fn verdict(name: &str, candidate: &dyn Rasterizer) -> Verdict {
    let scene = case(name);
    let reference = run_reference(&scene);
    run_candidate(&scene, &reference, candidate).verdict
}

fn failure(v: &Verdict) -> String {
    match v {
        Verdict::Fail(why) => why.join("; "),
        other => panic!("expected a failure, got {other:?}"),
    }
}

#[test]
fn the_reference_passes_and_a_band_pixel_drawn_passes() {
    for name in [
        "over_sliver_band",
        "flag_last_writer",
        "mesh_fan",
        "under_quarter_band",
    ] {
        assert_eq!(verdict(name, &Reference), Verdict::Pass, "{name}");
    }
    let band = Edited {
        name: "band",
        edit: |_, f| {
            // (0,3) is in the allowed band of over_sliver_band.
            let i = f.index(0, 3);
            f.hit(i, 0);
        },
    };
    assert_eq!(verdict("over_sliver_band", &band), Verdict::Pass);
    let scene = case("over_sliver_band");
    let reference = run_reference(&scene);
    let run = run_candidate(&scene, &reference, &band);
    let m = run.metrics.unwrap().conservative.unwrap();
    assert_eq!((m.band_drawn, m.band, m.required), (1, 4, 6));
}

#[test]
fn a_required_pixel_missing_fails() {
    let missing = Edited {
        name: "misses a touched corner",
        edit: |_, f| {
            f.coverage[0] = 0;
            f.last[0] = 0;
        },
    };
    let why = failure(&verdict("over_corner_touch", &missing));
    assert!(
        why.contains("required pixel(s) not drawn") && why.contains("(0, 0)"),
        "{why}"
    );
}

#[test]
fn a_forbidden_pixel_drawn_fails() {
    let grows = Edited {
        name: "grows too much",
        edit: |_, f| {
            // (1,1) is beyond the 1/256 band of over_u256_gap_beyond.
            let i = f.index(1, 1);
            f.hit(i, 0);
        },
    };
    let why = failure(&verdict("over_u256_gap_beyond", &grows));
    assert!(
        why.contains("forbidden pixel(s) drawn") && why.contains("(1, 1)"),
        "{why}"
    );
}

#[test]
fn a_wrong_flag_fails() {
    let partly = Edited {
        name: "fully covered on a partly covered pixel",
        edit: |_, f| {
            // (3,0) is touched, not covered, by flag_overestimate's triangle.
            let i = f.index(3, 0);
            f.fully_covered.as_mut().unwrap()[i] = true;
        },
    };
    let why = failure(&verdict("flag_overestimate", &partly));
    assert!(
        why.contains("fully-covered flag wrong") && why.contains("(3, 0)"),
        "{why}"
    );
    let none = Edited {
        name: "no flag",
        edit: |_, f| f.fully_covered = None,
    };
    let why = failure(&verdict("flag_overestimate", &none));
    assert!(why.contains("gives none"), "{why}");
}

#[test]
fn a_rasterizer_without_conservative_support_is_unsupported() {
    struct Plain;
    impl Rasterizer for Plain {
        fn name(&self) -> &str {
            "plain"
        }
        fn capabilities(&self) -> Capabilities {
            Capabilities::everything()
        }
        fn rasterize(&self, _: &Scene, _: &Plan) -> Result<Frame, RasterError> {
            unreachable!("a conservative case is refused unsent")
        }
    }
    match verdict("over_corner_touch", &Plain) {
        Verdict::Unsupported(why) => assert!(why.contains("conservative"), "{why}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_declared_uncertainty_is_judged_under() {
    // A rasterizer whose fixed uncertainty is 1/2 may draw column 1 of
    // over_u256_gap_beyond, which the case's 1/256 forbids.
    struct Wide;
    impl Rasterizer for Wide {
        fn name(&self) -> &str {
            "wide"
        }
        fn capabilities(&self) -> Capabilities {
            Capabilities::everything()
        }
        fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
            let mut frame = Reference.rasterize(scene, plan)?;
            let i = frame.index(1, 1);
            frame.hit(i, 0);
            Ok(frame)
        }
        fn conservative(&self) -> Option<ConservativeSupport> {
            Some(ConservativeSupport {
                overestimate: true,
                overestimation_uncertainty: Some(Number::ratio(1, 2)),
                ..ConservativeSupport::default()
            })
        }
    }
    let scene = case("over_u256_gap_beyond");
    let reference = run_reference(&scene);
    let run = run_candidate(&scene, &reference, &Wide);
    assert_eq!(run.verdict, Verdict::Pass);
    let m = run.metrics.unwrap().conservative.unwrap();
    assert!(
        m.judged_under.contains("uncertainty 1/2 px") && m.judged_under.contains("its own"),
        "{}",
        m.judged_under
    );
}

#[test]
fn the_report_pictures_the_three_classes_and_the_pixels() {
    use rastercheck::report::conservative::{write_picture, BAND_DRAWN, REQUIRED_DRAWN};
    let scene = case("over_sliver_band");
    let reference = run_reference(&scene);
    let band = Edited {
        name: "band",
        edit: |_, f| {
            let i = f.index(0, 3);
            f.hit(i, 0);
        },
    };
    let run = run_candidate(&scene, &reference, &band);
    let m = run.metrics.unwrap().conservative.unwrap();
    let dir = std::env::temp_dir().join(format!("rastercheck-cons-{}", std::process::id()));
    let paths = write_picture(&scene, "band", &m, &dir, 8).unwrap();
    let image = image::open(&paths[0]).unwrap().to_rgb8();
    // Pixel (0,3) drawn in the band, (3,2) required and drawn: sampled
    // inside each magnified pixel, off its grid lines and outlines.
    assert_eq!(image.get_pixel(3, 3 * 8 + 6).0, BAND_DRAWN);
    assert_eq!(image.get_pixel(3 * 8 + 3, 2 * 8 + 1).0, REQUIRED_DRAWN);
    std::fs::remove_dir_all(&dir).unwrap();
}
