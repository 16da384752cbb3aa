//! The float foils on the catalogue of hard cases (`cases/hard/`, written by
//! `tools/gen_hard_cases.py`).
//!
//! Production passing every hard case is the conformance harness's job
//! (`tests/conformance.rs` runs every case under `cases/`). This test shows
//! the other half: the textbook float rasterizers `float-f32` and
//! `float-f64` depart from the exact reference on exactly the families built
//! to break them, and on no other hard case. It prints a table of which foil
//! fails which case, with the number of samples that differ.

use std::collections::BTreeMap;
use std::path::PathBuf;

use rastercheck::production::foils::{FloatF32, FloatF64};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::Limits;
use rastercheck::suite::{self, Verdict};

/// Hard cases on which `float-f32` departs from the reference.
const F32_FAILS: &[&str] = &[
    // Near-ties at ±32768: an exact edge value of 2^-16 px² against
    // products of 2^31 px².
    "hard/far_b8_near_tie_fan",
    "hard/far_b16_near_tie_fan",
    // 25-bit coordinate differences rounded in f32.
    "hard/far_b8_bands_steep",
    // 16-bit fractions on far coordinates: f32 cannot hold the vertices.
    "hard/far_b16_strip",
    "hard/unsnapped_far_dyadic_bands",
    "hard/unsnapped_far_strip",
    // Slivers 1/65536 px thick: lost in f32.
    "hard/sliver_far_b16",
    // Snapping ties rounded half away from zero.
    "hard/snaptie_b4_negative",
    "hard/snaptie_b4_positive",
    "hard/snaptie_b8_negative",
    "hard/snaptie_b8_positive",
];

/// Hard cases on which `float-f64` departs from the reference.
const F64_FAILS: &[&str] = &[
    // Near-ties at 16 subpixel bits: products of ~64 bits.
    "hard/far_b16_near_tie_fan",
    // Snapping ties rounded half away from zero.
    "hard/snaptie_b4_negative",
    "hard/snaptie_b4_positive",
    "hard/snaptie_b8_negative",
    "hard/snaptie_b8_positive",
];

/// Samples whose coverage differs, per case, for a foil that fails it.
fn failures(foil: &dyn Rasterizer) -> (BTreeMap<String, u64>, usize) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases/hard");
    let found = suite::discover(&[dir]);
    assert!(found.errors.is_empty(), "{:?}", found.errors);
    let mut failed = BTreeMap::new();
    for file in &found.cases {
        let scene = suite::load(file, &Limits::default()).expect("hard cases are valid");
        let reference = suite::run_reference(&scene);
        let run = suite::run_candidate(&scene, &reference, foil);
        match run.verdict {
            Verdict::Pass => {}
            Verdict::Fail(_) => {
                let mismatched = run.metrics.as_ref().map_or(0, |m| m.coverage.mismatched());
                failed.insert(file.id.clone(), mismatched);
            }
            other => panic!("{} on {}: {other:?}", foil.name(), file.id),
        }
    }
    (failed, found.cases.len())
}

#[test]
fn the_float_foils_fail_exactly_the_families_built_to_break_them() {
    let (f32_failed, cases) = failures(&FloatF32);
    let (f64_failed, _) = failures(&FloatF64);
    assert!(cases >= 30, "only {cases} hard cases");

    let mut ids: Vec<&String> = f32_failed.keys().chain(f64_failed.keys()).collect();
    ids.sort();
    ids.dedup();
    println!(
        "{:<36} {:>10} {:>10}",
        "hard case", "float-f32", "float-f64"
    );
    let cell = |m: &BTreeMap<String, u64>, id: &str| {
        m.get(id)
            .map_or("exact".to_owned(), |n| format!("{n} differ"))
    };
    for id in &ids {
        println!(
            "{:<36} {:>10} {:>10}",
            id,
            cell(&f32_failed, id),
            cell(&f64_failed, id)
        );
    }
    println!(
        "float-f32 fails {} of {cases} hard cases, float-f64 {}",
        f32_failed.len(),
        f64_failed.len()
    );

    let names = |m: &BTreeMap<String, u64>| m.keys().cloned().collect::<Vec<_>>();
    let sorted = |list: &[&str]| {
        let mut v: Vec<String> = list.iter().map(|s| s.to_string()).collect();
        v.sort();
        v
    };
    assert_eq!(names(&f32_failed), sorted(F32_FAILS), "float-f32");
    assert_eq!(names(&f64_failed), sorted(F64_FAILS), "float-f64");
    // f64 departs only where f32 does too.
    assert!(f64_failed.keys().all(|id| f32_failed.contains_key(id)));
    // Each snapping-tie case moves a whole row, column or diagonal of
    // samples, in both types alike.
    for id in F64_FAILS.iter().filter(|id| id.contains("snaptie")) {
        assert!(f64_failed[*id] >= 16, "{id}: {}", f64_failed[*id]);
        assert_eq!(f32_failed[*id], f64_failed[*id], "{id}");
    }
    // The near-tie fans: f32 loses many of its 16 near-miss samples (and
    // more through rounded coordinates at 16 bits); f64 only at 16 bits.
    assert!(f32_failed["hard/far_b8_near_tie_fan"] >= 8);
    assert!(f32_failed["hard/far_b16_near_tie_fan"] >= 8);
    assert!(f64_failed["hard/far_b16_near_tie_fan"] >= 2);
}
