//! Subpixel precision as a convention (SPEC.md §3.2): a rasterizer whose
//! vertex precision is fixed declares its bits, and a case stated at more
//! bits (or unsnapped) is judged against the reference drawn at the
//! rasterizer's bits, and named so.
//!
//! The foil is production drawing every case restated at 4 subpixel bits
//! (as SwiftShader snaps), declaring 4 bits (honest) or 8 (not).

use std::path::PathBuf;

use rastercheck::frame::Frame;
use rastercheck::harness::judge::{run_candidate, CandidateRun, Verdict};
use rastercheck::harness::{discover, load, oracle};
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::scene::{Limits, Scene};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Production snapping to `snaps` bits whatever a case states (a case at
/// fewer bits lies on that grid already and is drawn as stated), and
/// declaring `declares`.
struct Snaps {
    snaps: u32,
    declares: u32,
}

impl Rasterizer for Snaps {
    fn name(&self) -> &str {
        "snaps"
    }
    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut drawn = scene.clone();
        if scene.rules.subpixel_bits.is_none_or(|b| b > self.snaps) {
            drawn.rules.subpixel_bits = Some(self.snaps);
        }
        Production.rasterize(&drawn, plan)
    }
    fn fixed_subpixel_bits(&self) -> Option<u32> {
        Some(self.declares)
    }
}

fn scene(id: &str) -> Scene {
    let file = discover::case_file(&root().join("cases").join(format!("{id}.json")));
    load::load(&file, &Limits::default()).unwrap()
}

fn judge(id: &str, candidate: &dyn Rasterizer) -> CandidateRun {
    let scene = scene(id);
    let reference = oracle::run_reference(&scene);
    run_candidate(&scene, &reference, candidate)
}

fn triangle_cases() -> Vec<String> {
    let mut ids: Vec<String> = std::fs::read_dir(root().join("cases/triangles"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| format!("triangles/{}", p.file_stem().unwrap().to_string_lossy()))
        .collect();
    ids.sort();
    ids
}

/// Declaring the 4 bits it snaps to, the foil passes every triangle case:
/// those stated at more bits, or none, are judged at 4 and named so.
#[test]
fn a_rasterizer_judged_at_its_own_bits_passes() {
    let foil = Snaps {
        snaps: 4,
        declares: 4,
    };
    let mut judged = 0;
    let mut failed = Vec::new();
    for id in triangle_cases() {
        let stated = scene(&id).rules.subpixel_bits;
        let run = judge(&id, &foil);
        if !matches!(run.verdict, Verdict::Pass | Verdict::Unsupported(_)) {
            failed.push(format!("{id}: {:?}", run.verdict));
        }
        let coarser = stated.is_none_or(|b| b > 4);
        assert_eq!(
            run.judged.subpixel_bits,
            coarser.then_some(4),
            "{id} states {stated:?}"
        );
        judged += usize::from(coarser);
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
    assert!(judged > 50, "{judged} judged at 4 bits");
}

/// Declaring 8 bits while snapping to 4 is caught: cases at 8 bits whose
/// vertices lie off the 1/16-pixel grid fail.
#[test]
fn a_rasterizer_coarser_than_it_declares_is_caught() {
    let foil = Snaps {
        snaps: 4,
        declares: 8,
    };
    let failed: Vec<String> = triangle_cases()
        .into_iter()
        .filter(|id| matches!(judge(id, &foil).verdict, Verdict::Fail(_)))
        .collect();
    assert!(!failed.is_empty(), "no case caught the 4-bit foil");
    assert!(
        failed
            .iter()
            .any(|id| id.contains("snap_tie_half_subpixel_b8")),
        "{failed:?}"
    );
}

/// A case at 16 bits on a rasterizer that snaps to 8 is judged at 8; a
/// case at fewer bits than the rasterizer's is judged as stated.
#[test]
fn finer_cases_are_judged_at_the_rasterizers_bits_coarser_as_stated() {
    let eight = Snaps {
        snaps: 8,
        declares: 8,
    };
    let run = judge("triangles/guard_band_b16", &eight);
    assert_eq!(run.judged.subpixel_bits, Some(8));
    assert_eq!(run.verdict, Verdict::Pass);
    let run = judge("triangles/snap_tie_half_subpixel_b4", &eight);
    assert_eq!(run.judged.subpixel_bits, None);
    assert_eq!(run.verdict, Verdict::Pass);
}
