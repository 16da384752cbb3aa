//! The triangle workloads: every triangle method timed in interleaved
//! rounds on one seeded scene, with the declared-blur pair, the parallel
//! ceiling, the drivers' empty-canvas frames and the reference on a prefix;
//! errors counted against the reference's exact frame.

use std::time::{Duration, Instant};

use super::declared::Declared;
use super::draw_call::DrawCall;
use super::llvmpipe::{is_driver, lp_num_threads};
use super::memory;
use super::methods::{is_exact, triangle_methods};
use super::model::{Measured, Workload};
use super::score::mismatched;
use super::sizes::Sizes;
use super::timing::{median, OnPool, ParallelCeiling, TILED_THREADS};
use super::workloads::{triangle_scene, SEED};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::scene::Scene;

fn subset(s: &Scene, n: usize) -> Scene {
    let mut out = s.clone();
    out.primitives.truncate(n);
    out
}

pub(super) fn measure_triangles(
    leg: u32,
    count: usize,
    reference_count: usize,
    sizes: &Sizes,
    notes: &mut Vec<String>,
) -> Workload {
    let s = triangle_scene(sizes.canvas, leg, count, SEED);
    let plan = Plan::for_scene(&s);
    // The exact frame, computed once, outside every timing: the reference
    // row's peak heap is this call's.
    let (exact, reference_peak) = memory::peak(|| crate::reference::render(&s, &plan));
    let covered: u64 = exact.coverage.iter().map(|&c| u64::from(c)).sum();
    let methods = triangle_methods();
    // The tiled method is timed inside its pool (OnPool::timed).
    let tiled_at = methods
        .iter()
        .position(|(name, _)| name == "production-tiled")
        .unwrap_or(usize::MAX);
    let tiled = (tiled_at != usize::MAX)
        .then(|| OnPool::new(Box::new(crate::production::tiled::Tiled), TILED_THREADS));
    let whole = |k: usize, r: &dyn Rasterizer, scene: &Scene| match tiled
        .as_ref()
        .filter(|_| k == tiled_at)
    {
        Some(pool) => pool.timed(scene, &plan),
        None => {
            let started = Instant::now();
            let result = r.rasterize(scene, &plan);
            (result, started.elapsed())
        }
    };
    let mut ceiling = ParallelCeiling::new(sizes.ceiling_steps);
    // Drivers create their device and pipelines on first use: once here,
    // untimed.
    for (_, r) in methods.iter().filter(|(name, _)| is_driver(name)) {
        std::hint::black_box(r.rasterize(&s, &plan).ok());
    }
    // Each method's own draw call, set up once (timed once, apart).
    let mut draws: Vec<Option<DrawCall>> = methods
        .iter()
        .map(|(_, r)| DrawCall::prepare(r.as_ref(), &s, &plan))
        .collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut frames: Vec<Result<Frame, String>> = vec![Err(String::new()); methods.len()];
    let reference_scene = subset(&s, reference_count);
    let mut reference_times = Vec::new();
    let mut declared = Declared::new(&s);
    for rep in 0..sizes.repetitions {
        for (k, (name, r)) in methods.iter().enumerate() {
            if rep > 0 && frames[k].is_err() {
                continue;
            }
            let (result, elapsed) = whole(k, r.as_ref(), &s);
            times[k].push(elapsed);
            if rep == 0 {
                frames[k] = result.map_err(|e| e.to_string());
            }
            if let Some(call) = draws[k].as_mut() {
                if let Err(e) = call.round(tiled.as_ref().filter(|_| k == tiled_at)) {
                    notes.push(format!("L={leg}: `{name}`'s draw call failed: {e}"));
                    draws[k] = None;
                }
            }
            if name == "production" {
                declared.round(rep, r.as_ref());
            }
            if k == tiled_at {
                ceiling.round();
            }
        }
        let started = Instant::now();
        let frame = crate::reference::render(&reference_scene, &plan);
        reference_times.push(started.elapsed());
        std::hint::black_box(frame);
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = methods
        .iter()
        .enumerate()
        .map(|(k, (_, r))| {
            frames[k]
                .is_ok()
                .then(|| memory::peak(|| whole(k, r.as_ref(), &s)).1)
                .flatten()
        })
        .collect();
    let declared_peaks = methods
        .iter()
        .find(|(name, _)| name == "production")
        .map_or([None, None], |(_, r)| declared.peaks(r.as_ref()));
    let mut measured: Vec<Measured> = Vec::new();
    for (k, (((name, _), times), frame)) in methods.iter().zip(times).zip(frames).enumerate() {
        let row = match frame {
            Ok(frame) => {
                let whole_call = median(times) / count as u32;
                let mut row = Measured {
                    errors: Some((mismatched(&exact, &frame), covered)),
                    exact: is_exact(name),
                    peak_heap: peaks[k],
                    ..Measured::whole(name, whole_call, count)
                };
                match draws[k].take().map(|call| call.finish(&frame)) {
                    Some(Ok(call)) => {
                        row.per_item = Some(call.draw / count as u32);
                        row.whole_call = Some(whole_call);
                        row.set_up = Some(call.set_up);
                        row.read_back = Some(call.read_back);
                        row.note = call.note(name);
                    }
                    Some(Err(e)) => {
                        row.note =
                            format!("its draw call could not be timed ({e}): the whole call");
                    }
                    None => {
                        row.note = "no draw call apart from the whole call".to_owned();
                    }
                }
                if is_driver(name) {
                    row.note = format!(
                        "LP_NUM_THREADS={}; {}",
                        lp_num_threads().unwrap_or_else(|| "unset".to_owned()),
                        row.note
                    );
                }
                row
            }
            Err(why) => Measured {
                exact: is_exact(name),
                ..Measured::not_run(name, why)
            },
        };
        measured.push(row);
    }
    measured.extend(declared.rows(&exact, covered, count, declared_peaks));
    measured.push(Measured {
        errors: Some((0, covered)),
        exact: true,
        peak_heap: reference_peak,
        note: if reference_count < count {
            format!(
                "timed on the first {reference_count} of the {count} triangles; \
                 peak heap on all {count}"
            )
        } else {
            String::new()
        },
        ..Measured::whole(
            "reference",
            median(reference_times) / reference_count as u32,
            reference_count,
        )
    });
    if reference_count < count {
        notes.push(format!(
            "L={leg}: the reference is timed on the first {reference_count} triangles; \
             its frame for all {count} is the exact answer every error is counted against"
        ));
    }
    Workload {
        name: format!(
            "triangles, L={leg} ({} px each), {}² canvas",
            leg * leg / 2,
            sizes.canvas
        ),
        short: format!("L={leg}"),
        baseline: "production".to_owned(),
        items: count,
        pixels_per_item: f64::from(leg * leg) / 2.0,
        error_unit: "samples".to_owned(),
        methods: measured,
        parallel_ceiling: ceiling.ratio(),
    }
}
