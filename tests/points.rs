//! Points (SPEC.md §17): production against the reference on random points
//! in screen and clip space under every fill rule and clip rule; the
//! reference against a direct formula written here from §17 alone; and
//! wrong point rasterizers, each caught by the bundled cases/points.

mod common;

use common::Rng;
use dashu_ratio::RBig;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::tiled::Tiled;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::scene::{
    parse_case, ClipXy, DepthMode, FillRule, Limits, Number, PointBounds, PointClip, Primitive,
    Scene,
};

fn scene(json: &str) -> Scene {
    parse_case(json, "t.json", &Limits::default()).unwrap_or_else(|e| panic!("{e}\n{json}"))
}

fn reference(scene: &Scene) -> Frame {
    rastercheck::reference::render(scene, &Plan::for_scene(scene))
}

fn draw(r: &dyn Rasterizer, scene: &Scene) -> Frame {
    r.rasterize(scene, &Plan::for_scene(scene))
        .unwrap_or_else(|e| panic!("{}: {e:?}", r.name()))
}

/// A random number k/2^d as exact decimal text.
fn dyadic(rng: &mut Rng, lo: i64, hi: i64, bits: u32) -> String {
    let k = rng.range(lo << bits, hi << bits);
    Number::ratio(k, 1 << bits).to_exact_string()
}

const SIZES: [&str; 10] = [
    "1", "2", "3", "0.5", "4.75", "1/3", "0.25", "7", "2.5", "12",
];

/// A random screen-space scene of 1 to 4 points (and sometimes a
/// triangle), 12 × 10 canvas, random bits and fill rule.
fn random_screen(rng: &mut Rng) -> String {
    let bits = rng.pick(&["0", "1", "2", "4", "8", "null"]);
    let rule = rng.pick(&FillRule::NAMES);
    let mut primitives = Vec::new();
    for _ in 0..rng.range(1, 4) {
        let frac = rng.pick(&[0u32, 1, 2, 3, 5]);
        let (x, y) = (dyadic(rng, -4, 16, frac), dyadic(rng, -4, 14, frac));
        let size = rng.pick(&SIZES);
        primitives.push(format!(
            r#"{{"point": {{"position": ["{x}", "{y}"], "z": "{}", "attributes": [{}]}}, "size": "{size}"}}"#,
            dyadic(rng, 0, 1, 4),
            rng.range(-5, 5)
        ));
    }
    format!(
        r#"{{"name": "t", "canvas": {{"width": 12, "height": 10}},
            "rules": {{"subpixel_bits": {bits}, "fill_rule": "{rule}"}},
            "primitives": [{}]}}"#,
        primitives.join(", ")
    )
}

/// A random clip-space scene of 1 to 3 points: centres inside, on and
/// outside the side planes, z inside and out, w ≤ 0 now and then, random
/// clip rules and viewport.
fn random_clip(rng: &mut Rng) -> String {
    let bits = rng.pick(&["0", "2", "4", "8", "null"]);
    let rule = rng.pick(&FillRule::NAMES);
    let depth = rng.pick(&DepthMode::NAMES);
    let clip_z = if depth == "clip" {
        format!(
            r#", "clip_z": "{}""#,
            rng.pick(&["clip-then-snap", "per-sample"])
        )
    } else {
        String::new()
    };
    let points = rng.pick(&PointClip::NAMES);
    let bounds = rng.pick(&PointBounds::NAMES);
    let xy = rng.pick(&ClipXy::NAMES);
    let mut primitives = Vec::new();
    for _ in 0..rng.range(1, 3) {
        let w = rng.pick(&["1", "2", "0.5", "3", "0", "-1", "0.001"]);
        let wq = Number::from_string(w).unwrap();
        // x, y as multiples of w/8 in [-1.5 w, 1.5 w]: often on a plane.
        let c = |rng: &mut Rng| {
            let k = rng.range(-12, 12);
            Number::from_rbig(wq.as_rbig() * Number::ratio(k, 8).as_rbig()).to_exact_string()
        };
        let (x, y) = (c(rng), c(rng));
        let z = Number::ratio(rng.range(-2, 10), 8);
        let z = Number::from_rbig(wq.as_rbig() * z.as_rbig()).to_exact_string();
        primitives.push(format!(
            r#"{{"point": {{"clip": ["{x}", "{y}", "{z}", "{w}"], "attributes": [{}]}}, "size": "{}"}}"#,
            rng.range(-5, 5),
            rng.pick(&SIZES)
        ));
    }
    let viewport = if rng.range(0, 1) == 0 {
        String::new()
    } else {
        format!(
            r#""viewport": {{"x": {}, "y": {}, "width": {}, "height": {}, "min_depth": 0.25, "max_depth": 0.75}},"#,
            rng.range(-2, 4),
            rng.range(-2, 4),
            rng.range(2, 10),
            rng.range(2, 8)
        )
    };
    format!(
        r#"{{"name": "t", "canvas": {{"width": 12, "height": 10}}, {viewport}
            "rules": {{"subpixel_bits": {bits}, "fill_rule": "{rule}", "depth": "{depth}"{clip_z},
                       "clip_points": "{points}", "point_bounds": "{bounds}", "clip_xy": "{xy}"}},
            "primitives": [{}]}}"#,
        primitives.join(", ")
    )
}

/// Coverage and owners equal; depth and attributes within §6.3's bound
/// of 2^-16 relative (a scene's triangles are shaded by f32 set-ups, from
/// unsnapped positions too under `interpolate_from: unsnapped`).
fn same(reference: &Frame, got: &Frame, what: &str, json: &str) {
    assert_eq!(reference.coverage, got.coverage, "{what} coverage\n{json}");
    assert_eq!(reference.last, got.last, "{what} owners\n{json}");
    let close = |a: f64, b: f64| (a - b).abs() <= 2f64.powi(-16) * a.abs().max(1.0);
    if let (Some(r), Some(g)) = (&reference.depth, &got.depth) {
        for (i, (a, b)) in r.iter().zip(g).enumerate() {
            assert!(
                reference.coverage[i] == 0 || close(*a, *b),
                "{what} depth at {i}: {a} against {b}\n{json}"
            );
        }
    }
    for (r, g) in reference.attributes.iter().zip(&got.attributes) {
        for (i, (a, b)) in r.iter().zip(g).enumerate() {
            assert!(
                reference.coverage[i] == 0 || close(*a, *b),
                "{what} attribute at {i}: {a} against {b}\n{json}"
            );
        }
    }
}

/// (a) Production (and its tiled method, in screen space) draws every
/// sample, owner, depth and attribute of random points as the reference.
#[test]
fn production_equals_the_reference_on_random_points() {
    let mut rng = Rng(0x9017);
    let mut drawn = [0usize; 2];
    for i in 0..400 {
        let clip = i % 2 == 1;
        let json = if clip {
            random_clip(&mut rng)
        } else {
            random_screen(&mut rng)
        };
        let s = scene(&json);
        let r = reference(&s);
        same(&r, &draw(&Production, &s), "production", &json);
        if !clip {
            same(&r, &draw(&Tiled, &s), "production-tiled", &json);
        }
        drawn[usize::from(clip)] += usize::from(r.covered_samples() > 0);
    }
    // Both spaces draw something often, and not always (clip space
    // discards many: w ≤ 0, z outside, centres popped).
    assert!(drawn.iter().all(|&d| d > 50 && d < 200), "{drawn:?}");
}

/// A pixel centre's coordinate c = i + 1/2 against [centre − h, centre + h]
/// with the ends owned as `low` and `high` say: SPEC.md §17.1 written out.
fn in_interval(i: i64, centre: &RBig, h: &RBig, low: bool, high: bool) -> bool {
    let c = RBig::from(2 * i + 1) / RBig::from(2);
    let (lo, hi) = (centre - h, centre + h);
    (if low { c >= lo } else { c > lo }) && (if high { c <= hi } else { c < hi })
}

/// Each pixel's count of points covering it by the formula of §17, and
/// the last one's index + 1.
fn by_formula(s: &Scene) -> (Vec<u16>, Vec<u32>) {
    let (w, h) = (s.canvas.width as i64, s.canvas.height as i64);
    let mut coverage = vec![0u16; (w * h) as usize];
    let mut last = vec![0u32; (w * h) as usize];
    let rule = s.rules.fill_rule;
    // Which sides own their samples, read off the rule's name (§3).
    let (left, right, top, bottom) = match rule {
        FillRule::TopLeft => (true, false, true, false),
        FillRule::BottomRight => (false, true, false, true),
        FillRule::TopRight => (false, true, true, false),
        FillRule::BottomLeft => (true, false, false, true),
        FillRule::AllEdges => (true, true, true, true),
    };
    let snap = |q: RBig| match s.rules.subpixel_bits {
        Some(bits) => Number::from_rbig(q).snapped(bits).as_rbig().clone(),
        None => q,
    };
    for (index, p) in s.primitives.iter().enumerate() {
        let Primitive::Point(point) = p else {
            panic!("points only")
        };
        let v = &point.vertices[0];
        let [x, y, z, wc] = [&v.x, &v.y, &v.z, &v.w].map(|n| n.as_rbig().clone());
        let centre = match &s.viewport {
            None => [snap(x), snap(y)],
            Some(vp) => {
                let clip = s.rules.clip;
                let outside = |c: &RBig| *c < -wc.clone() || *c > wc;
                if wc <= RBig::ZERO
                    || (clip.depth == DepthMode::Clip && (z < RBig::ZERO || z > wc))
                    || (clip.points == PointClip::Pop && (outside(&x) || outside(&y)))
                {
                    continue;
                }
                let half = RBig::ONE / RBig::from(2);
                let f = |o: &Number, size: &Number, c: &RBig| {
                    o.as_rbig() + size.as_rbig() * &half * (c / &wc + RBig::ONE)
                };
                [
                    snap(f(&vp.x, &vp.width, &x)),
                    snap(f(&vp.y, &vp.height, &y)),
                ]
            }
        };
        let half = point.size.as_rbig() / RBig::from(2);
        // Under `point_bounds: viewport`, pixel centres in [x, x + width)
        // × [y, y + height) only.
        let in_view = |px: i64, py: i64| match &s.viewport {
            Some(vp) if s.rules.clip.bounds == PointBounds::Viewport => {
                let c = |i: i64| RBig::from(2 * i + 1) / RBig::from(2);
                let (cx, cy) = (c(px), c(py));
                cx >= *vp.x.as_rbig()
                    && cx < vp.x.as_rbig() + vp.width.as_rbig()
                    && cy >= *vp.y.as_rbig()
                    && cy < vp.y.as_rbig() + vp.height.as_rbig()
            }
            _ => true,
        };
        for py in 0..h {
            for px in 0..w {
                if in_view(px, py)
                    && in_interval(px, &centre[0], &half, left, right)
                    && in_interval(py, &centre[1], &half, top, bottom)
                {
                    let i = (py * w + px) as usize;
                    coverage[i] += 1;
                    last[i] = index as u32 + 1;
                }
            }
        }
    }
    (coverage, last)
}

/// (b) The reference covers exactly what the formula of §17 covers, on
/// random points in both spaces.
#[test]
fn the_reference_follows_the_formula_of_section_17() {
    let mut rng = Rng(0x17);
    for i in 0..300 {
        let json = if i % 2 == 0 {
            random_screen(&mut rng)
        } else {
            random_clip(&mut rng)
        };
        let s = scene(&json);
        let r = reference(&s);
        let (coverage, last) = by_formula(&s);
        assert_eq!(r.coverage, coverage, "coverage\n{json}");
        assert_eq!(r.last, last, "owners\n{json}");
    }
}

/// The bundled point cases, read.
fn bundled() -> Vec<(String, Scene)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/points");
    let mut out: Vec<(String, Scene)> = std::fs::read_dir(&dir)
        .expect("cases/points")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            (name, scene(&text))
        })
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// The bundled cases this wrong rasterizer fails: its frame's coverage or
/// owners differ from the reference's, as `run` judges them.
fn caught_by(wrong: impl Fn(&Scene) -> Frame) -> Vec<String> {
    bundled()
        .into_iter()
        .filter(|(_, s)| {
            let (r, w) = (reference(s), wrong(s));
            r.coverage != w.coverage || r.last != w.last
        })
        .map(|(name, _)| name)
        .collect()
}

/// (c) Wrong point rasterizers, each production with one rule of §17
/// broken, are caught by the bundled cases, and production is not.
#[test]
fn wrong_point_rasterizers_are_caught_by_the_cases() {
    assert_eq!(caught_by(|s| draw(&Production, s)), Vec::<String>::new());
    // The centre not snapped: the square where the case wrote it (the
    // positions given as exact dyadics one bit finer than the grid).
    let unsnapped = caught_by(|s| {
        let mut s = s.clone();
        if s.viewport.is_none() {
            if let Some(bits) = s.rules.subpixel_bits {
                for v in s.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
                    for c in [&mut v.x, &mut v.y] {
                        // Rounded to 2^-(bits + 4): the snapping's effect
                        // is kept out, not the case's own fraction.
                        *c = c.snapped(bits + 4);
                    }
                }
                s.rules.subpixel_bits = None;
            }
        }
        draw(&Production, &s)
    });
    assert!(
        unsnapped.contains(&"snap_moves_centre".to_owned()),
        "{unsnapped:?}"
    );
    // Closed edges under every rule (all-edges for top-left).
    let closed = caught_by(|s| draw(&Production, &s.with_fill_rule(FillRule::AllEdges)));
    assert!(closed.contains(&"spec_square".to_owned()), "{closed:?}");
    assert!(closed.contains(&"ties_top_left".to_owned()), "{closed:?}");
    // Popping under guard-band, and guard-band under pop.
    let under = |rule: PointClip| {
        caught_by(move |s| {
            let mut s = s.clone();
            s.rules.clip.points = rule;
            draw(&Production, &s)
        })
    };
    let popping = under(PointClip::Pop);
    assert!(
        popping.contains(&"spec_clip_guard_band".to_owned()),
        "{popping:?}"
    );
    let never_pops = under(PointClip::GuardBand);
    assert!(
        never_pops.contains(&"spec_clip_pop".to_owned()),
        "{never_pops:?}"
    );
    // `point_bounds: viewport` ignored, and applied where the case says
    // canvas.
    let bounded = |bounds: PointBounds| {
        caught_by(move |s| {
            let mut s = s.clone();
            s.rules.clip.bounds = bounds;
            draw(&Production, &s)
        })
    };
    let unbounded = bounded(PointBounds::Canvas);
    for name in ["spec_bounds_viewport", "clip_bounds_guard_band_outside"] {
        assert!(unbounded.contains(&name.to_owned()), "{unbounded:?}");
    }
    let always_bounded = bounded(PointBounds::Viewport);
    assert!(
        always_bounded.contains(&"clip_viewport_not_a_scissor".to_owned()),
        "{always_bounded:?}"
    );
    // The square scissored to the viewport rectangle.
    let scissored = caught_by(|s| {
        let mut frame = draw(&Production, s);
        if let Some(vp) = &s.viewport {
            let (x0, y0) = (vp.x.to_f64_lossy(), vp.y.to_f64_lossy());
            let (x1, y1) = (x0 + vp.width.to_f64_lossy(), y0 + vp.height.to_f64_lossy());
            for py in 0..s.canvas.height {
                for px in 0..s.canvas.width {
                    let (cx, cy) = (f64::from(px) + 0.5, f64::from(py) + 0.5);
                    if cx < x0 || cx >= x1 || cy < y0 || cy >= y1 {
                        let i = frame.index(px, py);
                        frame.coverage[i] = 0;
                        frame.last[i] = 0;
                    }
                }
            }
        }
        frame
    });
    assert!(
        scissored.contains(&"clip_viewport_not_a_scissor".to_owned()),
        "{scissored:?}"
    );
    // The canvas limit dropped a pixel too far: a square reaching off the
    // canvas drawn one column short.
    let short = caught_by(|s| {
        let mut frame = draw(&Production, s);
        for py in 0..s.canvas.height {
            let i = frame.index(0, py);
            frame.coverage[i] = 0;
            frame.last[i] = 0;
        }
        frame
    });
    assert!(short.contains(&"off_canvas_left".to_owned()), "{short:?}");
}

/// Every bundled case's `samples_covered` (from tools/gen_points.py's
/// model) is what the reference covers.
#[test]
fn the_bundled_cases_pin_the_reference() {
    let cases = bundled();
    assert!(cases.len() >= 25, "{}", cases.len());
    for (name, s) in cases {
        let expected = s.expect.samples_covered.expect("every point case pins it");
        assert_eq!(reference(&s).covered_samples(), expected, "{name}");
    }
}

/// The bundled cases are what tools/gen_points.py writes (its exact model
/// of §17 gives every `samples_covered`), and its two wrong models each
/// change a pin (the generator asserts so before it compares).
#[test]
fn the_cases_are_the_generators() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let out = std::process::Command::new("python3")
        .arg(root.join("tools/gen_points.py"))
        .args(["--check", "-v"])
        .current_dir(root)
        .output()
        .expect("python3 runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "gen_points.py --check:\n{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("wrong model unsnapped changes"), "{stdout}");
    assert!(stdout.contains("wrong model pops changes"), "{stdout}");
}

/// Every case SPEC.md §17 names exists, and it names the worked examples.
#[test]
fn the_worked_examples_spec_section_17_names_exist() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let spec = std::fs::read_to_string(root.join("SPEC.md")).expect("SPEC.md");
    let section = &spec[spec.find("## 17. Points").expect("SPEC §17")..];
    let mut named = Vec::new();
    for (i, _) in section.match_indices("`cases/") {
        let rest = &section[i + 1..];
        let path = &rest[..rest.find('`').expect("closing backtick")];
        assert!(root.join(path).is_file(), "SPEC §17 names {path}");
        named.push(path);
    }
    for example in [
        "spec_square",
        "spec_clip_on_plane",
        "spec_clip_pop",
        "spec_bounds_viewport",
    ] {
        assert!(
            named.iter().any(|p| p.contains(example)),
            "SPEC §17 cites {example}: {named:?}"
        );
    }
}

/// `fuzz --family clip` draws points too, under both side-plane rules; a
/// scene with points reads back from the case file the fuzzer writes, and
/// production draws it as the reference does.
#[test]
fn the_fuzz_clip_family_draws_points_that_round_trip() {
    use rastercheck::explore::fuzz::{case_json, generate, Family};
    let (mut with_points, mut rules) = (0, Vec::new());
    for index in 0..150 {
        let (_, s) = generate(7, index, Some(Family::Clip));
        if !s.has_points() {
            continue;
        }
        with_points += 1;
        if !rules.contains(&s.rules.clip.points) {
            rules.push(s.rules.clip.points);
        }
        let text = case_json(&s);
        let back = scene(&text);
        assert_eq!(case_json(&back), text);
        same(
            &reference(&back),
            &draw(&Production, &back),
            "production",
            &text,
        );
    }
    assert!(with_points > 20, "{with_points} scenes with points");
    assert_eq!(rules.len(), 2, "{rules:?}");
}

/// Production, popping and bounding points one way whatever a case states:
/// what a driver does (SPEC.md §17.4).
struct FixedPoints(PointClip, PointBounds);

impl Rasterizer for FixedPoints {
    fn name(&self) -> &str {
        "fixed-points"
    }
    fn capabilities(&self) -> rastercheck::rasterizer::Capabilities {
        Production.capabilities()
    }
    fn rasterize(
        &self,
        scene: &Scene,
        plan: &Plan,
    ) -> Result<Frame, rastercheck::rasterizer::RasterError> {
        let mut s = scene.clone();
        s.rules.clip.points = self.0;
        s.rules.clip.bounds = self.1;
        Production.rasterize(&s, plan)
    }
}

/// (e) probe finds each of the four combinations of `clip_points` and
/// `point_bounds` a rasterizer may fix, and production following each
/// case's; a rasterizer without points is not probed.
#[test]
fn probe_finds_a_rasterizers_own_point_clipping() {
    use rastercheck::explore::probe::probe_points;
    let found = probe_points(&Production).expect("draws clip-space points");
    assert!(found.follows_case && found.consistent, "{found:?}");
    assert_eq!(found.scenes, 5, "{found:?}");
    for points in PointClip::ALL {
        for bounds in PointBounds::ALL {
            let found = probe_points(&FixedPoints(points, bounds)).expect("draws points");
            assert!(!found.follows_case && found.consistent, "{found:?}");
            assert_eq!(found.clip_points(), Some(points.name()), "{found:?}");
            assert_eq!(found.point_bounds(), Some(bounds.name()), "{found:?}");
        }
    }
    assert!(probe_points(&rastercheck::production::foils::FloatF32).is_none());
}
