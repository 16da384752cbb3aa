//! Magnified PNG pictures of a case: the reference, a candidate, and the
//! difference mask.
//!
//! Colour key (also in README.md):
//! - coverage images: black = not covered, white = covered once,
//!   orange = covered twice, red = three times or more;
//! - difference mask: black = empty in both, grey = covered alike,
//!   magenta = missing (the reference covers it, the candidate does not;
//!   VK-GL-CTS marks missing pixels in purple), red = extra (the candidate
//!   covers it more often), yellow = wrong owner (covered as often, but by
//!   another primitive: the sample went to the other side of a shared edge);
//! - every image: thin dark lines at pixel borders, and the snapped
//!   triangle outlines in cyan, drawn from f64 (display only).

use std::path::{Path, PathBuf};

use image::{Rgb, RgbImage};

use crate::frame::Frame;
use crate::metrics::SampleDiff;
use crate::scene::Scene;

pub const MISSING: [u8; 3] = [255, 0, 255];
pub const EXTRA: [u8; 3] = [255, 0, 0];
pub const WRONG_OWNER: [u8; 3] = [255, 220, 0];
pub const SAME_COVERED: [u8; 3] = [110, 110, 110];
const EDGE: [u8; 3] = [0, 200, 255];
const GRID: [u8; 3] = [40, 40, 40];

/// A magnification that makes the picture about 512 pixels across, so that
/// single pixels are easy to see (1 to 32).
pub fn auto_scale(frame: &Frame) -> u32 {
    (512 / frame.width.max(frame.height)).clamp(1, 32)
}

fn coverage_colour(count: u16) -> [u8; 3] {
    match count {
        0 => [0, 0, 0],
        1 => [255, 255, 255],
        2 => [255, 150, 0],
        _ => [255, 0, 0],
    }
}

fn diff_colour(diff: SampleDiff, covered: bool) -> [u8; 3] {
    match diff {
        SampleDiff::Same if covered => SAME_COVERED,
        SampleDiff::Same => [0, 0, 0],
        SampleDiff::Missing => MISSING,
        SampleDiff::Extra => EXTRA,
        SampleDiff::WrongOwner => WRONG_OWNER,
    }
}

/// Paints one colour per pixel, magnified, with grid lines and outlines.
fn picture(scene: &Scene, scale: u32, colour: impl Fn(usize) -> [u8; 3]) -> RgbImage {
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut img = RgbImage::new(w * scale, h * scale);
    for (px, py, out) in img.enumerate_pixels_mut() {
        let (x, y) = (px / scale, py / scale);
        let on_grid = scale >= 4 && (px % scale == 0 || py % scale == 0);
        *out = Rgb(if on_grid {
            GRID
        } else {
            colour((y * w + x) as usize)
        });
    }
    outline(scene, scale, &mut img);
    img
}

/// Draws the primitives' snapped edges (a line's centre line).
fn outline(scene: &Scene, scale: u32, img: &mut RgbImage) {
    let grid = scene.rules.subpixel_bits.map(|b| f64::from(1u32 << b));
    let snap = |v: f64| grid.map_or(v, |g| (v * g).round_ties_even() / g);
    let s = f64::from(scale);
    for primitive in &scene.primitives {
        let p: Vec<(f64, f64)> = primitive
            .vertices()
            .iter()
            .map(|v| (snap(v.x.to_f64_lossy()) * s, snap(v.y.to_f64_lossy()) * s))
            .collect();
        let edges = if p.len() == 2 { 1 } else { p.len() };
        for i in 0..edges {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            let steps =
                ((b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil() as usize).clamp(1, 1 << 20);
            for k in 0..=steps {
                let f = k as f64 / steps as f64;
                let (x, y) = (a.0 + (b.0 - a.0) * f, a.1 + (b.1 - a.1) * f);
                if x >= 0.0 && y >= 0.0 && (x as u32) < img.width() && (y as u32) < img.height() {
                    img.put_pixel(x as u32, y as u32, Rgb(EDGE));
                }
            }
        }
    }
}

/// Writes `reference.png`, `<candidate>.png` and `<candidate>.diff.png`
/// into `dir` (`:` and `/` in the name become `-`), so that the results of
/// several candidates on one case sit side by side. Returns the paths.
pub fn write_comparison(
    scene: &Scene,
    reference: &Frame,
    candidate_name: &str,
    candidate: &Frame,
    mask: &[SampleDiff],
    dir: &Path,
    scale: u32,
) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let file_name = candidate_name.replace([':', '/'], "-");
    let images = [
        (
            "reference.png".to_owned(),
            picture(scene, scale, |i| coverage_colour(reference.coverage[i])),
        ),
        (
            format!("{file_name}.png"),
            picture(scene, scale, |i| coverage_colour(candidate.coverage[i])),
        ),
        (
            format!("{file_name}.diff.png"),
            picture(scene, scale, |i| {
                diff_colour(mask[i], reference.coverage[i] > 0)
            }),
        ),
    ];
    let mut written = Vec::new();
    for (name, img) in images {
        let path = dir.join(name);
        img.save(&path)
            .map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(path);
    }
    Ok(written)
}
