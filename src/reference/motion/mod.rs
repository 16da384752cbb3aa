//! Exact time coverage of moving primitives, with a certified bound
//! (SPEC.md §15.2).
//!
//! A moving vertex is linear in the instant τ, so every quantity whose sign
//! decides whether a primitive covers a sample (edge functions, twice the
//! area, a line's side conditions) is a polynomial of degree ≤ 2 in τ with
//! integer coefficients on the grid (`motion/quadratic.rs`). Between their
//! real roots coverage is constant and is decided exactly at one rational
//! instant (`motion/measure.rs`); rational roots are exact points, and
//! irrational ones are isolated between rationals by an integer square root
//! and left undecided, which is the bound. The per-instant decisions are
//! §3 and §4.4 written out again (`motion/moving.rs`).
//!
//! Static primitives are drawn once by the static reference
//! (`coverage_under`): they cover a sample for the whole shutter or not at
//! all, and every kind of primitive may be static.
//!
//! What this module does not do: decide inside an isolating interval (it
//! is narrowed instead), or use a float anywhere but the final rounding of
//! [`frame`].

mod measure;
mod moving;
mod quadratic;

use dashu_int::{IBig, UBig};
use dashu_ratio::RBig;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::scene::time::limits::TIME_BITS;
use crate::scene::Scene;
use moving::{Moving, Rules};

#[doc(hidden)]
pub use moving::Mutation;

/// A time coverage and a certified bound on its error:
/// |exact − value| ≤ bound. The bound is 0 when every root involved is
/// rational.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Certified {
    pub value: RBig,
    pub bound: RBig,
}

/// The largest bound the oracle accepts of one primitive at one sample:
/// 2^-40 (it asserts it).
pub fn max_bound() -> RBig {
    RBig::from_parts(1.into(), dashu_int::UBig::ONE << 40)
}

/// Isolating intervals of width 2^-(bits+1)/|c2| in τ. A primitive has at
/// most 12 irrational roots at a sample (a line: 3 pieces, 2 quadratics
/// each; a triangle: 4 quadratics), each undecided over at most 2^-(bits+1),
/// half of which is the bound: 3·2^-bits in τ, at most 3·2^(16-bits) of a
/// shutter at least 2^-16 long. 60 bits give 2^-42 < 2^-40 on the first
/// pass; [`sample_measure`] refines anyway should that ever fail.
const ISOLATION_BITS: usize = 60;

/// The largest refinement tried before the bound assertion fails.
const MAX_ISOLATION_BITS: usize = 1024;

/// Each pixel's time coverage (row-major): the mean over its spatial
/// samples of the sum over primitives of the covered fraction of the
/// shutter, static primitives included. Only for plans with `motion`.
///
/// # Panics
/// When the plan has no `motion`, when its samples are not the scene's
/// own, or when a primitive's bound exceeds [`max_bound`].
pub fn time_coverage(scene: &Scene, plan: &Plan) -> Vec<Certified> {
    time_coverage_with(scene, plan, Mutation::None)
}

/// [`time_coverage`] of a deliberately wrong oracle, for the tests that
/// show they catch it.
#[doc(hidden)]
pub fn time_coverage_with(scene: &Scene, plan: &Plan, mutation: Mutation) -> Vec<Certified> {
    time_coverage_from(scene, plan, mutation, ISOLATION_BITS)
}

/// [`time_coverage_with`] whose first pass isolates roots to
/// `first_isolation` bits only (then to the 2^-40 bound): the tests' way to
/// reach the refinement that makes every pixel round once.
#[doc(hidden)]
pub fn time_coverage_from(
    scene: &Scene,
    plan: &Plan,
    mutation: Mutation,
    first_isolation: usize,
) -> Vec<Certified> {
    let motion = plan
        .motion
        .as_ref()
        .expect("time coverage is for plans with motion");
    let bits = scene
        .rules
        .subpixel_bits
        .expect("a moving scene has subpixel_bits");
    let [open, close] = motion.blur.shutter.map(IBig::from);
    let time_unit = IBig::ONE << TIME_BITS as usize;
    let span = [&open, &close].map(|u| RBig::from_parts_signed(u.clone(), time_unit.clone()));
    let length = &span[1] - &span[0];
    let (width, height) = (scene.canvas.width, scene.canvas.height);
    // Spatial samples as offsets within a pixel on a grid of `scale` units
    // per pixel, which holds the snapped vertices and every sample.
    let (offsets, scale) = match &plan.antialias {
        Some(samples) => {
            let scale = IBig::ONE << (bits as usize + 1).max(samples.position_bits as usize);
            let unit = &scale >> samples.position_bits as usize;
            let offsets: Vec<[IBig; 2]> = samples
                .offsets
                .iter()
                .map(|o| o.map(|c| IBig::from(c) * &unit))
                .collect();
            (offsets, scale)
        }
        None => {
            let scale = IBig::ONE << (bits as usize + 1);
            (vec![[&scale >> 1, &scale >> 1]], scale)
        }
    };
    let m = offsets.len();
    let static_counts = static_coverage(scene, plan);
    // Per pixel: Σ value and Σ bound of the moving primitives' samples,
    // in units of τ. A primitive moves when a vertex does (not as a
    // hand-made plan may say).
    let mut sums = vec![(RBig::ZERO, RBig::ZERO); scene.canvas.pixel_count()];
    let rules = Rules {
        fill: scene.rules.fill_rule,
        cull: scene.rules.cull,
        mutation,
    };
    // Each moving primitive with the pixels its swept box meets.
    let movers: Vec<(Moving, [std::ops::RangeInclusive<i64>; 2])> = scene
        .primitives
        .iter()
        .filter(|p| p.moves())
        .map(|primitive| {
            let mover = Moving::new(primitive, bits, &scale);
            let [xs, ys] = mover
                .bounds([&open, &close], &time_unit)
                .map(|[lo, hi]| pixel_range(&lo, &hi, &(&scale * &time_unit)));
            let xs = xs[0].max(0)..=xs[1].min(i64::from(width) - 1);
            let ys = ys[0].max(0)..=ys[1].min(i64::from(height) - 1);
            (mover, [xs, ys])
        })
        .collect();
    // Σ value and Σ bound of one moving primitive's samples in pixel (x, y),
    // isolating roots to `isolation` bits at least.
    let measure = |mover: &Moving, x: i64, y: i64, isolation: usize, pixel: &mut (RBig, RBig)| {
        let corner = [IBig::from(x) * &scale, IBig::from(y) * &scale];
        for offset in &offsets {
            let p = [&corner[0] + &offset[0], &corner[1] + &offset[1]];
            let (value, bound) = sample_measure(mover, &p, [&span[0], &span[1]], rules, isolation);
            pixel.0 += value;
            pixel.1 += bound;
        }
    };
    for (mover, [xs, ys]) in &movers {
        for y in ys.clone() {
            crate::deadline::check();
            for x in xs.clone() {
                let pixel = &mut sums[y as usize * width as usize + x as usize];
                measure(mover, x, y, first_isolation, pixel);
            }
        }
    }
    let samples = RBig::from(m);
    let per_sample = &length * &samples;
    let certify = |(value, bound): (RBig, RBig), count: u64| Certified {
        value: RBig::from(count) / &samples + value / &per_sample,
        bound: bound / &per_sample,
    };
    let mut certified: Vec<Certified> = sums
        .into_iter()
        .zip(&static_counts)
        .map(|(sum, &count)| certify(sum, count))
        .collect();
    // Where the certified interval meets two f64s, the exact value's
    // correctly rounded f64 is not yet known: the pixel is measured again
    // with finer isolation until it is (SPEC.md §15.4), up to
    // MAX_ISOLATION_BITS.
    for (i, c) in certified.iter_mut().enumerate() {
        let mut isolation = first_isolation;
        while !rounds_once(c) && isolation < MAX_ISOLATION_BITS {
            crate::deadline::check();
            isolation *= 2;
            let (x, y) = ((i % width as usize) as i64, (i / width as usize) as i64);
            let mut pixel = (RBig::ZERO, RBig::ZERO);
            for (mover, [xs, ys]) in &movers {
                if xs.contains(&x) && ys.contains(&y) {
                    measure(mover, x, y, isolation, &mut pixel);
                }
            }
            *c = certify(pixel, static_counts[i]);
        }
    }
    certified
}

/// Whether every value within a certified bound rounds to the same f64, so
/// that the nearest f64 to the certified value is the exact value's.
fn rounds_once(c: &Certified) -> bool {
    c.bound == RBig::ZERO
        || super::area::to_f64_nearest(&(&c.value - &c.bound))
            == super::area::to_f64_nearest(&(&c.value + &c.bound))
}

/// The time coverage of one primitive at one exact point (in pixels) over
/// the shutter [open, close] (instants in [0, 1]), as a fraction of the
/// shutter; the primitive may move or not.
///
/// # Panics
/// When the primitive is neither a triangle nor a `parallelogram` line,
/// when the scene has no `subpixel_bits`, when open ≥ close, or when the
/// bound exceeds [`max_bound`].
pub fn point_coverage(
    scene: &Scene,
    primitive: usize,
    point: [&RBig; 2],
    shutter: [&RBig; 2],
) -> Certified {
    point_coverage_with(scene, primitive, point, shutter, Mutation::None)
}

/// [`point_coverage`] of a deliberately wrong oracle.
#[doc(hidden)]
pub fn point_coverage_with(
    scene: &Scene,
    primitive: usize,
    point: [&RBig; 2],
    shutter: [&RBig; 2],
    mutation: Mutation,
) -> Certified {
    let bits = scene
        .rules
        .subpixel_bits
        .expect("a moving scene has subpixel_bits");
    assert!(
        shutter[0] < shutter[1],
        "the shutter opens before it closes"
    );
    // The grid: 2^bits and the point's denominators divide its scale.
    let scale = point.iter().fold(UBig::ONE << bits as usize, |l, c| {
        let d = c.denominator();
        let g = super::grid::gcd(&l, d);
        &l / g * d
    });
    let scale = IBig::from(scale);
    let p = point.map(|c| c.numerator() * (&scale / IBig::from(c.denominator().clone())));
    let mover = Moving::new(&scene.primitives[primitive], bits, &scale);
    let rules = Rules {
        fill: scene.rules.fill_rule,
        cull: scene.rules.cull,
        mutation,
    };
    let (value, bound) = sample_measure(&mover, &p, shutter, rules, ISOLATION_BITS);
    let length = shutter[1] - shutter[0];
    Certified {
        value: value / &length,
        bound: bound / &length,
    }
}

/// (value, bound) of one primitive at one sample, in units of τ: the
/// covered measure plus half of the undecided one, and that half. The
/// isolation is refined until the bound is at most [`max_bound`] of the
/// span, which is asserted.
fn sample_measure(
    mover: &Moving,
    p: &[IBig; 2],
    span: [&RBig; 2],
    rules: Rules,
    isolation: usize,
) -> (RBig, RBig) {
    let allowed = max_bound() * (span[1] - span[0]);
    let mut bits = isolation;
    loop {
        let measured = mover.measure(p, span, bits, rules);
        let bound = measured.undecided / RBig::from(2u8);
        if bound <= allowed || bits >= MAX_ISOLATION_BITS {
            assert!(
                bound <= allowed,
                "time coverage bound {} exceeds 2^-40 of the shutter at {p:?} after {bits}-bit isolation",
                bound / (span[1] - span[0])
            );
            return (measured.covered + &bound, bound);
        }
        bits *= 2;
    }
}

/// floor(lo/unit) and floor(hi/unit), clamped to the canvas limits (the
/// caller clips to the canvas).
fn pixel_range(lo: &IBig, hi: &IBig, unit: &IBig) -> [i64; 2] {
    let limit = IBig::from(crate::scene::rules::limits::MAX_CANVAS_SIDE) + IBig::ONE;
    [lo, hi].map(|v| {
        let f = super::exact::floor_div(v, unit).clamp(-IBig::ONE, limit.clone());
        i64::try_from(&f).expect("clamped")
    })
}

/// How many of each pixel's samples the static primitives cover, summed
/// over them: the static reference on the scene without its moving
/// primitives, each covering a sample for the whole shutter or not at all.
/// Taking the moving primitives and the blur away changes no sample, so
/// the scene's own plan serves.
///
/// # Panics
/// When the plan's samples are not the scene's own.
fn static_coverage(scene: &Scene, plan: &Plan) -> Vec<u64> {
    let mut still = scene.clone();
    still.primitives.retain(|p| !p.moves());
    still.effects.motion_blur = None;
    let own = still.effects.antialias.as_ref();
    assert!(
        own.map(|aa| (aa.offsets(), aa.position_bits, aa.adaptive))
            == plan
                .antialias
                .as_ref()
                .map(|s| (s.offsets.clone(), s.position_bits, s.adaptive)),
        "the plan's samples are the scene's own"
    );
    let m = plan.antialias.as_ref().map_or(1, |s| s.offsets.len());
    let pixels = scene.canvas.pixel_count();
    if still.primitives.is_empty() {
        return vec![0; pixels];
    }
    let counts = super::coverage_under(&still, plan, scene.rules.fill_rule);
    (0..pixels)
        .map(|p| {
            counts[p * m..(p + 1) * m]
                .iter()
                .map(|&c| u64::from(c))
                .sum()
        })
        .collect()
}

/// The reference's frame of a scene in which something moves: each
/// pixel's certified time coverage rounded to the nearest f64.
pub fn frame(scene: &Scene, plan: &Plan) -> Frame {
    frame_of(scene, &time_coverage(scene, plan))
}

/// The time-only frame of certified per-pixel values (one per pixel),
/// each rounded to the nearest f64: the one rounding of `frame` and of the
/// suite, which keeps the certified values for its checks. For values from
/// [`time_coverage`] this is the exact value's correctly rounded f64
/// wherever 1024-bit isolation decides it (SPEC.md §15.4).
pub fn frame_of(scene: &Scene, certified: &[Certified]) -> Frame {
    let time = certified
        .iter()
        .map(|c| super::area::to_f64_nearest(&c.value))
        .collect();
    Frame::time_only(scene.canvas.width, scene.canvas.height, time)
}
