//! `rastercheck bench`: time and error of each method, measured in one run on
//! the same seeded workloads, written as BENCH.md and a hand-drawn SVG chart.
//!
//! Timings are medians over interleaved repetitions (every method runs once
//! per round, so drift in the machine's speed hits all methods alike), and
//! the conclusions drawn from them are ratios between methods measured side
//! by side. Errors are counted against the exact reference.
//!
//! One file a stage, in the order a run crosses them: `sizes.rs` (how big a
//! run is), `workloads.rs` (the seeded scenes), `foils.rs` and `methods.rs`
//! (what is measured), `timing.rs` (medians, pools, the parallel ceiling),
//! `draw_call.rs` (a method's own draw call, timed apart from its adapter),
//! one file per workload family (`triangles.rs` with `declared.rs`,
//! `lines.rs`, `antialias.rs`, `motion.rs` with `translation.rs`), scored by
//! `score.rs`; `llvmpipe.rs` and `machine.rs` (the drivers and the machine),
//! `suite.rs` (the bundled cases through production), `targets.rs`
//! (judging), then the writers `markdown.rs` and `chart.rs`
//! (with `text.rs`), all from the result model in `model.rs`. Peak heap is
//! `memory.rs`'s counting allocator.

use std::path::Path;
use std::time::Instant;

mod antialias;
mod chart;
mod declared;
mod draw_call;
mod foils;
mod lines;
mod llvmpipe;
mod machine;
mod markdown;
pub mod memory;
mod methods;
mod model;
mod motion;
mod score;
mod sizes;
mod suite;
mod targets;
mod text;
mod timing;
mod translation;
mod triangles;
mod workloads;

pub use declared::{DECLARED, PAIRED};
pub use foils::{NaiveBbox, PlainMidpoint};
pub use llvmpipe::{lp_num_threads, DRIVERS, LLVMPIPE_COMMAND};
pub use methods::{triangle_methods, MOTION_BASELINE};
pub use model::{Measured, Report, Target, Workload};
pub use score::time_error;
pub use timing::{OnPool, ParallelCeiling, TILED_THREADS};
pub use translation::translation_time_coverage;
pub use workloads::{line_scene, motion_scene, triangle_scene, SEED};

use antialias::measure_antialias;
use lines::measure_lines;
use llvmpipe::pin_llvmpipe_threads;
use machine::{load_average, machine};
use motion::measure_motion;
use sizes::Sizes;
use targets::targets;
use triangles::measure_triangles;

/// Whether BENCH.md can be written at `out`, and bench.svg beside it,
/// checked before a run rather than after its minutes of measuring: the
/// folder must exist and take a new file (one is created there and removed
/// at once), and either file that exists already must open for writing
/// (opened to append, left as it is). `Err` says why not, naming the path.
pub fn check_out_path(out: &Path) -> Result<(), String> {
    let dir = match out.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(format!(
            "{}: no such folder (create it before the run)",
            dir.display()
        ));
    }
    if out.is_dir() {
        return Err(format!(
            "{}: a folder; name the file to write, e.g. {}",
            out.display(),
            out.join("BENCH.md").display()
        ));
    }
    let probe = dir.join(format!(".rastercheck-bench-{}.tmp", std::process::id()));
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .map_err(|e| format!("{}: cannot write a file there: {e}", dir.display()))?;
    std::fs::remove_file(&probe).map_err(|e| format!("{}: {e}", probe.display()))?;
    for file in [out.to_path_buf(), out.with_file_name("bench.svg")] {
        if file.exists() {
            std::fs::OpenOptions::new()
                .append(true)
                .open(&file)
                .map_err(|e| format!("{}: cannot write it: {e}", file.display()))?;
        }
    }
    Ok(())
}

/// How big a run is.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    pub quick: bool,
}

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

#[cfg(test)]
mod tests {
    use super::check_out_path;
    use std::path::Path;

    #[test]
    fn out_path_in_a_missing_folder_is_refused_before_the_run() {
        let out = std::env::temp_dir().join("rastercheck-no-such-folder-7f3a/BENCH.md");
        let why = check_out_path(&out).unwrap_err();
        assert!(why.contains("no such folder"), "{why}");
    }

    #[test]
    fn out_path_in_a_writable_folder_passes_and_leaves_nothing() {
        let dir = std::env::temp_dir().join(format!("rastercheck-out-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        assert_eq!(check_out_path(&dir.join("BENCH.md")), Ok(()));
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
        let why = check_out_path(&dir).unwrap_err();
        assert!(why.contains("a folder"), "{why}");
        std::fs::remove_dir(&dir).unwrap();
    }

    #[test]
    fn a_bare_file_name_is_checked_in_the_current_folder() {
        assert_eq!(check_out_path(Path::new("BENCH.md")), Ok(()));
    }
}
