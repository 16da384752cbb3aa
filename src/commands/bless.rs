//! `rastercheck bless`: the oracle draws every case and its golden file
//! (`reference/<case id>.exr`) is written anew. CI never blesses.

use super::console::outln;
use std::path::PathBuf;

use clap::Args;

use super::cases::discover;
use super::exit::Exit;
use super::limits::LimitArgs;
use crate::harness::{discover, golden, load, oracle};

/// The arguments of `bless`.
#[derive(Args)]
pub struct BlessArgs {
    /// Case files or folders (default: cases).
    pub paths: Vec<PathBuf>,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// `rastercheck bless`: rewrite the golden files from the oracle.
pub fn bless(args: BlessArgs) -> Exit {
    let limits = args.limits.limits();
    let paths = args.paths;
    let (found, mut bad_input) = discover(paths);
    let root = PathBuf::from(".");
    let mut written = 0;
    for file in &found.cases {
        let scene = match load::load(file, &limits) {
            Ok(scene) => scene,
            Err(e) => {
                eprintln!("error: {e}");
                bad_input = true;
                continue;
            }
        };
        let plan = crate::plan::Plan::for_scene(&scene);
        if let Some(over) = crate::harness::runner::over_memory(&scene, &plan, &limits, 0) {
            eprintln!("error: {}: {over}", file.path.display());
            bad_input = true;
            continue;
        }
        let reference = match crate::deadline::within(limits.case_timeout, || {
            oracle::run_reference_planned(&scene, plan)
        }) {
            Ok(reference) => reference,
            Err(exceeded) => {
                eprintln!("error: {}: the reference {exceeded}", file.path.display());
                bad_input = true;
                continue;
            }
        };
        let path = golden::path_for(&discover::golden_root(&file.path, &root), &file.id);
        match golden::write(&reference.frame, &path) {
            Ok(()) => written += 1,
            Err(e) => {
                eprintln!("error: {e}");
                bad_input = true;
            }
        }
    }
    outln!("blessed {written} golden files under reference/");
    if bad_input {
        Exit::BadInput
    } else {
        Exit::Pass
    }
}
