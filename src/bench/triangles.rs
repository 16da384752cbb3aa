//! The triangle workloads: every triangle method timed in interleaved
//! rounds on one seeded scene, with the declared-blur pair, the parallel
//! ceiling, the drivers' empty-canvas frames and the reference on a prefix;
//! errors counted against the reference's exact frame.

use std::time::{Duration, Instant};

use super::declared::Declared;
use super::llvmpipe::{is_driver, lp_num_threads, marginal_name, marginal_per_item};
use super::memory;
use super::methods::{is_exact, triangle_methods};
use super::model::{Measured, Workload};
use super::score::mismatched;
use super::sizes::Sizes;
use super::text::time_text;
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
    let draw = |k: usize, r: &dyn Rasterizer, scene: &Scene| match tiled
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
    // The fixed per-frame cost of production and the drivers: the same
    // call on the same canvas with no triangles.
    let empty = subset(&s, 0);
    let with_empty = |name: &str| name == "production" || is_driver(name);
    let mut empty_times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut ceiling = ParallelCeiling::new(sizes.ceiling_steps);
    // Drivers create their device and pipelines on first use: once here,
    // untimed.
    for (_, r) in methods.iter().filter(|(name, _)| is_driver(name)) {
        std::hint::black_box(r.rasterize(&s, &plan).ok());
    }
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
            let (result, elapsed) = draw(k, r.as_ref(), &s);
            times[k].push(elapsed);
            if rep == 0 {
                frames[k] = result.map_err(|e| e.to_string());
            }
            if with_empty(name) && frames[k].is_ok() {
                let (result, elapsed) = draw(k, r.as_ref(), &empty);
                empty_times[k].push(elapsed);
                std::hint::black_box(result.ok());
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
                .then(|| memory::peak(|| draw(k, r.as_ref(), &s)).1)
                .flatten()
        })
        .collect();
    let declared_peaks = methods
        .iter()
        .find(|(name, _)| name == "production")
        .map_or([None, None], |(_, r)| declared.peaks(r.as_ref()));
    let mut measured: Vec<Measured> = Vec::new();
    for (k, (((name, _), times), frame)) in methods.iter().zip(times).zip(frames).enumerate() {
        let empty_frame = (!empty_times[k].is_empty()).then(|| median(empty_times[k].clone()));
        let row = match frame {
            Ok(frame) => Measured {
                method: name.clone(),
                per_item: Some(median(times) / count as u32),
                timed_items: count,
                errors: Some((mismatched(&exact, &frame), covered)),
                coverage_error: None,
                exact: is_exact(name),
                peak_heap: peaks[k],
                empty_frame,
                note: match empty_frame {
                    Some(e) if is_driver(name) => format!(
                        "LP_NUM_THREADS={}; the whole call: vertex stream, upload, draw, \
                         read-back of the targets into a frame ({} per frame on an empty canvas)",
                        lp_num_threads().unwrap_or_else(|| "unset".to_owned()),
                        time_text(e)
                    ),
                    Some(e) => format!("{} per frame on an empty canvas", time_text(e)),
                    None => String::new(),
                },
            },
            Err(why) => Measured {
                exact: is_exact(name),
                ..Measured::not_run(name, why)
            },
        };
        let marginal = is_driver(name)
            .then(|| marginal_per_item(&row).zip(row.empty_frame))
            .flatten()
            .map(|(t, e)| Measured {
                method: marginal_name(name),
                per_item: Some(Duration::from_secs_f64(t)),
                timed_items: count,
                errors: row.errors,
                coverage_error: None,
                exact: false,
                peak_heap: None,
                empty_frame: None,
                note: format!(
                    "`{name}`'s time minus its {} on the same canvas with no triangles \
                     (clearing and reading back the targets, filling the frame), per triangle",
                    time_text(e)
                ),
            });
        measured.push(row);
        measured.extend(marginal);
    }
    measured.extend(declared.rows(&exact, covered, count, declared_peaks));
    measured.push(Measured {
        method: "reference".to_owned(),
        per_item: Some(median(reference_times) / reference_count as u32),
        timed_items: reference_count,
        errors: Some((0, covered)),
        coverage_error: None,
        exact: true,
        peak_heap: reference_peak,
        empty_frame: None,
        note: if reference_count < count {
            format!(
                "timed on the first {reference_count} of the {count} triangles; \
                 peak heap on all {count}"
            )
        } else {
            String::new()
        },
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
