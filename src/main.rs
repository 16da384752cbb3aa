//! The command line: parse arguments, call the library, map outcomes to exit
//! codes (SPEC.md §9: 0 everything judged passes; 1 something failed; 2
//! bad input or usage; 3 nothing was judged).
//! Every command's body, and its argument types, live in
//! `rastercheck::commands`.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

use rastercheck::commands::{
    self, baseline::BaselineCommand, bench::BenchArgs, bless::BlessArgs, diff::DiffArgs,
    docs::DocsArgs, fuzz::FuzzArgs, matrix::MatrixArgs, merge::MergeArgs, probe::ProbeArgs,
    run::RunArgs, show::ShowArgs, Exit,
};

/// The system allocator, counting only while `bench` measures a method's
/// peak heap (one relaxed atomic load per allocation otherwise).
#[global_allocator]
static ALLOCATOR: rastercheck::bench::memory::Counting = rastercheck::bench::memory::Counting;

#[derive(Parser)]
#[command(
    name = "rastercheck",
    version,
    about = "Conformance and accuracy tests for rasterizers, against an exact reference"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run cases through rasterizers and compare them with the exact reference.
    Run(RunArgs),
    /// Rewrite the golden reference files (reference/<case>.exr) from the oracle.
    Bless(BlessArgs),
    /// Write magnified PNGs of one case: reference, candidate and difference mask.
    Show(ShowArgs),
    /// List the rasterizers that can be named with --rasterizer.
    Rasterizers,
    /// Record accuracy metrics per case and rasterizer (`save`), or hold a
    /// run to them (`check`: exit 1 when a metric gets worse).
    #[command(subcommand)]
    Baseline(BaselineCommand),
    /// Search random and adversarial scenes for a failure of one rasterizer,
    /// shrink it to a minimal scene that fails the same check, and write it
    /// as a case file (exit 1 when one is found, 0 when none, 3 when every
    /// scene was unsupported).
    Fuzz(FuzzArgs),
    /// Run the cases through several rasterizers and print a conformance
    /// matrix (rows: rasterizers, columns: case families) with findings.
    Matrix(MatrixArgs),
    /// Time and error of each method on the same seeded workloads
    /// (triangles, lines, antialiasing, motion blur); writes BENCH.md and
    /// bench.svg beside it.
    Bench(BenchArgs),
    /// Find a rasterizer's conventions from its rendered frames: fill
    /// rule, y direction, subpixel precision, sample position, coverage
    /// encoding, clipping, interpolation error; write them as a profile for
    /// `run --profile`.
    Probe(ProbeArgs),
    /// Compare two reports (report.json, or report folders): newly failing,
    /// fixed, added and removed cases, metric deltas worst first; exit 1
    /// on a regression.
    Diff(DiffArgs),
    /// Merge reports (report.json, or report folders) from the shards of
    /// one run, or from the same cases on other rasterizers or machines,
    /// into one report folder; disagreeing reports exit 2.
    Merge(MergeArgs),
    /// Check (or with --write rewrite) the generated blocks of README.md
    /// and docs/: tables and figures taken from the code and the cases.
    Docs(DocsArgs),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            let exit = if e.use_stderr() {
                Exit::BadInput
            } else {
                Exit::Pass
            };
            return ExitCode::from(exit.code());
        }
    };
    // A signal kills the external programs a command started (each leads
    // a process group of its own) and ends it; `run` installs its own
    // handler, which stops the run and writes a partial report.
    rastercheck::stop::install_exiting();
    let exit = match cli.command {
        Command::Run(args) => commands::run::run(args),
        Command::Bless(args) => commands::bless::bless(args),
        Command::Show(args) => commands::show::show(args),
        Command::Baseline(command) => commands::baseline::baseline(command),
        Command::Fuzz(args) => commands::fuzz::fuzz(args),
        Command::Matrix(args) => commands::matrix::matrix(args),
        Command::Probe(args) => commands::probe::probe(args),
        Command::Bench(args) => commands::bench::bench(args),
        Command::Diff(args) => commands::diff::diff(args),
        Command::Merge(args) => commands::merge::merge(args),
        Command::Docs(args) => commands::docs::docs(args),
        Command::Rasterizers => commands::list_rasterizers(),
    };
    leave(exit.code())
}

/// Ends the process with `code` once everything is written, without the
/// C library's exit handlers. The driver adapters load Mesa's lavapipe
/// and llvmpipe GL into this process, each with LLVM, and their exit-time
/// destructors can crash when both were used ("double free or corruption"
/// after a complete `run -r vulkan -r gl`, seen on Mesa 22.3): that would
/// turn a finished run's exit code into 134. Every report file is closed
/// by now (the commands return after writing them); stdout and stderr are
/// flushed here.
fn leave(code: u8) -> ExitCode {
    use std::io::Write;
    let flushed = std::io::stdout().flush().is_ok() & std::io::stderr().flush().is_ok();
    #[cfg(unix)]
    if flushed {
        // SAFETY: _exit ends the process at once; nothing after it runs,
        // and nothing this process still holds needs a destructor (the OS
        // closes descriptors; the commands waited for their children).
        unsafe { libc::_exit(i32::from(code)) }
    }
    let _ = flushed;
    ExitCode::from(code)
}
