//! The foils of issue 40's probe findings, each diagnosed by `probe` and
//! judged over the bundled family it concerns:
//!
//! - `foil-truncate` / `foil-truncate-undeclared`: vertices at ⌊x⌋, ⌊y⌋;
//!   probe finds the truncation (0 bits) on its own scene; declared, the
//!   foil passes every triangle case; undeclared, it is caught.
//! - `foil-coarse-edges`: 8-bit vertices, slanted edges stepped by slopes
//!   truncated to 1/16 px per row; probe measures the vertex grid (8 bits)
//!   and the edge stepping (fewer) apart, never "6 subpixel bits".
//! - `foil-outline-over-fill`: hairlines over a point-sampled fill; probe
//!   tells it from any-coverage (and the any-coverage foil stays that).
//! - `foil-empty-antialias`: nothing drawn; probe says so, and it fails
//!   every antialiased case where the exact area of some primitive in some
//!   pixel exceeds one step.
//! - `foil-alpha256` / `foil-alpha256-as-unorm` / `foil-alpha255`: coverage
//!   as a byte over 256 (declared or read as unorm) or over 255; probe
//!   finds the encoding, and the bytes read as declared pass the
//!   antialias family while alpha over 256 read as unorm is caught.
//! - production: none of these findings.

use std::path::PathBuf;

use rastercheck::explore::probe::{self, Profile, SamplerKind};
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::profile::{CoverageEncoding, Profiled};
use rastercheck::harness::{discover, load, oracle};
use rastercheck::rasterizer::{Declaration, Rasterizer};
use rastercheck::registry::by_name;
use rastercheck::scene::{Limits, Scene};

fn probe_of(name: &str) -> Profile {
    let r = by_name(name).unwrap_or_else(|| panic!("no rasterizer {name}"));
    let p = probe::probe(r.as_ref()).unwrap_or_else(|e| panic!("{name}: {e}"));
    eprintln!("{}", p.describe());
    p
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The ids of one bundled family, sorted.
fn family(name: &str) -> Vec<String> {
    let dir = root().join("cases").join(name);
    let mut out: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| format!("{name}/{}", p.file_stem().unwrap().to_string_lossy()))
        .collect();
    out.sort();
    out
}

fn scene(id: &str) -> Scene {
    let file = discover::case_file(&root().join("cases").join(format!("{id}.json")));
    load::load(&file, &Limits::default()).unwrap()
}

/// Passed ids, failed ids with their reasons, and unsupported ids.
struct Tally {
    pass: Vec<String>,
    fail: Vec<(String, String)>,
    unsupported: usize,
}

fn tally(ids: &[String], candidate: &dyn Rasterizer) -> Tally {
    let mut t = Tally {
        pass: Vec::new(),
        fail: Vec::new(),
        unsupported: 0,
    };
    for id in ids {
        let scene = scene(id);
        let reference = oracle::run_reference(&scene);
        match run_candidate(&scene, &reference, candidate).verdict {
            Verdict::Pass => t.pass.push(id.clone()),
            Verdict::Fail(why) => t.fail.push((id.clone(), why.join("; "))),
            Verdict::Unsupported(_) => t.unsupported += 1,
            Verdict::Error(why) => panic!("{id}: {why}"),
            Verdict::Flaky(_) => panic!("{id}: flaky in a single drawing"),
        }
    }
    eprintln!(
        "{}: {} pass, {} fail, {} unsupported",
        candidate.name(),
        t.pass.len(),
        t.fail.len(),
        t.unsupported
    );
    t
}

#[test]
fn production_has_none_of_these_findings() {
    let p = probe_of("production");
    assert_eq!(p.sampler, SamplerKind::Point);
    assert!(
        p.truncation.starts_with("does not truncate"),
        "{}",
        p.truncation
    );
    assert_eq!(p.vertex_precision, "exact");
    assert_eq!(p.edge_precision, "as the vertices");
    assert_eq!(p.subpixel, "exact");
    assert!(!p
        .departures
        .iter()
        .any(|d| d.contains("truncated") || d.contains("Slanted edges") || d.contains("outline")));
}

#[test]
fn truncation_to_whole_pixels_is_found_and_named_with_its_scene() {
    for name in ["foil-truncate", "foil-truncate-undeclared"] {
        let p = probe_of(name);
        assert!(
            p.truncation
                .starts_with("truncates vertices to whole pixels"),
            "{name}: {}",
            p.truncation
        );
        assert!(p.truncation.contains("[2.625, 6.375]"), "{}", p.truncation);
        assert_eq!(p.subpixel_bits, Some(0), "{name}: {}", p.subpixel);
        assert!(p.subpixel.contains("truncated to whole pixels"));
        assert!(
            p.departures
                .iter()
                .any(|d| d.starts_with("Vertices are truncated to whole pixels")),
            "{:?}",
            p.departures
        );
        // Never a word on a grid it did not measure.
        assert!(!p.departures.iter().any(|d| d.contains("snap to 0")));
    }
    let honest = probe_of("foil-truncate");
    assert_eq!(
        honest.declared_snapping.as_deref(),
        Some("declares truncation to whole pixels; measured 0 (agrees)")
    );
    assert_eq!(probe_of("foil-truncate-undeclared").declared_snapping, None);
}

#[test]
fn truncation_declared_passes_the_triangles_and_undeclared_is_caught() {
    let ids = family("triangles");
    let honest = tally(&ids, by_name("foil-truncate").unwrap().as_ref());
    assert!(honest.fail.is_empty(), "{:#?}", honest.fail);
    assert!(honest.pass.len() > 30, "{}", honest.pass.len());
    let liar = tally(&ids, by_name("foil-truncate-undeclared").unwrap().as_ref());
    assert!(liar.fail.len() >= 10, "{}", liar.fail.len());
    assert!(liar.fail.iter().all(|(_, why)| !why.is_empty()));
}

#[test]
fn coarse_edge_stepping_is_measured_apart_from_the_vertex_grid() {
    let p = probe_of("foil-coarse-edges");
    assert_eq!(p.sampler, SamplerKind::Point);
    assert_eq!(p.sample_position, "centre");
    assert_eq!(p.vertex_resolved.x, Some(8));
    assert_eq!(p.vertex_resolved.y, Some(8));
    assert_eq!(p.vertex_precision, "8 bits");
    assert_eq!(p.subpixel_bits, Some(8), "{}", p.subpixel);
    // Three rows down a slanted edge, x resolves what a 1/16 px step per
    // row keeps (the y sweep's edges run across rows, stepped differently).
    let x = p.subpixel_resolved.x.unwrap();
    assert!(x < 8, "edges resolve x {x}");
    assert!(
        p.edge_precision
            .ends_with("stepped coarser than the vertex grid"),
        "{}",
        p.edge_precision
    );
    assert!(
        p.departures
            .iter()
            .any(|d| d.starts_with("Slanted edges resolve")),
        "{:?}",
        p.departures
    );
    // The 8-bit vertex grid is D3D11's: no departure for it.
    assert!(!p.departures.iter().any(|d| d.contains("Vertices snap")));
    assert!(p.precision_measured_on.contains("first sample row"));
}

#[test]
fn coarse_edge_stepping_fails_slanted_triangles() {
    let t = tally(
        &family("triangles"),
        by_name("foil-coarse-edges").unwrap().as_ref(),
    );
    assert!(t.fail.len() >= 5, "{}", t.fail.len());
    assert!(t.pass.len() >= 5, "{}", t.pass.len());
}

#[test]
fn outline_over_fill_is_told_from_any_coverage() {
    let p = probe_of("foil-outline-over-fill");
    assert_eq!(
        p.sampler,
        SamplerKind::OutlineOverFill,
        "{}",
        p.sampler_evidence
    );
    assert!(
        p.sampler_evidence.contains("undrawn"),
        "{}",
        p.sampler_evidence
    );
    assert_eq!(p.fill_rule, None);
    assert!(p.subpixel.starts_with("not applicable"), "{}", p.subpixel);
    assert!(
        p.departures[0].contains("outline over fill"),
        "{:?}",
        p.departures
    );
    let any = probe_of("foil-any-coverage");
    assert_eq!(
        any.sampler,
        SamplerKind::AnyCoverage,
        "{}",
        any.sampler_evidence
    );
    assert!(any.sampler_evidence.contains("draws every one"));
}

#[test]
fn outline_over_fill_fails_meshes_by_overdraw() {
    let t = tally(
        &family("triangles"),
        by_name("foil-outline-over-fill").unwrap().as_ref(),
    );
    assert!(t.fail.len() >= 10, "{}", t.fail.len());
    assert!(
        t.fail
            .iter()
            .any(|(id, _)| id == "triangles/shared_edge_vertical"),
        "{:?}",
        t.fail
    );
}

#[test]
fn an_empty_antialiased_answer_is_said_to_draw_nothing() {
    let p = probe_of("foil-empty-antialias");
    assert_eq!(p.sampler, SamplerKind::Unknown);
    assert!(
        p.sampler_evidence.contains("draws nothing"),
        "{}",
        p.sampler_evidence
    );
    assert_eq!(p.fill_rule, None);
}

#[test]
fn an_empty_antialiased_answer_fails_wherever_an_area_exceeds_a_step() {
    let t = tally(
        &family("antialias"),
        by_name("foil-empty-antialias").unwrap().as_ref(),
    );
    assert!(t.fail.len() > 40, "{}", t.fail.len());
    for (id, why) in &t.fail {
        assert!(
            why.contains("nothing") || why.contains("step"),
            "{id}: {why}"
        );
    }
    // Legitimately passable: the seven sample-position probes, whose
    // triangles are too small for any primitive's exact area in a pixel
    // to exceed the default step (SPEC.md §14.4).
    assert_eq!(t.pass.len(), 7, "{:?}", t.pass);
    assert!(
        t.pass
            .iter()
            .all(|id| id.starts_with("antialias/probe_standard")),
        "{:?}",
        t.pass
    );
}

/// The antialias family judged as `foil-alpha256`'s bytes are read: as
/// declared (alpha over 256, saturating), as 8-bit unorm (alpha over 255:
/// `foil-alpha256-as-unorm`), and as unorm with a profile that declares
/// what probe measured.
#[test]
fn alpha_over_256_passes_as_declared_and_is_caught_read_as_unorm() {
    let ids = family("antialias");
    let declared = tally(&ids, by_name("foil-alpha256").unwrap().as_ref());
    assert!(declared.fail.is_empty(), "{:#?}", declared.fail);
    assert!(declared.pass.len() > 40, "{}", declared.pass.len());
    let unorm = tally(&ids, by_name("foil-alpha256-as-unorm").unwrap().as_ref());
    // Read as steps of 1/255, every whole pixel it draws (255/256) is not
    // 1: caught wherever a primitive covers a whole pixel, on piglit's
    // rule per primitive, and nowhere else (its fractions lie within
    // 1/512 of the exact areas, inside one step of 1/255).
    assert_eq!(
        unorm.fail.len(),
        ALPHA256_AS_UNORM_FAILURES,
        "{:#?}",
        unorm.fail
    );
    for (id, why) in &unorm.fail {
        assert!(why.contains("not exactly 1 or 0"), "{id}: {why}");
        assert!(!why.contains("more than"), "{id}: {why}");
    }
    assert_eq!(
        unorm.pass.len() + unorm.fail.len(),
        declared.pass.len(),
        "the same cases judged"
    );
    // A profile declaring the encoding probe measured judges it as the
    // honest foil is judged.
    let profile = probe_of("foil-alpha256-as-unorm");
    let profiled = Profiled {
        inner: by_name("foil-alpha256-as-unorm").unwrap(),
        rule: None,
        conventions: Declaration::default(),
        coverage: Some(CoverageEncoding {
            fraction: profile.coverage_encoding == Some("fraction"),
            bits: profile.coverage_bits.unwrap(),
        }),
    };
    let read_right = tally(&ids, &profiled);
    assert!(read_right.fail.is_empty(), "{:#?}", read_right.fail);
    assert_eq!(read_right.pass, declared.pass);
}

/// Bundled antialias cases (of 71) where a primitive covers a whole pixel,
/// which alpha over 256 read as alpha over 255 fails (the library,
/// judged over its own cases: 10).
const ALPHA256_AS_UNORM_FAILURES: usize = 49;

#[test]
fn probe_finds_the_coverage_encoding() {
    let honest = probe_of("foil-alpha256");
    assert_eq!(
        honest.sampler,
        SamplerKind::Area,
        "{}",
        honest.sampler_evidence
    );
    assert_eq!(honest.coverage_encoding, Some("fraction"));
    assert_eq!(honest.coverage_bits, Some(8));
    let words = honest.coverage.clone().unwrap();
    assert!(words.starts_with("8-bit fraction"), "{words}");
    assert!(words.contains("area × 256 capped at 255"), "{words}");
    assert!(
        words.contains("measured on two antialiased triangles"),
        "{words}"
    );
    assert!(
        honest
            .declared_coverage
            .as_deref()
            .is_some_and(|d| d.ends_with("(agrees)")),
        "{:?}",
        honest.declared_coverage
    );
    let liar = probe_of("foil-alpha256-as-unorm");
    assert_eq!(liar.coverage_encoding, Some("fraction"));
    assert_eq!(liar.coverage_bits, Some(8));
    assert_eq!(
        liar.declared_coverage.as_deref(),
        Some("declares coverage as 8-bit unorm (steps of 1/255); measured 8-bit fraction (steps of 1/256, saturating at 255/256)")
    );
    assert!(
        liar.departures
            .iter()
            .any(|d| d.contains("declares coverage as 8-bit unorm")),
        "{:?}",
        liar.departures
    );
    let unorm = probe_of("foil-alpha255");
    assert_eq!(unorm.coverage_encoding, Some("unorm"));
    assert_eq!(unorm.coverage_bits, Some(8));
    assert!(unorm
        .coverage
        .as_deref()
        .unwrap()
        .starts_with("8-bit unorm"));
    // A sample method and an unquantized area method have none to declare.
    let production = probe_of("production");
    assert_eq!(production.coverage_encoding, None);
    assert!(
        production
            .coverage
            .as_deref()
            .unwrap()
            .starts_with("a sample method"),
        "{:?}",
        production.coverage
    );
    let float = probe_of("area-f32");
    assert_eq!(float.coverage_encoding, None);
    assert!(
        float
            .coverage
            .as_deref()
            .unwrap()
            .starts_with("not quantized"),
        "{:?}",
        float.coverage
    );
}

/// Production drawing vertices snapped to 8 bits along x and 5 along y
/// (a grid finer across than down, as a library with 16.8 x and 26.6 y
/// coordinates has): probe's vertex cells measure each axis apart.
struct SplitGrid;

impl Rasterizer for SplitGrid {
    fn name(&self) -> &str {
        "split-grid"
    }
    fn capabilities(&self) -> rastercheck::rasterizer::Capabilities {
        by_name("production").unwrap().capabilities()
    }
    fn is_foil(&self) -> bool {
        true
    }
    fn rasterize(
        &self,
        scene: &Scene,
        plan: &rastercheck::plan::Plan,
    ) -> Result<rastercheck::frame::Frame, rastercheck::rasterizer::RasterError> {
        let mut s = scene.clone();
        for v in s.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
            v.x = v.x.snapped(8);
            v.y = v.y.snapped(5);
        }
        by_name("production").unwrap().rasterize(&s, plan)
    }
}

#[test]
fn the_vertex_grid_is_measured_along_x_and_along_y() {
    let p = probe::probe(&SplitGrid).unwrap();
    eprintln!("{}", p.describe());
    assert_eq!(p.vertex_resolved.x, Some(8), "{}", p.vertex_precision);
    assert_eq!(p.vertex_resolved.y, Some(5), "{}", p.vertex_precision);
    assert_eq!(p.vertex_precision, "x 8, y 5 bits");
    // No single grid to declare: SPEC's snapping is one.
    assert_eq!(p.subpixel_bits, None);
    assert!(p.precision_measured_on.contains("along x and along y"));
    // Production and the 4-bit foil keep one grid on both axes.
    let production = probe_of("production");
    assert_eq!(production.vertex_resolved.y, production.vertex_resolved.x);
    let snap4 = probe_of("foil-snap4");
    assert_eq!(
        (snap4.vertex_resolved.x, snap4.vertex_resolved.y),
        (Some(4), Some(4))
    );
    assert_eq!(snap4.subpixel_bits, Some(4));
}
