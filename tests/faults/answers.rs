//! Faults: wrong answers the harness gave (golden lookup, the reference on its own cases, motion).

use std::path::PathBuf;

use dashu_int::ops::Abs;

use dashu_ratio::RBig;
use rastercheck::harness::{discover, golden, load};
use rastercheck::plan::Plan;
use rastercheck::reference::motion;
use rastercheck::scene::Limits;

use crate::common::cli::{scratch, text, workspace};

fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The golden-file line of a run's output: (match, differ, missing).
fn golden_counts(t: &str) -> (u64, u64, u64) {
    let line = t
        .lines()
        .find(|l| l.starts_with("golden files:"))
        .unwrap_or_else(|| panic!("no golden line in {t}"));
    let n: Vec<u64> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter(|w| !w.is_empty())
        .map(|w| w.parse().unwrap())
        .collect();
    (n[0], n[1], n[2])
}

const SQUARE: &str = r#"{"name": "square", "canvas": {"width": 4, "height": 4},
  "primitives": [{"triangle": [[0, 0], [3, 0], [0, 3]]}]}"#;

#[test]
fn golden_files_are_found_beside_the_cases_folder_from_any_folder() {
    // The bundled triangles, by absolute path, from a folder with no
    // reference/ of its own.
    let elsewhere = scratch("answers-elsewhere");
    let cases = repo().join("cases/triangles");
    let out = crate::bounded_run(&elsewhere, &["run", cases.to_str().unwrap(), "-q"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    let (matching, differing, missing) = golden_counts(&t);
    assert!(matching > 0 && differing == 0 && missing == 0, "{t}");
    assert!(!elsewhere.join("reference").exists());

    // Inside cases/, a relative path names the same cases and files.
    let out = crate::bounded_run(&repo().join("cases"), &["run", "triangles", "-q"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    assert_eq!(golden_counts(&t), (matching, 0, 0), "{t}");
}

#[test]
fn bless_writes_beside_the_cases_folder_and_run_finds_it() {
    let suite = workspace("answers-bless", &[("cases/shapes/square.json", SQUARE)]);
    let elsewhere = scratch("answers-bless-elsewhere");
    let cases = suite.join("cases");
    let out = crate::bounded_run(&elsewhere, &["bless", cases.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    assert!(suite.join("reference/shapes/square.exr").is_file());
    assert!(!elsewhere.join("reference").exists());
    let file = cases.join("shapes/square.json");
    let out = crate::bounded_run(&elsewhere, &["run", file.to_str().unwrap(), "-q"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    assert_eq!(golden_counts(&t), (1, 0, 0), "{t}");
    // From the suite's own folder, with a relative path: the same file.
    let out = crate::bounded_run(&suite, &["run", "cases", "-q"]);
    assert_eq!(golden_counts(&text(&out)), (1, 0, 0));
}

#[test]
fn a_case_with_no_cases_folder_above_it_uses_the_working_directory() {
    let dir = workspace("answers-loose", &[("loose/square.json", SQUARE)]);
    let out = crate::bounded_run(&dir, &["bless", "loose/square.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    assert!(dir.join("reference/loose/square.exr").is_file());
    let out = crate::bounded_run(&dir, &["run", "loose/square.json", "-q"]);
    assert_eq!(golden_counts(&text(&out)), (1, 0, 0));
}

#[test]
fn the_reference_passes_every_bundled_case() {
    let report = scratch("answers-reference");
    let out = crate::bounded_run(
        &repo(),
        &[
            "run",
            "cases",
            "-r",
            "reference",
            "-q",
            "--report",
            report.to_str().unwrap(),
        ],
    );
    let t = text(&out);
    assert_eq!(out.status.code(), Some(0), "{t}");
    let json = crate::common::cli::read_json(&report.join("report.json"));
    let cases = json["cases"].as_array().unwrap();
    assert!(cases.len() > 300, "{} cases", cases.len());
    let antialiased = cases
        .iter()
        .filter(|c| c["id"].as_str().unwrap().starts_with("antialias/"))
        .count();
    assert!(antialiased > 60, "{antialiased} antialiasing cases");
    for case in cases {
        assert_eq!(case["status"], "ran", "{case}");
        assert_eq!(case["results"][0]["verdict"], "pass", "{case}");
        assert_eq!(case["golden"], "match", "{case}");
    }
    assert!(!t.contains("box resolve"), "{t}");
}

#[test]
fn a_resolve_that_is_neither_the_box_nor_the_exact_area_still_fails() {
    // The mutant rounds the box resolve down to quarters: on an
    // antialiased case with sloped edges it is neither its mask's box resolve nor the exact
    // area, so the resolve check still catches it.
    let first = repo().join("cases/antialias/edge_slope_1_16_standard16.json");
    let out = crate::bounded_run(
        &repo(),
        &[
            "run",
            first.to_str().unwrap(),
            "-r",
            "mutant:coarse-resolve",
        ],
    );
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(t.contains("box resolve of their own samples"), "{t}");
}

#[test]
fn a_moving_scene_without_snapping_is_refused_and_16_bits_say_it() {
    let dir = workspace(
        "answers-unsnapped",
        &[
            (
                "cases/unsnapped.json",
                r#"{"name": "moving", "canvas": {"width": 8, "height": 8}, "rules": {"subpixel_bits": null},
                    "effects": {"motion_blur": {"samples": 4}},
                    "primitives": [{"triangle": [{"from": [0, 0], "to": [0.5, 0]}, [6, 0], [0, 6]]}]}"#,
            ),
            (
                "cases/bits16.json",
                r#"{"name": "moving", "canvas": {"width": 8, "height": 8}, "rules": {"subpixel_bits": 16},
                    "effects": {"motion_blur": {"samples": 4}},
                    "primitives": [{"triangle": [{"from": [0, 0], "to": [0.5, 0]}, [6, 0], [0, 6]]}]}"#,
            ),
        ],
    );
    let out = crate::bounded_run(&dir, &["run", "cases/unsnapped.json"]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(2), "{t}");
    assert!(
        t.contains("$.rules.subpixel_bits") && t.contains("needs subpixel_bits"),
        "{t}"
    );
    crate::bounded_run(&dir, &["bless", "cases/bits16.json"]);
    let out = crate::bounded_run(&dir, &["run", "cases/bits16.json"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
}

/// Every bundled moving case: its golden time layer is what SPEC §15.4
/// says: the exact time coverage correctly rounded to f64. Where the bound
/// is 0 the certified value is exact; elsewhere the whole certified
/// interval rounds to the stored f64, so the exact value inside it does
/// too; and the bound is at most m·2^-40.
#[test]
fn the_motion_golden_time_layer_is_what_spec_says() {
    let dir = repo().join("cases/motion");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    let (mut exact_pixels, mut bounded_pixels) = (0, 0);
    for path in files {
        let file = discover::case_file(&path);
        let scene = load::load(&file, &Limits::default()).unwrap();
        let plan = Plan::for_scene(&scene);
        if plan.motion.is_none() {
            continue;
        }
        let certified = motion::time_coverage(&scene, &plan);
        let frame = motion::frame_of(&scene, &certified);
        let stored = golden::path_for(&repo(), &file.id);
        assert_eq!(golden::check(&frame, &stored), Ok(()), "{}", file.id);
        let time = frame.time.as_ref().unwrap();
        let moving = scene.primitives.iter().filter(|p| p.moves()).count();
        let most = RBig::from(moving) * motion::max_bound();
        for (c, &v) in certified.iter().zip(time) {
            assert!(c.bound <= most, "{}: bound {}", file.id, c.bound);
            let half_ulp = (f64::from_bits(v.to_bits() + 1) - v) / 2.0;
            let off = (RBig::try_from(v).unwrap() - &c.value).abs();
            assert!(off <= RBig::try_from(half_ulp).unwrap(), "{}", file.id);
            if c.bound == RBig::ZERO {
                exact_pixels += 1;
                assert_eq!(v, c.value.to_f64().value(), "{}", file.id);
            } else {
                bounded_pixels += 1;
                let lo = (&c.value - &c.bound).to_f64().value();
                let hi = (&c.value + &c.bound).to_f64().value();
                assert_eq!((lo, hi), (v, v), "{}: not decided", file.id);
            }
        }
    }
    assert!(exact_pixels > 0 && bounded_pixels > 0);
}

/// A pixel whose certified interval meets two f64s is measured again until
/// one f64 holds it: from a first pass of 4-bit isolation (which leaves
/// bounds near 2^-40, far wider than an ulp) the oracle still ends with
/// every pixel of a rotating triangle rounding once, to the same f64s as
/// from 60 bits.
#[test]
fn the_oracle_refines_a_pixel_until_it_rounds_once() {
    let path = repo().join("cases/motion/rotate_triangle_stratified16.json");
    let scene = load::load(&discover::case_file(&path), &Limits::default()).unwrap();
    let plan = Plan::for_scene(&scene);
    let fine = motion::time_coverage(&scene, &plan);
    let coarse = motion::time_coverage_from(&scene, &plan, motion::Mutation::None, 4);
    for c in &coarse {
        let lo = (&c.value - &c.bound).to_f64().value();
        let hi = (&c.value + &c.bound).to_f64().value();
        assert_eq!(lo, hi, "a pixel left across a rounding boundary");
    }
    assert_eq!(
        motion::frame_of(&scene, &coarse),
        motion::frame_of(&scene, &fine)
    );
}
