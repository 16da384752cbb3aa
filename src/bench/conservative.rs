//! The conservative workload (SPEC.md §19): the same seeded triangles
//! drawn by production's ordinary fill (the baseline), by production's
//! conservative rasterizer (overestimation at u = 1/256, and
//! underestimation), and by the reference's exact classes (on fewer
//! triangles, timed per triangle), side by side in one run, so the
//! conservative path's cost reads as a ratio. Production's conservative
//! pixels are checked against the reference's classes on the reference's
//! triangles: a required pixel missing or a forbidden one drawn is an
//! error.

use std::time::{Duration, Instant};

use super::model::{Measured, Workload};
use super::sizes::Sizes;
use super::timing::median;
use super::workloads::{triangle_scene, SEED};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::Production;
use crate::rasterizer::Rasterizer;
use crate::reference::conservative::{classify, PixelClass};
use crate::scene::{Conservative, Number, Scene};

/// The baseline's name: production's ordinary (top-left) fill.
const ORDINARY: &str = "production, ordinary fill";

/// `scene` drawn conservatively in `mode` at u = 1/256.
fn conservative(scene: &Scene, state: Conservative) -> Scene {
    let mut s = scene.clone();
    s.effects.conservative = Some(Conservative {
        uncertainty: Number::ratio(1, 256),
        ..state
    });
    s
}

/// Pixels of `frame` against the reference's classes of `scene`: (wrong,
/// pixels), wrong a required pixel missing or a forbidden one drawn.
fn wrong_pixels(scene: &Scene, frame: &Frame) -> Result<(u64, u64), String> {
    let classes = classify(scene).map_err(|e| e.to_string())?;
    let wrong = classes
        .drawn
        .iter()
        .zip(&frame.coverage)
        .filter(|(class, &c)| !class.admits(c > 0) && **class != PixelClass::Allowed)
        .count() as u64;
    Ok((wrong, classes.drawn.len() as u64))
}

pub(super) fn measure_conservative(sizes: &Sizes, notes: &mut Vec<String>) -> Workload {
    let (leg, count, reference_count) = sizes.conservative;
    let base = triangle_scene(sizes.canvas, leg, count, SEED ^ 0x4352);
    let few = Scene {
        primitives: base.primitives[..reference_count.min(count)].to_vec(),
        ..base.clone()
    };
    let over = conservative(&base, Conservative::overestimate());
    let under = conservative(&base, Conservative::underestimate());
    let few_over = conservative(&few, Conservative::overestimate());
    let rows: [(&str, &Scene, usize); 4] = [
        (ORDINARY, &base, count),
        ("production, conservative overestimate", &over, count),
        ("production, conservative underestimate", &under, count),
        (
            "reference, conservative overestimate",
            &few_over,
            few.primitives.len(),
        ),
    ];
    let plans: Vec<Plan> = rows.iter().map(|(_, s, _)| Plan::for_scene(s)).collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); rows.len()];
    let mut failed: Vec<Option<String>> = vec![None; rows.len()];
    for _ in 0..sizes.repetitions {
        for (k, (name, scene, _)) in rows.iter().enumerate() {
            if failed[k].is_some() {
                continue;
            }
            let started = Instant::now();
            let result = if name.starts_with("reference") {
                classify(scene).map(|c| c.drawn.len())
            } else {
                Production
                    .rasterize(scene, &plans[k])
                    .map(|f| f.coverage.len())
            };
            times[k].push(started.elapsed());
            if let Err(e) = std::hint::black_box(result) {
                failed[k] = Some(e.to_string());
            }
        }
    }
    // Production's conservative pixels against the reference's classes,
    // on the reference's triangles, outside every timing.
    let checked = Production
        .rasterize(&few_over, &Plan::for_scene(&few_over))
        .map_err(|e| e.to_string())
        .and_then(|frame| wrong_pixels(&few_over, &frame));
    let methods = rows
        .iter()
        .zip(times)
        .zip(failed)
        .enumerate()
        .map(|(k, (((name, _, items), times), failed))| {
            if let Some(why) = failed {
                return Measured::not_run(name, why);
            }
            let mut m = Measured::whole(name, median(times) / (*items).max(1) as u32, *items);
            if k == 1 {
                match &checked {
                    Ok((wrong, of)) => {
                        m.errors = Some((*wrong, *of));
                        m.exact = *wrong == 0;
                        m.note = format!(
                            "checked against the reference's classes on its {} triangles",
                            few.primitives.len()
                        );
                    }
                    Err(why) => m.note = format!("not checked: {why}"),
                }
            }
            if k == 3 {
                m.exact = true;
                m.note = format!(
                    "exact rational classes, timed on the first {} triangles",
                    few.primitives.len()
                );
            }
            m
        })
        .collect();
    notes.push(format!(
        "Conservative: the same {count} triangles (L={leg}) drawn by production's ordinary \
         fill and conservatively (u = 1/256), the reference's exact classes on the first \
         {reference_count}; × is each row's speed against the ordinary fill. Errors: required \
         pixels missing plus forbidden pixels drawn, of all pixels."
    ));
    Workload {
        name: format!(
            "conservative rasterization, L={leg} ({} px each), {}² canvas",
            leg * leg / 2,
            sizes.canvas
        ),
        short: "CR".to_owned(),
        baseline: ORDINARY.to_owned(),
        items: count,
        pixels_per_item: f64::from(leg * leg) / 2.0,
        error_unit: "pixels".to_owned(),
        methods,
        parallel_ceiling: None,
    }
}
