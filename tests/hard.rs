//! The float foils on the catalogue of hard cases (`cases/hard/`, written by
//! `tools/gen_hard_cases.py`).
//!
//! Production passing every hard case is the conformance harness's job
//! (`tests/conformance.rs` runs every case under `cases/`). This test shows
//! the other half: the textbook float rasterizers `float-f32` and
//! `float-f64` depart from the exact reference on exactly the families built
//! to break them, and on no other hard case. It prints a table of which foil
//! fails which case, with the number of samples that differ.
//!
//! The polygon and antialiasing families (`aa_*`, `poly_*`) are beyond the
//! float foils (unsupported there); the methods and mutants that draw them
//! fail the families built for their weakness.

use std::collections::BTreeMap;
use std::path::PathBuf;

use rastercheck::harness::judge::Verdict;
use rastercheck::harness::{discover, judge, load, oracle};
use rastercheck::production::foils::{FloatF32, FloatF64};
use rastercheck::rasterizer::Rasterizer;
use rastercheck::registry;
use rastercheck::scene::Limits;

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

/// Samples whose coverage differs, per case, for a foil that fails it; the
/// cases it does not support; the number of cases.
fn failures(foil: &dyn Rasterizer) -> (BTreeMap<String, u64>, Vec<String>, usize) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases/hard");
    let found = discover::discover(&[dir]);
    assert!(found.errors.is_empty(), "{:?}", found.errors);
    let mut failed = BTreeMap::new();
    let mut unsupported = Vec::new();
    for file in &found.cases {
        let scene = load::load(file, &Limits::default()).expect("hard cases are valid");
        let reference = oracle::run_reference(&scene);
        let run = judge::run_candidate(&scene, &reference, foil);
        match run.verdict {
            Verdict::Pass => {}
            Verdict::Unsupported(_) => unsupported.push(file.id.clone()),
            Verdict::Fail(_) => {
                let mismatched = run.metrics.as_ref().map_or(0, |m| m.coverage.mismatched());
                failed.insert(file.id.clone(), mismatched);
            }
            other => panic!("{} on {}: {other:?}", foil.name(), file.id),
        }
    }
    (failed, unsupported, found.cases.len())
}

/// The polygon and antialiasing hard cases.
fn is_polygon_or_aa(id: &str) -> bool {
    id.starts_with("hard/aa_") || id.starts_with("hard/poly_")
}

#[test]
fn the_float_foils_fail_exactly_the_families_built_to_break_them() {
    let (f32_failed, f32_unsupported, cases) = failures(&FloatF32);
    let (f64_failed, f64_unsupported, _) = failures(&FloatF64);
    assert!(cases >= 30, "only {cases} hard cases");
    // The foils draw triangles and lines only, without antialiasing.
    for unsupported in [&f32_unsupported, &f64_unsupported] {
        assert!(
            unsupported.iter().all(|id| is_polygon_or_aa(id)),
            "{unsupported:?}"
        );
        assert!(unsupported.len() >= 20, "{unsupported:?}");
    }

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

/// Each method or mutant that draws polygons or antialiases, with hard cases
/// it must fail (a subset: the families built against its weakness) and
/// whether it must pass every other polygon and antialiasing case it
/// supports.
const METHOD_FAILS: &[(&str, &[&str], bool)] = &[
    // Exact methods: everything they support passes.
    ("production", &[], true),
    ("production-tiled", &[], true),
    ("adaptive-resolve", &[], true),
    // f32 area accumulation: sums of partial areas that do not round to
    // exactly 1 in full pixels, and a winding-weighted area where a contour
    // winds twice (even-odd: the doubled heptagon is not empty).
    (
        "area-f32",
        &[
            "hard/aa_abut_fan_64_standard16",
            "hard/aa_abut_fan_128_corner_standard16",
            "hard/aa_abut_grid_square_standard16",
            "hard/poly_wind_twice_even_odd_standard16",
            "hard/poly_wind_twice_nonzero_standard16",
            "hard/poly_overlap_contours_even_odd_standard16",
        ],
        false,
    ),
    // Flood fill from seeds inside the outline: wrong where contours
    // overlap, double back or wind twice.
    (
        "flood-fill",
        &[
            "hard/poly_wind_twice_even_odd",
            "hard/poly_doubled_edges_nonzero",
            "hard/poly_overlap_contours_even_odd",
            "hard/poly_zero_area_contour_nonzero",
            "hard/poly_collinear_repeated_vertices",
        ],
        false,
    ),
    // Deliberate bugs: ties on shared edges under 16x, full pixels not
    // exactly 1, samples moved off the pattern.
    (
        "mutant:flipped-ties",
        &[
            "hard/aa_tie_unit_grid_top_left_standard16",
            "hard/aa_tie_unit_grid_top_right_standard16",
            "hard/aa_tie_unit_grid_bottom_left_standard16",
            "hard/aa_tie_unit_grid_bottom_right_standard16",
            "hard/aa_abut_grid_square_standard16",
            "hard/poly_doubled_edges_nonzero",
        ],
        false,
    ),
    (
        "mutant:leaky-full",
        &[
            "hard/aa_abut_fan_64_standard16",
            "hard/aa_abut_grid_square_standard16",
            "hard/aa_tie_border_samples_polygon_nonzero_standard16",
            "hard/poly_far_zigzag_b8_nonzero_standard16",
        ],
        false,
    ),
    (
        "mutant:shifted-samples",
        &[
            "hard/aa_abut_fan_64_standard16",
            "hard/aa_tie_vertices_on_samples_standard16",
            "hard/poly_collinear_repeated_vertices_standard16",
        ],
        false,
    ),
];

#[test]
fn polygon_and_antialiasing_families_catch_the_methods_built_to_fail_them() {
    for &(name, must_fail, exact) in METHOD_FAILS {
        let candidate = registry::by_name(name).expect("a known rasterizer");
        let (failed, unsupported, _) = failures(&*candidate);
        let ours = |id: &&String| is_polygon_or_aa(id);
        println!(
            "{name:<24} fails {:>2}, unsupported {:>2}: {:?}",
            failed.keys().filter(ours).count(),
            unsupported.iter().filter(ours).count(),
            failed.keys().filter(ours).collect::<Vec<_>>()
        );
        for id in must_fail {
            assert!(failed.contains_key(*id), "{name} passes {id}");
        }
        if exact {
            assert!(failed.is_empty(), "{name}: {failed:?}");
        }
    }
}
