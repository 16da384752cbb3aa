//! Each pixel's certified time coverage (SPEC.md §15.2): the moving
//! primitives measured sample by sample over their swept boxes, the static
//! ones drawn once by the static reference.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::certified::{rounds_once, Certified};
use super::moving::{Moving, Mutation, Rules};
use super::sample::{sample_measure, ISOLATION_BITS, MAX_ISOLATION_BITS};
use crate::plan::Plan;
use crate::reference::coverage::coverage_under;
use crate::reference::exact::floor_div;
use crate::scene::time::limits::TIME_BITS;
use crate::scene::Scene;

/// Each pixel's time coverage (row-major): the mean over its spatial
/// samples of the sum over primitives of the covered fraction of the
/// shutter, static primitives included. Only for plans with `motion`.
///
/// # Panics
/// When the plan has no `motion`, when its samples are not the scene's
/// own, or when a primitive's bound exceeds
/// [`max_bound`](super::certified::max_bound).
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

/// floor(lo/unit) and floor(hi/unit), clamped to the canvas limits (the
/// caller clips to the canvas).
fn pixel_range(lo: &IBig, hi: &IBig, unit: &IBig) -> [i64; 2] {
    let limit = IBig::from(crate::scene::rules::limits::MAX_CANVAS_SIDE) + IBig::ONE;
    [lo, hi].map(|v| {
        let f = floor_div(v, unit).clamp(-IBig::ONE, limit.clone());
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
    let counts = coverage_under(&still, plan, scene.rules.fill_rule);
    (0..pixels)
        .map(|p| {
            counts[p * m..(p + 1) * m]
                .iter()
                .map(|&c| u64::from(c))
                .sum()
        })
        .collect()
}
