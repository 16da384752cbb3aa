//! `rastercheck show`: magnified PNGs of one case: the reference, the
//! candidate and the difference mask, with the colour key.

use super::console::outln;
use std::path::PathBuf;

use clap::Args;

use super::exit::Exit;
use super::limits::LimitArgs;
use super::names::rasterizer_named;
use crate::harness::judge::Verdict;
use crate::harness::{discover, judge, load, oracle};
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
    /// Magnification, 1 to 64 (default: about 512 pixels across). Lowered,
    /// with a note, so that no picture exceeds 2^26 pixels (8192 × 8192);
    /// a canvas larger than that is refused.
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
    let file = discover::case_file(&case);
    let scene = match load::load(&file, &limits) {
        Ok(scene) => scene,
        Err(e) => {
            eprintln!("error: {e}");
            return Exit::BadInput;
        }
    };
    let (w, h) = (
        u64::from(scene.canvas.width),
        u64::from(scene.canvas.height),
    );
    let Some(largest) = largest_scale(w, h) else {
        eprintln!(
            "error: {}: a {w}×{h} canvas is more than {MAX_PICTURE_PIXELS} pixels, the most a picture of `show` may have",
            case.display()
        );
        return Exit::BadInput;
    };
    let plan = crate::plan::Plan::for_scene(&scene);
    if let Some(over) = crate::harness::runner::over_memory(&scene, &plan, &limits, 1) {
        eprintln!("error: {}: {over}", case.display());
        return Exit::BadInput;
    }
    let reference = oracle::run_reference_planned(&scene, plan);
    let result = judge::run_candidate(&scene, &reference, candidate.as_ref());
    let (Some(frame), Some(metrics)) = (&result.frame, &result.metrics) else {
        eprintln!("{}: {}", candidate.name(), judge::describe(&result));
        return Exit::Fail;
    };
    let asked = scale.unwrap_or_else(|| png::auto_scale(frame)).clamp(1, 64);
    let scale = asked.min(largest);
    if scale < asked {
        eprintln!(
            "note: scale {asked} would make {}×{} pictures; scale {scale} instead (at most {MAX_PICTURE_PIXELS} pixels a picture)",
            w * u64::from(asked),
            h * u64::from(asked)
        );
    }
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
                outln!("wrote {}", p.display());
            }
            // A foil's failure is a departure, labelled as `run` labels it.
            let label = match result.verdict {
                Verdict::Fail(_) if candidate.is_foil() => "FOIL",
                _ => result.verdict.label(),
            };
            outln!(
                "{} {}: {}",
                label,
                candidate.name(),
                judge::describe(&result)
            );
            outln!("key: magenta = missing, red = extra, yellow = wrong owner, grey = covered alike; cyan = snapped edges");
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

/// The most pixels one picture of `show` may have: 2^26 (8192 × 8192, 192
/// MiB of RGB), whatever `--scale` asks.
pub const MAX_PICTURE_PIXELS: u64 = 1 << 26;

/// The largest magnification (at most 64) whose pictures of a `w`×`h`
/// canvas stay within [`MAX_PICTURE_PIXELS`]; `None` when even 1 does not.
fn largest_scale(w: u64, h: u64) -> Option<u32> {
    (1..=64u32)
        .rev()
        .find(|&s| w * h * u64::from(s) * u64::from(s) <= MAX_PICTURE_PIXELS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pictures_stay_within_the_bound() {
        assert_eq!(largest_scale(8, 8), Some(64));
        assert_eq!(largest_scale(4096, 4096), Some(2));
        assert_eq!(largest_scale(8192, 8192), Some(1));
        assert_eq!(largest_scale(8193, 8192), None);
    }
}
