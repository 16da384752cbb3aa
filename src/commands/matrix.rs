//! `rastercheck matrix`: every case through several rasterizers, printed as
//! a conformance matrix with findings (rows: rasterizers, columns: case
//! families), and optionally written into a README between its markers.

use super::console::{out, outln};
use std::path::PathBuf;

use clap::Args;

use super::cases::discover;
use super::exit::Exit;
use super::limits::LimitArgs;
use super::names::unknown_rasterizer;
use crate::explore::matrix;
use crate::harness::today::today;
use crate::registry;

#[derive(Args)]
pub struct MatrixArgs {
    /// Case files or folders (default: cases).
    pub paths: Vec<PathBuf>,
    /// Row; repeat for several (default: the registry's matrix rows:
    /// production, the foils, tiny-skia, euc, the Python example and the
    /// drivers, whether or not compiled in).
    #[arg(long = "rasterizer", short = 'r')]
    pub rasterizers: Vec<String>,
    /// Replace the text between `<!-- matrix:begin -->` and
    /// `<!-- matrix:end -->` in this file with the matrix.
    #[arg(long, value_name = "FILE")]
    pub write_readme: Option<PathBuf>,
    /// Worker threads, at most 256 (default, or 0: one per core).
    /// Results do not depend on it.
    #[arg(long, value_parser = super::values::threads)]
    pub threads: Option<usize>,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// `rastercheck matrix`: the conformance matrix, printed and optionally
/// written into a README.
pub fn matrix(args: MatrixArgs) -> Exit {
    let names = if args.rasterizers.is_empty() {
        registry::matrix_default_rows()
    } else {
        args.rasterizers
    };
    if let Err(exit) = super::names::check_names(&names) {
        return exit;
    }
    if let Some(name) = names.iter().find(|n| matrix::rasterizer(n).is_none()) {
        eprintln!("error: {}", unknown_rasterizer(name));
        return Exit::BadInput;
    }
    for name in &names {
        if let Err(exit) = super::names::environment_for(name) {
            return exit;
        }
    }
    let (found, bad_input) = discover(args.paths);
    if found.cases.is_empty() {
        if bad_input {
            eprintln!("error: no case files found");
            return Exit::BadInput;
        }
        eprintln!("error: no case files found; nothing was judged");
        return Exit::NothingJudged;
    }
    let m = matrix::build(&found.cases, &args.limits.limits(), &names, args.threads);
    out!("{}", m.to_markdown());
    if m.unreadable > 0 {
        eprintln!(
            "error: {} case files could not be read (run `rastercheck run` to see why)",
            m.unreadable
        );
    }
    if let Some(file) = &args.write_readme {
        let written = std::fs::read_to_string(file)
            .map_err(|e| e.to_string())
            .and_then(|text| {
                matrix::replace_block(
                    &text,
                    &m.readme_block(&today(), &file.display().to_string()),
                )
            })
            .and_then(|text| std::fs::write(file, text).map_err(|e| e.to_string()));
        match written {
            Ok(()) => outln!("\nwrote the matrix into {}", file.display()),
            Err(e) => {
                eprintln!("error: {}: {e}", file.display());
                return Exit::BadInput;
            }
        }
    }
    // Judged: some cell drew a case and got a verdict other than unsupported.
    let judged = m
        .rows
        .iter()
        .flat_map(|r| &r.cells)
        .any(|c| c.pass + c.fail + c.departures + c.error > 0);
    if bad_input || m.unreadable > 0 {
        Exit::BadInput
    } else if !judged {
        eprintln!("error: nothing was judged: every case is unsupported by every rasterizer");
        Exit::NothingJudged
    } else {
        Exit::Pass
    }
}
