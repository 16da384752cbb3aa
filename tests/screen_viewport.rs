//! Screen-space cases beyond a device's largest viewport (SPEC.md §16.9):
//! a rasterizer that declares `clip_xy: clip-then-snap` and reports the
//! viewport it draws such a case through is judged against the reference
//! clipped exactly there, and the result names it. The declaration is held
//! to: one that reports a viewport and clips nowhere, or clips at another
//! rectangle, is caught; one that clips where it says passes.
//!
//! The candidates are production wrapped: `Clips` draws the case as
//! production draws it after clipping every primitive at a rectangle
//! (`harness::clipped::clip_scene`, the same exact clip the judge restates
//! with: the point here is the foils, which depart from it).

use std::path::PathBuf;

use rastercheck::frame::Frame;
use rastercheck::harness::clipped::clip_scene;
use rastercheck::harness::judge::{run_candidate, Verdict};
use rastercheck::harness::{discover, load, oracle};
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::{Capabilities, RasterError, Rasterizer, ScreenViewport, Snapping};
use rastercheck::scene::{parse_case, ClipXy, ClipZ, Limits, Scene};

fn scene(id: &str) -> Scene {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let file = discover::case_file(&root.join("cases").join(format!("{id}.json")));
    load::load(&file, &Limits::default()).unwrap()
}

/// The canvas of a 64 px case, as a viewport.
const CANVAS: ScreenViewport = ScreenViewport {
    origin: [0, 0],
    size: [64, 64],
};

/// Production, declaring `clip-then-snap` (when `declares`) and reporting
/// `reported` as its viewport, and clipping at `clips_at` (or nowhere).
struct Clips {
    reported: ScreenViewport,
    clips_at: Option<ScreenViewport>,
    declares: bool,
}

impl Rasterizer for Clips {
    fn name(&self) -> &str {
        "clips"
    }
    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        self.declares
            .then_some((ClipXy::ClipThenSnap, ClipZ::ClipThenSnap))
    }
    fn screen_viewport(&self, scene: &Scene, _plan: &Plan) -> Option<ScreenViewport> {
        (!scene.in_clip_space()).then_some(self.reported)
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut drawn = scene.clone();
        if let Some(window) = self.clips_at {
            clip_scene(&mut drawn, window, scene.rules.subpixel_bits);
        }
        Production.rasterize(&drawn, plan)
    }
}

fn judged(id: &str, candidate: &Clips) -> (Verdict, Option<ScreenViewport>) {
    let scene = scene(id);
    let reference = oracle::run_reference(&scene);
    let run = run_candidate(&scene, &reference, candidate);
    (run.verdict, run.judged.viewport)
}

/// Far triangles, far polygons, and far antialiased triangles.
const FAR: [&str; 3] = [
    "hard/far_b8_bands",
    "hard/poly_far_zigzag_b8_nonzero",
    "hard/aa_sliver_near_collinear_far_standard16",
];

#[test]
fn clipping_where_it_says_passes_and_is_named() {
    for id in FAR {
        let canvas = scene(id).canvas;
        let window = ScreenViewport {
            origin: [0, 0],
            size: [canvas.width, canvas.height],
        };
        let honest = Clips {
            reported: window,
            clips_at: Some(window),
            declares: true,
        };
        let (verdict, viewport) = judged(id, &honest);
        assert!(matches!(verdict, Verdict::Pass), "{id}: {verdict:?}");
        assert_eq!(viewport, Some(window), "{id}");
    }
}

#[test]
fn a_declared_viewport_it_does_not_clip_at_is_caught() {
    // Clips nowhere: production's unclipped frame, exact as the case states.
    let nowhere = Clips {
        reported: CANVAS,
        clips_at: None,
        declares: true,
    };
    let (verdict, _) = judged("hard/far_b8_bands", &nowhere);
    assert!(matches!(verdict, Verdict::Fail(_)), "{verdict:?}");
    // Clips at a larger rectangle than it reports.
    let elsewhere = Clips {
        reported: CANVAS,
        clips_at: Some(ScreenViewport {
            origin: [-64, -64],
            size: [192, 192],
        }),
        declares: true,
    };
    let (verdict, _) = judged("hard/far_b8_bands", &elsewhere);
    assert!(matches!(verdict, Verdict::Fail(_)), "{verdict:?}");
    // Reports a larger rectangle than it clips at.
    let smaller = Clips {
        reported: ScreenViewport {
            origin: [-64, -64],
            size: [192, 192],
        },
        clips_at: Some(CANVAS),
        declares: true,
    };
    let (verdict, _) = judged("hard/far_b8_bands", &smaller);
    assert!(matches!(verdict, Verdict::Fail(_)), "{verdict:?}");
}

#[test]
fn a_viewport_without_declared_clipping_restates_nothing() {
    // Not declaring clip-then-snap: the case is judged as stated (whole),
    // so production clipping at the canvas is caught and unclipped passes.
    let clipping = Clips {
        reported: CANVAS,
        clips_at: Some(CANVAS),
        declares: false,
    };
    let (verdict, viewport) = judged("hard/far_b8_bands", &clipping);
    assert_eq!(viewport, None);
    assert!(matches!(verdict, Verdict::Fail(_)), "{verdict:?}");
    let whole = Clips {
        clips_at: None,
        ..clipping
    };
    let (verdict, _) = judged("hard/far_b8_bands", &whole);
    assert!(matches!(verdict, Verdict::Pass), "{verdict:?}");
}

/// A 1 px canvas at 3 subpixel bits, found by `fuzz -r gl --seed 11
/// --family polygons --check coverage`: the degenerate far triangle puts
/// a vertex past every viewport, so the adapter draws through the canvas,
/// and the first triangle's edge crosses it at y = 0.4426 (x = 0) and
/// 0.5533 (x = 1). On the case's 1/8 grid both new vertices snap to 0.5,
/// putting the pixel centre on the edge (owned under bottom-left); on a
/// driver's 1/256 grid they do not, and the centre is outside.
const COARSE: &str = r#"{"name": "coarse", "canvas": {"width": 1, "height": 1},
  "rules": {"subpixel_bits": 3, "fill_rule": "bottom-left", "cull": "none"},
  "primitives": [{"triangle": [[-4, 0], [57, 6.75], [0, 0]]},
                 {"triangle": [[0, 0], [22038, 0], [0, 0]]}]}"#;

/// The 1 px canvas, as a viewport.
const PIXEL: ScreenViewport = ScreenViewport {
    origin: [0, 0],
    size: [1, 1],
};

/// Production declaring 8 subpixel bits and `clip-then-snap` at the
/// canvas, drawing the case's vertices on its own grid (all of
/// [`COARSE`]'s lie on it) and the new vertices snapped to `.0` bits.
struct NewVerticesAt(u32);

impl Rasterizer for NewVerticesAt {
    fn name(&self) -> &str {
        "new-vertices-at"
    }
    fn capabilities(&self) -> Capabilities {
        Production.capabilities()
    }
    fn fixed_clip_rules(&self) -> Option<(ClipXy, ClipZ)> {
        Some((ClipXy::ClipThenSnap, ClipZ::ClipThenSnap))
    }
    fn fixed_snapping(&self) -> Option<Snapping> {
        Some(Snapping::Bits(8))
    }
    fn screen_viewport(&self, _scene: &Scene, _plan: &Plan) -> Option<ScreenViewport> {
        Some(PIXEL)
    }
    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut drawn = scene.clone();
        clip_scene(&mut drawn, PIXEL, scene.rules.subpixel_bits);
        drawn.rules.subpixel_bits = Some(self.0);
        Production.rasterize(&drawn, plan)
    }
}

/// A case at fewer subpixel bits than the driver's own is restated at the
/// driver's (SPEC.md §16.9, `clipped::clip_scene_on_grid`): a driver that
/// snaps the new vertices to its 8 bits passes, and one that declares 8
/// bits but snaps them to the case's 3 is caught.
#[test]
fn new_vertices_are_judged_on_the_drivers_finer_grid() {
    let scene = parse_case(COARSE, "coarse.json", &Limits::default()).unwrap();
    let reference = oracle::run_reference(&scene);
    let driver = run_candidate(&scene, &reference, &NewVerticesAt(8));
    assert!(
        matches!(driver.verdict, Verdict::Pass),
        "{:?}",
        driver.verdict
    );
    assert_eq!(driver.judged.viewport, Some(PIXEL));
    let coarse = run_candidate(&scene, &reference, &NewVerticesAt(3));
    assert!(
        matches!(coarse.verdict, Verdict::Fail(_)),
        "{:?}",
        coarse.verdict
    );
}

/// A far case with attributes (`tests/data/far_values_clipped.json`,
/// SPEC.md §16.9) is restated clipped with its pieces' values from the
/// whole triangles, and said so; a candidate that clips at the viewport it
/// reports but draws the pieces without their values (production on the
/// polygons: a restatement that loses the values) is caught on them.
#[test]
fn a_clip_that_loses_the_values_is_caught() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/far_values_clipped.json");
    let text = std::fs::read_to_string(&path).unwrap();
    let scene = parse_case(&text, "far_values_clipped.json", &Limits::default()).unwrap();
    let canvas = ScreenViewport {
        origin: [0, 0],
        size: [scene.canvas.width, scene.canvas.height],
    };
    let loses = Clips {
        reported: canvas,
        clips_at: Some(canvas),
        declares: true,
    };
    let reference = oracle::run_reference(&scene);
    let run = run_candidate(&scene, &reference, &loses);
    assert!(run.judged.viewport_values, "its values not restated");
    let Verdict::Fail(reasons) = &run.verdict else {
        panic!("{:?}", run.verdict);
    };
    assert!(
        reasons.iter().any(|r| r.starts_with("attribute 0")),
        "{reasons:?}"
    );
    // Its coverage is the restated case's: only the values are wrong.
    let coverage = &run.metrics.as_ref().unwrap().coverage;
    assert_eq!((coverage.missing, coverage.extra), (0, 0), "{reasons:?}");
}
