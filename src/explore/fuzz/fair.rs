//! The fairness check for moving scenes: a scene whose time bounds the
//! sample method of SPEC.md §15.3 breaks with the case's own instants is no
//! test of a candidate, and is skipped rather than blamed.

use dashu_int::UBig;
use dashu_ratio::RBig;

use super::geometry::{minus, ratio, Point};
use crate::frame::Frame;
use crate::harness::oracle::ReferenceRun;
use crate::plan::Plan;
use crate::reference;
use crate::scene::{Canvas, Effects, Expect, Number, Primitive, Scene};

/// Whether a moving scene is a fair test of its time bounds: the sample
/// method of SPEC.md §15.3 with the case's own instants
/// ([`sampled_time`]) meets them. The default RMS bound is statistical
/// (about twice what independent instants give on average), so on a
/// scene with few moving pixels an honest sampler can break it, and such
/// a scene says nothing about a candidate; `Err` says why it is refused.
/// Like the antialiasing check in [`evaluate`](super::evaluate), which refuses a scene the
/// exact N-sample method fails.
pub(super) fn fair_time(scene: &Scene, reference: &ReferenceRun) -> Result<(), String> {
    use crate::metrics::time;
    let whole = match &reference.time {
        Some(Ok(check)) => Some(check.whole.as_slice()),
        _ => None,
    };
    let Canvas { width, height } = scene.canvas;
    let sampled = Frame::time_only(width, height, sampled_time(scene, &reference.plan));
    let m = time::measure(&reference.frame, &sampled, whole, time::bounds(scene))
        .ok_or("the reference has no time coverage for a moving scene")?;
    let broken = time::failures(&m);
    if broken.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "the sample method with the case's own instants breaks the time bounds: {}",
            broken.join("; ")
        ))
    }
}

/// Each pixel's time coverage as SPEC.md §15.3's sample method estimates
/// it with the case's own instants (each pixel's u from its seed), every
/// test decided by the static reference at its exact instant: what every
/// conforming sampler returns (production does, test by test:
/// tests/motion_production.rs). Static primitives cover a sample at every
/// instant or at none. Moving ones are tested only at the pixels of their
/// swept box (elsewhere they cover nothing at any instant), each test a
/// one-pixel scene whose centre is the sample: the primitives at the
/// instant, moved there exactly (a translation keeps every decision).
///
/// # Panics
/// When the plan has no `motion` or the scene no `subpixel_bits`.
fn sampled_time(scene: &Scene, plan: &Plan) -> Vec<f64> {
    let blur = &plan.motion.as_ref().expect("a moving scene").blur;
    let bits = scene
        .rules
        .subpixel_bits
        .expect("a moving scene has subpixel_bits");
    let Canvas { width, height } = scene.canvas;
    let half = ratio(1, 2);
    let offsets: Vec<Point> = match &plan.antialias {
        Some(a) => {
            let unit = RBig::from(UBig::ONE << a.position_bits as usize);
            a.offsets
                .iter()
                .map(|o| o.map(|c| RBig::from(c) / &unit))
                .collect()
        }
        None => vec![[half.clone(), half.clone()]],
    };
    let (m, n) = (offsets.len(), blur.samples as usize);
    let mut still = scene.clone();
    still.primitives.retain(|p| !p.moves());
    still.effects.motion_blur = None;
    let fixed = if still.primitives.is_empty() {
        vec![0u16; scene.canvas.pixel_count() * m]
    } else {
        reference::coverage_under(&still, plan, scene.rules.fill_rule)
    };
    let mut totals: Vec<u64> = fixed
        .chunks(m)
        .map(|c| c.iter().map(|&k| u64::from(k)).sum::<u64>() * n as u64)
        .collect();
    // The moving primitives alone on one pixel; each vertex's snapped
    // position at open and its displacement to close.
    let mut one = scene.clone();
    one.primitives.retain(Primitive::moves);
    one.canvas = Canvas {
        width: 1,
        height: 1,
    };
    one.rules.subpixel_bits = None;
    one.effects = Effects::default();
    one.expect = Expect::default();
    let ends: Vec<[Point; 2]> = one
        .vertices()
        .map(|v| {
            let open = [&v.x, &v.y].map(|c| c.snapped(bits).as_rbig().clone());
            let close = v.end().map(|c| c.snapped(bits).as_rbig().clone());
            let d = minus(&close, &open);
            [open, d]
        })
        .collect();
    // The swept box, widened by a line's width and a pixel: a sample
    // outside it is never covered.
    let margin = one
        .primitives
        .iter()
        .map(|p| match p {
            Primitive::Line(l) => l.width.to_f64_lossy(),
            _ => 0.0,
        })
        .fold(0.0, f64::max)
        + 1.0;
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for [open, d] in &ends {
        for axis in 0..2 {
            for c in [open[axis].clone(), &open[axis] + &d[axis]] {
                let f = c.to_f64().value();
                lo[axis] = lo[axis].min(f);
                hi[axis] = hi[axis].max(f);
            }
        }
    }
    let span = |axis: usize, size: u32| {
        let clamp = |v: f64| v.clamp(0.0, f64::from(size)) as u32;
        clamp((lo[axis] - margin).floor())..clamp((hi[axis] + margin).ceil())
    };
    let unit_time = RBig::from(UBig::ONE << 32);
    for y in span(1, height) {
        for x in span(0, width) {
            let p = (y * width + x) as usize;
            let us = blur.pixel_times(p as u64, m as u32);
            for (j, &u) in us.iter().enumerate() {
                let tau = RBig::from(blur.instant(u)) / &unit_time;
                let o = &offsets[j / n];
                let shift = [&half - RBig::from(x) - &o[0], &half - RBig::from(y) - &o[1]];
                let vertices = one.primitives.iter_mut().flat_map(|q| q.vertices_mut());
                for (v, [open, d]) in vertices.zip(&ends) {
                    v.x = Number::from_rbig(&open[0] + &tau * &d[0] + &shift[0]);
                    v.y = Number::from_rbig(&open[1] + &tau * &d[1] + &shift[1]);
                    v.to = None;
                }
                // `one` has no effects: one sample, the pixel centre.
                let counts =
                    reference::coverage_under(&one, &Plan::coverage_only(), scene.rules.fill_rule);
                totals[p] += u64::from(counts[0]);
            }
        }
    }
    let tests = (m * n) as f64;
    totals.into_iter().map(|t| t as f64 / tests).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explore::fuzz::case_json::case_json;
    use crate::explore::fuzz::family::{generate, Family};
    use crate::explore::fuzz::judge::{evaluate, Outcome};
    use crate::harness::judge::Verdict;
    use crate::harness::{judge, oracle};
    use crate::rasterizer::Rasterizer;

    /// The fairness check's sampler (the static reference at each of the
    /// case's own instants) is production's frame, value for value: two
    /// independent readings of SPEC.md §15.3. Other instants (another
    /// seed) give other values.
    #[test]
    fn sampled_time_is_productions_frame() {
        use crate::production::Production;
        let mut differ = 0;
        for i in 0..40 {
            let (_, scene) = generate(9, i, Some(Family::Motion));
            let plan = Plan::for_scene(&scene);
            if plan.motion.is_none() {
                continue;
            }
            let sampled = sampled_time(&scene, &plan);
            let frame = Production
                .rasterize(&scene, &plan)
                .expect("production draws it");
            assert_eq!(
                frame.time.as_deref(),
                Some(sampled.as_slice()),
                "{}",
                case_json(&scene)
            );
            // The same with every pixel's instants taken from its
            // neighbour's seed: a sampler with the wrong instants.
            let mut other = scene.clone();
            if let Some(b) = other.effects.motion_blur.as_mut() {
                b.seed ^= 1;
            }
            differ += usize::from(sampled_time(&other, &Plan::for_scene(&other)) != sampled);
        }
        assert!(differ > 10, "{differ}");
    }

    /// Where few pixels move, the default time RMS bound can fail an
    /// honest sampler: production fails `run` on such a scene, and without
    /// the fairness check the search would blame it. It is skipped instead.
    #[test]
    fn unfair_moving_scenes_are_skipped_not_blamed() {
        use crate::production::Production;
        let mut skipped = 0;
        for i in 0..100 {
            let (_, scene) = generate(1, i, Some(Family::Motion));
            let Outcome::Invalid(why) = evaluate(&scene, &Production) else {
                continue;
            };
            if !why.contains("the sample method with the case's own instants") {
                continue;
            }
            skipped += 1;
            let reference = oracle::run_reference(&scene);
            let run = judge::run_candidate(&scene, &reference, &Production);
            let Verdict::Fail(reasons) = run.verdict else {
                panic!("production passes a scene refused as unfair: {why}");
            };
            assert!(
                reasons.iter().all(|r| r.starts_with("time: ")),
                "{reasons:?}"
            );
        }
        assert!(skipped > 0);
    }
}
