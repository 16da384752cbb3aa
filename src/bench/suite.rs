//! The bundled suite through production: every case under `cases/` (the
//! folder in the working directory; `invalid/` folders aside), read and
//! planned once, then drawn by production in each round, the whole suite
//! timed as one: the target that it stays under a second.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use super::timing::median;
use crate::harness::discover::discover;
use crate::harness::load::load;
use crate::plan::Plan;
use crate::production::Production;
use crate::rasterizer::Rasterizer;
use crate::scene::Limits;

/// The suite's cases and the median time production took to draw them all.
pub(super) struct SuiteTime {
    pub cases: usize,
    pub drawn: usize,
    pub median: Duration,
}

/// `None` when there is no `cases/` folder here to time.
pub(super) fn measure_suite(repetitions: usize) -> Option<SuiteTime> {
    let root = PathBuf::from("cases");
    if !root.is_dir() {
        return None;
    }
    let limits = Limits::default();
    let scenes: Vec<_> = discover(&[root])
        .cases
        .iter()
        .filter_map(|file| load(file, &limits).ok())
        .map(|scene| {
            let plan = Plan::for_scene(&scene);
            (scene, plan)
        })
        .collect();
    let mut times = Vec::new();
    let mut drawn = 0;
    for _ in 0..repetitions.max(1) {
        let started = Instant::now();
        drawn = 0;
        for (scene, plan) in &scenes {
            if Production.capabilities().refuses(scene).is_some() {
                continue;
            }
            drawn += usize::from(std::hint::black_box(Production.rasterize(scene, plan)).is_ok());
        }
        times.push(started.elapsed());
    }
    Some(SuiteTime {
        cases: scenes.len(),
        drawn,
        median: median(times),
    })
}
