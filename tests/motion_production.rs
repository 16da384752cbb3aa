//! Production's motion blur (SPEC.md §15.3) against the static rules at
//! each instant, its error against exact time coverage as N grows, and the
//! static primitives of a moving scene drawn once.
//!
//! The oracle of a single test is the static reference at the test's
//! instant: `Scene::at_instant(τ)` puts every vertex at
//! (1 − τ)·snap(from) + τ·snap(to) exactly, and the reference's coverage of
//! that static scene at the spatial samples is what production's test at τ
//! must decide. The statistical test needs no oracle at all: a long edge
//! sweeping by a pure translation crosses a pixel centre at one rational
//! instant, so the exact time coverage is written down directly.

mod common;

use common::Rng;
use rastercheck::frame::Frame;
use rastercheck::plan::Plan;
use rastercheck::production::antialias::Sampling;
use rastercheck::production::motion::Sampler;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::reference;
use rastercheck::scene::time::limits::TIME_ONE;
use rastercheck::scene::{
    Antialias, Canvas, Cull, Effects, Expect, FillRule, Interpolation, LastPixel, Line,
    LineParameter, LineRule, MotionBlur, Number, Pattern, Primitive, Rules, Scene, TimePattern,
    Triangle, Vertex,
};

/// A point in units of 2^-g px (g = `grid`), as exact numbers.
type Units = [i64; 2];

fn number(units: i64, grid: u32) -> Number {
    Number::ratio(units, 1 << grid)
}

fn still(p: Units, grid: u32) -> Vertex {
    Vertex::at(number(p[0], grid), number(p[1], grid))
}

fn moving(from: Units, to: Units, grid: u32) -> Vertex {
    let mut v = still(from, grid);
    v.to = Some(Box::new([number(to[0], grid), number(to[1], grid)]));
    v
}

fn triangle(vertices: [Vertex; 3]) -> Primitive {
    Primitive::Triangle(Triangle {
        vertices,
        interpolation: Interpolation::Linear,
    })
}

fn parallelogram(vertices: [Vertex; 2], width: Number) -> Primitive {
    Primitive::Line(Line {
        vertices,
        rule: LineRule::Parallelogram,
        width,
        last_pixel: LastPixel::Include,
        parameter: LineParameter::Major,
        interpolation: Interpolation::Linear,
    })
}

fn blur(samples: u32, pattern: TimePattern, seed: u64) -> MotionBlur {
    MotionBlur {
        shutter: [0, TIME_ONE],
        samples,
        pattern,
        seed,
    }
}

fn scene(canvas: Canvas, rules: Rules, primitives: Vec<Primitive>, effects: Effects) -> Scene {
    Scene {
        name: "motion".to_owned(),
        description: String::new(),
        canvas,
        rules,
        primitives,
        effects,
        expect: Expect::default(),
        attribute_count: 0,
        has_depth: false,
        viewport: None,
    }
}

const SMALL: Canvas = Canvas {
    width: 8,
    height: 6,
};

/// A moving primitive of one of the kinds that make ties likely: a
/// translation, a turn or a scaling about a point (a half turn and a
/// scaling by −1 pass through zero area at τ = ½, a scaling by 0 ends
/// there), a flip of one vertex across the opposite edge (the winding
/// changes mid-shutter), any motion at all, a parallelogram line whose
/// major axis may change mid-shutter, and a huge triangle whose edge
/// products leave i128 at 16 subpixel bits. Coordinates in units of 2^-g.
fn moving_primitive(rng: &mut Rng, g: u32) -> Primitive {
    let unit = 1i64 << g;
    let point = |rng: &mut Rng| {
        [
            rng.range(-2 * unit, (SMALL.width as i64 + 2) * unit),
            rng.range(-2 * unit, (SMALL.height as i64 + 2) * unit),
        ]
    };
    let p: [Units; 3] = [point(rng), point(rng), point(rng)];
    let about = |rng: &mut Rng, map: fn(Units) -> Units| {
        let c = [rng.range(2, 6) * unit, rng.range(1, 5) * unit];
        p.map(|v| {
            let r = map([v[0] - c[0], v[1] - c[1]]);
            [c[0] + r[0], c[1] + r[1]]
        })
    };
    let to: [Units; 3] = match rng.range(0, 8) {
        0 => {
            let d = [
                rng.range(-5 * unit, 5 * unit),
                rng.range(-4 * unit, 4 * unit),
            ];
            p.map(|v| [v[0] + d[0], v[1] + d[1]])
        }
        1 => about(rng, |[x, y]| [-y, x]),
        2 => about(rng, |[x, y]| [-x, -y]),
        3 => about(rng, |[x, y]| [2 * x, 2 * y]),
        4 => about(rng, |_| [0, 0]),
        5 => {
            // v2 mirrored across the horizontal or vertical line through v0.
            let k = rng.range(0, 1) as usize;
            let mut q = p;
            q[1][k] = p[0][k];
            let mut to = q;
            to[2][k] = 2 * p[0][k] - p[2][k];
            return triangle([0, 1, 2].map(|i| moving(q[i], to[i], g)));
        }
        7 => {
            // An edge along a column (row) of pixel centres or, on the
            // integer grid, of pixel borders, sliding along itself: its
            // samples ride on it all shutter long, on the swept box's side.
            let k = rng.range(0, 1) as usize;
            let line = rng.range(0, 6) * unit + unit / 2;
            let mut q = p;
            q[0][k] = line;
            q[1][k] = line;
            let mut d = [0, 0];
            d[1 - k] = rng.range(-4 * unit, 4 * unit);
            let to = q.map(|v| [v[0] + d[0], v[1] + d[1]]);
            return triangle([0, 1, 2].map(|i| moving(q[i], to[i], g)));
        }
        6 => {
            let ends = [point(rng), point(rng)];
            let to = if rng.range(0, 1) == 0 {
                [point(rng), point(rng)]
            } else {
                // A quarter turn about the first end: the major axis swaps.
                let d = [ends[1][0] - ends[0][0], ends[1][1] - ends[0][1]];
                [ends[0], [ends[0][0] - d[1], ends[0][1] + d[0]]]
            };
            let width = rng.pick(&[(1, 1), (2, 1), (1, 2), (3, 4), (5, 2)]);
            return parallelogram(
                [0, 1].map(|i| moving(ends[i], to[i], g)),
                Number::ratio(width.0, width.1),
            );
        }
        _ => [point(rng), point(rng), point(rng)],
    };
    triangle([0, 1, 2].map(|i| moving(p[i], to[i], g)))
}

/// A huge triangle far beyond the canvas whose edge crosses it, moving a
/// few pixels: with 16 subpixel bits its edge products need 256 bits, and
/// with 12 its edge functions come near the fast path's bound.
fn far_primitive(rng: &mut Rng, g: u32) -> Primitive {
    let unit = 1i64 << g;
    let far = 30_000 * unit;
    let a = [rng.range(0, 8) * unit + rng.range(0, unit), -far];
    let b = [rng.range(0, 8) * unit + rng.range(0, unit), far];
    let c = [rng.pick(&[-far, far]), rng.range(-far, far)];
    let d = [rng.range(-3 * unit, 3 * unit), rng.range(-unit, unit)];
    let shifted = |v: Units| [v[0] + d[0], v[1] + d[1]];
    triangle([a, b, c].map(|v| moving(v, shifted(v), g)))
}

fn static_primitive(rng: &mut Rng, g: u32) -> Primitive {
    let unit = 1i64 << g;
    let line = rng.next().is_multiple_of(3);
    let mut point = || {
        let p = [
            rng.range(-unit, (SMALL.width as i64 + 1) * unit),
            rng.range(-unit, (SMALL.height as i64 + 1) * unit),
        ];
        still(p, g)
    };
    if line {
        parallelogram([point(), point()], Number::ONE)
    } else {
        triangle([point(), point(), point()])
    }
}

/// A sample count the pattern allows, at most 4.
fn spatial_count(rng: &mut Rng, pattern: Pattern) -> u32 {
    match pattern {
        Pattern::Standard => rng.pick(&[1, 2, 4]),
        Pattern::Grid | Pattern::Stratified => rng.pick(&[1, 4]),
        Pattern::Random | Pattern::NRooks => rng.range(1, 4) as u32,
    }
}

/// A small random moving scene: every fill rule and cull, with and
/// without antialiasing, every time pattern, a shutter that is sometimes
/// part of [0, 1]; coordinates on coarse grids (ties at instants on 1/16)
/// or off the snapping grid (snapping matters). Something moves.
fn random_scene(rng: &mut Rng) -> Scene {
    loop {
        let s = maybe_moving_scene(rng);
        if s.moves() {
            return s;
        }
    }
}

fn maybe_moving_scene(rng: &mut Rng) -> Scene {
    // Production tests triangles one way up to 12 subpixel bits (13
    // fraction bits) and another beyond.
    let bits = rng.pick(&[1, 2, 4, 8, 12, 13, 16]);
    let g = if rng.range(0, 3) == 0 {
        bits + 2 // off the snapping grid: snapped at the ends
    } else {
        bits.min(rng.pick(&[0, 1, 2]))
    };
    let mut primitives: Vec<Primitive> = (0..rng.range(1, 3))
        .map(|_| moving_primitive(rng, g))
        .collect();
    if bits >= 12 && rng.range(0, 1) == 0 {
        primitives.push(far_primitive(rng, g));
    }
    for _ in 0..rng.range(0, 2) {
        let at = rng.range(0, primitives.len() as i64) as usize;
        primitives.insert(at, static_primitive(rng, g));
    }
    let antialias = (rng.range(0, 1) == 0).then(|| {
        let pattern = rng.pick(&Pattern::ALL);
        Antialias {
            samples: spatial_count(rng, pattern),
            pattern,
            seed: rng.next() % 100,
            adaptive: rng.range(0, 1) == 0,
            position_bits: rng.pick(&[4, 8]),
        }
    });
    let mut motion = blur(
        rng.range(1, 4) as u32,
        rng.pick(&TimePattern::ALL),
        rng.next() % 1000,
    );
    if rng.range(0, 3) == 0 {
        let open = rng.range(0, i64::from(TIME_ONE) - 2) as u32;
        motion.shutter = [
            open,
            rng.range(i64::from(open) + 1, i64::from(TIME_ONE)) as u32,
        ];
    }
    scene(
        SMALL,
        Rules {
            subpixel_bits: Some(bits),
            fill_rule: rng.pick(&FillRule::ALL),
            cull: rng.pick(&[Cull::None, Cull::Clockwise, Cull::CounterClockwise]),
            ..Rules::default()
        },
        primitives,
        Effects {
            antialias,
            motion_blur: Some(motion),
            conservative: None,
        },
    )
}

/// The static reference at instant t/2^32: how many primitives cover each
/// spatial sample (sample s of pixel p at p·M + s).
fn oracle_at(scene: &Scene, t: u64) -> Vec<u16> {
    let at = scene.at_instant(&Number::ratio(t as i64, 1 << 32));
    reference::coverage_under(&at, &Plan::for_scene(&at), scene.rules.fill_rule)
}

fn sampler(scene: &Scene) -> Sampler {
    let plan = Plan::for_scene(scene);
    assert!(plan.motion.is_some(), "{} moves", scene.name);
    Sampler::new(scene, &plan, Sampling::for_plan(&plan)).expect("production draws it")
}

/// The instants every random scene is tested at: the sixteenths of [0, 1]
/// (where the coarse scenes' ties fall) and a few anywhere.
fn instants(rng: &mut Rng) -> Vec<u64> {
    let mut out: Vec<u64> = (0..=16).map(|j| j << 28).collect();
    out.extend((0..4).map(|_| rng.next() % ((1 << 32) + 1)));
    out
}

/// Every (pixel, spatial sample) where `decide` differs from the oracle at
/// instant t, as readable strings.
fn mismatches(scene: &Scene, t: u64, decide: impl Fn(u32, u32, usize) -> u32) -> Vec<String> {
    let oracle = oracle_at(scene, t);
    let m = oracle.len() / SMALL.pixel_count();
    let mut out = Vec::new();
    for y in 0..scene.canvas.height {
        for x in 0..scene.canvas.width {
            for s in 0..m {
                let p = (y * scene.canvas.width + x) as usize;
                let want = u32::from(oracle[p * m + s]);
                let got = decide(x, y, s);
                if got != want {
                    out.push(format!("({x},{y})#{s} at t={t}: oracle {want}, got {got}"));
                }
            }
        }
    }
    out
}

const SCENES: u64 = 500;

/// Each of production's tests decides its sample exactly as the static
/// rules at its instant: on random scenes, at every pixel and spatial
/// sample, at instants where ties fall (zero area, a sample on an edge, a
/// line at 45°) and at others.
#[test]
fn each_test_is_the_static_rule_at_its_instant() {
    let mut rng = Rng(0x6d6f_7469_6f6e);
    let mut tested = 0;
    for i in 0..SCENES {
        let s = random_scene(&mut rng);
        let production = sampler(&s);
        for t in instants(&mut rng) {
            let wrong = mismatches(&s, t, |x, y, k| production.coverage_at(x, y, k, t));
            assert!(wrong.is_empty(), "scene {i}: {s:#?}\n{wrong:#?}");
            tested += 1;
        }
    }
    assert_eq!(tested, SCENES * 21);
}

/// A production that snapped the vertices at each instant instead of at
/// the shutter's ends (drawn here by production's static path on the
/// scene at τ with its snapping back on) is caught by the same comparison.
#[test]
fn snapping_at_the_instant_is_caught() {
    let mut rng = Rng(0x6d6f_7469_6f6e);
    let mut caught = 0;
    for _ in 0..SCENES {
        let s = random_scene(&mut rng);
        for t in instants(&mut rng) {
            let mut snapped = s.at_instant(&Number::ratio(t as i64, 1 << 32));
            snapped.rules.subpixel_bits = s.rules.subpixel_bits;
            let frame = Production
                .rasterize(&snapped, &Plan::for_scene(&snapped))
                .unwrap();
            let m = frame.samples as usize;
            let w = s.canvas.width;
            caught += mismatches(&s, t, |x, y, k| {
                u32::from(frame.coverage[(y * w + x) as usize * m + k])
            })
            .len();
        }
    }
    assert!(caught > 0, "snapping at τ went unnoticed");
    eprintln!("snapping at τ: {caught} samples caught");
}

/// The time loop as the frame runs it: every slot's count is the oracle's
/// at that slot's instant (SPEC.md §15.3's u of the pixel and slot) for
/// that slot's spatial sample; the frame's time coverage is their sum over
/// M·N, and the sample tests count the moving primitives' tests. Taking
/// the instant of the neighbouring slot instead is caught.
#[test]
fn each_slot_is_tested_at_its_own_instant() {
    let mut rng = Rng(0x736c_6f74);
    let mut shifted_caught = 0;
    let mut slots_checked = 0;
    for i in 0..SCENES {
        let s = random_scene(&mut rng);
        let production = sampler(&s);
        let plan = Plan::for_scene(&s);
        let frame = Production.rasterize(&s, &plan).unwrap();
        let tiled = rastercheck::production::tiled::Tiled
            .rasterize(&s, &plan)
            .unwrap();
        assert_eq!(frame, tiled, "production-tiled draws production's frame");
        let blur = s.effects.motion_blur.as_ref().unwrap();
        let (m, n) = (production.spatial_samples(), production.time_samples());
        let time = frame.time.as_ref().expect("a time-only frame");
        assert_eq!((frame.samples, frame.coverage.len()), (0, 0));
        for y in 0..s.canvas.height {
            for x in 0..s.canvas.width {
                let p = (y * s.canvas.width + x) as usize;
                let slots = production.slot_counts(x, y);
                // Each slot as a test with no swept box would decide it.
                let times = blur.pixel_times(p as u64, m as u32);
                let unboxed: Vec<u32> = (0..m * n)
                    .map(|j| production.coverage_at(x, y, j / n, blur.instant(times[j])))
                    .collect();
                assert_eq!(slots, unboxed, "scene {i} ({x},{y}): {s:#?}");
                let sum: u32 = slots.iter().sum();
                assert_eq!(
                    time[p],
                    f64::from(sum) / (m * n) as f64,
                    "scene {i} ({x},{y})"
                );
            }
        }
        // Two pixels, every slot against the oracle at its instant.
        for _ in 0..2 {
            let (x, y) = (
                rng.range(0, i64::from(s.canvas.width) - 1) as u32,
                rng.range(0, i64::from(s.canvas.height) - 1) as u32,
            );
            let p = u64::from(y * s.canvas.width + x);
            let times: Vec<u64> = blur
                .pixel_times(p, m as u32)
                .iter()
                .map(|&u| blur.instant(u))
                .collect();
            let oracle: Vec<u32> = times
                .iter()
                .enumerate()
                .map(|(j, &t)| u32::from(oracle_at(&s, t)[p as usize * m + j / n]))
                .collect();
            let slots = production.slot_counts(x, y);
            assert_eq!(slots, oracle, "scene {i} ({x},{y}): {s:#?}");
            let shifted: Vec<u32> = (0..m * n)
                .map(|j| slots[j / n * n + (j % n + 1) % n])
                .collect();
            shifted_caught += usize::from(shifted != oracle);
            slots_checked += slots.len();
        }
    }
    assert!(
        shifted_caught > 0,
        "the neighbouring slot's instant went unnoticed"
    );
    eprintln!(
        "{slots_checked} slots checked; neighbouring instants caught on {shifted_caught} pixels"
    );
}

// --- Statistics -----------------------------------------------------------------

/// A long edge a→b of a triangle whose third vertex c is far away, all
/// translated by v over the shutter, in whole pixels; only that edge
/// crosses the canvas at any instant.
struct Sweep {
    a: [i64; 2],
    b: [i64; 2],
    c: [i64; 2],
    v: [i64; 2],
}

const SWEEP_CANVAS: Canvas = Canvas {
    width: 128,
    height: 96,
};

const SWEEPS: [Sweep; 3] = [
    Sweep {
        a: [20, -2000],
        b: [60, 2000],
        c: [-6000, 0],
        v: [40, 3],
    },
    Sweep {
        a: [-2000, 30],
        b: [2000, 50],
        c: [0, 6000],
        v: [-5, 30],
    },
    Sweep {
        a: [150, -2000],
        b: [-10, 2000],
        c: [6000, 0],
        v: [-37, 11],
    },
];

impl Sweep {
    fn scene(&self, samples: u32, pattern: TimePattern, seed: u64) -> Scene {
        let px = |p: [i64; 2]| p.map(|c| c * 2);
        let to = |p: [i64; 2]| [2 * (p[0] + self.v[0]), 2 * (p[1] + self.v[1])];
        let vertices = [self.a, self.b, self.c].map(|p| moving(px(p), to(p), 1));
        scene(
            SWEEP_CANVAS,
            Rules::default(),
            vec![triangle(vertices)],
            Effects {
                antialias: None,
                motion_blur: Some(blur(samples, pattern, seed)),
                conservative: None,
            },
        )
    }

    /// The exact time coverage of the centre of pixel (x, y): the edge
    /// function at q is linear in τ, E(τ) = α − τ·β with α the cross
    /// product (b − a) × (q − a) and β = (b − a) × v, and the sample is
    /// inside while E has the sign σ of the third vertex's; so the covered
    /// instants are τ < α/β or τ > α/β. In half pixels, every value is an
    /// integer.
    fn exact(&self, x: i64, y: i64) -> f64 {
        let cross = |u: [i64; 2], w: [i64; 2]| u[0] * w[1] - u[1] * w[0];
        let d = [2 * (self.b[0] - self.a[0]), 2 * (self.b[1] - self.a[1])];
        let q = [2 * x + 1 - 2 * self.a[0], 2 * y + 1 - 2 * self.a[1]];
        let alpha = cross(d, q);
        let beta = cross(d, [2 * self.v[0], 2 * self.v[1]]);
        let sigma = cross(
            d,
            [2 * (self.c[0] - self.a[0]), 2 * (self.c[1] - self.a[1])],
        )
        .signum();
        assert!(beta != 0 && sigma != 0);
        let root = (alpha as f64 / beta as f64).clamp(0.0, 1.0);
        if sigma * beta.signum() > 0 {
            root
        } else {
            1.0 - root
        }
    }
}

/// RMS of production's time coverage minus the exact one over moving
/// pixels (exact value strictly between 0 and 1, or production's not
/// exact), pooled over the sweeps; and how many such pixels.
fn sweep_rms(samples: u32, pattern: TimePattern) -> (f64, usize) {
    let (mut sum, mut count) = (0.0, 0);
    for (k, sweep) in SWEEPS.iter().enumerate() {
        let s = sweep.scene(samples, pattern, 17 + k as u64);
        let frame = Production.rasterize(&s, &Plan::for_scene(&s)).unwrap();
        let time = frame.time.unwrap();
        for y in 0..SWEEP_CANVAS.height as i64 {
            for x in 0..SWEEP_CANVAS.width as i64 {
                let exact = sweep.exact(x, y);
                let got = time[(y * SWEEP_CANVAS.width as i64 + x) as usize];
                if (exact > 0.0 && exact < 1.0) || got != exact {
                    sum += (got - exact) * (got - exact);
                    count += 1;
                }
            }
        }
    }
    ((sum / count as f64).sqrt(), count)
}

/// Least squares of ln RMS against ln N: (slope, e^intercept).
fn fit(points: &[(u32, f64)]) -> (f64, f64) {
    let xs: Vec<f64> = points.iter().map(|p| f64::from(p.0).ln()).collect();
    let ys: Vec<f64> = points.iter().map(|p| p.1.ln()).collect();
    let n = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    let slope = sxy / sxx;
    (slope, (my - slope * mx).exp())
}

const COUNTS: [u32; 7] = [4, 8, 16, 32, 64, 128, 256];

fn measured(pattern: TimePattern) -> Vec<(u32, f64)> {
    COUNTS
        .iter()
        .map(|&n| {
            let (rms, pixels) = sweep_rms(n, pattern);
            assert!(pixels > 5000, "{pixels} moving pixels");
            (n, rms)
        })
        .collect()
}

/// Whether a log–log fit has the slope `want` ± 0.1 and a constant near
/// the anchor 0.41 (√(1/6): E[c(1 − c)] for uniform c under random
/// instants, and the mean of f(1 − f)/N² over one stratum's crossing point
/// under stratified ones).
fn fits(points: &[(u32, f64)], want: f64) -> bool {
    let (slope, constant) = fit(points);
    (slope - want).abs() <= 0.1 && (0.3..=0.55).contains(&constant)
}

/// The done-when: random instants' RMS error falls like N^-1/2 and
/// stratified ones' like N^-1 (a log–log fit over N = 4 … 256 on fixed
/// seeds), against exact time coverage of edges sweeping by translation.
/// Random instants fail the stratified check: it tells the two apart.
#[test]
fn time_error_falls_like_the_patterns_promise() {
    let random = measured(TimePattern::Random);
    let stratified = measured(TimePattern::Stratified);
    for (name, points) in [("random", &random), ("stratified", &stratified)] {
        let (slope, constant) = fit(points);
        eprintln!(
            "{name}: slope {slope:.3}, constant {constant:.3} (anchor 0.41); RMS by N: {}",
            points
                .iter()
                .map(|(n, r)| format!("{n}: {r:.5}"))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    assert!(fits(&random, -0.5), "random: {:?}", fit(&random));
    assert!(
        fits(&stratified, -1.0),
        "stratified: {:?}",
        fit(&stratified)
    );
    assert!(!fits(&random, -1.0) && !fits(&stratified, -0.5));
}

/// The sweeps' exact values are the static rules' time coverage: at each
/// centre, the reference at instants inside and outside the covered
/// interval agrees (the interval's end α/β is where E changes sign).
#[test]
fn sweep_exact_values_are_the_reference_at_instants() {
    for (k, sweep) in SWEEPS.iter().enumerate() {
        let s = sweep.scene(1, TimePattern::Random, 0);
        let open = oracle_at(&s, 0);
        for j in [1u64, 5, 8, 11, 15] {
            let t = j << 28;
            let oracle = oracle_at(&s, t);
            for y in (0..SWEEP_CANVAS.height).step_by(7) {
                for x in 0..SWEEP_CANVAS.width {
                    let exact = sweep.exact(i64::from(x), i64::from(y));
                    // Covered instants are [0, c) or (1 − c, 1]: which one
                    // shows at τ = 0 (the reference there).
                    let at_open = open[(y * SWEEP_CANVAS.width + x) as usize] == 1;
                    let tau = j as f64 / 16.0;
                    let inside = if at_open {
                        tau < exact
                    } else {
                        tau > 1.0 - exact
                    };
                    let boundary = if at_open { exact } else { 1.0 - exact };
                    if (tau - boundary).abs() < 1e-9 {
                        continue;
                    }
                    assert_eq!(
                        oracle[(y * SWEEP_CANVAS.width + x) as usize] == 1,
                        inside,
                        "sweep {k} ({x},{y}) at τ = {tau}: exact {exact}"
                    );
                }
            }
        }
    }
}

// --- Static primitives, static scenes, patterns ------------------------------------

/// A translating triangle and a static one over it, 16 instants.
fn with_static(include_static: bool) -> Scene {
    let mut primitives = vec![triangle([
        moving([2, 2], [22, 6], 1),
        moving([16, 2], [30, 4], 1),
        moving([4, 12], [20, 11], 1),
    ])];
    if include_static {
        primitives.push(triangle([
            still([6, 0], 0),
            still([8, 6], 0),
            still([0, 6], 0),
        ]));
    }
    scene(
        Canvas {
            width: 20,
            height: 8,
        },
        Rules::default(),
        primitives,
        Effects {
            antialias: None,
            motion_blur: Some(blur(16, TimePattern::Stratified, 5)),
            conservative: None,
        },
    )
}

/// Static primitives are drawn once: they add N covered instants to each
/// sample they cover and no test. The tests are exactly the swept box's
/// samples times N (the box of the moving triangle at open and close,
/// in half pixels [1, 15] × [1, 6]: centres of columns 0 … 7, rows 0 … 5
/// whose centres (2i + 1)/2 lie in it). A production that tested the
/// static triangle at every instant (a hand-made plan calling it moving)
/// draws the same time coverage with more tests: the count tells.
#[test]
fn static_primitives_are_drawn_once() {
    let both = with_static(true);
    let alone = with_static(false);
    let plan = Plan::for_scene(&both);
    assert_eq!(plan.motion.as_ref().unwrap().moving, vec![true, false]);
    let frame = Production.rasterize(&both, &plan).unwrap();
    let moving_only = Production
        .rasterize(&alone, &Plan::for_scene(&alone))
        .unwrap();
    // Columns whose centre x + ½ lies in [1, 15]: 1 … 14; rows in [1, 6]: 1 … 5.
    let in_box = 14 * 5;
    let tests = frame.sample_tests.unwrap();
    assert_eq!(tests.tests, in_box * 16);
    assert_eq!(moving_only.sample_tests.unwrap(), tests);
    assert!(tests.covered > 0 && tests.covered < tests.tests);
    // The static triangle's own frame, drawn alone and static.
    let mut lone = both.clone();
    lone.primitives.remove(0);
    let statics = Production
        .rasterize(&lone, &Plan::for_scene(&lone))
        .unwrap();
    assert!(statics.coverage.iter().any(|&c| c > 0));
    for (p, &c) in statics.coverage.iter().enumerate() {
        let with = frame.time.as_ref().unwrap()[p];
        let without = moving_only.time.as_ref().unwrap()[p];
        // Multiples of 1/16: exact.
        assert_eq!(with - without, f64::from(c), "pixel {p}");
    }
    // The static triangle tested per instant: the same values, more tests.
    let mut every = plan.clone();
    every.motion.as_mut().unwrap().moving = vec![true, true];
    let tested = Production.rasterize(&both, &every).unwrap();
    assert_eq!(tested.time, frame.time);
    assert!(tested.sample_tests.unwrap().tests > tests.tests);
}

/// A scene that declares motion blur and moves nothing (its vertices give
/// `to` equal to `from`) is a static scene: no time loop, and exactly the
/// frame of the same scene without motion blur.
#[test]
fn a_scene_that_moves_nothing_is_static() {
    for antialias in [
        None,
        Some(Antialias {
            samples: 4,
            pattern: Pattern::Standard,
            seed: 0,
            adaptive: false,
            position_bits: 8,
        }),
    ] {
        let fixed = |p: Units| moving(p, p, 1);
        let declared = scene(
            SMALL,
            Rules::default(),
            vec![triangle([fixed([1, 1]), fixed([13, 3]), fixed([3, 11])])],
            Effects {
                antialias: antialias.clone(),
                motion_blur: Some(blur(8, TimePattern::Random, 1)),
                conservative: None,
            },
        );
        let mut plain = declared.clone();
        plain.effects.motion_blur = None;
        let plan = Plan::for_scene(&declared);
        assert!(plan.motion.is_none());
        assert_eq!(plan, Plan::for_scene(&plain));
        let frame = Production.rasterize(&declared, &plan).unwrap();
        assert!(frame.time.is_none() && frame.sample_tests.is_none());
        assert!(frame.coverage.iter().any(|&c| c > 0));
        assert_eq!(frame, Production.rasterize(&plain, &plan).unwrap());
    }
}

/// Without antialiasing (M = 1) the three stratified patterns draw the
/// same instants (SPEC.md §15.3), so the same frame; random instants draw
/// another.
#[test]
fn stratified_patterns_agree_without_antialiasing() {
    let mut rng = Rng(0x7374_7261);
    let mut differs = 0;
    for _ in 0..20 {
        let mut s = random_scene(&mut rng);
        s.effects.antialias = None;
        let frames: Vec<Frame> = TimePattern::ALL
            .iter()
            .map(|&pattern| {
                let mut one = s.clone();
                let motion = one.effects.motion_blur.as_mut().unwrap();
                motion.pattern = pattern;
                motion.samples = 8;
                Production.rasterize(&one, &Plan::for_scene(&one)).unwrap()
            })
            .collect();
        // ALL: random, stratified, jittered-xy-t, stratified-shuffled.
        assert_eq!(frames[1], frames[2]);
        assert_eq!(frames[1], frames[3]);
        differs += usize::from(frames[0].time != frames[1].time);
    }
    assert!(differs > 0);
}

/// Only the methods that draw moving scenes claim to: each that does draws
/// production's frame, and production and production-tiled do.
#[test]
fn only_methods_with_a_time_loop_claim_motion_blur() {
    let mut names = vec!["production", "dda-f32", "dda-f64", "float-f32", "float-f64"];
    names.extend(rastercheck::production::methods().iter().map(|m| m.name));
    let mut rng = Rng(0x636c_6169);
    let scenes: Vec<Scene> = (0..10).map(|_| random_scene(&mut rng)).collect();
    let mut claim = Vec::new();
    for name in names {
        let method = rastercheck::registry::by_name(name).unwrap();
        if !method.capabilities().motion_blur {
            continue;
        }
        claim.push(name);
        for s in &scenes {
            let plan = Plan::for_scene(s);
            assert_eq!(
                method.rasterize(s, &plan).unwrap(),
                Production.rasterize(s, &plan).unwrap(),
                "{name}"
            );
        }
    }
    assert_eq!(claim, ["production", "production-tiled"]);
}
