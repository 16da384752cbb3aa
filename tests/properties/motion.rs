//! Motion blur (SPEC.md §15): time coverage in range and within the
//! certified bound, and equal to the static coverage when nothing moves.

use crate::config;
use dashu_ratio::RBig;
use proptest::prelude::*;
use rastercheck::plan::Plan;
use rastercheck::production::Production;
use rastercheck::rasterizer::Rasterizer;
use rastercheck::reference;
use rastercheck::scene::Scene;
use rastercheck::scene::{parse_case, Limits};

// --- Motion blur (SPEC.md §15) ----------------------------------------------

/// How one vertex of a moving scene moves.
#[derive(Clone, Debug)]
enum Motion {
    /// A position.
    Still,
    /// `from` and `to` that differ by less than half a subpixel step:
    /// both ends snap to the same point, so the vertex moves in the case
    /// file (the scene goes through the time loop) but not on the grid.
    Within(i64),
    /// A real move, by up to 4 px in 1/256 steps.
    By(i64, i64),
}

const BLUR_SIZE: i64 = 8;

/// n / 2^bits as the exact decimal a case file spells.
fn dyadic(n: i64, bits: u32) -> String {
    let scaled = i128::from(n.unsigned_abs()) * 5i128.pow(bits);
    let ten = 10i128.pow(bits);
    let fraction = format!("{:0width$}", scaled % ten, width = bits as usize);
    let fraction = fraction.trim_end_matches('0');
    let sign = if n < 0 { "-" } else { "" };
    if fraction.is_empty() {
        format!("{sign}{}", scaled / ten)
    } else {
        format!("{sign}{}.{fraction}", scaled / ten)
    }
}

fn motion() -> impl Strategy<Value = Motion> {
    prop_oneof![
        1 => Just(Motion::Still),
        2 => (1i64..1 << 11).prop_map(Motion::Within),
        3 => (-1024i64..1025, -1024i64..1025).prop_map(|(x, y)| Motion::By(x, y)),
    ]
}

/// 1 or 2 triangles on an 8² canvas, 8 subpixel bits, vertices on the
/// 1/256 grid (ties at centres, edges through samples), each still,
/// moving within a snap step, or moving; under `effects.motion_blur` with
/// every pattern, 1 to 16 time samples, a full or partial shutter, and
/// sometimes 4× antialiasing. `real` = false keeps every vertex from
/// moving on the grid.
fn moving_case(real: bool) -> impl Strategy<Value = (String, String)> {
    let vertex = (
        (-256i64..(BLUR_SIZE + 1) * 256),
        (-256i64..(BLUR_SIZE + 1) * 256),
        motion(),
    );
    let triangle = prop::collection::vec(vertex, 3);
    (
        prop::collection::vec(triangle, 1..3),
        prop::sample::select(vec![
            "random",
            "stratified",
            "jittered-xy-t",
            "stratified-shuffled",
        ]),
        1u32..17,
        any::<bool>(),
        any::<bool>(),
        prop::sample::select(vec!["none", "cw", "ccw"]),
        any::<u16>(),
    )
        .prop_map(move |(triangles, pattern, n, partial, aa, cull, seed)| {
            let d = |n: i64| dyadic(n, 8);
            let still = |x: i64, y: i64| format!("[{}, {}]", d(x), d(y));
            let mut moving = Vec::new();
            let mut fixed = Vec::new();
            for t in &triangles {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                for (x, y, m) in t {
                    let m = match m {
                        Motion::By(..) if !real => &Motion::Within(1),
                        m => m,
                    };
                    b.push(still(*x, *y));
                    a.push(match m {
                        Motion::Still => still(*x, *y),
                        Motion::Within(k) => format!(
                            r#"{{"from": [{}, {}], "to": [{}, {}]}}"#,
                            d(*x),
                            d(*y),
                            dyadic(x * 4096 + k, 20),
                            d(*y)
                        ),
                        Motion::By(dx, dy) => format!(
                            r#"{{"from": [{}, {}], "to": [{}, {}]}}"#,
                            d(*x),
                            d(*y),
                            d(x + dx),
                            d(y + dy)
                        ),
                    });
                }
                moving.push(format!(r#"{{"triangle": [{}]}}"#, a.join(", ")));
                fixed.push(format!(r#"{{"triangle": [{}]}}"#, b.join(", ")));
            }
            let shutter = if partial { "[0.25, 0.75]" } else { "[0, 1]" };
            let antialias = if aa {
                r#", "antialias": {"samples": 4, "pattern": "standard"}"#
            } else {
                ""
            };
            let case = |primitives: &[String], effects: &str| {
                format!(
                    r#"{{"name": "p", "canvas": {{"width": {BLUR_SIZE}, "height": {BLUR_SIZE}}},
                    "rules": {{"subpixel_bits": 8, "cull": "{cull}"}},
                    "effects": {{{effects}}},
                    "primitives": [{}]}}"#,
                    primitives.join(", ")
                )
            };
            let blur = format!(
                r#""motion_blur": {{"shutter": {shutter}, "samples": {n}, "pattern": "{pattern}", "seed": {seed}}}"#
            );
            (
                case(&moving, &format!("{blur}{antialias}")),
                case(&fixed, antialias.trim_start_matches(", ")),
            )
        })
}

pub fn parse(text: &str) -> Result<Scene, rastercheck::scene::CaseError> {
    parse_case(text, "motion.json", &Limits::default())
}

/// Production's time coverage, or `None` when it does not draw the scene.
fn production_time(scene: &Scene, plan: &Plan) -> Option<Vec<f64>> {
    Production.rasterize(scene, plan).ok()?.time
}

proptest! {
    #![proptest_config(config(64))]

    /// Time coverage lies in [0, k] for k primitives (in [0, 1] for one),
    /// within the certified bound, in the reference and in production.
    #[test]
    fn time_coverage_lies_between_0_and_the_primitive_count(case in moving_case(true)) {
        let scene = parse(&case.0).expect("a valid moving case");
        let plan = Plan::for_scene(&scene);
        let k = RBig::from(scene.primitives.len() as u64);
        if plan.motion.is_none() {
            // Every vertex snapped still: nothing to measure over time.
            return Ok(());
        }
        for (p, c) in reference::motion::time_coverage(&scene, &plan).iter().enumerate() {
            prop_assert!(&c.value + &c.bound >= RBig::ZERO && &c.value - &c.bound <= k, "pixel {}: {} ± {}", p, c.value, c.bound);
        }
        if let Some(time) = production_time(&scene, &plan) {
            let k = scene.primitives.len() as f64;
            prop_assert!(time.iter().all(|t| (0.0..=k).contains(t)), "production: {:?}", time);
        }
    }

    /// When no vertex moves on the grid (each `to` snaps onto its `from`),
    /// the time loop still runs, and every pixel's time coverage equals
    /// its static coverage: covered spatial samples (counted per
    /// primitive) over M, exactly, with a bound of 0. The same in
    /// production.
    #[test]
    fn time_coverage_equals_the_static_coverage_when_nothing_moves(case in moving_case(false)) {
        let scene = parse(&case.0).expect("a valid moving case");
        let still = parse(&case.1).expect("the same case without motion");
        let plan = Plan::for_scene(&scene);
        let still_plan = Plan::for_scene(&still);
        prop_assert!(still_plan.motion.is_none());
        if !scene.moves() {
            return Ok(());
        }
        prop_assert!(plan.motion.is_some(), "a vertex with from ≠ to takes the time loop");
        let frame = reference::render(&still, &still_plan);
        let m = frame.samples as usize;
        let exact: Vec<RBig> = frame
            .coverage
            .chunks(m)
            .map(|s| RBig::from_parts(s.iter().map(|&c| u64::from(c)).sum::<u64>().into(), (m as u64).into()))
            .collect();
        let certified = reference::motion::time_coverage(&scene, &plan);
        for (p, (c, e)) in certified.iter().zip(&exact).enumerate() {
            prop_assert!(c.bound == RBig::ZERO && &c.value == e, "pixel {}: time {} ± {}, static {}", p, c.value, c.bound, e);
        }
        if let Some(time) = production_time(&scene, &plan) {
            for (p, (t, e)) in time.iter().zip(&exact).enumerate() {
                prop_assert_eq!(*t, e.to_f64().value(), "production, pixel {}", p);
            }
        }
    }
}
