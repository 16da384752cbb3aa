//! Point checks every driver adapter that claims `points` runs
//! (`vulkan.rs`, `gl/`): scenes of points drawn by the driver against the
//! point rule (SPEC.md §17) computed here, directly, per sample: the
//! square [X − h, X + h] × [Y − h, Y + h] of the snapped centre, its edges
//! owning samples as the fill rule says, and in clip space the centre
//! placed by the viewport and tested against the planes. Positions and
//! sizes are dyadic with few bits, so every number here is exact in f64.

use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::rasterizer::{RasterError, Rasterizer};
use rastercheck::scene::{FillRule, Number, Point, PointClip, Primitive, Scene, Vertex};

use super::inline;

/// One point: its position (screen pixels, or clip x, y, z, w) and size.
#[derive(Clone, Copy, Debug)]
pub struct Spot {
    pub at: [f64; 4],
    pub size: f64,
}

/// A screen-space point at (x, y) of side `size`.
pub fn spot(x: f64, y: f64, size: f64) -> Spot {
    Spot {
        at: [x, y, 0.0, 1.0],
        size,
    }
}

fn number(v: f64) -> Number {
    Number::from_string(&format!("{v:?}")).expect("a dyadic number")
}

/// A `canvas`² scene of `spots` in scene order, each with attribute
/// 10·(index + 1), under `rules` (inner JSON of the case's `rules`),
/// `antialias` (JSON of the case's `antialias`, or none) and, in clip
/// space, `viewport` (JSON of the case's `viewport`).
pub fn scene(
    canvas: u32,
    spots: &[Spot],
    rules: &str,
    antialias: Option<&str>,
    viewport: Option<&str>,
) -> Scene {
    let effects = antialias.map_or(String::new(), |a| {
        format!(r#""effects": {{"antialias": {a}}},"#)
    });
    let view = viewport.map_or(String::new(), |v| format!(r#""viewport": {v},"#));
    // A stand-in triangle for the case's form; its primitives are replaced.
    let vertex = if viewport.is_some() {
        r#"{"clip": [0, 0, 0, 1], "attributes": [1]}"#
    } else {
        r#"{"position": [0, 0], "attributes": [1]}"#
    };
    let mut scene = inline(&format!(
        r#"{{"name": "points", "canvas": {{"width": {canvas}, "height": {canvas}}},
            {effects} {view}
            "rules": {{{rules}}},
            "primitives": [{{"triangle": [{vertex}, {vertex}, {vertex}]}}]}}"#
    ));
    scene.primitives = spots
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let mut v = Vertex::at(number(s.at[0]), number(s.at[1]));
            v.z = number(s.at[2]);
            v.w = number(s.at[3]);
            v.attributes = vec![Number::from_int(10 * (i as i64 + 1))];
            Primitive::Point(Point {
                vertices: [v],
                size: number(s.size),
            })
        })
        .collect();
    // The stand-in's flags: depth where a point has z.
    scene.has_depth |= spots.iter().any(|s| s.at[2] != 0.0);
    scene
}

/// The frame `candidate` draws of `scene`, or the test fails.
pub fn drawn(candidate: &dyn Rasterizer, scene: &Scene) -> Frame {
    candidate
        .rasterize(scene, &Plan::for_scene(scene))
        .unwrap_or_else(|e| panic!("{}: {e}", candidate.name()))
}

/// Whether `s` lies in [c − h, c + h] with the low end closed when
/// `low_closed` and the high end closed when `high_closed`.
fn within(s: f64, c: f64, h: f64, low_closed: bool, high_closed: bool) -> bool {
    let lo = if low_closed { s >= c - h } else { s > c - h };
    let hi = if high_closed { s <= c + h } else { s < c + h };
    lo && hi
}

/// Which ends of the square's x and y ranges are closed under `rule`
/// (y down): `[x low, x high, y low, y high]`.
fn closed_ends(rule: FillRule) -> [bool; 4] {
    match rule {
        FillRule::TopLeft => [true, false, true, false],
        FillRule::BottomRight => [false, true, false, true],
        FillRule::TopRight => [false, true, true, false],
        FillRule::BottomLeft => [true, false, false, true],
        FillRule::AllEdges => [true; 4],
    }
}

/// The snapped centre of a point in pixels, with its depth, or `None`
/// when clip space discards it (w ≤ 0, depth clip, or the side planes
/// under `pop`): the rule of SPEC.md §17.
fn centre(scene: &Scene, s: &Spot) -> Option<[f64; 2]> {
    let bits = f64::from(scene.rules.subpixel_bits.expect("snapped scenes"));
    let snap = |v: f64| (v * bits.exp2()).round_ties_even() / bits.exp2();
    let Some(view) = &scene.viewport else {
        return Some([snap(s.at[0]), snap(s.at[1])]);
    };
    let [x, y, z, w] = s.at;
    if w <= 0.0 {
        return None;
    }
    let clip = &scene.rules.clip;
    if clip.depth == rastercheck::scene::DepthMode::Clip && (z < 0.0 || z > w) {
        return None;
    }
    if clip.points == PointClip::Pop && (x < -w || x > w || y < -w || y > w) {
        return None;
    }
    let f = |n: &Number| n.to_f64_lossy();
    let xf = f(&view.x) + f(&view.width) * (x / w + 1.0) / 2.0;
    let yf = f(&view.y) + f(&view.height) * (y / w + 1.0) / 2.0;
    Some([snap(xf), snap(yf)])
}

/// Every sample's coverage count under the point rule with `rule` for
/// the edges, computed here per sample (pixel centres, or the scene's
/// sample positions).
pub fn expected(scene: &Scene, rule: FillRule) -> Vec<u16> {
    let plan = Plan::for_scene(scene);
    let offsets: Vec<[f64; 2]> = match &plan.antialias {
        Some(a) => {
            let one = f64::from(a.position_bits).exp2();
            a.offsets
                .iter()
                .map(|o| [f64::from(o[0]) / one, f64::from(o[1]) / one])
                .collect()
        }
        None => vec![[0.5, 0.5]],
    };
    let [xl, xh, yl, yh] = closed_ends(rule);
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut counts = vec![0u16; (w * h) as usize * offsets.len()];
    for p in &scene.primitives {
        let Primitive::Point(point) = p else {
            continue;
        };
        let v = &point.vertices[0];
        let spot = Spot {
            at: [&v.x, &v.y, &v.z, &v.w].map(Number::to_f64_lossy),
            size: point.size.to_f64_lossy(),
        };
        let Some([cx, cy]) = centre(scene, &spot) else {
            continue;
        };
        let half = spot.size / 2.0;
        for row in 0..h {
            for col in 0..w {
                for (k, o) in offsets.iter().enumerate() {
                    let (sx, sy) = (f64::from(col) + o[0], f64::from(row) + o[1]);
                    if within(sx, cx, half, xl, xh) && within(sy, cy, half, yl, yh) {
                        counts[((row * w + col) as usize) * offsets.len() + k] += 1;
                    }
                }
            }
        }
    }
    counts
}

/// The samples where `frame`'s coverage differs from `want`.
pub fn departures(frame: &Frame, want: &[u16]) -> usize {
    assert_eq!(frame.coverage.len(), want.len(), "sample counts");
    frame
        .coverage
        .iter()
        .zip(want)
        .filter(|(a, b)| a != b)
        .count()
}

/// The fill rules under which the driver's frame of `scene` is the point
/// rule's, sample for sample.
pub fn matching_rules(candidate: &dyn Rasterizer, scene: &Scene) -> Vec<FillRule> {
    let frame = drawn(candidate, scene);
    FillRule::ALL
        .into_iter()
        .filter(|&r| departures(&frame, &expected(scene, r)) == 0)
        .collect()
}

/// A text picture of `frame`'s coverage (one character per sample of a
/// one-sample frame), for the measurements' output.
pub fn picture(frame: &Frame) -> String {
    let n = frame.samples as usize;
    (0..frame.height as usize)
        .map(|r| {
            (0..frame.width as usize)
                .map(|c| {
                    let covered = (0..n)
                        .filter(|s| frame.coverage[(r * frame.width as usize + c) * n + s] > 0)
                        .count();
                    char::from_digit(covered as u32, 36).unwrap_or('*')
                })
                .collect::<String>()
                + "\n"
        })
        .collect()
}

/// Prints what the driver does with points: which fill rules its squares
/// follow at several sizes and subpixel positions, and its pictures. A
/// measurement, not a check (`--nocapture`).
pub fn measure(candidate: &dyn Rasterizer) {
    let sizes = [
        1.0,
        2.0,
        3.0,
        0.5,
        2.5,
        1.25,
        4.0,
        0.25,
        0.125,
        1.0 + 1.0 / 256.0,
    ];
    let positions = [
        (8.0, 8.0),
        (8.5, 8.5),
        (8.25, 8.75),
        (8.125, 8.375),
        (8.0 + 1.0 / 256.0, 8.0 - 1.0 / 256.0),
    ];
    for size in sizes {
        for (x, y) in positions {
            let scene = scene(16, &[spot(x, y, size)], "", None, None);
            measure_rules(candidate, &scene, &format!("size {size} at ({x}, {y})"));
        }
    }
    // Clip space: 16×16 viewport at (4, 4) in a 24×24 canvas; w = 2.
    let viewport = r#"{"x": 4, "y": 4, "width": 16, "height": 16}"#;
    let clip_spots = [
        ("inside", [0.0, 0.0, 1.0, 2.0], 4.0),
        ("centre just outside x = w", [2.0625, 0.0, 1.0, 2.0], 4.0),
        ("centre on x = w", [2.0, 0.0, 1.0, 2.0], 4.0),
        ("centre just outside x = -w", [-2.0625, 0.0, 1.0, 2.0], 4.0),
        ("centre just outside y = w", [0.0, 2.0625, 1.0, 2.0], 4.0),
        ("centre just outside y = -w", [0.0, -2.0625, 1.0, 2.0], 4.0),
        ("square over the viewport edge", [1.75, 0.0, 1.0, 2.0], 6.0),
        ("z just below 0", [0.0, 0.0, -0.0625, 2.0], 4.0),
        ("z just above w", [0.0, 0.0, 2.0625, 2.0], 4.0),
        ("w negative", [0.0, 0.0, -1.0, -2.0], 4.0),
    ];
    for depth in ["clip", "clamp"] {
        for (what, at, size) in clip_spots {
            let rules = format!(r#""depth": "{depth}""#);
            let scene = scene(24, &[Spot { at, size }], &rules, None, Some(viewport));
            match candidate.rasterize(&scene, &Plan::for_scene(&scene)) {
                Ok(frame) => {
                    let n = frame.coverage.iter().filter(|&&c| c > 0).count();
                    let mut fits = vec![];
                    for points in [PointClip::Pop, PointClip::GuardBand] {
                        let mut s = scene.clone();
                        s.rules.clip.points = points;
                        for r in FillRule::ALL {
                            if departures(&frame, &expected(&s, r)) == 0 {
                                fits.push(format!("{}/{}", points.name(), r.name()));
                            }
                        }
                    }
                    let d = frame
                        .depth
                        .as_ref()
                        .and_then(|d| frame.coverage.iter().position(|&c| c > 0).map(|i| d[i]));
                    eprintln!("MEASURE {} clip depth {depth} {what}: {n} samples, depth {d:?}, fits {fits:?}", candidate.name());
                    if fits.is_empty() {
                        eprintln!("{}", picture(&frame));
                    }
                }
                Err(e) => eprintln!("MEASURE {} clip {depth} {what}: {e}", candidate.name()),
            }
        }
    }
    // Multisampled: the standard 4× pattern.
    for size in [1.0, 2.0, 2.5, 0.5] {
        for (x, y) in [(8.0, 8.0), (8.125, 8.375), (8.375, 8.125)] {
            let scene = scene(
                16,
                &[spot(x, y, size)],
                "",
                Some(r#"{"samples": 4, "pattern": "standard"}"#),
                None,
            );
            measure_rules(
                candidate,
                &scene,
                &format!("msaa4 size {size} at ({x}, {y})"),
            );
        }
    }
}

/// Sizes the checks draw: whole and half pixels (halves on quarters), and
/// a wide one; on GL's granularity of 0.1 from 1 as on Vulkan's.
const SIZES: [f64; 7] = [1.0, 2.0, 3.0, 2.5, 1.5, 4.0, 7.5];

/// Centres on subpixel fractions: on pixel corners and centres (every
/// edge of an integer or half-integer square through a row of samples),
/// quarters, eighths and the grid's last bit.
const CENTRES: [(f64, f64); 6] = [
    (8.0, 8.0),
    (8.5, 8.5),
    (8.25, 8.75),
    (8.125, 8.375),
    (7.875, 8.625),
    (8.0 + 1.0 / 256.0, 8.0 - 1.0 / 256.0),
];

/// The rule `candidate`'s squares follow: its declared fill rule.
fn own_rule(candidate: &dyn Rasterizer) -> FillRule {
    candidate
        .fixed_fill_rule()
        .expect("a driver declares its rule")
}

/// Asserts the driver's frame of `scene` is the point rule's under its
/// own fill rule, sample for sample, and draws something where the rule
/// does.
pub fn assert_follows_the_rule(candidate: &dyn Rasterizer, scene: &Scene, what: &str) {
    let frame = drawn(candidate, scene);
    // At the driver's own subpixel bits (SwiftShader snaps to 4), as a run
    // judges it.
    let own = rastercheck::harness::profile::OwnConventions::of(candidate, scene).restate(scene);
    let want = expected(&own, own_rule(candidate));
    let off = departures(&frame, &want);
    assert!(
        off == 0,
        "{} {what}: {off} samples depart from the point rule\n{}",
        candidate.name(),
        picture(&frame)
    );
    assert!(
        want.iter().all(|&c| c == 0) || frame.coverage.iter().any(|&c| c > 0),
        "{what}: drew nothing"
    );
}

/// Screen space: every size at every centre, one point per scene; then
/// all sizes at once, overlapping, whose flat attribute and depth are
/// each covering point's, the last drawn on top.
pub fn assert_screen_points(candidate: &dyn Rasterizer) {
    for size in SIZES {
        for (x, y) in CENTRES {
            let scene = scene(16, &[spot(x, y, size)], "", None, None);
            assert_follows_the_rule(candidate, &scene, &format!("size {size} at ({x}, {y})"));
        }
    }
    // Centres outside the canvas (and the target's viewport): the rule
    // draws the part of the square on the canvas; a driver that pops
    // points by their centre draws nothing, and its adapter must refuse.
    let pops = candidate.fixed_point_clip() == Some(PointClip::Pop);
    for (x, y) in [
        (17.0, 8.0),
        (-1.5, 8.25),
        (8.5, 17.25),
        (-1.0, -1.0),
        (0.25, 8.0),
    ] {
        let scene = scene(16, &[spot(x, y, 4.0)], "", None, None);
        let what = format!("size 4 at ({x}, {y}), off the canvas");
        if pops {
            assert_refused(
                candidate,
                &scene,
                "less than half a pixel inside the canvas",
            );
        } else {
            assert_follows_the_rule(candidate, &scene, &what);
        }
    }
    let spots: Vec<Spot> = SIZES
        .iter()
        .zip(CENTRES.iter().cycle())
        .map(|(&size, &(x, y))| Spot {
            at: [x - 1.0 + size / 2.0, y, 0.125 * size, 1.0],
            size,
        })
        .collect();
    let scene = scene(16, &spots, "", None, None);
    assert_follows_the_rule(candidate, &scene, "overlapping points");
    let frame = drawn(candidate, &scene);
    let depth = frame.depth.as_ref().expect("points write depth");
    for (i, &c) in frame.coverage.iter().enumerate() {
        if c == 0 {
            continue;
        }
        // `last` is index + 1 of the last point over the sample.
        let last = frame.last[i] as usize;
        assert_eq!(
            frame.attributes[0][i],
            10.0 * last as f64,
            "sample {i}: flat value"
        );
        assert_eq!(
            depth[i],
            spots[last - 1].at[2],
            "sample {i}: the point's depth"
        );
    }
}

/// Clip space: a 16×16 viewport at (4, 4) of a 24×24 canvas. Points inside
/// it at several w (the centre divided and placed by the viewport), on
/// its edges (the square touching them from inside), and the depth
/// planes: discarded under `depth: clip`, drawn with their depth clamped
/// under `clamp`; w ≤ 0 discarded.
pub fn assert_clip_points(candidate: &dyn Rasterizer) {
    let viewport = r#"{"x": 4, "y": 4, "width": 16, "height": 16}"#;
    let spots = [
        ("centre", [0.0, 0.0, 1.0, 2.0], 4.0),
        (
            "w = 1/2, quarter pixels",
            [0.0703125, -0.1015625, 0.25, 0.5],
            2.5,
        ),
        ("w = 4", [-1.25, 2.5, 1.0, 4.0], 3.0),
        ("touching the right edge", [1.5, 0.0, 1.0, 2.0], 4.0),
        (
            "touching the top-left corner",
            [-1.75, -1.75, 1.0, 2.0],
            2.0,
        ),
        ("z below 0", [0.0, 0.0, -0.0625, 2.0], 4.0),
        ("z above w", [0.0, 0.0, 2.0625, 2.0], 4.0),
        ("w negative", [0.0, 0.0, -1.0, -2.0], 4.0),
    ];
    for depth in ["clip", "clamp"] {
        for (what, at, size) in spots {
            let rules = format!(r#""depth": "{depth}""#);
            let scene = scene(24, &[Spot { at, size }], &rules, None, Some(viewport));
            let mut judged = scene.clone();
            judged.rules.clip.points = candidate.fixed_point_clip().expect("declared");
            let frame = drawn(candidate, &scene);
            let off = departures(&frame, &expected(&judged, own_rule(candidate)));
            assert!(
                off == 0,
                "{} depth {depth}, {what}: {off} samples depart\n{}",
                candidate.name(),
                picture(&frame)
            );
            let covered: Vec<usize> = (0..frame.coverage.len())
                .filter(|&i| frame.coverage[i] > 0)
                .collect();
            let want_depth = match (depth, what) {
                (_, "w negative") | ("clip", "z below 0" | "z above w") => None,
                ("clamp", "z below 0") => Some(0.0),
                ("clamp", "z above w") => Some(1.0),
                _ => Some(at[2] / at[3]),
            };
            assert_eq!(
                covered.is_empty(),
                want_depth.is_none(),
                "depth {depth}, {what}: drawn?"
            );
            let depths = frame.depth.as_ref().expect("clip space writes depth");
            for i in covered {
                let d = want_depth.expect("drawn");
                assert!(
                    (depths[i] - d).abs() < 1e-6,
                    "depth {depth}, {what}: sample {i} depth {}, want {d}",
                    depths[i]
                );
                assert_eq!(
                    frame.attributes[0][i], 10.0,
                    "depth {depth}, {what}: flat value"
                );
            }
        }
    }
}

/// Multisampled: the standard 4× pattern (the driver's own samples where
/// the adapter draws natively) and a stratified one (shifted passes).
///
/// A pattern whose offsets are off the driver's subpixel grid is refused
/// for it (a device limit: SwiftShader's 4 bits against the stratified
/// pattern's 8) and left out; the 4-bit n-rooks pattern is on every
/// driver's grid, so at least two patterns are drawn.
pub fn assert_multisampled_points(candidate: &dyn Rasterizer) {
    let mut drawn_patterns = 0;
    for pattern in [
        r#"{"samples": 4, "pattern": "standard"}"#,
        r#"{"samples": 4, "pattern": "stratified"}"#,
        r#"{"samples": 4, "pattern": "n-rooks", "seed": 7, "position_bits": 4}"#,
    ] {
        let first = scene(16, &[spot(8.0, 8.0, 1.0)], "", Some(pattern), None);
        if let Err(RasterError::Unsupported(why)) =
            candidate.rasterize(&first, &Plan::for_scene(&first))
        {
            assert!(why.contains("off the driver's grid"), "{pattern}: {why}");
            eprintln!("{}: {pattern} left out: {why}", candidate.name());
            continue;
        }
        drawn_patterns += 1;
        for size in [1.0, 2.0, 2.5, 1.5] {
            for (x, y) in [(8.0, 8.0), (8.125, 8.375), (8.375, 8.125), (7.875, 8.625)] {
                let scene = scene(16, &[spot(x, y, size)], "", Some(pattern), None);
                assert_follows_the_rule(
                    candidate,
                    &scene,
                    &format!("{pattern}: size {size} at ({x}, {y})"),
                );
            }
        }
    }
    assert!(drawn_patterns >= 2, "only {drawn_patterns} patterns drawn");
}

/// Points the driver cannot draw as the rule's square are refused, each
/// with its reason.
pub fn assert_point_refusals(candidate: &dyn Rasterizer) {
    // A viewport whose left side lies 1/1024 px past the centres of
    // column 4, where Mesa's whole-pixel rectangle ((int)(x + 0.499))
    // departs from the rule.
    let viewport = r#"{"x": 4.5009765625, "y": 4, "width": 16, "height": 16}"#;
    let cases = [
        // Under one pixel (below the range, or drawn one pixel wide), off
        // the 8-bit grid by half a step, beyond the range.
        (
            scene(16, &[spot(8.0, 8.0, 0.5)], "", None, None),
            "point size 0.5: ",
        ),
        (
            scene(16, &[spot(8.0, 8.0, 1.0 + 1.0 / 256.0)], "", None, None),
            "point size 1.00390625: ",
        ),
        (
            scene(16, &[spot(8.0, 8.0, 1.0e6)], "", None, None),
            "point size 1000000: ",
        ),
        (
            scene(
                24,
                &[Spot {
                    at: [1.75, 0.0, 1.0, 2.0],
                    size: 6.0,
                }],
                "",
                None,
                Some(viewport),
            ),
            "past a pixel centre",
        ),
        (
            scene(
                24,
                &[Spot {
                    at: [-2.0, 0.0, 1.0, 2.0],
                    size: 4.0,
                }],
                "",
                None,
                Some(viewport),
            ),
            "past a pixel centre",
        ),
    ];
    for (scene, why) in cases {
        assert_refused(candidate, &scene, why);
    }
}

/// Squares reaching outside a viewport rectangle on whole pixels are drawn
/// and pass under the driver's own `point_bounds` (the viewport, as Mesa
/// draws them), and the frame departs from the canvas-bounded rule: the
/// square is cut at the viewport's side, not drawn whole.
pub fn assert_squares_cut_at_the_viewport(candidate: &dyn Rasterizer) {
    use rastercheck::harness::judge::Verdict;
    use rastercheck::scene::PointBounds;
    assert_eq!(candidate.fixed_point_bounds(), Some(PointBounds::Viewport));
    let viewport = r#"{"x": 4, "y": 4, "width": 16, "height": 16}"#;
    // Inside near x = w (X = 19, [16, 22]), on x = w (X = 20, [18, 22]).
    for (x, size, cut) in [(1.75, 6.0, 24), (2.0, 4.0, 8)] {
        let scene = scene(
            24,
            &[Spot {
                at: [x, 0.0, 1.0, 2.0],
                size,
            }],
            "",
            None,
            Some(viewport),
        );
        let (_, run) = super::run(&scene, candidate);
        assert_eq!(run.verdict, Verdict::Pass, "x = {x}: {:?}", run.verdict);
        let frame = run.frame.expect("a frame");
        let drawn = frame.coverage.iter().filter(|&&c| c > 0).count();
        assert_eq!(drawn, cut, "x = {x}:\n{}", picture(&frame));
        // With the viewport's left side through the centres of column 4,
        // Mesa's whole-pixel rectangle keeps the columns the rule keeps.
        let mut through = scene.clone();
        through.viewport.as_mut().unwrap().x = rastercheck::scene::Number::ratio(9, 2);
        let (_, on_centres) = super::run(&through, candidate);
        assert_eq!(
            on_centres.verdict,
            Verdict::Pass,
            "x = {x}, viewport from 4.5"
        );
        let mut whole = scene.clone();
        whole.rules.clip.bounds = PointBounds::Canvas;
        let canvas_bounded = rastercheck::reference::render(&whole, &Plan::for_scene(&whole));
        assert!(
            frame.coverage != canvas_bounded.coverage,
            "x = {x}: the canvas-bounded square is told apart"
        );
    }
}

/// probe, which knows nothing of the driver's declarations, finds the
/// point clipping and bounds the driver declares (`fixed_point_clip`,
/// `fixed_point_bounds`) as its own, consistently.
pub fn assert_probe_finds_declared_point_clipping(candidate: &dyn Rasterizer) {
    let found = rastercheck::explore::probe::probe_points(candidate).expect("draws points");
    assert!(found.consistent && !found.follows_case, "{found:?}");
    assert_eq!(found.scenes, 5, "every probe point drawn: {found:?}");
    let declared = candidate.fixed_point_clip().expect("declared").name();
    assert_eq!(found.clip_points(), Some(declared), "{found:?}");
    let bounds = candidate.fixed_point_bounds().expect("declared").name();
    assert_eq!(found.point_bounds(), Some(bounds), "{found:?}");
}

/// Asserts `candidate` refuses `scene` with a reason containing `why`.
fn assert_refused(candidate: &dyn Rasterizer, scene: &Scene, why: &str) {
    match candidate.rasterize(scene, &Plan::for_scene(scene)) {
        Err(rastercheck::rasterizer::RasterError::Unsupported(reason)) => assert!(
            reason.contains(why),
            "{}: refused for {reason:?}, want {why:?}",
            candidate.name()
        ),
        other => panic!(
            "{}: want unsupported ({why}), got {:?}",
            candidate.name(),
            other.map(|f| picture(&f))
        ),
    }
}

/// The checks can fail: the driver's frames depart from a rule with the
/// other ties (the opposite fill rule), from squares whose size is
/// snapped to whole pixels, and from squares around an unsnapped centre.
pub fn assert_wrong_rules_are_caught(candidate: &dyn Rasterizer) {
    let own = own_rule(candidate);
    let opposite = match own {
        FillRule::TopLeft => FillRule::BottomRight,
        FillRule::BottomRight => FillRule::TopLeft,
        FillRule::TopRight => FillRule::BottomLeft,
        FillRule::BottomLeft => FillRule::TopRight,
        FillRule::AllEdges => FillRule::TopLeft,
    };
    // Size 3 at a pixel corner: all four edges run through samples.
    let tie = scene(16, &[spot(8.0, 8.0, 3.0)], "", None, None);
    assert!(
        departures(&drawn(candidate, &tie), &expected(&tie, opposite)) > 0,
        "the opposite ties"
    );
    // Size 2.5 at a pixel centre covers 3 × 3 samples, size 2 there 2 × 2;
    // at (11.25, 11.75) it covers 2 columns, size 3 there 3.
    let quarter = scene(
        16,
        &[spot(4.5, 4.5, 2.5), spot(11.25, 11.75, 2.5)],
        "",
        None,
        None,
    );
    let frame = drawn(candidate, &quarter);
    for size in [2.0, 3.0] {
        let mut wrong = quarter.clone();
        for p in &mut wrong.primitives {
            if let Primitive::Point(p) = p {
                p.size = number(size);
            }
        }
        assert!(
            departures(&frame, &expected(&wrong, own)) > 0,
            "size {size} for 2.5 is caught"
        );
    }
    // A centre 1/512 off the 8-bit grid snaps onto the corner (8, 8); a
    // rule that did not snap it (16 bits keep it) moves two edges off
    // their samples.
    let off_grid = scene(
        16,
        &[spot(8.0 + 1.0 / 512.0, 8.0 + 1.0 / 512.0, 3.0)],
        "",
        None,
        None,
    );
    let frame = drawn(candidate, &off_grid);
    assert_eq!(
        departures(&frame, &expected(&off_grid, own)),
        0,
        "the snapped centre"
    );
    let mut unsnapped = off_grid.clone();
    unsnapped.rules.subpixel_bits = Some(16);
    assert!(
        departures(&frame, &expected(&unsnapped, own)) > 0,
        "an unsnapped centre is caught"
    );
}

/// `OwnConventions` judges a clip-space case with points under the
/// candidate's `fixed_point_clip`, and a case without points under the
/// case's own `clip_points`.
pub fn assert_judged_under_own_point_clip(candidate: &dyn Rasterizer) {
    use rastercheck::harness::profile::OwnConventions;
    let viewport = r#"{"x": 4, "y": 4, "width": 16, "height": 16}"#;
    let own = candidate
        .fixed_point_clip()
        .expect("a driver declares its point clipping");
    let at = Spot {
        at: [0.0, 0.0, 1.0, 2.0],
        size: 2.0,
    };
    let mut scene = scene(24, &[at], "", None, Some(viewport));
    for stated in [PointClip::Pop, PointClip::GuardBand] {
        scene.rules.clip.points = stated;
        let judged = OwnConventions::of(candidate, &scene).clip.map(|c| c.points);
        assert_eq!(judged.unwrap_or(stated), own, "stated {}", stated.name());
        if stated != own {
            let conventions = OwnConventions::of(candidate, &scene);
            assert!(conventions
                .describe()
                .contains(&format!("clip_points {}", own.name())));
        }
    }
    // Its `point_bounds` too: a case stating canvas is judged under the
    // driver's viewport bound, and says so.
    if let Some(bounds) = candidate.fixed_point_bounds() {
        scene.rules.clip.points = own;
        scene.rules.clip.bounds = rastercheck::scene::PointBounds::Canvas;
        let conventions = OwnConventions::of(candidate, &scene);
        assert_eq!(conventions.clip.map(|c| c.bounds), Some(bounds));
        assert!(conventions
            .describe()
            .contains(&format!("point_bounds {}", bounds.name())));
    }
    let mut triangles = scene.clone();
    triangles.primitives = inline(&format!(
        r#"{{"name": "t", "canvas": {{"width": 24, "height": 24}}, "viewport": {viewport},
            "primitives": [{{"triangle": [{{"clip": [0, 0, 0, 1]}}, {{"clip": [1, 0, 0, 1]}}, {{"clip": [0, 1, 0, 1]}}]}}]}}"#
    ))
    .primitives;
    triangles.rules.clip.points = PointClip::Pop;
    let points = OwnConventions::of(candidate, &triangles)
        .clip
        .map_or(PointClip::Pop, |c| c.points);
    assert_eq!(
        points,
        PointClip::Pop,
        "a case without points keeps its clip_points"
    );
}

/// Prints the fill rules under which the driver's frame of `scene` follows
/// the point rule, or why it drew nothing (part of `measure`).
fn measure_rules(candidate: &dyn Rasterizer, scene: &Scene, label: &str) {
    match candidate.rasterize(scene, &Plan::for_scene(scene)) {
        Ok(frame) => {
            let rules: Vec<&str> = FillRule::ALL
                .into_iter()
                .filter(|&r| departures(&frame, &expected(scene, r)) == 0)
                .map(|r| r.name())
                .collect();
            let n = frame.coverage.iter().filter(|&&c| c > 0).count();
            eprintln!(
                "MEASURE {} {label}: {n} samples, rules {rules:?}",
                candidate.name()
            );
            if rules.is_empty() {
                eprintln!("{}", picture(&frame));
            }
        }
        Err(e) => eprintln!("MEASURE {} {label}: {e}", candidate.name()),
    }
}
