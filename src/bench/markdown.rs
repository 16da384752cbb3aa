//! BENCH.md: the run's machine and settings, one table per workload, the
//! targets and the notes, written from a [`Report`]. The chart is
//! `chart.rs`'s.

use std::fmt::Write as _;

use super::llvmpipe::LLVMPIPE_COMMAND;
use super::memory;
use super::model::Report;
use super::text::{significant, time_text};
use super::timing::TILED_THREADS;
use super::workloads::SEED;

impl Report {
    pub fn to_markdown(&self, svg_name: &str) -> String {
        let mut md = String::new();
        let _ = writeln!(md, "# rastercheck bench\n");
        let command = match (self.quick, self.lp_num_threads.is_some()) {
            (true, _) => "`rastercheck bench --quick`".to_owned(),
            (false, true) => format!("`{LLVMPIPE_COMMAND}`"),
            (false, false) => format!(
                "`cargo run --release -- bench` (with the llvmpipe rows: `{LLVMPIPE_COMMAND}`)"
            ),
        };
        let _ = writeln!(
            md,
            "Written by {command}. Every number below was measured in this one run, on the \
             same seeded workloads (seed {SEED:#x}), one thread (but `production-tiled`, on a \
             pool of {TILED_THREADS}).\n"
        );
        let _ = writeln!(md, "- machine: {} ({} cores)", self.machine, self.cores);
        let _ = writeln!(md, "- date: {}", self.date);
        let _ = writeln!(md, "- rastercheck version: {}", self.version);
        let _ = writeln!(
            md,
            "- timing: median of {} interleaved repetitions per method; run took {:.1} s",
            self.repetitions,
            self.elapsed.as_secs_f64()
        );
        if let Some((before, after)) = &self.load {
            let _ = writeln!(
                md,
                "- load average (1, 5, 15 min): {before} before the run, {after} after; \
                 above 0 it is other work sharing the {} cores, which the two-thread \
                 method feels most",
                self.cores
            );
        }
        match &self.lp_num_threads {
            Some((v, by_bench)) => {
                let _ = writeln!(
                    md,
                    "- llvmpipe rows (`lavapipe`, `gl`): LP_NUM_THREADS={v}, {}",
                    if *by_bench {
                        "set by the bench (one rasterizer thread; the calling thread bins and waits)"
                    } else {
                        "as set before the run"
                    }
                );
            }
            None => {
                let _ = writeln!(
                    md,
                    "- llvmpipe rows: not in this build (`{LLVMPIPE_COMMAND}` adds them)"
                );
            }
        }
        let _ = writeln!(
            md,
            "- peak heap: {}",
            if self.memory_counted {
                "each method run once more, outside every timing, with a counting allocator \
                 (see the notes)"
            } else {
                "not measured (no counting allocator in this program)"
            }
        );
        if self.quick {
            let _ = writeln!(
                md,
                "- **quick run**: small canvas, few items; timings are indicative only"
            );
        }
        let _ = writeln!(md);
        let _ = writeln!(md, "![accuracy against time]({svg_name})\n");
        let _ = writeln!(md, "## Workloads\n");
        for w in &self.workloads {
            let _ = writeln!(md, "### {} ({} items)\n", w.name, w.items);
            let per_second = if w.short == "lines" {
                "Mlines/s"
            } else {
                "Mtri/s"
            };
            // Workloads whose methods have draw calls timed apart show the
            // whole call and the adapter's overhead beside them.
            let calls = w.methods.iter().any(|m| m.whole_call.is_some());
            let (time_head, call_heads, call_rule) = if calls {
                (
                    "draw call per item",
                    " whole call per item | adapter overhead |",
                    "---|---|",
                )
            } else {
                ("time per item", "", "")
            };
            let _ = writeln!(
                md,
                "| method | {time_head} | {per_second} | Mpix/s | × `{}` |{call_heads} error ({}) | peak heap | note |",
                w.baseline, w.error_unit
            );
            let _ = writeln!(md, "|---|---|---|---|---|{call_rule}---|---|---|");
            for m in &w.methods {
                let (time, rate, mpix) = match m.per_item {
                    Some(d) if d.as_nanos() > 0 => {
                        let s = d.as_secs_f64();
                        (
                            time_text(d),
                            significant(1e-6 / s),
                            significant(w.pixels_per_item * 1e-6 / s),
                        )
                    }
                    _ => ("—".to_owned(), "—".to_owned(), "—".to_owned()),
                };
                let ratio = w
                    .ratio(&m.method, &w.baseline)
                    .map_or("—".to_owned(), |r| format!("{r:.2}"));
                let error = match (m.errors, m.coverage_error) {
                    (_, Some((rms, max))) => {
                        format!("{} / {}", significant(rms), significant(max))
                    }
                    (Some((0, of)), None) => format!("0 of {of} (exact)"),
                    (Some((e, of)), None) => {
                        format!("{e} of {of} ({:.3}%)", 100.0 * e as f64 / of.max(1) as f64)
                    }
                    (None, None) => "—".to_owned(),
                };
                let heap = match (m.peak_heap, m.per_item) {
                    (Some(b), _) => memory::bytes_text(b),
                    (None, Some(_)) if !self.memory_counted => "not measured".to_owned(),
                    (None, _) => "—".to_owned(),
                };
                let call_cells = match (calls, m.whole_call, m.overhead()) {
                    (false, _, _) => String::new(),
                    (true, Some(whole), Some(overhead)) => format!(
                        " {} | {} ({:.0}%) |",
                        time_text(whole),
                        time_text(overhead),
                        100.0 * overhead.as_secs_f64() / whole.as_secs_f64().max(1e-12)
                    ),
                    (true, _, _) => " — | — |".to_owned(),
                };
                let _ = writeln!(
                    md,
                    "| `{}` | {time} | {rate} | {mpix} | {ratio} |{call_cells} {error} | {heap} | {} |",
                    m.method, m.note
                );
            }
            let _ = writeln!(md);
        }
        let _ = writeln!(
            md,
            "“×” is the method's speed relative to the workload's baseline measured side by side \
             (above 1: faster). Mpix/s counts nominal pixels (a triangle's area L²/2, a line's \
             mean length). Triangle errors are samples whose coverage count or last primitive \
             differs from the exact reference's frame for the whole workload, out of the \
             reference's covered samples (counted with multiplicity).\n"
        );
        let _ = writeln!(md, "## How each method is timed\n");
        let _ = writeln!(
            md,
            "As Blend2D's `bl_bench` does: every method draws the same seeded shapes on the \
             same canvas; each is warmed up before the rounds (a driver creates its device and \
             pipelines then); the methods take turns in interleaved rounds, so that drift in \
             the machine's speed hits them alike; each figure is the median of the rounds; \
             and each claim is a ratio between methods measured side by side, per size.\n"
        );
        let _ = writeln!(
            md,
            "A method is timed at its own work. Where it has a draw call apart from its \
             adapter (`Rasterizer::prepare`), the scene is converted into the method's own \
             input once (production: vertices snapped into its fixed point; tiny-skia: paths \
             built; euc: clip-space vertices; a driver: its vertex stream uploaded), its \
             targets are allocated once and cleared before each draw, untimed, and only the \
             draw is timed: every triangle into the targets as they stand, and for a driver \
             from submission to the fence. Read-back is timed apart. The frame each draw call \
             reads back must name the same last primitive at every sample as the whole call \
             that was judged (each row's note says so). “×” compares draw calls with draw \
             calls, and whole calls with whole calls where a row has no draw call apart; the \
             whole call (`Rasterizer::rasterize`: conversion, upload, draw, read-back into a \
             new frame) and the adapter's overhead, whole call minus draw call, have columns \
             of their own.\n"
        );
        let _ = writeln!(md, "## Performance targets\n");
        let _ = writeln!(md, "| target | measured | status | note |");
        let _ = writeln!(md, "|---|---|---|---|");
        for t in &self.targets {
            let status = match t.met {
                Some(true) => "met",
                Some(false) => "not met",
                None => "not measured",
            };
            let _ = writeln!(
                md,
                "| {} | {} | {status} | {} |",
                t.target, t.measured, t.note
            );
        }
        let _ = writeln!(md, "\n## Notes\n");
        for n in &self.notes {
            let _ = writeln!(md, "- {n}");
        }
        let _ = writeln!(
            md,
            "- Adapters (tiny-skia, euc, and lavapipe and gl where built in) have their whole \
             call through rastercheck's adapter timed too (converting the scene, and reading \
             their pixels back into a frame); the llvmpipe adapters create their device (or \
             EGL context) and pipelines once per process, on an untimed first draw."
        );
        let _ = writeln!(
            md,
            "- Peak heap: each method is run once more after its timings, never inside one, \
             with a counting global allocator on (`bench::memory`): the most heap it held \
             above the level at the call's start, on every thread it used, the frame it \
             returns included. Counted: every allocation through Rust's allocator (for the \
             llvmpipe adapters, wgpu's and the adapter's own: the vertex stream, the bytes \
             copied out of the driver's read-back buffers, the frame). Not counted: memory Mesa's C code allocates itself \
             (render targets, JIT-compiled shaders, bins, its threads' heap), stacks, and pages \
             kept by the allocator after a free. The reference's figure is for its exact frame \
             of the whole workload."
        );
        if let Some(c) = self
            .workloads
            .iter()
            .filter_map(|w| w.parallel_ceiling.map(|c| (w, c)))
            .map(|(w, c)| format!("{} {c:.2}×", w.short))
            .reduce(|a, b| format!("{a}, {b}"))
        {
            let _ = writeln!(
                md,
                "- Parallel ceiling: a perfectly parallel integer loop (no memory traffic) on \
                 the tiled method's pool of {TILED_THREADS} threads against one thread, timed \
                 in the rounds of each triangle workload: {c}. Near {TILED_THREADS}× the \
                 cores were free; below, other work shared them."
            );
        }
        let _ = writeln!(
            md,
            "- Only ratios measured side by side in this run are claims; absolute times \
             depend on the machine."
        );
        md
    }
}
