//! `rastercheck matrix`: every case through several rasterizers, printed as
//! a conformance matrix with findings (rows: rasterizers, columns: case
//! families), and optionally written into a README between its markers.

use std::path::PathBuf;

use clap::Args;

use super::{discover, unknown_rasterizer, Exit, LimitArgs};
use crate::harness::matrix;

#[derive(Args)]
pub struct MatrixArgs {
    /// Case files or folders (default: cases).
    pub paths: Vec<PathBuf>,
    /// Row; repeat for several (default: production, the foils, tiny-skia,
    /// euc, the Python example and lavapipe).
    #[arg(long = "rasterizer", short = 'r')]
    pub rasterizers: Vec<String>,
    /// Replace the text between `<!-- matrix:begin -->` and
    /// `<!-- matrix:end -->` in this file with the matrix.
    #[arg(long, value_name = "FILE")]
    pub write_readme: Option<PathBuf>,
    /// Worker threads (default: one per core). Results do not depend on it.
    #[arg(long)]
    pub threads: Option<usize>,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// `rastercheck matrix`: the conformance matrix, printed and optionally
/// written into a README.
pub fn matrix(args: MatrixArgs) -> Exit {
    let names = if args.rasterizers.is_empty() {
        matrix::default_rows()
    } else {
        args.rasterizers
    };
    if let Some(name) = names.iter().find(|n| matrix::rasterizer(n).is_none()) {
        eprintln!("error: {}", unknown_rasterizer(name));
        return Exit::BadInput;
    }
    let (found, bad_input) = discover(args.paths);
    if found.cases.is_empty() {
        eprintln!("error: no case files found");
        return Exit::BadInput;
    }
    let m = matrix::build(&found.cases, &args.limits.limits(), &names, args.threads);
    print!("{}", m.to_markdown());
    if m.unreadable > 0 {
        eprintln!(
            "error: {} case files could not be read (run `rastercheck run` to see why)",
            m.unreadable
        );
    }
    if let Some(file) = &args.write_readme {
        let written = std::fs::read_to_string(file)
            .map_err(|e| e.to_string())
            .and_then(|text| matrix::replace_block(&text, &m.readme_block(&matrix::today())))
            .and_then(|text| std::fs::write(file, text).map_err(|e| e.to_string()));
        match written {
            Ok(()) => println!("\nwrote the matrix into {}", file.display()),
            Err(e) => {
                eprintln!("error: {}: {e}", file.display());
                return Exit::BadInput;
            }
        }
    }
    if bad_input || m.unreadable > 0 {
        Exit::BadInput
    } else {
        Exit::Pass
    }
}
