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
//!   another primitive: the sample went to the other side of a shared edge),
//!   green = an accepted tie (a candidate with no tie rule, `fill_rule:
//!   "none"`, took a sample exactly on an edge by a choice of sides, SPEC.md
//!   §3.1.1: counted on the card's ties line, not a mismatch);
//! - every image: thin dark lines at pixel borders, and the snapped
//!   triangle outlines in cyan, drawn from f64 (display only).
//!
//! Antialiased cases (SPEC.md §14) are pictured by their resolved coverage:
//! - reference and candidate: grey levels, black = 0, white = 1 (the exact
//!   area, and the candidate's resolved value), orange above 1 (overlap);
//! - `.diff.png`: the signed coverage error, candidate − exact: black = 0,
//!   red = too much coverage, blue = too little, full colour at the largest
//!   |error| of the picture (at least 2^-20, so rounding noise stays dark);
//! - `.samples.png`, for a candidate whose samples differ from the
//!   reference's (on canvases up to 128 pixels a side): every sample as a
//!   dot at its position in the magnified pixel, coloured as in the
//!   difference mask (white = covered alike, dark grey = empty in both),
//!   over the exact area in dim grey.
//!
//! Scenes in which something moves (SPEC.md §15.4) are pictured the same
//! way by their time coverage per pixel: the exact time coverage and the
//! candidate's in grey, and the signed error. Their outlines are drawn
//! twice: where the primitives are at shutter open (cyan) and at shutter
//! close (lime).

use std::path::{Path, PathBuf};

use image::{Rgb, RgbImage};

use crate::frame::Frame;
use crate::metrics::{antialias, SampleDiff};
use crate::scene::Scene;

pub const MISSING: [u8; 3] = [255, 0, 255];
pub const EXTRA: [u8; 3] = [255, 0, 0];
pub const WRONG_OWNER: [u8; 3] = [255, 220, 0];
pub const SAME_COVERED: [u8; 3] = [110, 110, 110];
/// A tie sample decided by a choice of sides, accepted for a candidate with
/// no tie rule (SPEC.md §3.1.1): green, neither a mismatch nor alike.
pub const TIE_ACCEPTED: [u8; 3] = [0, 190, 90];
const EDGE: [u8; 3] = [0, 200, 255];
/// Edges of moving primitives at shutter close.
pub const EDGE_AT_CLOSE: [u8; 3] = [180, 255, 0];
const GRID: [u8; 3] = [40, 40, 40];
/// Resolved coverage above 1 (primitives overlap).
pub const OVER_ONE: [u8; 3] = [255, 150, 0];
/// Signed coverage error: too much, too little (full strength).
pub const TOO_MUCH: [u8; 3] = [255, 40, 40];
pub const TOO_LITTLE: [u8; 3] = [40, 120, 255];
/// A sample both leave empty, in the samples picture.
pub const SAMPLE_EMPTY: [u8; 3] = [70, 70, 70];
/// A sample both cover alike, in the samples picture.
pub const SAMPLE_SAME: [u8; 3] = [235, 235, 235];
/// The smallest full-strength error of a signed error map.
pub const MIN_ERROR_SCALE: f64 = 1.0 / 1048576.0;

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
        SampleDiff::Tie => TIE_ACCEPTED,
    }
}

/// The grey level of a resolved coverage value; orange above 1.
pub fn resolved_colour(v: f64) -> [u8; 3] {
    if v > 1.0 {
        OVER_ONE
    } else {
        let g = (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        [g, g, g]
    }
}

/// The colour of a signed error at full strength `scale`: black for 0,
/// red for positive, blue for negative.
pub fn signed_colour(error: f64, scale: f64) -> [u8; 3] {
    let t = if error.is_nan() {
        1.0
    } else {
        (error.abs() / scale).clamp(0.0, 1.0)
    };
    let end = if error < 0.0 { TOO_LITTLE } else { TOO_MUCH };
    end.map(|c| (f64::from(c) * t).round() as u8)
}

/// The full-strength error of a signed map: its largest |error|, at least
/// [`MIN_ERROR_SCALE`].
pub fn error_scale(errors: &[f64]) -> f64 {
    errors
        .iter()
        .map(|e| if e.is_finite() { e.abs() } else { 0.0 })
        .fold(MIN_ERROR_SCALE, f64::max)
}

/// A frame's coverage per pixel: its time coverage (a moving scene), its
/// resolved value, or the box resolve of its samples when it has neither.
pub fn resolved_of(frame: &Frame) -> Vec<f64> {
    match (&frame.time, &frame.resolved) {
        (Some(t), _) if t.len() == frame.pixel_count() => t.clone(),
        (_, Some(r)) if r.len() == frame.pixel_count() => r.clone(),
        _ if frame.samples > 0 && frame.sample_count() > 0 => frame.box_resolve(),
        _ => vec![0.0; frame.pixel_count()],
    }
}

/// Whether a frame is pictured by its resolved coverage: it antialiases,
/// holds other than one sample per pixel, or holds time coverage.
pub fn pictured_resolved(frame: &Frame) -> bool {
    frame.resolved.is_some() || frame.samples != 1 || frame.time.is_some()
}

/// The resolved coverage as grey levels, magnified.
pub fn resolved_picture(scene: &Scene, values: &[f64], scale: u32) -> RgbImage {
    picture(scene, scale, |i| {
        resolved_colour(values.get(i).copied().unwrap_or(0.0))
    })
}

/// The signed coverage error, magnified, full strength at `full`.
pub fn error_picture(scene: &Scene, errors: &[f64], full: f64, scale: u32) -> RgbImage {
    picture(scene, scale, |i| {
        signed_colour(errors.get(i).copied().unwrap_or(0.0), full)
    })
}

/// The largest canvas side that gets a samples picture: at 8 times
/// magnification, 1024 pixels across. Beyond it the dots of a pixel blur
/// together and the picture costs megabytes.
pub const SAMPLES_MAX_SIDE: u32 = 128;

/// The samples picture's least magnification, so that the dots of one
/// pixel are apart.
pub const SAMPLES_MIN_SCALE: u32 = 8;

/// Every sample as a dot at its offset in the magnified pixel, coloured by
/// how it differs from the reference, over the reference's resolved
/// coverage (dimmed). `None` when no sample differs (the picture would show
/// nothing the others do not), the canvas is wider or taller than
/// [`SAMPLES_MAX_SIDE`], the scene has no sample pattern, or the mask does
/// not hold one entry per sample.
pub fn samples_picture(
    scene: &Scene,
    reference: &Frame,
    mask: &[SampleDiff],
    scale: u32,
) -> Option<RgbImage> {
    let aa = scene.effects.antialias.as_ref()?;
    let offsets = aa.offsets();
    let n = offsets.len();
    if n == 0
        || reference.samples as usize != n
        || mask.len() != reference.sample_count()
        || reference.width.max(reference.height) > SAMPLES_MAX_SIDE
        || mask.iter().all(|d| *d == SampleDiff::Same)
    {
        return None;
    }
    let exact = resolved_of(reference);
    let mut img = picture(scene, scale, |i| {
        resolved_colour(exact[i]).map(|c| (u16::from(c) * 2 / 5) as u8)
    });
    let lattice = f64::from(1u32 << aa.position_bits);
    // Dots about a third of the samples' mean spacing across; samples that
    // differ one pixel larger all round, so that they stand out.
    let spacing = f64::from(scale) / (n as f64).sqrt();
    let radius = ((spacing / 3.0 - 1.0) / 2.0).round().max(0.0) as i64;
    let (w, h) = (i64::from(img.width()), i64::from(img.height()));
    for (slot, diff) in mask.iter().enumerate() {
        let (pixel, s) = (slot / n, slot % n);
        let (x, y) = (
            pixel as u32 % scene.canvas.width,
            pixel as u32 / scene.canvas.width,
        );
        let [ox, oy] = offsets[s];
        let cx = ((f64::from(x) + f64::from(ox) / lattice) * f64::from(scale)) as i64;
        let cy = ((f64::from(y) + f64::from(oy) / lattice) * f64::from(scale)) as i64;
        let (colour, r) = match diff {
            SampleDiff::Same if reference.coverage[slot] > 0 => (SAMPLE_SAME, radius),
            SampleDiff::Same => (SAMPLE_EMPTY, radius),
            other => (diff_colour(*other, true), radius + 1),
        };
        for dy in -r..=r {
            for dx in -r..=r {
                let (px, py) = (cx + dx, cy + dy);
                if (0..w).contains(&px) && (0..h).contains(&py) {
                    img.put_pixel(px as u32, py as u32, Rgb(colour));
                }
            }
        }
    }
    Some(img)
}

/// Paints one colour per pixel, magnified, with grid lines and outlines.
pub(super) fn picture(scene: &Scene, scale: u32, colour: impl Fn(usize) -> [u8; 3]) -> RgbImage {
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

/// Draws the primitives' snapped edges (a line's centre line); a moving
/// primitive's at shutter close too, in [`EDGE_AT_CLOSE`] (where it is at
/// τ = 1: the shutter's ends are drawn only as far as τ = 0 and 1).
fn outline(scene: &Scene, scale: u32, img: &mut RgbImage) {
    let grid = scene.rules.subpixel_bits.map(|b| f64::from(1u32 << b));
    let snap = |v: f64| grid.map_or(v, |g| (v * g).round_ties_even() / g);
    let s = f64::from(scale);
    let moving = scene.effects.motion_blur.is_some();
    for primitive in &scene.primitives {
        let open: Vec<(f64, f64)> = primitive
            .vertices()
            .iter()
            .map(|v| (snap(v.x.to_f64_lossy()) * s, snap(v.y.to_f64_lossy()) * s))
            .collect();
        if moving && primitive.moves() {
            let close: Vec<(f64, f64)> = primitive
                .vertices()
                .iter()
                .map(|v| {
                    let [x, y] = v.end();
                    (snap(x.to_f64_lossy()) * s, snap(y.to_f64_lossy()) * s)
                })
                .collect();
            polyline(&close, EDGE_AT_CLOSE, img);
        }
        polyline(&open, EDGE, img);
    }
}

/// A closed outline through `p` (a segment for two points).
fn polyline(p: &[(f64, f64)], colour: [u8; 3], img: &mut RgbImage) {
    let edges = if p.len() == 2 { 1 } else { p.len() };
    for i in 0..edges {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        let steps = ((b.0 - a.0).abs().max((b.1 - a.1).abs()).ceil() as usize).clamp(1, 1 << 20);
        for k in 0..=steps {
            let f = k as f64 / steps as f64;
            let (x, y) = (a.0 + (b.0 - a.0) * f, a.1 + (b.1 - a.1) * f);
            if x >= 0.0 && y >= 0.0 && (x as u32) < img.width() && (y as u32) < img.height() {
                img.put_pixel(x as u32, y as u32, Rgb(colour));
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
    if pictured_resolved(reference) {
        return write_resolved_comparison(
            scene, reference, &file_name, candidate, mask, dir, scale,
        );
    }
    let has_mask = mask.len() == reference.sample_count()
        && candidate.sample_count() == reference.sample_count();
    let covered = |frame: &Frame, i: usize| frame.coverage.get(i).copied().unwrap_or(0);
    let images = [
        (
            "reference.png".to_owned(),
            picture(scene, scale, |i| coverage_colour(covered(reference, i))),
        ),
        (
            format!("{file_name}.png"),
            picture(scene, scale, |i| coverage_colour(covered(candidate, i))),
        ),
        (
            format!("{file_name}.diff.png"),
            picture(scene, scale, |i| {
                let diff = if has_mask { mask[i] } else { SampleDiff::Same };
                diff_colour(diff, reference.coverage[i] > 0)
            }),
        ),
    ];
    save_all(dir, images)
}

/// The pictures of an antialiased case: resolved coverage of the reference
/// and the candidate, the signed error, and (for a candidate with samples)
/// the samples picture.
fn write_resolved_comparison(
    scene: &Scene,
    reference: &Frame,
    file_name: &str,
    candidate: &Frame,
    mask: &[SampleDiff],
    dir: &Path,
    scale: u32,
) -> Result<Vec<PathBuf>, String> {
    let (exact, resolved) = (resolved_of(reference), resolved_of(candidate));
    let errors: Vec<f64> = resolved.iter().zip(&exact).map(|(r, e)| r - e).collect();
    let errors = if errors.len() == reference.pixel_count() {
        errors
    } else if reference.time.is_some() {
        crate::metrics::time::signed_errors(reference, candidate)
    } else {
        antialias::signed_errors(reference, candidate)
    };
    let mut images = vec![
        (
            "reference.png".to_owned(),
            resolved_picture(scene, &exact, scale),
        ),
        (
            format!("{file_name}.png"),
            resolved_picture(scene, &resolved, scale),
        ),
        (
            format!("{file_name}.diff.png"),
            error_picture(scene, &errors, error_scale(&errors), scale),
        ),
    ];
    if let Some(img) = samples_picture(scene, reference, mask, scale.max(SAMPLES_MIN_SCALE)) {
        images.push((format!("{file_name}.samples.png"), img));
    }
    save_all(dir, images)
}

pub(super) fn save_all(
    dir: &Path,
    images: impl IntoIterator<Item = (String, RgbImage)>,
) -> Result<Vec<PathBuf>, String> {
    let mut written = Vec::new();
    for (name, img) in images {
        let path = dir.join(name);
        let mut bytes = Vec::new();
        img.write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(super::files::write_file(&path, &bytes)?);
    }
    Ok(written)
}
