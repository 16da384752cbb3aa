//! The line workload: production's midpoint, the float DDAs and the plain
//! midpoint loop timed on one seeded scene; pixel sets compared line by
//! line, each line drawn alone, and production checked against the
//! reference on a prefix.

use std::time::{Duration, Instant};

use super::foils::PlainMidpoint;
use super::memory;
use super::model::{Measured, Workload};
use super::score::lit;
use super::sizes::Sizes;
use super::timing::median;
use super::workloads::{line_scene, SEED};
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;

pub(super) fn measure_lines(sizes: &Sizes, notes: &mut Vec<String>) -> Workload {
    let s = line_scene(sizes.line_canvas, sizes.line_lengths, sizes.lines, SEED);
    let plan = Plan::for_scene(&s);
    let names = ["production", "dda-f32", "dda-f64", "midpoint-plain"];
    let methods: Vec<Box<dyn Rasterizer>> = names
        .iter()
        .map(|&n| match n {
            "midpoint-plain" => Box::new(PlainMidpoint),
            n => crate::registry::by_name(n).expect("a built-in rasterizer"),
        })
        .collect();
    let mut times: Vec<Vec<Duration>> = vec![Vec::new(); methods.len()];
    for _ in 0..sizes.repetitions {
        for (k, r) in methods.iter().enumerate() {
            let started = Instant::now();
            let frame = r.rasterize(&s, &plan);
            times[k].push(started.elapsed());
            std::hint::black_box(frame.expect("lines draw"));
        }
    }
    // Peak heap: each method once more, outside every timing.
    let peaks: Vec<Option<u64>> = methods
        .iter()
        .map(|r| memory::peak(|| r.rasterize(&s, &plan)).1)
        .collect();
    // Pixel sets, line by line: each line alone in the full canvas, so that
    // the float methods round exactly as in the timed run.
    let alone = |i: usize| {
        let mut one = s.clone();
        one.primitives = vec![s.primitives[i].clone()];
        one
    };
    let compared = sizes.lines_compared.min(sizes.lines);
    let mut differ = vec![0u64; names.len()];
    let mut disagree_with_reference = 0;
    for i in 0..compared {
        let one = alone(i);
        let sets: Vec<Vec<usize>> = methods
            .iter()
            .map(|r| lit(&r.rasterize(&one, &plan).expect("lines draw")))
            .collect();
        for k in 1..names.len() {
            differ[k] += u64::from(sets[k] != sets[0]);
        }
        if i < sizes.lines_verified {
            let exact = lit(&crate::reference::render(&one, &plan));
            disagree_with_reference += u64::from(exact != sets[0]);
        }
    }
    differ[0] = disagree_with_reference;
    notes.push(format!(
        "Lines: the exact rule is production's midpoint; it drew the reference's pixel set \
         on {} of the {} lines checked against the reference. Pixel sets are compared \
         on the first {compared} of the {} lines, each drawn alone.",
        sizes.lines_verified.min(compared) as u64 - disagree_with_reference,
        sizes.lines_verified.min(compared),
        sizes.lines
    ));
    let measured = names
        .iter()
        .zip(times)
        .enumerate()
        .map(|(k, (name, times))| Measured {
            method: (*name).to_owned(),
            per_item: Some(median(times) / sizes.lines as u32),
            timed_items: sizes.lines,
            errors: Some(if k == 0 {
                (differ[0], sizes.lines_verified.min(compared) as u64)
            } else {
                (differ[k], compared as u64)
            }),
            coverage_error: None,
            exact: k == 0,
            peak_heap: peaks[k],
            whole_call: None,
            set_up: None,
            read_back: None,
            note: if k == 0 {
                "error against the reference".to_owned()
            } else {
                "error against the exact midpoint rule".to_owned()
            },
        })
        .collect();
    Workload {
        name: format!(
            "lines, {}–{} px, {}² canvas",
            sizes.line_lengths.0, sizes.line_lengths.1, sizes.line_canvas
        ),
        short: "lines".to_owned(),
        baseline: "production".to_owned(),
        items: sizes.lines,
        pixels_per_item: (sizes.line_lengths.0 + sizes.line_lengths.1) / 2.0,
        error_unit: "lines".to_owned(),
        methods: measured,
        parallel_ceiling: None,
    }
}
