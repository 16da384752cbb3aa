//! One bench run: every workload measured in turn, the bundled suite timed,
//! the targets judged, into the report model.

use std::time::Instant;

use super::antialias::measure_antialias;
use super::conservative::measure_conservative;
use super::lines::measure_lines;
use super::llvmpipe::pin_llvmpipe_threads;
use super::machine::{load_average, machine};
use super::memory;
use super::model::Report;
use super::motion::measure_motion;
use super::sizes::{Options, Sizes};
use super::suite;
use super::targets::targets;
use super::triangles::measure_triangles;

/// Runs every workload.
pub fn run(options: Options, progress: &mut dyn FnMut(&str)) -> Report {
    let lp_num_threads = pin_llvmpipe_threads();
    let memory_counted = memory::installed();
    let load_before = load_average();
    let started = Instant::now();
    let sizes = Sizes::for_options(options);
    let mut notes = Vec::new();
    let mut workloads = Vec::new();
    for (k, &(leg, count)) in sizes.triangles.iter().enumerate() {
        if count == 0 {
            notes.push(format!(
                "L={leg} is left out of the quick run (it does not fit a small canvas)."
            ));
            continue;
        }
        progress(&format!("triangles L={leg}: {count} triangles"));
        workloads.push(measure_triangles(
            leg,
            count,
            sizes.reference_triangles[k],
            &sizes,
            &mut notes,
        ));
    }
    progress(&format!("lines: {} lines", sizes.lines));
    workloads.push(measure_lines(&sizes, &mut notes));
    progress(&format!(
        "antialiasing: {} triangles, L={}",
        sizes.antialias.1, sizes.antialias.0
    ));
    workloads.push(measure_antialias(&sizes, &mut notes));
    progress(&format!(
        "conservative: {} triangles, L={}",
        sizes.conservative.1, sizes.conservative.0
    ));
    workloads.push(measure_conservative(&sizes, &mut notes));
    let (leg, count, _) = sizes.motion;
    progress(&format!("motion blur: {count} moving triangles, L={leg}"));
    workloads.push(measure_motion(&sizes, &mut notes));
    progress("the bundled suite through production");
    let suite = suite::measure_suite(sizes.repetitions);
    let (machine, cores) = machine();
    let targets = targets(
        &workloads,
        options.quick,
        lp_num_threads.as_ref(),
        suite.as_ref(),
    );
    Report {
        quick: options.quick,
        machine,
        cores,
        date: crate::harness::today::today(),
        version: env!("CARGO_PKG_VERSION").to_owned(),
        repetitions: sizes.repetitions,
        workloads,
        targets,
        notes,
        elapsed: started.elapsed(),
        load: load_before.zip(load_average()),
        memory_counted,
        lp_num_threads,
    }
}
