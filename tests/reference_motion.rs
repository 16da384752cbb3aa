//! The certified time-coverage oracle (SPEC.md §15.2) against brute force:
//! the static reference at many exact instants of the shutter. Also the
//! bound's promises, hand-computed special cases, static primitives in
//! moving scenes, and two deliberately wrong oracles that the comparison
//! catches.
//!
//! The brute force is the midpoint rule over K equal strata of the
//! shutter. At one sample a primitive's coverage is a step function of τ
//! that changes at most C times (a root of one of the polynomials deciding
//! it: C = 8 for a triangle, whose area and three edge functions are
//! quadratics; C = 16 for a line: 2 instants where |dx| = |dy|, the roots
//! of dx and dy, of the 4 end conditions and of the 4 side quadratics,
//! see `motion/moving.rs`). A stratum holding c changes is off by at most
//! min(1, c/2)/K of the shutter, so the rule is within C/(2K) of the exact
//! value: a rigorous tolerance, with no guess about where the roots are.

use std::time::Instant as Clock;

use dashu_ratio::RBig;
use rastercheck::plan::Plan;
use rastercheck::reference::motion::{self, Certified, Mutation};
use rastercheck::reference::{self};
use rastercheck::scene::samples::SplitMix64;
use rastercheck::scene::{parse_case, Cull, FillRule, Limits, Number, Primitive, Scene};

fn r(n: i64, d: i64) -> RBig {
    RBig::from_parts_signed(n.into(), d.into())
}

fn text(q: &RBig) -> String {
    format!("{}/{}", q.numerator(), q.denominator())
}

/// A vertex at `from` at τ = 0 and `to` at τ = 1, in pixels.
#[derive(Clone, Debug)]
struct Move {
    from: [RBig; 2],
    to: [RBig; 2],
}

fn still(p: [RBig; 2]) -> Move {
    Move {
        from: p.clone(),
        to: p,
    }
}

fn moving(from: [RBig; 2], to: [RBig; 2]) -> Move {
    Move { from, to }
}

fn vertex(v: &Move) -> String {
    let [fx, fy] = &v.from;
    let [tx, ty] = &v.to;
    format!(
        r#"{{"from": ["{}", "{}"], "to": ["{}", "{}"]}}"#,
        text(fx),
        text(fy),
        text(tx),
        text(ty)
    )
}

fn triangle(v: &[Move]) -> String {
    let vs: Vec<String> = v.iter().map(vertex).collect();
    format!(r#"{{"triangle": [{}]}}"#, vs.join(", "))
}

fn line(v: &[Move], width: &RBig) -> String {
    format!(
        r#"{{"line": [{}, {}], "rule": "parallelogram", "width": "{}"}}"#,
        vertex(&v[0]),
        vertex(&v[1]),
        text(width)
    )
}

/// Everything about a scene but its primitives.
#[derive(Clone, Debug)]
struct Setup {
    size: u32,
    bits: u32,
    fill: FillRule,
    cull: Cull,
    /// [open, close] as fractions of [0, 1], multiples of 2^-16.
    shutter: [RBig; 2],
    /// `effects.antialias`, as JSON.
    antialias: Option<String>,
}

impl Setup {
    fn new(size: u32) -> Setup {
        Setup {
            size,
            bits: 8,
            fill: FillRule::TopLeft,
            cull: Cull::None,
            shutter: [RBig::ZERO, RBig::ONE],
            antialias: None,
        }
    }

    fn scene(&self, primitives: &[String]) -> Scene {
        let antialias = self
            .antialias
            .as_ref()
            .map_or(String::new(), |a| format!(r#", "antialias": {a}"#));
        let json = format!(
            r#"{{"name": "t", "canvas": {{"width": {s}, "height": {s}}},
                "rules": {{"subpixel_bits": {}, "fill_rule": "{}", "cull": "{}"}},
                "primitives": [{}],
                "effects": {{"motion_blur": {{"shutter": ["{}", "{}"], "samples": 4}}{antialias}}}}}"#,
            self.bits,
            self.fill.name(),
            self.cull.name(),
            primitives.join(", "),
            text(&self.shutter[0]),
            text(&self.shutter[1]),
            s = self.size,
        );
        parse_case(&json, "t.json", &Limits::default()).unwrap_or_else(|e| panic!("{e}\n{json}"))
    }
}

/// The spatial samples of a pixel, as offsets in pixels from its corner.
fn offsets(scene: &Scene) -> Vec<[RBig; 2]> {
    match Plan::for_scene(scene).antialias {
        Some(samples) => samples
            .offsets
            .iter()
            .map(|o| o.map(|c| r(i64::from(c), 1 << samples.position_bits)))
            .collect(),
        None => vec![[r(1, 2), r(1, 2)]],
    }
}

/// The K stratified instants open + (close − open)(j + ½)/K.
fn instants(scene: &Scene, k: usize) -> Vec<RBig> {
    let [open, close] = shutter(scene);
    (0..k)
        .map(|j| &open + (&close - &open) * r(2 * j as i64 + 1, 2 * k as i64))
        .collect()
}

fn shutter(scene: &Scene) -> [RBig; 2] {
    let blur = scene.effects.motion_blur.as_ref().expect("motion blur");
    blur.shutter.map(|u| r(i64::from(u), 1 << 16))
}

/// Brute force: each sample slot's coverage count at each instant, from
/// the static reference on the static scene at that instant
/// (`Scene::at_instant`). `coverage_under` is the visit `reference::render`
/// counts coverage with, without the exact areas an antialiased render
/// also computes.
fn brute_samples(scene: &Scene, instants: &[RBig]) -> Vec<Vec<u16>> {
    instants
        .iter()
        .map(|t| {
            let at = scene.at_instant(&Number::from_rbig(t.clone()));
            reference::coverage_under(&at, scene.rules.fill_rule)
        })
        .collect()
}

/// Each pixel's mean over instants and spatial samples.
fn brute_pixels(samples: &[Vec<u16>], m: usize) -> Vec<RBig> {
    let pixels = samples[0].len() / m;
    (0..pixels)
        .map(|p| {
            let sum: u64 = samples
                .iter()
                .flat_map(|at| &at[p * m..(p + 1) * m])
                .map(|&c| u64::from(c))
                .sum();
            r(sum as i64, (samples.len() * m) as i64)
        })
        .collect()
}

/// C of the module doc, summed over the moving primitives.
fn changes(scene: &Scene) -> i64 {
    scene
        .primitives
        .iter()
        .filter(|p| p.moves())
        .map(|p| match p {
            Primitive::Triangle(_) => 8,
            _ => 16,
        })
        .sum()
}

/// Pixels where |brute − value| > C/(2K) + bound, described.
fn disagreements(scene: &Scene, certified: &[Certified], brute: &[RBig], k: usize) -> Vec<String> {
    let tolerance = r(changes(scene), 2 * k as i64);
    certified
        .iter()
        .zip(brute)
        .enumerate()
        .filter(|(_, (c, b))| {
            let error = &c.value - *b;
            let error = if error < RBig::ZERO { -error } else { error };
            error > &tolerance + &c.bound
        })
        .map(|(p, (c, b))| {
            let w = scene.canvas.width as usize;
            format!(
                "({}, {}): certified {} (±{:e}), brute {}",
                p % w,
                p / w,
                c.value.to_f64().value(),
                c.bound.to_f64().value(),
                b.to_f64().value()
            )
        })
        .collect()
}

fn coverage(scene: &Scene) -> Vec<Certified> {
    motion::time_coverage(scene, &Plan::for_scene(scene))
}

fn mutated(scene: &Scene, mutation: Mutation) -> Vec<Certified> {
    motion::time_coverage_with(scene, &Plan::for_scene(scene), mutation)
}

struct Rng(SplitMix64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0.next_u64() % n
    }

    fn pick<T: Clone>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize].clone()
    }

    /// A coordinate in [lo, hi]: mostly on half and quarter pixels, where
    /// samples and edges meet, sometimes thirds, which snap.
    fn coordinate(&mut self, lo: i64, hi: i64) -> RBig {
        let den = self.pick(&[1, 2, 2, 2, 4, 8, 3]);
        let span = ((hi - lo) * den + 1) as u64;
        r(lo * den + self.below(span) as i64, den)
    }

    fn point(&mut self, lo: i64, hi: i64) -> [RBig; 2] {
        [self.coordinate(lo, hi), self.coordinate(lo, hi)]
    }
}

/// Rotations with rational cosines and sines: (cos, sin) in Pythagorean
/// triples, a quarter turn and a half turn (which passes through a point).
const TURNS: [(i64, i64, i64); 6] = [
    (3, 4, 5),
    (4, -3, 5),
    (0, 1, 1),
    (-1, 0, 1),
    (5, 12, 13),
    (-3, 4, 5),
];

fn turned(p: &[RBig; 2], centre: &[RBig; 2], (c, s, h): (i64, i64, i64)) -> [RBig; 2] {
    let (c, s) = (r(c, h), r(s, h));
    let d = [&p[0] - &centre[0], &p[1] - &centre[1]];
    [
        &centre[0] + &c * &d[0] - &s * &d[1],
        &centre[1] + &s * &d[0] + &c * &d[1],
    ]
}

/// Where the vertices `from` go, by one of several kinds of motion:
/// translation, rotation, scaling (through a point, or a point
/// reflection), free ends, a winding flip (the last vertex mirrored
/// through the others' midpoint), a mirror image, or one vertex alone.
fn random_motion(rng: &mut Rng, from: &[[RBig; 2]]) -> Vec<[RBig; 2]> {
    let centre = rng.point(0, 8);
    match rng.below(7) {
        0 => {
            let v = rng.point(-6, 6);
            from.iter()
                .map(|p| [&p[0] + &v[0], &p[1] + &v[1]])
                .collect()
        }
        1 => {
            let turn = rng.pick(&TURNS);
            from.iter().map(|p| turned(p, &centre, turn)).collect()
        }
        2 => {
            let k = rng.pick(&[r(-1, 1), r(0, 1), r(2, 1), r(1, 2), r(-1, 2)]);
            from.iter()
                .map(|p| [0, 1].map(|i| &centre[i] + &k * (&p[i] - &centre[i])))
                .collect()
        }
        3 => from.iter().map(|_| rng.point(-2, 10)).collect(),
        4 => {
            let n = from.len();
            let mut to = from.to_vec();
            if n == 3 {
                to[2] = [0, 1].map(|i| &from[0][i] + &from[1][i] - &from[2][i]);
            } else {
                to.swap(0, 1);
            }
            to
        }
        5 => from
            .iter()
            .map(|p| [&centre[0] * RBig::from(2) - &p[0], p[1].clone()])
            .collect(),
        _ => {
            let mut to = from.to_vec();
            to[0] = rng.point(-2, 10);
            to
        }
    }
}

fn random_primitive(rng: &mut Rng, lines: bool) -> String {
    let n = if lines { 2 } else { 3 };
    let from: Vec<[RBig; 2]> = (0..n).map(|_| rng.point(-2, 10)).collect();
    let to = random_motion(rng, &from);
    let v: Vec<Move> = from
        .into_iter()
        .zip(to)
        .map(|(f, t)| moving(f, t))
        .collect();
    if lines {
        let width = rng.pick(&[r(1, 2), r(1, 1), r(3, 2), r(2, 1), r(5, 2), r(1, 3)]);
        line(&v, &width)
    } else {
        triangle(&v)
    }
}

fn random_setup(rng: &mut Rng) -> Setup {
    let shutter = match rng.below(3) {
        0 => [RBig::ZERO, RBig::ONE],
        1 => {
            let a = rng.below(8) as i64;
            let b = a + 1 + rng.below(8 - a as u64) as i64;
            [r(a, 8), r(b, 8)]
        }
        _ => {
            let a = rng.below(1 << 15) as i64;
            let b = a + 1 + rng.below((1 << 16) - a as u64) as i64;
            [r(a, 1 << 16), r(b, 1 << 16)]
        }
    };
    let antialias = match rng.below(3) {
        0 => Some(rng.pick(&[
            r#"{"samples": 4, "pattern": "standard"}"#.to_owned(),
            r#"{"samples": 4, "pattern": "grid", "position_bits": 4}"#.to_owned(),
            r#"{"samples": 2, "pattern": "random", "seed": 7}"#.to_owned(),
        ])),
        _ => None,
    };
    Setup {
        size: 8,
        bits: rng.pick(&[1, 2, 3, 4, 8]),
        fill: rng.pick(&FillRule::ALL),
        cull: rng.pick(&[Cull::None, Cull::Clockwise, Cull::CounterClockwise]),
        shutter,
        antialias,
    }
}

/// What one family of random scenes showed.
#[derive(Debug, Default)]
struct Tally {
    scenes: usize,
    /// Sample-primitive pairs whose bound is not 0 (pixels, really).
    bounded_pixels: usize,
    worst_bound: f64,
    /// Scenes on which each wrong oracle disagrees with brute force.
    linear_edges_caught: usize,
    winding_at_open_caught: usize,
    /// Long constant runs checked on sub-shutters.
    runs: usize,
}

/// Random scenes of one or two moving primitives, each held against brute
/// force at K instants, and the same comparison run on the wrong oracles.
fn random_family(seed: u64, scenes: usize, lines: bool, k: usize) -> Tally {
    let mut rng = Rng(SplitMix64::new(seed));
    let mut tally = Tally::default();
    for round in 0..scenes {
        let setup = random_setup(&mut rng);
        let count = 1 + usize::from(rng.below(4) == 0);
        let prims: Vec<String> = (0..count)
            .map(|_| random_primitive(&mut rng, lines))
            .collect();
        let scene = setup.scene(&prims);
        if !scene.moves() {
            continue;
        }
        tally.scenes += 1;
        let certified = coverage(&scene);
        let times = instants(&scene, k);
        let samples = brute_samples(&scene, &times);
        let m = offsets(&scene).len();
        let brute = brute_pixels(&samples, m);
        let wrong = disagreements(&scene, &certified, &brute, k);
        assert!(
            wrong.is_empty(),
            "round {round}: {setup:?}\n{}\n{}",
            prims.join("\n"),
            wrong.join("\n")
        );
        for c in &certified {
            assert!(c.bound <= motion::max_bound() * RBig::from(count), "{c:?}");
            if c.bound > RBig::ZERO {
                tally.bounded_pixels += 1;
                tally.worst_bound = tally.worst_bound.max(c.bound.to_f64().value());
            }
        }
        let caught =
            |mutation| !disagreements(&scene, &mutated(&scene, mutation), &brute, k).is_empty();
        tally.linear_edges_caught += usize::from(caught(Mutation::LinearEdges));
        tally.winding_at_open_caught += usize::from(caught(Mutation::WindingAtOpen));
        if count == 1 {
            tally.runs += check_long_runs(&scene, &samples, &times);
        }
    }
    tally
}

/// Where one sample's brute-force coverage stays v over a long run of
/// instants τ_a … τ_b but changes somewhere else, the certified coverage
/// over the sub-shutter [τ_a, τ_b] is within (C/2)/(b − a) of v: every
/// instant of the run is v, so any other value lies in excursions strictly
/// between two neighbouring instants, each at most one stratum wide and
/// each spending two of the C changes. Returns how many runs it checked.
fn check_long_runs(scene: &Scene, samples: &[Vec<u16>], times: &[RBig]) -> usize {
    let k = times.len();
    let m = offsets(scene).len();
    let offsets = offsets(scene);
    let width = scene.canvas.width as usize;
    let mut checked = 0;
    for slot in 0..samples[0].len() {
        let series: Vec<u16> = samples.iter().map(|at| at[slot]).collect();
        if series.iter().all(|&c| c == series[0]) {
            continue;
        }
        // The longest run of equal values.
        let (mut best, mut start) = ((0, 0), 0);
        for j in 1..=k {
            if j == k || series[j] != series[start] {
                if j - 1 - start > best.1 - best.0 {
                    best = (start, j - 1);
                }
                start = j;
            }
        }
        let (a, b) = best;
        if b - a < k / 4 {
            continue;
        }
        let (pixel, s) = (slot / m, slot % m);
        let point = [
            r((pixel % width) as i64, 1) + &offsets[s][0],
            r((pixel / width) as i64, 1) + &offsets[s][1],
        ];
        let c = motion::point_coverage(scene, 0, [&point[0], &point[1]], [&times[a], &times[b]]);
        let v = RBig::from(series[a]);
        let error = &c.value - &v;
        let error = if error < RBig::ZERO { -error } else { error };
        let allowed = r(changes(scene) / 2, (b - a) as i64) + &c.bound;
        assert!(
            error <= allowed,
            "sample {slot}: brute force holds {v} over instants {a}..={b}, certified {} over them",
            c.value.to_f64().value()
        );
        checked += 1;
        if checked == 2 {
            break;
        }
    }
    checked
}

#[test]
fn certified_matches_brute_force_on_random_moving_triangles() {
    let start = Clock::now();
    let tally = random_family(1, 250, false, 1024);
    eprintln!("triangles: {tally:?} in {:?}", start.elapsed());
    assert!(tally.scenes >= 240, "{tally:?}");
    assert!(tally.bounded_pixels > 0, "some roots were irrational");
    assert!(tally.runs > 10, "{tally:?}");
    // Both wrong oracles fail the same comparison on some scenes.
    assert!(tally.linear_edges_caught > 0, "{tally:?}");
    assert!(tally.winding_at_open_caught > 0, "{tally:?}");
}

#[test]
fn certified_matches_brute_force_on_random_moving_lines() {
    let start = Clock::now();
    let tally = random_family(2, 160, true, 1024);
    eprintln!("lines: {tally:?} in {:?}", start.elapsed());
    assert!(tally.scenes >= 150, "{tally:?}");
    assert!(tally.bounded_pixels > 0, "some roots were irrational");
    assert!(tally.linear_edges_caught > 0, "{tally:?}");
}

/// `point_coverage` of primitive 0 at a pixel's centre.
fn at_centre(scene: &Scene, x: i64, y: i64, shutter: [&RBig; 2]) -> Certified {
    motion::point_coverage(scene, 0, [&r(2 * x + 1, 2), &r(2 * y + 1, 2)], shutter)
}

fn exact(value: RBig) -> Certified {
    Certified {
        value,
        bound: RBig::ZERO,
    }
}

fn p(x: i64, y: i64) -> [RBig; 2] {
    [r(x, 1), r(y, 1)]
}

/// A point of pixel coordinates given in halves.
fn h(x: i64, y: i64) -> [RBig; 2] {
    [r(x, 2), r(y, 2)]
}

/// Every pixel of a scene against brute force (a check of the hand values
/// below as much as of the oracle).
fn assert_brute(scene: &Scene, k: usize) {
    let certified = coverage(scene);
    let brute = brute_pixels(
        &brute_samples(scene, &instants(scene, k)),
        offsets(scene).len(),
    );
    let wrong = disagreements(scene, &certified, &brute, k);
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn translation_is_exact_with_bound_zero() {
    // A vertical edge x = 4τ sweeps right across row 0; the triangle lies
    // right of it, so the centre x + ½ is covered while 4τ < x + ½.
    let setup = Setup::new(8);
    let tri = [
        moving(p(0, -10), p(4, -10)),
        moving(p(0, 30), p(4, 30)),
        moving(p(40, 10), p(44, 10)),
    ];
    let scene = setup.scene(&[triangle(&tri)]);
    let time = coverage(&scene);
    for x in 0..8 {
        let expected = r(2 * x + 1, 8).min(RBig::ONE);
        assert_eq!(time[x as usize], exact(expected), "pixel ({x}, 0)");
    }
    // The reference's frame is the time layer, rounded.
    let frame = reference::render(&scene, &Plan::for_scene(&scene));
    let rounded: Vec<f64> = time.iter().map(|c| c.value.to_f64().value()).collect();
    assert_eq!(frame.time.as_ref(), Some(&rounded));
    let [zero, one] = [RBig::ZERO, RBig::ONE];
    assert_eq!(at_centre(&scene, 1, 0, [&zero, &one]), exact(r(3, 8)));
    // Over [¼, ½] it is covered during [¼, ⅜): half of it.
    assert_eq!(
        at_centre(&scene, 1, 0, [&r(1, 4), &r(1, 2)]),
        exact(r(1, 2))
    );
    // Random translations, antialiased too: every bound is exactly 0. The
    // move is by whole pixels, so that both ends snap alike (ties to even
    // included: subpixel_bits ≥ 1 here) and the snapped motion is still a
    // translation.
    let mut rng = Rng(SplitMix64::new(3));
    for round in 0..40 {
        let mut setup = random_setup(&mut rng);
        setup.size = 6;
        let lines = round % 3 == 0;
        let n = if lines { 2 } else { 3 };
        let v = [0, 1].map(|_| r(rng.below(11) as i64 - 5, 1));
        let moves: Vec<Move> = (0..n)
            .map(|_| {
                let a = rng.point(-2, 8);
                let b = [&a[0] + &v[0], &a[1] + &v[1]];
                moving(a, b)
            })
            .collect();
        let prim = if lines {
            line(&moves, &r(3, 2))
        } else {
            triangle(&moves)
        };
        let scene = setup.scene(&[prim]);
        assert!(
            coverage(&scene).iter().all(|c| c.bound == RBig::ZERO),
            "round {round}"
        );
    }
}

#[test]
fn a_double_root_grazes_the_sample_exactly() {
    // Edge a→b at sample q = (8.5, 8.5) has E(τ) = 3(2τ − 1)²: it touches q
    // at τ = ½ only (a top edge then), a double root, rational.
    let q = h(17, 17);
    let a = moving(
        [&q[0] - r(2, 1), &q[1] + r(1, 1)],
        [q[0].clone(), &q[1] - r(1, 1)],
    );
    let b = moving(
        [&q[0] + r(1, 1), &q[1] - r(2, 1)],
        [&q[0] + r(3, 1), &q[1] + r(2, 1)],
    );
    let shutter = [&RBig::ZERO, &RBig::ONE];
    for (third, expected) in [(r(20, 1), RBig::ONE), (r(-20, 1), RBig::ZERO)] {
        let c = still([&q[0] - r(3, 1), &q[1] + &third]);
        for fill in FillRule::ALL {
            let scene = Setup {
                fill,
                ..Setup::new(16)
            }
            .scene(&[triangle(&[a.clone(), b.clone(), c.clone()])]);
            assert_eq!(at_centre(&scene, 8, 8, shutter), exact(expected.clone()));
        }
    }
}

#[test]
fn parallel_velocities_make_every_edge_linear() {
    // a and b slide along x at different speeds, c stands still: no
    // velocity cross product is non-zero, yet the shape changes. The edge
    // a→b reaches (10.5, 6.5) at τ = 10/23.
    let tri = [
        moving(p(8, 2), p(16, 2)),
        moving(p(8, 10), p(12, 10)),
        still(p(0, 6)),
    ];
    let scene = Setup::new(16).scene(&[triangle(&tri)]);
    assert_eq!(
        at_centre(&scene, 10, 6, [&RBig::ZERO, &RBig::ONE]),
        exact(r(13, 23))
    );
    assert_brute(&scene, 256);
}

#[test]
fn a_vertex_through_the_sample_at_one_half() {
    // An apex pointing right crosses (8.5, 8.5) at τ = ½; the triangle
    // covers the sample once the apex has passed it.
    let apex = h(17, 17);
    let shifted = |dx: i64, dy: i64| {
        moving(
            [&apex[0] + r(dx - 2, 1), &apex[1] + r(dy, 1)],
            [&apex[0] + r(dx + 2, 1), &apex[1] + r(dy, 1)],
        )
    };
    let tri = [shifted(0, 0), shifted(-4, -2), shifted(-4, 2)];
    for fill in FillRule::ALL {
        let scene = Setup {
            fill,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        assert_eq!(
            at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]),
            exact(r(1, 2))
        );
    }
}

#[test]
fn coverage_starting_or_ending_at_the_shutter_ends() {
    // Shutter [¼, ¾]. A vertical edge meets (1.5, 0.5) exactly at open
    // (x = −½ + 8τ) or exactly at close (x = −9/2 + 8τ).
    let setup = Setup {
        shutter: [r(1, 4), r(3, 4)],
        ..Setup::new(4)
    };
    let wall = |x0: RBig, side: i64| {
        let at = |x: &RBig, y: i64| [x.clone(), r(y, 1)];
        let x1 = &x0 + r(8, 1);
        triangle(&[
            moving(at(&x0, -20), at(&x1, -20)),
            moving(at(&x0, 40), at(&x1, 40)),
            moving(at(&(&x0 + r(side, 1)), 10), at(&(&x1 + r(side, 1)), 10)),
        ])
    };
    let cases = [
        // Right of the edge, which passes the sample at open: never.
        (wall(r(-1, 2), 60), RBig::ZERO),
        // Left of it: covered from open on.
        (wall(r(-1, 2), -60), RBig::ONE),
        // Right of it, reaching the sample at close: covered until then.
        (wall(r(-9, 2), 60), RBig::ONE),
        (wall(r(-9, 2), -60), RBig::ZERO),
    ];
    for (prim, expected) in cases {
        let scene = setup.scene(&[prim]);
        assert_eq!(coverage(&scene)[1], exact(expected));
    }
}

#[test]
fn winding_flips_mid_shutter_under_each_cull() {
    // a and b swap places: clockwise before τ = ½, zero area at ½,
    // counter-clockwise after. (6.5, 8.5) is covered while |τ − ½| > ⅓.
    let tri = [
        moving(p(2, 2), p(10, 2)),
        moving(p(10, 2), p(2, 2)),
        still(p(6, 10)),
    ];
    let shutter = [&RBig::ZERO, &RBig::ONE];
    for (cull, expected, wrong) in [
        (Cull::None, r(1, 3), r(1, 3)),
        (Cull::Clockwise, r(1, 6), RBig::ZERO),
        (Cull::CounterClockwise, r(1, 6), r(1, 3)),
    ] {
        let scene = Setup {
            cull,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        assert_eq!(at_centre(&scene, 6, 8, shutter), exact(expected));
        assert_brute(&scene, 192);
        // Culling by the winding at open is caught.
        let open = motion::point_coverage_with(
            &scene,
            0,
            [&r(13, 2), &r(17, 2)],
            shutter,
            Mutation::WindingAtOpen,
        );
        assert_eq!(open, exact(wrong));
    }
}

#[test]
fn collapse_at_one_half_on_an_edge_the_sample_rides() {
    // (4.5, 4.5) lies on edge a→b at every instant. c crosses that edge at
    // τ = ½: before, the triangle lies below it (a top edge, clockwise);
    // after, above it (a bottom edge, counter-clockwise); at ½ it has no
    // area and covers nothing.
    let tri = [still(h(0, 9)), still(h(16, 9)), moving(p(4, 12), p(4, -3))];
    let half = r(1, 2);
    let expect = |fill: FillRule, cull: Cull| -> RBig {
        let before = (fill.owns_top() && cull != Cull::Clockwise) as i64;
        let after = (fill.owns_bottom() && cull != Cull::CounterClockwise) as i64;
        &half * RBig::from(before + after)
    };
    for fill in FillRule::ALL {
        for cull in [Cull::None, Cull::Clockwise, Cull::CounterClockwise] {
            let scene = Setup {
                fill,
                cull,
                ..Setup::new(8)
            }
            .scene(&[triangle(&tri)]);
            let c = at_centre(&scene, 4, 4, [&RBig::ZERO, &RBig::ONE]);
            assert_eq!(c, exact(expect(fill, cull)), "{fill:?} {cull:?}");
        }
    }
}

#[test]
fn an_edge_the_sample_rides_turns_horizontal() {
    // (8.5, 8.5) is the midpoint of a→b at every instant; the edge turns
    // about it, horizontal at τ = ½. With c below, it is a left edge
    // before ½ and a right edge after.
    let q = h(17, 17);
    let end = |sign: i64| {
        let e = |tau: i64| [r(4 * sign, 1), r(sign * (-4 + 8 * tau), 1)];
        let (e0, e1) = (e(0), e(1));
        moving(
            [&q[0] + &e0[0], &q[1] + &e0[1]],
            [&q[0] + &e1[0], &q[1] + &e1[1]],
        )
    };
    let tri = [end(-1), end(1), still([q[0].clone(), &q[1] + r(10, 1)])];
    for fill in FillRule::ALL {
        let scene = Setup {
            fill,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        let expected = r(1, 2) * RBig::from(fill.owns_left() as i64 + fill.owns_right() as i64);
        assert_eq!(
            at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]),
            exact(expected),
            "{fill:?}"
        );
    }
}

#[test]
fn an_irrational_crossing_is_within_its_bound() {
    // E(τ) = −8(2τ² − 1) at (8.5, 8.5): covered until τ = 1/√2.
    let q = h(17, 17);
    let tri = [
        moving(
            [q[0].clone(), &q[1] + r(1, 1)],
            [&q[0] + r(2, 1), &q[1] + r(1, 1)],
        ),
        moving(
            [&q[0] - r(8, 1), &q[1] + r(1, 1)],
            [&q[0] - r(6, 1), &q[1] - r(7, 1)],
        ),
        still(p(20, 0)),
    ];
    let scene = Setup::new(16).scene(&[triangle(&tri)]);
    let c = at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]);
    assert!(
        c.bound > RBig::ZERO && c.bound <= motion::max_bound(),
        "{c:?}"
    );
    // value − bound ≤ 1/√2 ≤ value + bound, squared.
    let two = RBig::from(2);
    let low = &c.value - &c.bound;
    let high = &c.value + &c.bound;
    assert!(
        &low * &low * &two <= RBig::ONE && &high * &high * &two >= RBig::ONE,
        "{c:?}"
    );
    assert_brute(&scene, 256);
    // Without the τ² term the edge function is the constant 8: covered
    // throughout, which the brute force refutes.
    let wrong = mutated(&scene, Mutation::LinearEdges);
    assert_eq!(wrong[8 * 16 + 8], exact(RBig::ONE));
    let brute = brute_pixels(&brute_samples(&scene, &instants(&scene, 256)), 1);
    assert!(!disagreements(&scene, &wrong, &brute, 256).is_empty());
}

/// Whether q ≤ b/√2, exactly.
fn at_most_root_half(q: &RBig, b: &RBig) -> bool {
    let (q2, b2) = (q * q * RBig::from(2), b * b);
    match (*q <= RBig::ZERO, *b >= RBig::ZERO) {
        (true, true) => true,
        (false, true) => q2 <= b2,
        (true, false) => q2 >= b2,
        (false, false) => false,
    }
}

/// |value − (a + b/√2)| ≤ bound, exactly; the bound is not 0 when b is not.
fn assert_near_root_half(c: &Certified, a: &RBig, b: &RBig, what: &str) {
    let x = &c.value - a;
    let low = &x - &c.bound;
    let high = &x + &c.bound;
    let minus_high = -&high;
    let minus_b = -b;
    // low ≤ b/√2 and −high ≤ −b/√2.
    assert!(
        at_most_root_half(&low, b) && at_most_root_half(&minus_high, &minus_b),
        "{what}: {c:?} is not {a} + {b}/√2"
    );
    assert!(c.bound <= motion::max_bound(), "{what}: {c:?}");
}

#[test]
fn a_sample_riding_an_edge_sees_the_winding_flip_at_an_irrational_instant() {
    // (8.5, 8.5) is the midpoint of a→b = (2, 2τ) at every instant, and c
    // = q + (2τ, 1) crosses that edge's line when 1 − 2τ² = 0: the
    // winding flips at 1/√2, so the edge's ownership changes there. Before,
    // clockwise with the triangle left of a downward edge (a right edge);
    // after, a left edge. (Contrary to SPEC.md §15.2's last sentence, such
    // an instant need not be rational: it is a root of A(τ), isolated like
    // any other.)
    let q = h(17, 17);
    let tri = [
        moving(
            [&q[0] - r(1, 1), q[1].clone()],
            [&q[0] - r(1, 1), &q[1] - r(1, 1)],
        ),
        moving(
            [&q[0] + r(1, 1), q[1].clone()],
            [&q[0] + r(1, 1), &q[1] + r(1, 1)],
        ),
        moving(
            [q[0].clone(), &q[1] + r(1, 1)],
            [&q[0] + r(2, 1), &q[1] + r(1, 1)],
        ),
    ];
    let root = r(1, 1);
    for fill in FillRule::ALL {
        for cull in [Cull::None, Cull::Clockwise, Cull::CounterClockwise] {
            let scene = Setup {
                fill,
                cull,
                ..Setup::new(16)
            }
            .scene(&[triangle(&tri)]);
            let c = at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]);
            // Covered for τ < 1/√2 (b/√2 with b = 1) when the right edge
            // owns it and clockwise is drawn, and for τ > 1/√2 (1 − 1/√2)
            // when the left edge does and counter-clockwise is drawn.
            let before = fill.owns_right() && cull != Cull::Clockwise;
            let after = fill.owns_left() && cull != Cull::CounterClockwise;
            let a = if after { RBig::ONE } else { RBig::ZERO };
            let b = RBig::from(before as i64 - after as i64) * &root;
            assert_near_root_half(&c, &a, &b, &format!("{fill:?} {cull:?}"));
            assert!(c.bound > RBig::ZERO, "an irrational root in the shutter");
            assert_brute(&scene, 256);
        }
    }
}

#[test]
fn a_vertex_riding_the_sample_flips_at_an_irrational_instant() {
    // Vertex a stays on (8.5, 8.5); b − a = 4(−1, 2τ), c − a = 4(τ, −1), so
    // A(τ) = 16(1 − 2τ²). Near τ = 1/√2 the corner at a opens to almost a
    // half-plane, on one side of the line before and on the other after.
    // Top-left nudges the sample towards (1, ε): inside the corner only
    // after 1/√2, when it is counter-clockwise.
    let q = h(17, 17);
    let tri = [
        still(q.clone()),
        moving(
            [&q[0] - r(4, 1), q[1].clone()],
            [&q[0] - r(4, 1), &q[1] + r(8, 1)],
        ),
        moving(
            [q[0].clone(), &q[1] - r(4, 1)],
            [&q[0] + r(4, 1), &q[1] - r(4, 1)],
        ),
    ];
    for (cull, after) in [
        (Cull::None, true),
        (Cull::Clockwise, true),
        (Cull::CounterClockwise, false),
    ] {
        let scene = Setup {
            cull,
            ..Setup::new(16)
        }
        .scene(&[triangle(&tri)]);
        let c = at_centre(&scene, 8, 8, [&RBig::ZERO, &RBig::ONE]);
        let (a, b) = if after {
            (RBig::ONE, -RBig::ONE)
        } else {
            (RBig::ZERO, RBig::ZERO)
        };
        assert_near_root_half(&c, &a, &b, &format!("{cull:?}"));
        for fill in FillRule::ALL {
            assert_brute(
                &Setup {
                    fill,
                    cull,
                    ..Setup::new(16)
                }
                .scene(&[triangle(&tri)]),
                256,
            );
        }
    }
}

#[test]
fn static_primitives_keep_their_static_coverage() {
    // Static triangle, polygon and lines beside a moving triangle; pixels
    // the mover never reaches hold the static reference's counts exactly.
    let mover = triangle(&[
        moving(h(1, 1), h(9, 3)),
        moving(h(7, 1), h(13, 5)),
        moving(h(1, 7), h(5, 9)),
    ]);
    let statics = [
        triangle(&[still(h(3, 10)), still(h(29, 13)), still(h(9, 31))]),
        r#"{"polygon": [[16, 1], [31, 2], [20, 9], [30, 14]], "fill": "even-odd"}"#.to_owned(),
        line(&[still(h(2, 30)), still(h(30, 20))], &r(3, 2)),
    ];
    let midpoint = r#"{"line": [[0.5, 12.5], [15.5, 14]]}"#.to_owned();
    for antialias in [None, Some(r#"{"samples": 4}"#.to_owned())] {
        let setup = Setup {
            antialias: antialias.clone(),
            ..Setup::new(16)
        };
        let mut prims: Vec<String> = statics.to_vec();
        if antialias.is_none() {
            prims.push(midpoint.clone());
        }
        let alone = setup.scene(&prims);
        prims.push(mover.clone());
        let scene = setup.scene(&prims);
        let m = offsets(&scene).len();
        let counts = reference::coverage_under(&alone, alone.rules.fill_rule);
        let time = coverage(&scene);
        let mut untouched = 0;
        for (pixel, c) in time.iter().enumerate() {
            let (x, y) = (pixel % 16, pixel / 16);
            if x < 8 && y < 6 {
                continue; // the mover's swept box
            }
            let sum: u16 = counts[pixel * m..(pixel + 1) * m].iter().sum();
            assert_eq!(*c, exact(r(i64::from(sum), m as i64)), "({x}, {y})");
            untouched += usize::from(sum > 0);
        }
        assert!(untouched > 40);
        assert_brute(&scene, 128);
    }
}

#[test]
fn zero_velocity_agrees_with_the_static_reference() {
    // The oracle's own decision at an instant, on static triangles and
    // parallelograms on coarse coordinates (samples on edges and at
    // vertices), against the static reference, sample by sample.
    let mut rng = Rng(SplitMix64::new(5));
    let mut covered = 0;
    for round in 0..150 {
        let mut setup = random_setup(&mut rng);
        setup.size = 6;
        let lines = round % 3 == 0;
        let n = if lines { 2 } else { 3 };
        let v: Vec<Move> = (0..n)
            .map(|_| {
                let a = [
                    r(rng.below(13) as i64 - 1, 2),
                    r(rng.below(13) as i64 - 1, 2),
                ];
                still(a)
            })
            .collect();
        let prim = if lines {
            line(&v, &rng.pick(&[r(1, 1), r(2, 1), r(1, 2)]))
        } else {
            triangle(&v)
        };
        let scene = setup.scene(&[prim]);
        let counts = reference::coverage_under(&scene, scene.rules.fill_rule);
        let offsets = offsets(&scene);
        let m = offsets.len();
        let [open, close] = setup.shutter.clone();
        for (slot, &count) in counts.iter().enumerate() {
            let (pixel, s) = (slot / m, slot % m);
            let point = [
                r((pixel % 6) as i64, 1) + &offsets[s][0],
                r((pixel / 6) as i64, 1) + &offsets[s][1],
            ];
            let c = motion::point_coverage(&scene, 0, [&point[0], &point[1]], [&open, &close]);
            assert_eq!(c, exact(RBig::from(count)), "round {round} slot {slot}");
            covered += usize::from(count > 0);
        }
    }
    assert!(covered > 500, "{covered}");
}

#[test]
fn timing_a_triangle_moving_100_pixels() {
    // Rotating while it moves, so its edges are true quadratics.
    let from = [p(-30, 10), p(-6, 18), p(-22, 40)];
    let centre = p(-20, 22);
    let moves: Vec<Move> = from
        .iter()
        .map(|v| {
            let t = turned(v, &centre, (3, 4, 5));
            moving(v.clone(), [&t[0] + r(100, 1), &t[1] + r(10, 1)])
        })
        .collect();
    for antialias in [None, Some(r#"{"samples": 4}"#.to_owned())] {
        let scene = Setup {
            antialias: antialias.clone(),
            ..Setup::new(64)
        }
        .scene(&[triangle(&moves)]);
        let start = Clock::now();
        let time = coverage(&scene);
        let elapsed = start.elapsed();
        let worst = time
            .iter()
            .map(|c| c.bound.to_f64().value())
            .fold(0.0, f64::max);
        let moving = time.iter().filter(|c| c.value > RBig::ZERO).count();
        eprintln!(
            "64×64, one triangle moving 100 px, M = {}: {elapsed:?}, {moving} pixels covered at some instant, worst bound {worst:e}",
            offsets(&scene).len()
        );
        assert!(moving > 500);
    }
}
