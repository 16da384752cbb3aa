//! A conservative case in the report (SPEC.md §19): one picture of the
//! reference's three classes with the candidate's pixels on them, and its
//! colour key.

use std::path::{Path, PathBuf};

use super::png::{picture, save_all, EXTRA, MISSING};
use crate::metrics::conservative::{ConservativeMetrics, ConservativePixel};
use crate::scene::Scene;

/// Required and drawn.
pub const REQUIRED_DRAWN: [u8; 3] = [235, 235, 235];
/// In the allowed band and drawn: the uncertainty used.
pub const BAND_DRAWN: [u8; 3] = [255, 190, 0];
/// In the allowed band and not drawn.
pub const BAND_EMPTY: [u8; 3] = [95, 75, 20];
/// Forbidden and not drawn.
pub const FORBIDDEN_EMPTY: [u8; 3] = [0, 0, 0];

/// The colour of one pixel.
pub fn colour(pixel: ConservativePixel) -> [u8; 3] {
    match pixel {
        ConservativePixel::RequiredDrawn => REQUIRED_DRAWN,
        ConservativePixel::RequiredMissing => MISSING,
        ConservativePixel::BandDrawn => BAND_DRAWN,
        ConservativePixel::BandEmpty => BAND_EMPTY,
        ConservativePixel::ForbiddenDrawn => EXTRA,
        ConservativePixel::ForbiddenEmpty => FORBIDDEN_EMPTY,
    }
}

/// The picture's colour key, in words.
pub const KEY: [([u8; 3], &str); 6] = [
    (REQUIRED_DRAWN, "required, drawn"),
    (MISSING, "required, not drawn (fails)"),
    (BAND_DRAWN, "drawn in the allowed band"),
    (BAND_EMPTY, "allowed band, not drawn"),
    (EXTRA, "forbidden, drawn (fails)"),
    (FORBIDDEN_EMPTY, "forbidden, not drawn"),
];

/// The name of a candidate's picture, beside its other pictures.
pub fn file_name(candidate: &str) -> String {
    format!("{}.conservative.png", candidate.replace([':', '/'], "-"))
}

/// Writes `<candidate>.conservative.png` into `dir`: every pixel in the
/// colour of its class and whether the candidate drew it, with the snapped
/// outlines.
pub fn write_picture(
    scene: &Scene,
    candidate: &str,
    m: &ConservativeMetrics,
    dir: &Path,
    scale: u32,
) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let image = picture(scene, scale, |i| {
        m.pixels.get(i).copied().map_or(FORBIDDEN_EMPTY, colour)
    });
    save_all(dir, [(file_name(candidate), image)])
}
