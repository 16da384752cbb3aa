//! Faults injected into whole runs (issue 17): every verdict survives a
//! crash, hang, huge or hostile input, signal or limit in one case. Each
//! module is one family of fault; each test asserts that the run finishes,
//! the other cases keep their verdicts, report.json parses, and the exit
//! code is the documented one, and that the run's peak RSS stays under a
//! bound (the soak, a Python script, keeps its own).
//!
//! Peak RSS is `wait4`'s `ru_maxrss` for the binary (`common::cli::
//! run_measured`): the largest of its own peak, the peaks of the programs
//! it ran and reaped (python, about 13 MiB), and this test process's RSS
//! when it forked (a few MiB). Measured on a release build:
//!
//! | test (module) | measured | bound | without the fix it guards |
//! |---|---|---|---|
//! | flood, one-shot and persistent (external) | 15 MiB | 64 MiB | the whole flood, 256 MiB by default, unbounded without the limit |
//! | huge EXR answer (external) | 18 MiB | 64 MiB | 8 GiB to decode a 32768×32768 layer |
//! | huge golden file (external) | 13 MiB | 64 MiB | the same, for a golden file |
//! | huge case file (input) | 6 MiB | 64 MiB | 600 MB read, about 20 GB parsed |
//! | hostile values, 5 MB each (input) | 35 MiB | 128 MiB | (the values are read: they are under every limit; parsed on more threads with more cores) |
//! | `show` at `--scale 64`, lowered to 7 (exit_codes) | 492 MiB | 1024 MiB | pictures of 70400×64000 pixels, 17 GiB each |
//! | a case whose frames would take 27 GiB (memory) | 15 MiB | 200 MiB | the 27 GiB, allocated or aborted |
//! | six cases of 156 MiB of frames, one thread (memory) | 363 MiB | 450 MiB | 1064 MiB: every case's frames kept to the end |
//! | a v2 program writing 256 MiB to stdout between requests (persistent) | 17 MiB | 64 MiB | 188 MiB here, 2.6 GB for the 2 GB: the reader kept what an idle program wrote |
//! | a right answer for a 4096² case, 1 GiB address-space cap (bounded) | 384 MiB | 900 MiB | aborted at 3.86 GB under a 4 GiB cap (a `Value` of the answer) |
//! | a 2048² request at 16 instants, 1 GiB cap (bounded) | 428 MiB | 900 MiB | aborted at 3.95 GB under a 4 GiB cap (the request built three times) |
//! | every other run (external, input, exit_codes, answers, reports, persistent, bounded); SIGINT, SIGTERM (reports: VmHWM just before the signal) | 4–32 MiB | 64 MiB | |
//!
//! One bound for all but four: three to four times the largest measured,
//! and far under what any of the guarded faults would cost.

#[path = "../common/mod.rs"]
mod common;

mod answers;
mod bounded;
mod exit_codes;
mod external;
mod input;
mod memory;
mod persistent;
mod reports;
mod soak;

/// The peak RSS (MiB) a run of the binary stays under through any fault
/// here; see the table above.
const RSS_BOUND_MIB: f64 = 64.0;

/// The binary run in `dir` with `args`, its peak RSS held to
/// [`RSS_BOUND_MIB`]: for the runs of `answers` and `reports` that need
/// nothing more of it than its output.
fn bounded_run(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    run_within(dir, args, RSS_BOUND_MIB)
}

/// The binary run in `dir` with `args`, its peak RSS held to `bound_mib`.
fn run_within(dir: &std::path::Path, args: &[&str], bound_mib: f64) -> std::process::Output {
    let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_rastercheck"));
    command.args(args).current_dir(dir);
    let m = common::cli::run_measured(&mut command, std::time::Duration::from_secs(300));
    common::cli::assert_peak_rss(&format!("{args:?}"), &m, bound_mib);
    m.output
}
