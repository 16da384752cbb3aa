//! The antialiasing workload: every antialiasing method timed on the same
//! seeded triangles, each with its own pattern; resolved coverage scored
//! against the reference's exact per-pixel areas.

use std::time::{Duration, Instant};

use super::memory;
use super::methods::aa_methods;
use super::model::{Measured, Workload};
use super::score::coverage_error;
use super::sizes::Sizes;
use super::timing::median;
use super::workloads::{triangle_scene, SEED};
use crate::plan::Plan;
use crate::scene::{Antialias, Pattern, Scene};

pub(super) fn measure_antialias(sizes: &Sizes, notes: &mut Vec<String>) -> Workload {
    let (leg, count) = sizes.antialias;
    let base = triangle_scene(sizes.canvas, leg, count, SEED ^ 0x4141);
    let mut aa_scene = base.clone();
    aa_scene.effects.antialias = Some(Antialias {
        samples: 1,
        pattern: Pattern::Standard,
        seed: 0,
        adaptive: false,
        position_bits: 8,
    });
    let exact: Vec<f64> = crate::reference::exact_areas(&aa_scene)
        .iter()
        .map(|a| a.to_f64().value())
        .collect();
    let methods = aa_methods(sizes.antialias_samples);
    let scenes: Vec<(Scene, Plan)> = methods
        .iter()
        .map(|m| {
            let mut s = base.clone();
            s.effects.antialias = m.antialias.clone();
            let plan = Plan::for_scene(&s);
            (s, plan)
        })
        .collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    let mut results: Vec<Result<(f64, f64), String>> = vec![Err(String::new()); methods.len()];
    for rep in 0..sizes.repetitions {
        for (k, m) in methods.iter().enumerate() {
            if rep > 0 && results[k].is_err() {
                continue;
            }
            let (s, plan) = &scenes[k];
            let started = Instant::now();
            let result = m.rasterizer.rasterize(s, plan);
            times[k].push(started.elapsed());
            if rep == 0 {
                results[k] = result
                    .map(|frame| coverage_error(&exact, &frame))
                    .map_err(|e| e.to_string());
            }
        }
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = methods
        .iter()
        .zip(&scenes)
        .zip(&results)
        .map(|((m, (s, plan)), result)| {
            result
                .is_ok()
                .then(|| memory::peak(|| m.rasterizer.rasterize(s, plan)).1)
                .flatten()
        })
        .collect();
    let measured = methods
        .iter()
        .zip(times)
        .zip(results)
        .zip(peaks)
        .map(|(((m, times), result), peak_heap)| match result {
            Ok(error) => Measured {
                method: m.name.clone(),
                per_item: Some(median(times) / count as u32),
                timed_items: count,
                errors: None,
                coverage_error: Some(error),
                exact: false,
                peak_heap,
                whole_call: None,
                set_up: None,
                read_back: None,
                note: String::new(),
            },
            Err(why) => Measured::not_run(&m.name, why),
        })
        .collect();
    notes.push(format!(
        "Antialiasing: errors are resolved coverage minus the exact area of each pixel \
         (the reference's rational areas, summed over overlapping triangles), RMS over edge \
         pixels and largest; the aliased 1× row resolves each pixel to its centre's coverage. \
         Seeded patterns use seed {SEED:#x}, the same offsets in every pixel."
    ));
    Workload {
        name: format!(
            "antialiasing, L={leg} ({} px each), {}² canvas",
            leg * leg / 2,
            sizes.canvas
        ),
        short: "AA".to_owned(),
        baseline: "production 1× (aliased)".to_owned(),
        items: count,
        pixels_per_item: f64::from(leg * leg) / 2.0,
        error_unit: "coverage, RMS over edge pixels / max".to_owned(),
        methods: measured,
        parallel_ceiling: None,
    }
}
