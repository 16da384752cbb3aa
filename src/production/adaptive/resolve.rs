//! `adaptive-resolve`: production's adaptive sampling computing only the
//! resolved coverage, with no sample mask.
//!
//! Each pixel keeps the number of covered samples summed over the
//! primitives that cover it: a pixel wholly inside a triangle (judged
//! strictly from its closed square, or its 8 × 8 block's, as
//! [`Sampling::Adaptive`] does) adds N without a sample being tested, one
//! wholly outside adds nothing, and an edge pixel adds the samples it
//! covers, each decided by the same exact integer test as production's.
//! The sum is a small integer (exact in an f64), divided by N once at the
//! end: the box resolve of production's full supersampling, bit for bit,
//! as long as no sample is covered more than 65535 times (production's
//! per-sample counts saturate there).
//!
//! What this module does not do: depth, attributes, lines or polygons
//! (production draws those; this method says it cannot).

use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::antialias::cover::{abs, classify, At, Class, SampleSink, BLOCK};
use crate::production::antialias::sampling::{Samples, Sampling};
use crate::production::dispatch::Production;
use crate::production::fixed::{EdgeInt, Fixed};
use crate::production::scene_format::{format_for, place};
use crate::production::setup::{self, Footprint};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Primitive, Scene};

/// The `adaptive-resolve` method.
#[derive(Clone, Copy, Debug, Default)]
pub struct AdaptiveResolve;

impl Rasterizer for AdaptiveResolve {
    fn name(&self) -> &str {
        "adaptive-resolve"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            attributes: false,
            depth: false,
            polygons: false,
            antialias: true,
            motion_blur: false,
            clip_space: false,
            points: false,
            ..Production.capabilities()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let unsupported = |why: &str| Err(RasterError::Unsupported(why.to_owned()));
        let Some(sample_plan) = plan.antialias.as_ref() else {
            return unsupported("adaptive-resolve draws antialiased scenes only");
        };
        if plan.interpolates() {
            return unsupported("adaptive-resolve computes coverage only, not depth or attributes");
        }
        if scene
            .primitives
            .iter()
            .any(|p| !matches!(p, Primitive::Triangle(_)))
        {
            return unsupported("adaptive-resolve draws triangles only");
        }
        let samples = Samples {
            plan: sample_plan,
            sampling: Sampling::Adaptive,
        };
        let format = format_for(scene, Some(&samples))?;
        let canvas = scene.canvas;
        let mut counts = vec![0.0f64; canvas.pixel_count()];
        if format.fits_i64() {
            draw::<i64>(scene, plan, &samples, format, &mut counts);
        } else {
            draw::<i128>(scene, plan, &samples, format, &mut counts);
        }
        let n = samples.count() as f64;
        for c in &mut counts {
            if *c != 0.0 {
                *c /= n;
            }
        }
        Ok(Frame::resolved_only(canvas.width, canvas.height, counts))
    }
}

fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    samples: &Samples,
    format: crate::production::fixed::Format,
    counts: &mut [f64],
) {
    let offsets = samples.offsets_in(format);
    let mut sink = Counts {
        counts,
        width: scene.canvas.width as usize,
    };
    for primitive in &scene.primitives {
        let Primitive::Triangle(triangle) = primitive else {
            continue;
        };
        let positions: [[Fixed; 2]; 3] = triangle
            .vertices
            .each_ref()
            .map(|v| [place(scene, format, &v.x), place(scene, format, &v.y)]);
        let Some(setup) = setup::setup_in::<E>(
            positions,
            triangle,
            format,
            scene.rules.fill_rule,
            scene.rules.cull,
            scene.canvas,
            plan,
            |_, _| None,
            Footprint::Squares,
        ) else {
            continue;
        };
        count::<E>(&setup, format, &offsets, &mut sink);
    }
}

/// Adds each pixel's covered samples of one set-up triangle to the
/// counts: [`cover`] under [`Sampling::Adaptive`], the same blocks and the
/// same strict classification of blocks and pixels, with an edge pixel's
/// samples counted in one branch-free pass instead of handed over one by
/// one.
fn count<E: EdgeInt>(
    setup: &crate::production::setup::TriangleSetup<E>,
    format: crate::production::fixed::Format,
    offsets: &[[i64; 2]],
    sink: &mut Counts,
) {
    let zero = E::default();
    let half = format.one() / 2;
    let edges = &setup.edges;
    let n = offsets.len();
    // What each sample adds to each edge's value at the pixel centre, one
    // array per edge.
    let deltas: [Vec<E>; 3] = [0, 1, 2].map(|k| {
        let e = &edges[k];
        offsets
            .iter()
            .map(|o| e.per_unit[0] * E::from(o[0] - half) + e.per_unit[1] * E::from(o[1] - half))
            .collect()
    });
    let spread = edges.map(|e| (abs(e.per_unit[0]) + abs(e.per_unit[1])) * E::from(half));
    let low = spread.map(|v| zero - v);
    let bias = edges.map(|e| e.bias);
    let whole = n as f64;
    let samples_in = |centre: &[E; 3]| -> u32 {
        let (d0, d1, d2) = (&deltas[0][..n], &deltas[1][..n], &deltas[2][..n]);
        let mut covered = 0u32;
        for s in 0..n {
            let v = (centre[0] + d0[s]) | (centre[1] + d1[s]) | (centre[2] + d2[s]);
            covered += u32::from(v >= zero);
        }
        covered
    };
    let b = setup.bounds;
    let mut by = b.y0;
    while by < b.y1 {
        let bh = BLOCK.min(b.y1 - by);
        let mut bx = b.x0;
        while bx < b.x1 {
            let bw = BLOCK.min(b.x1 - bx);
            let first_centre = edges.map(|e| e.at(bx, by));
            let reach = |k: usize, pick: fn(E, E) -> E| {
                let e = &edges[k];
                pick(zero, e.step_x * E::from(bw - 1)) + pick(zero, e.step_y * E::from(bh - 1))
            };
            let block_low = [0, 1, 2].map(|k| reach(k, E::min) - spread[k]);
            let block_high = [0, 1, 2].map(|k| reach(k, E::max) + spread[k]);
            match classify(&first_centre, &bias, block_low, block_high, true) {
                Class::Outside => {}
                Class::Inside => {
                    for y in by..by + bh {
                        let row = y as usize * sink.width;
                        let run = row + bx as usize..row + (bx + bw) as usize;
                        for c in &mut sink.counts[run] {
                            *c += whole;
                        }
                    }
                }
                Class::Edge => {
                    for y in by..by + bh {
                        let row = y as usize * sink.width;
                        let mut centre = edges.map(|e| e.at(bx, y));
                        for x in bx..bx + bw {
                            let add = match classify(&centre, &bias, low, spread, true) {
                                Class::Outside => 0,
                                Class::Inside => n as u32,
                                Class::Edge => samples_in(&centre),
                            };
                            sink.counts[row + x as usize] += f64::from(add);
                            for (value, e) in centre.iter_mut().zip(edges) {
                                *value = *value + e.step_x;
                            }
                        }
                    }
                }
            }
            bx += BLOCK;
        }
        by += BLOCK;
    }
}

/// Covered samples per pixel; as a [`SampleSink`] it is what [`cover`]
/// would hand them to (the test `counting_is_cover_counted` compares the
/// two).
///
/// [`cover`]: crate::production::antialias::cover::cover
struct Counts<'a> {
    counts: &'a mut [f64],
    width: usize,
}

impl<E: EdgeInt> SampleSink<E> for Counts<'_> {
    #[inline]
    fn sample(&mut self, x: i64, y: i64, _s: usize, _at: At<E>) {
        self.counts[y as usize * self.width + x as usize] += 1.0;
    }

    #[inline]
    fn whole(&mut self, x: i64, y: i64, samples: usize, _at: impl Fn(usize) -> At<E>) {
        self.counts[y as usize * self.width + x as usize] += samples as f64;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::production::antialias::cover::cover;

    #[test]
    fn counting_is_cover_counted() {
        let scene = crate::bench::triangle_scene(64, 20, 30, 5);
        for pattern in crate::scene::Pattern::ALL {
            let mut s = scene.clone();
            s.effects.antialias = Some(crate::scene::Antialias {
                samples: 16,
                pattern,
                seed: 9,
                adaptive: true,
                position_bits: 8,
            });
            let plan = Plan::for_scene(&s);
            let samples = Samples {
                plan: plan.antialias.as_ref().unwrap(),
                sampling: Sampling::Adaptive,
            };
            let format = format_for(&s, Some(&samples)).unwrap();
            let offsets = samples.offsets_in(format);
            let (mut a, mut b) = (vec![0.0; 64 * 64], vec![0.0; 64 * 64]);
            for primitive in &s.primitives {
                let Primitive::Triangle(t) = primitive else {
                    continue;
                };
                let positions = t
                    .vertices
                    .each_ref()
                    .map(|v| [place(&s, format, &v.x), place(&s, format, &v.y)]);
                let Some(setup) = setup::setup_in::<i64>(
                    positions,
                    t,
                    format,
                    s.rules.fill_rule,
                    s.rules.cull,
                    s.canvas,
                    &plan,
                    |_, _| None,
                    Footprint::Squares,
                ) else {
                    continue;
                };
                let mut sink = Counts {
                    counts: &mut a,
                    width: 64,
                };
                count(&setup, format, &offsets, &mut sink);
                let mut sink = Counts {
                    counts: &mut b,
                    width: 64,
                };
                cover(&setup, format, &offsets, Sampling::Adaptive, &mut sink);
            }
            assert_eq!(a, b, "{pattern:?}");
            assert!(a.iter().any(|&c| c > 0.0 && c < 16.0));
        }
    }
}
