//! The motion-blur workload: translating triangles drawn at several time
//! patterns and N, each on its own pool, against the static frame at
//! shutter open; time coverage scored against the exact one of
//! `translation.rs`.

use std::time::Duration;

use super::memory;
use super::methods::{motion_methods, MOTION_BASELINE};
use super::model::{Measured, Workload};
use super::score::time_error;
use super::sizes::Sizes;
use super::text::significant;
use super::timing::{median, OnPool, TILED_THREADS};
use super::translation::translation_time_coverage;
use super::workloads::{motion_scene, SEED};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::scene::{Scene, TimePattern};

pub(super) fn measure_motion(sizes: &Sizes, notes: &mut Vec<String>) -> Workload {
    let (leg, count, reach) = sizes.motion;
    let seed = SEED ^ 0x4d42;
    let methods = motion_methods();
    let scenes: Vec<(Scene, Plan)> = methods
        .iter()
        .map(|(_, time, _)| {
            let (pattern, n) = time.unwrap_or((TimePattern::Stratified, 1));
            let mut s = motion_scene(sizes.canvas, leg, count, reach, n, pattern, seed);
            if time.is_none() {
                s.effects.motion_blur = None;
                for v in s.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
                    v.to = None;
                }
            }
            let plan = Plan::for_scene(&s);
            (s, plan)
        })
        .collect();
    let exact = translation_time_coverage(&scenes[1].0).expect("pure translations");
    let pools: Vec<OnPool> = methods
        .iter()
        .map(|(name, _, threads)| {
            let inner: Box<dyn Rasterizer> = if name.starts_with("production-tiled") {
                Box::new(crate::production::tiled::Tiled)
            } else {
                Box::new(crate::production::Production)
            };
            OnPool::new(inner, *threads)
        })
        .collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut frames: Vec<Option<Result<Frame, String>>> = vec![None; methods.len()];
    for rep in 0..sizes.repetitions {
        for (k, pool) in pools.iter().enumerate() {
            let (s, plan) = &scenes[k];
            let (result, elapsed) = pool.timed(s, plan);
            times[k].push(elapsed);
            if rep == 0 {
                frames[k] = Some(result.map_err(|e| e.to_string()));
            }
        }
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = pools
        .iter()
        .zip(&scenes)
        .map(|(pool, (s, plan))| memory::peak(|| pool.timed(s, plan)).1)
        .collect();
    let measured = methods
        .iter()
        .zip(times)
        .zip(frames)
        .zip(peaks)
        .map(
            |((((name, _, _), times), frame), peak_heap)| match frame.expect("drawn") {
                Ok(frame) => {
                    let time = frame.time.clone().unwrap_or_else(|| frame.box_resolve());
                    let note = match frame.sample_tests {
                        Some(tests) => format!(
                            "sample test efficiency {} ({} of {} tests covered)",
                            significant(tests.efficiency()),
                            tests.covered,
                            tests.tests
                        ),
                        None => "the error of ignoring motion".to_owned(),
                    };
                    Measured {
                        method: name.clone(),
                        per_item: Some(median(times) / count as u32),
                        timed_items: count,
                        errors: None,
                        coverage_error: Some(time_error(&exact, &time)),
                        exact: false,
                        peak_heap,
                        whole_call: None,
                        set_up: None,
                        read_back: None,
                        note,
                    }
                }
                Err(why) => Measured::not_run(name, why),
            },
        )
        .collect();
    notes.push(format!(
        "Motion blur: {count} triangles (legs {leg} px) each translated by {}–{reach} px over \
         the shutter; errors are time coverage minus the exact value at each pixel centre \
         (`bench::translation_time_coverage`: under translation each edge crosses a centre \
         at one rational instant), RMS over moving pixels and largest. Production rows run \
         on a pool of one thread, the tiled row on {TILED_THREADS}. Sample test efficiency: \
         covered tests of moving triangles over all their tests (a triangle is tested only \
         at centres in the box it sweeps).",
        reach / 2.0
    ));
    Workload {
        name: format!(
            "motion blur, L={leg} ({} px each), {}² canvas",
            leg * leg / 2,
            sizes.canvas
        ),
        short: "motion".to_owned(),
        baseline: MOTION_BASELINE.to_owned(),
        items: count,
        pixels_per_item: f64::from(leg * leg) / 2.0,
        error_unit: "time coverage, RMS over moving pixels / max".to_owned(),
        methods: measured,
        parallel_ceiling: None,
    }
}
