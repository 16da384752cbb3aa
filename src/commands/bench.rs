//! `rastercheck bench`: every method timed on the same seeded workloads and
//! scored against the reference; writes BENCH.md and bench.svg beside it
//! (`--quick`: under out/bench/ unless `--out` says where).

use super::console::outln;
use std::path::PathBuf;

use clap::Args;

use super::exit::Exit;
use crate::bench;

/// The arguments of `bench`.
#[derive(Args)]
pub struct BenchArgs {
    /// Small workloads that run in a few seconds.
    #[arg(long)]
    pub quick: bool,
    /// The report to write; the chart goes beside it as bench.svg. Default:
    /// BENCH.md here, or out/bench/BENCH.md with --quick.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// `rastercheck bench`: time and error of every method; BENCH.md and the
/// chart.
pub fn bench(args: BenchArgs) -> Exit {
    let BenchArgs { quick, out } = args;
    let out = match bench::prepare_report_path(quick, out) {
        Ok(out) => out,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    if let Err(e) = bench::check_out_path(&out) {
        eprintln!("error: {}: {e}", out.display());
        return Exit::BadInput;
    }
    let report = bench::run(bench::Options { quick }, &mut |line| {
        outln!("bench: {line}")
    });
    let svg = out.with_file_name("bench.svg");
    let written = std::fs::write(&out, report.to_markdown("bench.svg"))
        .and_then(|()| std::fs::write(&svg, report.to_svg()));
    if let Err(e) = written {
        eprintln!("error: {}: {e}", out.display());
        return Exit::BadInput;
    }
    for w in &report.workloads {
        outln!("{}", w.name);
        for m in &w.methods {
            let time = m.per_item.map_or("—".to_owned(), |d| {
                format!("{:.3} µs", d.as_secs_f64() * 1e6)
            });
            let error = m
                .errors
                .map_or("—".to_owned(), |(e, of)| format!("{e}/{of}"));
            let heap = m
                .peak_heap
                .map_or("—".to_owned(), bench::memory::bytes_text);
            outln!(
                "  {:<12} {time:>14} per item, error {error}, peak heap {heap}",
                m.method
            );
        }
    }
    for t in &report.targets {
        let status = match t.met {
            Some(true) => "met",
            Some(false) => "NOT met",
            None => "not measured",
        };
        outln!("target: {}: {} ({status})", t.target, t.measured);
    }
    outln!("wrote {} and {}", out.display(), svg.display());
    Exit::Pass
}
