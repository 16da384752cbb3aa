//! Random moving triangles and lines against brute force, and the two
//! wrong oracles that the comparison catches.

use std::time::Instant as Clock;

use crate::brute::{
    brute_pixels, brute_samples, changes, coverage, disagreements, instants, mutated, offsets,
};
use crate::scenes::{line, moving, r, triangle, Move, Setup};
use dashu_ratio::RBig;
use rastercheck::reference::motion::{self, Mutation};
use rastercheck::scene::samples::SplitMix64;
use rastercheck::scene::{Cull, FillRule, Scene};

pub struct Rng(pub SplitMix64);

impl Rng {
    pub fn below(&mut self, n: u64) -> u64 {
        self.0.next_u64() % n
    }

    pub fn pick<T: Clone>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize].clone()
    }

    /// A coordinate in [lo, hi]: mostly on half and quarter pixels, where
    /// samples and edges meet, sometimes thirds, which snap.
    pub fn coordinate(&mut self, lo: i64, hi: i64) -> RBig {
        let den = self.pick(&[1, 2, 2, 2, 4, 8, 3]);
        let span = ((hi - lo) * den + 1) as u64;
        r(lo * den + self.below(span) as i64, den)
    }

    pub fn point(&mut self, lo: i64, hi: i64) -> [RBig; 2] {
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

pub fn turned(p: &[RBig; 2], centre: &[RBig; 2], (c, s, h): (i64, i64, i64)) -> [RBig; 2] {
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

pub fn random_setup(rng: &mut Rng) -> Setup {
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
