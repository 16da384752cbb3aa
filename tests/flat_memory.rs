//! Issue 39's flat memory: a run's memory does not grow with its number of
//! cases. Each case's report entry goes to disk as it is judged
//! (`report/spool.rs`) and the summaries are written by reading them back
//! (`report/write.rs`), so what a run keeps per case is only its place in
//! the selection, held compactly (`harness/case_list.rs`: the ids in one
//! buffer, the paths rebuilt from a shared prefix, 8 bytes more), and a
//! slot of 8 bytes (5 for every 4 cases) in the table of its names' hashes
//! (names must be unique: `harness/unique_names.rs`).
//!
//! Two runs of generated tiny cases (a 4×4 canvas, one triangle each: the
//! generator RELIABILITY.md gives a user), 2 000 and 200 000 cases, one
//! thread, a full report folder: the peak RSS may grow by at most
//! [`BOUND_BYTES`] per case between them. Measured (RELIABILITY.md): 35
//! to 69 bytes a case (16.0 to 17.1 MiB at 2 000 cases, 22.8 to 29.0 MiB
//! at 200 000). The code before, which kept each path beside its id, 12
//! bytes of bounds and order, and a `HashMap` of 64-bit hashes to indices,
//! grew by 96 bytes a case here (14.9 MiB, 33.0 MiB, one run); the code
//! before that (`CaseFile`s and a `HashSet` of names) by about 235 and
//! fails this bound, and the code before the spool by about 6.7 KiB.

mod common;

use std::path::Path;
use std::process::Command;
use std::time::Duration;

use common::cli::{run_measured, scratch, text, Measured};

/// The most the peak RSS may grow per case, in bytes: the growth measured
/// (35 to 69 bytes in five pairs of runs, RELIABILITY.md) and a margin for
/// what moves between two runs of the same cases: the peak of 200 000
/// cases measured from 22.8 to 29.0 MiB, most likely the case entries
/// waiting to be handed over (up to `runner::AHEAD`, more under load),
/// about 26 bytes a case over these 198 000. Twice as much as the code
/// before the compact selection (216), but too close to the code just
/// before this one (96) to tell them apart reliably here: the unit tests
/// of `case_list.rs` and `unique_names.rs` hold those bytes exactly.
const BOUND_BYTES: f64 = 100.0;

/// The two runs' sizes.
const SMALL: usize = 2_000;
const LARGE: usize = 200_000;

/// Writes `n` tiny case files into `dir/gen`, as RELIABILITY.md's
/// generator does.
fn generate(dir: &Path, n: usize) {
    let gen = dir.join("gen");
    std::fs::create_dir_all(&gen).unwrap();
    for k in 0..n {
        std::fs::write(
            gen.join(format!("c{k:07}.json")),
            format!(
                "{{\"name\": \"c{k:07}\", \"canvas\": {{\"width\": 4, \"height\": 4}}, \"primitives\": [{{\"triangle\": [[0, 0], [{}, 0], [0, 4]]}}]}}\n",
                1 + k % 4
            ),
        )
        .unwrap();
    }
}

/// `run gen -r production -q --threads 1 --report out` over `n` generated
/// cases, measured.
fn run(n: usize) -> (Measured, std::path::PathBuf) {
    let dir = scratch(&format!("flat-memory-{n}"));
    generate(&dir, n);
    let measured = run_measured(
        Command::new(env!("CARGO_BIN_EXE_rastercheck"))
            .args(["run", "gen", "-r", "production", "-q"])
            .args(["--threads", "1", "--report", "out"])
            .current_dir(&dir),
        Duration::from_secs(600),
    );
    let t = text(&measured.output);
    assert_eq!(measured.output.status.code(), Some(0), "{t}");
    // The totals whole, each case counted and passed over (a `Value` of
    // 200 000 entries would take over a GiB of the test's own memory).
    #[derive(serde::Deserialize)]
    struct Counted {
        totals: serde_json::Value,
        cases: Vec<serde::de::IgnoredAny>,
    }
    let file = std::fs::File::open(dir.join("out/report.json")).unwrap();
    let report: Counted = serde_json::from_reader(std::io::BufReader::new(file)).unwrap();
    assert_eq!(report.totals["cases"], n, "{t}");
    assert_eq!(report.cases.len(), n);
    assert_eq!(report.totals["verdicts"][0]["pass"], n);
    (measured, dir)
}

#[test]
fn peak_memory_grows_by_less_than_the_bound_per_case() {
    let (small, small_dir) = run(SMALL);
    let (large, large_dir) = run(LARGE);
    let growth =
        (large.peak_rss_kib as f64 - small.peak_rss_kib as f64) * 1024.0 / (LARGE - SMALL) as f64;
    eprintln!(
        "peak RSS: {:.1} MiB at {SMALL} cases, {:.1} MiB at {LARGE}: {growth:.0} bytes per case (bound {BOUND_BYTES})",
        small.peak_rss_mib(),
        large.peak_rss_mib()
    );
    assert!(
        growth < BOUND_BYTES,
        "the peak RSS grew by {growth:.0} bytes per case ({:.1} MiB at {SMALL} cases, {:.1} MiB at {LARGE}), over the bound of {BOUND_BYTES}",
        small.peak_rss_mib(),
        large.peak_rss_mib()
    );
    // Every result is in junit.xml; the index lists a bounded part and says so.
    let junit = std::fs::read_to_string(large_dir.join("out/junit.xml")).unwrap();
    assert_eq!(junit.matches("<testcase ").count(), LARGE);
    let index = std::fs::read_to_string(large_dir.join("out/index.html")).unwrap();
    assert!(index.contains(&format!("This page lists 2000 of the {LARGE} cases")));
    assert!(index.len() < 2_000_000, "{} bytes", index.len());
    // Nothing temporary left beside the report.
    let left: Vec<String> = std::fs::read_dir(large_dir.join("out"))
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.') && n != ".rastercheck-report")
        .collect();
    assert!(left.is_empty(), "{left:?}");
    let _ = std::fs::remove_dir_all(small_dir);
    let _ = std::fs::remove_dir_all(large_dir);
}
