//! Conventions a rasterizer cannot choose, beyond the fill rule (SPEC.md
//! §2.1, §3.2, §12.9, §14.2.1): snapping (bits, none, truncation), sample
//! positions, y direction, pixel centre and coverage encodings, each judged
//! under the rasterizer's declaration, named in every report, and a
//! declaration it does not keep caught.
//!
//! - The foils `foil-snap4` (4 bits, declared) and `foil-snap4-as-8` (the
//!   same frames, declaring 8) over every bundled case: the first departs
//!   nowhere, the second is caught.
//! - `foil-grid-samples` (grid positions, declaring the standard ones) is
//!   caught; a rasterizer that really has only the standard positions
//!   passes every antialiased case it draws, judged at them.
//! - A real program (`tests/clients/conventions.py`) sampling at whole
//!   coordinates, reading y up, truncating or not snapping, or encoding
//!   coverage as area × 256 capped at 255, passes when its hello says so
//!   and is caught when it does not.
//! - probe's measured precision against each declaration: it agrees for
//!   the honest foil and names the liar's ("declares 8 subpixel bits;
//!   measured 4").

mod common;

use std::path::{Path, PathBuf};

use common::cli::{run_client, verdicts};
use rastercheck::frame::Frame;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::{discover, load, oracle};
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer};
use rastercheck::registry::by_name;
use rastercheck::scene::{Limits, Pattern, Scene};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every bundled case's id, sorted (the negative tests left out).
fn bundled() -> Vec<String> {
    fn walk(dir: &Path, base: &Path, out: &mut Vec<String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let path = e.unwrap().path();
            if path.is_dir() {
                if path.file_name().is_some_and(|n| n != "invalid") {
                    walk(&path, base, out);
                }
            } else if path.extension().is_some_and(|x| x == "json") {
                let id = path.strip_prefix(base).unwrap().with_extension("");
                out.push(id.to_string_lossy().into_owned());
            }
        }
    }
    let base = root().join("cases");
    let mut out = Vec::new();
    walk(&base, &base, &mut out);
    out.sort();
    out
}

fn scene(id: &str) -> Scene {
    let file = discover::case_file(&root().join("cases").join(format!("{id}.json")));
    load::load(&file, &Limits::default()).unwrap()
}

/// (passed, failed ids, unsupported) of `candidate` over `ids`.
fn tally(ids: &[String], candidate: &dyn Rasterizer) -> (usize, Vec<String>, usize) {
    let (mut pass, mut fail, mut unsupported) = (0, Vec::new(), 0);
    for id in ids {
        let scene = scene(id);
        let reference = oracle::run_reference(&scene);
        let run = run_candidate(&scene, &reference, candidate);
        match &run.verdict {
            Verdict::Pass => pass += 1,
            Verdict::Fail(why) => fail.push(format!("{id}: {}", why.join("; "))),
            Verdict::Unsupported(_) => unsupported += 1,
            Verdict::Error(why) => panic!("{id}: {why}"),
            Verdict::Flaky(_) => panic!("{id}: flaky in a single drawing"),
        }
    }
    (pass, fail, unsupported)
}

/// A foil that snaps to 4 bits: declaring 4 it departs on no bundled case
/// (those stated at more bits or none are judged at 4, antialiasing bounds
/// the exact 4-bit mask breaks raised to what it achieves); declaring 8 it
/// is caught on many.
#[test]
fn a_4_bit_foil_passes_declaring_4_and_is_caught_declaring_8() {
    let ids = bundled();
    let honest = by_name("foil-snap4").unwrap();
    let (pass, fail, unsupported) = tally(&ids, honest.as_ref());
    eprintln!(
        "foil-snap4: {pass} pass, {} fail, {unsupported} unsupported",
        fail.len()
    );
    assert!(fail.is_empty(), "{fail:#?}");
    assert!(pass > 400, "{pass}");
    let liar = by_name("foil-snap4-as-8").unwrap();
    let (pass, fail, _) = tally(&ids, liar.as_ref());
    eprintln!("foil-snap4-as-8: {pass} pass, {} fail", fail.len());
    assert!(fail.len() >= 100, "{}", fail.len());
    assert!(fail.iter().any(|f| f.starts_with("triangles/")));
}

/// Production drawing every antialiased case at the standard positions
/// whatever it states, and declaring them: a device with only its
/// standard positions.
struct StandardOnly;

impl Rasterizer for StandardOnly {
    fn name(&self) -> &str {
        "standard-only"
    }
    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }
    fn rasterize(&self, scene: &Scene, _plan: &Plan) -> Result<Frame, RasterError> {
        let mut drawn = scene.clone();
        if let Some(aa) = drawn.effects.antialias.as_mut() {
            aa.pattern = Pattern::Standard;
        }
        Production.rasterize(&drawn, &Plan::for_scene(&drawn))
    }
    fn fixed_sample_pattern(&self) -> Option<Pattern> {
        Some(Pattern::Standard)
    }
}

/// Sample positions as a convention: judged at its own standard positions
/// a rasterizer that has only those passes every antialiased case it can
/// draw (a count with no standard pattern is unsupported, with the
/// reason); one that declares them and uses a grid is caught.
#[test]
fn sample_positions_are_judged_as_declared_and_a_false_declaration_is_caught() {
    let ids: Vec<String> = bundled()
        .into_iter()
        .filter(|id| id.starts_with("antialias/"))
        .collect();
    let mut restated = 0;
    for id in &ids {
        let scene = scene(id);
        let reference = oracle::run_reference(&scene);
        let run = run_candidate(&scene, &reference, &StandardOnly);
        let aa = scene.effects.antialias.unwrap();
        match &run.verdict {
            Verdict::Pass => {}
            Verdict::Unsupported(why) => {
                assert!(
                    Pattern::Standard.check_count(aa.samples).is_err(),
                    "{id}: {why}"
                );
                assert!(why.contains("its own sample positions"), "{id}: {why}");
            }
            other => panic!("{id}: {other:?}"),
        }
        if aa.pattern != Pattern::Standard && run.verdict == Verdict::Pass {
            assert_eq!(run.judged.sample_pattern, Some(Pattern::Standard), "{id}");
            restated += 1;
        }
    }
    assert!(restated >= 5, "{restated}");
    let liar = by_name("foil-grid-samples").unwrap();
    let (_, fail, _) = tally(&ids, liar.as_ref());
    eprintln!("foil-grid-samples: {} antialias cases caught", fail.len());
    assert!(!fail.is_empty());
    assert!(fail.iter().any(|f| f.contains("standard4")), "{fail:#?}");
}

/// The client's verdicts over `cases`, with `flags`: (fails, results that
/// name `field`, what was printed).
fn client(tag: &str, flags: &str, cases: &[&str], field: &str) -> (Vec<String>, usize, String) {
    let (report, printed) = run_client(tag, "conventions.py", "own", flags, cases);
    let fails: Vec<String> = verdicts(&report)
        .into_iter()
        .filter(|(_, v, _)| v == "fail" || v == "error")
        .map(|(id, v, why)| format!("{id} {v}: {why}"))
        .collect();
    let named = report["cases"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| !c["results"][0][field].is_null())
        .count();
    let passed = verdicts(&report)
        .iter()
        .filter(|(_, v, _)| v == "pass")
        .count();
    assert!(passed > 0, "{tag}: nothing passed\n{printed}");
    (fails, named, printed)
}

/// A program whose samples lie at whole coordinates: declared, it is judged
/// on each case moved by (½, ½) and passes; undeclared, it is caught; a
/// program declaring it while sampling at the centre is caught.
#[test]
fn an_integer_pixel_centre_is_judged_as_declared() {
    let cases = ["cases/triangles"];
    let (fails, named, printed) = client(
        "centre-declared",
        "--centre integer",
        &cases,
        "judged_pixel_centre",
    );
    assert!(fails.is_empty(), "{fails:#?}");
    assert!(named > 0);
    assert!(
        printed.contains("samples at whole coordinates"),
        "{printed}"
    );
    let (fails, _, _) = client(
        "centre-undeclared",
        "--centre integer --undeclared",
        &cases,
        "judged_pixel_centre",
    );
    assert!(!fails.is_empty());
    let (fails, _, _) = client(
        "centre-lie",
        "--centre integer --lie-centre",
        &cases,
        "judged_pixel_centre",
    );
    assert!(!fails.is_empty());
}

/// A program reading y up (its fill rule and cull words mirrored on
/// screen): declared, it passes every triangle case; undeclared, its ties
/// and culling are caught.
#[test]
fn a_y_up_program_is_judged_as_declared() {
    let cases = ["cases/triangles"];
    let (fails, named, _) = client("y-declared", "--y up", &cases, "judged_y");
    assert!(fails.is_empty(), "{fails:#?}");
    assert!(named > 0);
    let (fails, _, _) = client("y-undeclared", "--y up --undeclared", &cases, "judged_y");
    assert!(!fails.is_empty());
}

/// Snapping words: truncation to whole pixels and no snapping, declared,
/// pass every triangle case judged under them; truncation undeclared is
/// caught.
#[test]
fn truncation_and_no_snapping_are_judged_as_declared() {
    let cases = ["cases/triangles"];
    for (tag, flags) in [("truncate", "--snap truncate"), ("none", "--snap none")] {
        let (fails, named, printed) = client(tag, flags, &cases, "judged_snapping");
        assert!(fails.is_empty(), "{tag}: {fails:#?}");
        assert!(named > 0, "{tag}");
        assert!(printed.contains("judged under its own"), "{tag}");
    }
    let (fails, _, _) = client(
        "truncate-undeclared",
        "--snap truncate --undeclared",
        &cases,
        "judged_snapping",
    );
    assert!(!fails.is_empty());
}

/// Coverage as area × 256 capped at 255 (`coverage_encoding: "fraction"`):
/// declared, its saturated full pixels and its 1/256 steps pass; read as
/// 8-bit unorm it is caught on its full pixels.
#[test]
fn a_saturating_coverage_encoding_is_judged_as_declared() {
    let cases = ["cases/antialias"];
    let (fails, _, _) = client(
        "encoding-declared",
        "--encoding fraction",
        &cases,
        "judged_snapping",
    );
    assert!(fails.is_empty(), "{fails:#?}");
    let (fails, _, _) = client(
        "encoding-undeclared",
        "--encoding fraction --undeclared-encoding",
        &cases,
        "judged_snapping",
    );
    assert!(!fails.is_empty());
}

/// probe's precision against the declarations: the honest 4-bit foil's
/// agrees, the liar's is named as a departure, production declares none.
#[test]
fn probe_checks_each_declared_precision() {
    use rastercheck::explore::probe::probe;
    let honest = probe(by_name("foil-snap4").unwrap().as_ref()).unwrap();
    assert_eq!(honest.subpixel_bits, Some(4), "{}", honest.subpixel);
    assert_eq!(
        honest.declared_snapping.as_deref(),
        Some("declares 4 subpixel bits; measured 4 (agrees)")
    );
    let liar = probe(by_name("foil-snap4-as-8").unwrap().as_ref()).unwrap();
    let words = "declares 8 subpixel bits; measured 4";
    assert_eq!(liar.declared_snapping.as_deref(), Some(words));
    assert!(
        liar.departures.iter().any(|d| d == words),
        "{:?}",
        liar.departures
    );
    let production = probe(&Production).unwrap();
    assert_eq!(production.declared_snapping, None);
}
