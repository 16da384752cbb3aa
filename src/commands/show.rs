//! `rastercheck show`: magnified PNGs of one case: the reference, the
//! candidate and the difference mask, with the colour key.

use std::path::PathBuf;

use clap::Args;

use super::{rasterizer_named, Exit, LimitArgs};
use crate::harness::suite::{self, Verdict};
use crate::report::png;

/// The arguments of `show`.
#[derive(Args)]
pub struct ShowArgs {
    /// The case file.
    pub case: PathBuf,
    /// Folder for the images.
    #[arg(long)]
    pub out: PathBuf,
    /// The candidate rasterizer (default: production).
    #[arg(long = "rasterizer", short = 'r', default_value = "production")]
    pub rasterizer: String,
    /// Magnification (default: about 512 pixels across).
    #[arg(long)]
    pub scale: Option<u32>,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// `rastercheck show`: magnified pictures of one case.
pub fn show(args: ShowArgs) -> Exit {
    let ShowArgs {
        case,
        out,
        rasterizer,
        scale,
        limits,
    } = args;
    let (name, limits) = (rasterizer.as_str(), limits.limits());
    let candidate = match rasterizer_named(name) {
        Ok(candidate) => candidate,
        Err(exit) => return exit,
    };
    let file = suite::case_file(&case);
    let scene = match suite::load(&file, &limits) {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    let reference = suite::run_reference(&scene);
    let result = suite::run_candidate(&scene, &reference, candidate.as_ref());
    let (Some(frame), Some(metrics)) = (&result.frame, &result.metrics) else {
        eprintln!("{}: {}", candidate.name(), suite::describe(&result));
        return Exit::Fail;
    };
    let scale = scale.unwrap_or_else(|| png::auto_scale(frame)).clamp(1, 64);
    match png::write_comparison(
        &scene,
        &reference.frame,
        candidate.name(),
        frame,
        &metrics.coverage.mask,
        &out,
        scale,
    ) {
        Ok(paths) => {
            for p in paths {
                println!("wrote {}", p.display());
            }
            println!(
                "{} {}: {}",
                result.verdict.label(),
                candidate.name(),
                suite::describe(&result)
            );
            println!("key: magenta = missing, red = extra, yellow = wrong owner, grey = covered alike; cyan = snapped edges");
            if matches!(result.verdict, Verdict::Pass) {
                Exit::Pass
            } else {
                Exit::Fail
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            Exit::BadInput
        }
    }
}
