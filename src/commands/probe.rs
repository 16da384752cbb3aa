//! `rastercheck probe`: find a rasterizer's conventions from its frames and
//! write them as a profile for `run --profile`.

use super::console::{out, outln};
use std::path::PathBuf;

use clap::Args;

use super::exit::Exit;
use super::names::rasterizer_named;

/// The arguments of `probe`.
#[derive(Args)]
pub struct ProbeArgs {
    /// The rasterizer to probe.
    #[arg(long = "rasterizer", short = 'r')]
    pub rasterizer: String,
    /// Write the profile (schema rastercheck-profile/1) to this file.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// `rastercheck probe`: a rasterizer's conventions, printed and optionally
/// written as a profile.
pub fn probe(args: ProbeArgs) -> Exit {
    let ProbeArgs { rasterizer, out } = args;
    let name = rasterizer.as_str();
    let candidate = match rasterizer_named(name) {
        Ok(candidate) => candidate,
        Err(exit) => return exit,
    };
    let profile = match crate::explore::probe::probe(candidate.as_ref()) {
        Ok(p) => p,
        // It could draw none of the probe scenes (a program that cannot
        // start, say): bad input, with the reason.
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    out!("{}", profile.describe());
    if let Some(file) = out {
        if let Err(e) = std::fs::write(&file, profile.to_json()) {
            eprintln!("error: {}: {e}", file.display());
            return Exit::BadInput;
        }
        outln!("wrote {}", file.display());
    }
    Exit::Pass
}
