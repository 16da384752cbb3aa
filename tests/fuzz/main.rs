//! Robustness of the case reader and the binary against hostile input.
//!
//! - `parse_case` is fed arbitrary strings, random JSON (extreme numbers,
//!   non-finite strings, deep nesting, case-shaped objects with random
//!   values: triangles, lines and polygons, moving vertices, antialiasing
//!   and motion blur, time expectations) and mutations of the real case
//!   files under `cases/`, the moving ones included (byte flips,
//!   truncations, duplicated keys, swapped types, extreme numbers). It must
//!   never panic, and every error must name a location: a JSON path
//!   (`$...`) or `line L column C`. Cases that read are drawn by the
//!   reference and production, which must not panic either (moving scenes
//!   too, when small enough for the certified oracle to stay fast).
//! - The binary runs a folder of mutated case files and must exit 0, 1 or
//!   2, never panic, and report every file.
//!
//! `RASTERCHECK_FUZZ_CASES` scales the work (default 1000): each proptest
//! property runs that many inputs, and the binary gets a tenth as many files
//! (at least 200). `RASTERCHECK_FUZZ_SEED` changes the binary test's
//! mutations (default fixed). For example:
//! `RASTERCHECK_FUZZ_CASES=20000 cargo test --release --test fuzz`.
//!
//! This file holds the reader's check and its three properties; the inputs
//! come from `random_json.rs` and `mutations.rs`, and `binary.rs` runs the
//! binary.

mod binary;
mod mutations;
mod random_json;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::reference;
use rastercheck::scene::{parse_case, Limits, Scene};

use mutations::mutated_case;
use random_json::{case_shaped, deep_nesting, json_text};

fn fuzz_cases() -> u32 {
    std::env::var("RASTERCHECK_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1000)
}

fn config() -> Config {
    Config {
        cases: fuzz_cases(),
        failure_persistence: None,
        ..Config::default()
    }
}

/// Every case file under `cases/`, valid and invalid, as text.
fn case_texts() -> Vec<String> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "json") {
                out.push(path);
            }
        }
    }
    let mut paths = Vec::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("cases"),
        &mut paths,
    );
    paths.sort();
    assert!(paths.len() > 50, "expected the case files under cases/");
    paths
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect()
}

/// Whether an error location is a JSON path or a line and column.
fn names_a_location(location: &str) -> bool {
    if location.starts_with('$') {
        return true;
    }
    let words: Vec<&str> = location.split(' ').collect();
    matches!(words.as_slice(), ["line", l, "column", c]
        if l.parse::<u64>().is_ok() && c.parse::<u64>().is_ok())
}

thread_local! {
    /// What [`check`] drew on this thread: scenes, and scenes in which
    /// something moves.
    static DRAWN: std::cell::Cell<[u64; 2]> = const { std::cell::Cell::new([0, 0]) };
}

/// Whether a moving scene is too much work for a property test: the
/// oracle certifies each spatial sample of each moving primitive (about
/// 10 µs each), and production tests each at N instants.
fn too_slow(scene: &Scene, plan: &Plan) -> bool {
    let Some(motion) = &plan.motion else {
        return false;
    };
    let moving = motion.moving.iter().filter(|m| **m).count() as u64;
    let samples = scene.canvas.pixel_count() as u64 * u64::from(plan.samples_per_pixel) * moving;
    samples > 4096 || samples * u64::from(motion.blur.samples) > 1 << 20
}

/// Reads `text`; asserts the reader neither panics nor returns an error
/// without a location; draws what reads (on small canvases) with the
/// reference and production, which must not panic.
fn check(text: &str) -> Result<(), TestCaseError> {
    let limits = Limits {
        max_canvas_pixels: 64 * 64,
        max_primitives: 2000,
        ..Limits::default()
    };
    let result = catch_unwind(|| parse_case(text, "fuzz.json", &limits));
    prop_assert!(result.is_ok(), "the reader panicked on {:?}", text);
    match result.unwrap() {
        Err(e) => {
            prop_assert_eq!(&e.file, "fuzz.json");
            prop_assert!(
                names_a_location(&e.location),
                "no location in {:?} for {:?}",
                e.to_string(),
                text
            );
            prop_assert!(!e.message.is_empty());
        }
        Ok(scene) => {
            let plan = Plan::for_scene(&scene);
            if too_slow(&scene, &plan) {
                return Ok(());
            }
            DRAWN.with(|d| {
                let [all, moving] = d.get();
                d.set([all + 1, moving + u64::from(plan.motion.is_some())]);
            });
            let drawn = catch_unwind(AssertUnwindSafe(|| reference::render(&scene, &plan)));
            prop_assert!(drawn.is_ok(), "the reference panicked on {:?}", text);
            let drawn = catch_unwind(AssertUnwindSafe(|| Production.rasterize(&scene, &plan)));
            prop_assert!(drawn.is_ok(), "production panicked on {:?}", text);
            if let Err(RasterError::Failed(why)) = drawn.unwrap() {
                prop_assert!(false, "production broke ({}) on {:?}", why, text);
            }
        }
    }
    Ok(())
}

/// Runs a property on a thread with a large stack: generating and
/// shrinking proptest's recursive JSON strategy nests deeply (the reader
/// itself stops at serde_json's recursion limit of 128 and is fine on the
/// default stack, which `deep_nesting` checks).
/// Returns how many read cases were drawn, and how many of those move.
fn run<S: Strategy<Value = String>>(
    name: &str,
    strategy: impl FnOnce() -> S + Send + 'static,
) -> [u64; 2] {
    let name = name.to_owned();
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let mut runner = TestRunner::new(config());
            let result = runner.run(&strategy(), |text| check(&text));
            if let Err(e) = result {
                panic!("{name}: {e}");
            }
            DRAWN.with(|d| d.get())
        })
        .unwrap()
        .join()
        .unwrap()
}

#[test]
fn the_reader_survives_arbitrary_strings() {
    run("arbitrary strings", || {
        prop_oneof![
            any::<String>(),
            "[\\[\\]{}\":,0-9eE.+\\- a-z/]{0,200}",
            prop::collection::vec(any::<u8>(), 0..300)
                .prop_map(|b| String::from_utf8_lossy(&b).into_owned()),
        ]
    });
}

#[test]
fn the_reader_survives_random_json() {
    let [drawn, moving] = run(
        "random JSON",
        || prop_oneof![1 => json_text(), 2 => case_shaped(), 1 => deep_nesting()],
    );
    eprintln!("random JSON: {drawn} cases drawn, {moving} of them moving");
    // Case-shaped input reaches the rasterizers, moving scenes included
    // (about 1 in 25 case-shaped inputs reads; 2 in 3 of those move).
    if fuzz_cases() >= 1000 {
        assert!(moving >= 3, "{drawn} drawn, {moving} moving");
    }
}

#[test]
fn the_reader_survives_mutated_case_files() {
    let texts = case_texts();
    let moving_files = texts.iter().filter(|t| t.contains("\"from\"")).count();
    assert!(moving_files >= 20, "the motion cases are among them");
    let [drawn, moving] = run("mutated case files", || mutated_case(texts));
    eprintln!("mutated case files: {drawn} cases drawn, {moving} of them moving");
    if fuzz_cases() >= 1000 {
        assert!(moving >= 3, "{drawn} drawn, {moving} moving");
    }
}
