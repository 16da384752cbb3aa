//! The sampler decision, made before every other probe: is coverage decided
//! at one point per pixel (`point`: the fill-rule, subpixel and
//! sample-position probes apply), by how much of the pixel a primitive
//! covers (`area`), or by whether it touches the pixel at all
//! (`any-coverage`, conservative rasterization)? The other probes assume a
//! point sampler; run on anything else they invent a rule and a precision
//! (an area rasterizer reads as "6 subpixel bits"), so they are not run.
//!
//! Three scenes separate the kinds exactly, by where they put area and
//! where they put sample points:
//!
//! - **Slivers.** Four thin triangles (2/32 px thick), each inside its own
//!   pixel, along the four sides of the square and pairwise disjoint in
//!   pixel-relative position. None holds a point of the 1/8 lattice (their
//!   bands lie strictly between two lattice lines), and a point sampler
//!   whose sample is at offset o draws a sliver only where the fractional
//!   part of o lies in it: it draws at most one, the four being disjoint.
//!   An any-coverage rasterizer draws all four, each in its pixel.
//! - **Strips.** 96 strips 1/8 px high across a 12 × 12 canvas, each two
//!   triangles, their edges placed so that no point of the 1/8 lattice lies
//!   on one (the tie rule never matters). They tile the canvas: a point sampler (with a
//!   consistent tie rule, its sample anywhere from −1 to 2 px) draws every
//!   pixel of the middle 6 × 6, while no strip covers more than 1/8 of any
//!   pixel, so an area rasterizer (a pixel is drawn when a primitive covers
//!   at least half of it, or any threshold above 1/8) draws none.
//! - **Whole pixels.** One triangle over the whole canvas: what an area
//!   rasterizer draws. Drawing it and no strip is the area signature.
//!
//! Drawing all four slivers is any-coverage's signature, and also that of
//! a fill with its edges stroked over it as hairlines: `outline.rs` tells
//! the two apart on one triangle's edge pixels.
//!
//! A frame that carries `resolved` (fractional coverage) for these
//! single-sample scenes is an area rasterizer's on its face. A rasterizer
//! that refuses single-sample scenes altogether (vello_cpu, `area-f32`) is
//! asked for an antialiased half-covered pixel instead: a frame of resolved
//! coverage only, with no sample slots, is an area method's; one whose
//! coverage is zero everywhere draws nothing, and is said to.

use serde_json::json;

use super::diagnosis::{Sampler, SamplerKind};
use crate::frame::Frame;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::scene::{parse_case, Limits, Scene};

use super::infer::draw;
use super::outline;
use super::scenes::{mesh_scene, tri};

/// The sliver of pixel-relative corners (in 1/32 px), each in its own pixel.
const SLIVERS: [[(i32, i32); 3]; 4] = [
    [(4, 1), (28, 1), (16, 3)],
    [(4, 31), (16, 29), (28, 31)],
    [(1, 4), (3, 16), (1, 28)],
    [(31, 4), (31, 28), (29, 16)],
];

/// The pixel sliver k lies in.
fn sliver_pixel(k: usize) -> (u32, u32) {
    (2 * k as u32 + 1, 1)
}

pub(super) fn sliver_scene() -> Scene {
    let triangles = SLIVERS
        .iter()
        .enumerate()
        .map(|(k, corners)| {
            let (px, py) = sliver_pixel(k);
            tri(corners.map(|(x, y)| {
                (
                    f64::from(px) + f64::from(x) / 32.0,
                    f64::from(py) + f64::from(y) / 32.0,
                )
            }))
        })
        .collect();
    mesh_scene("probe_sampler_slivers", 10, 3, 8, triangles)
}

/// The strips' canvas side, and the middle square every point sampler fills.
const STRIPS_SIDE: u32 = 12;
const STRIPS_MIDDLE: std::ops::Range<u32> = 3..9;

pub(super) fn strip_scene() -> Scene {
    // Each strip runs from x = −1/16 to 12 − 1/16 and is cut along its
    // diagonal, which meets the lines y = m/8 + 1/8 at x ≡ −1/16 (mod 1/2):
    // no point of the 1/8 lattice lies on any edge.
    let (left, right) = (-1.0 / 16.0, f64::from(STRIPS_SIDE) - 1.0 / 16.0);
    let mut triangles = Vec::new();
    for m in 0..8 * STRIPS_SIDE {
        let top = f64::from(m) / 8.0 + 1.0 / 16.0;
        let bottom = top + 1.0 / 8.0;
        triangles.push(tri([(left, top), (right, top), (right, bottom)]));
        triangles.push(tri([(left, top), (right, bottom), (left, bottom)]));
    }
    mesh_scene(
        "probe_sampler_strips",
        STRIPS_SIDE,
        STRIPS_SIDE,
        8,
        triangles,
    )
}

fn whole_scene() -> Scene {
    let side = 2.0 * f64::from(STRIPS_SIDE);
    mesh_scene(
        "probe_sampler_whole",
        STRIPS_SIDE,
        STRIPS_SIDE,
        8,
        vec![tri([(0.0, 0.0), (side, 0.0), (0.0, side)])],
    )
}

/// An antialiased pixel half covered (below its diagonal), for a
/// rasterizer that draws antialiased scenes only.
fn antialiased_scene() -> Scene {
    parse_case(
        &json!({
            "name": "probe_sampler_antialiased",
            "canvas": {"width": 3, "height": 3},
            "rules": {"subpixel_bits": 8, "cull": "none"},
            "effects": {"antialias": {"samples": 4}},
            "primitives": [tri([(1.0, 1.0), (2.0, 1.0), (1.0, 2.0)])],
        })
        .to_string(),
        "probe",
        &Limits::default(),
    )
    .unwrap_or_else(|e| panic!("a probe scene is invalid: {e}"))
}

fn drawn(frame: &Frame, (x, y): (u32, u32)) -> bool {
    frame.samples > 0 && frame.coverage[frame.index(x, y)] > 0
}

/// Whether a frame carries fractional resolved coverage.
fn fractional(frame: &Frame) -> bool {
    frame
        .resolved
        .as_ref()
        .is_some_and(|r| r.iter().any(|v| v.fract() != 0.0))
}

/// Whether a frame of resolved coverage draws nothing at all.
fn nothing(frame: &Frame) -> bool {
    frame
        .resolved
        .as_ref()
        .is_none_or(|r| r.iter().all(|&v| v == 0.0))
}

fn right_size(frame: &Frame, scene: &Scene) -> bool {
    (frame.width, frame.height) == (scene.canvas.width, scene.canvas.height)
        && frame.coverage.len() == frame.pixel_count() * frame.samples as usize
}

/// Decides the sampler. `Err` when the candidate draws none of its scenes,
/// single-sample or antialiased.
pub fn decide(candidate: &dyn Rasterizer) -> Result<Sampler, String> {
    let decided = |kind, evidence: &str| {
        Ok(Sampler {
            kind,
            evidence: evidence.to_owned(),
        })
    };
    let slivers = sliver_scene();
    let frame = match draw(candidate, &slivers) {
        Ok(f) if right_size(&f, &slivers) => f,
        Ok(_) => return Err("returned a frame of the wrong size".to_owned()),
        Err(RasterError::Unsupported(why)) => return decide_antialiased(candidate, &why),
        Err(e) => return Err(e.to_string()),
    };
    if fractional(&frame) {
        return decided(
            SamplerKind::Area,
            "its frame of a single-sample scene carries fractional resolved coverage",
        );
    }
    let touched = (0..SLIVERS.len())
        .filter(|&k| drawn(&frame, sliver_pixel(k)))
        .count();
    if touched == SLIVERS.len() {
        // Any-coverage, or a fill with its edges stroked over it: one
        // triangle's edge pixels tell them apart (`outline.rs`).
        return Ok(outline::decide(
            candidate,
            "it draws all four slivers that avoid every point of the 1/8 lattice, each in its pixel (a point sampler draws at most one)",
        ));
    }
    let strips = strip_scene();
    let whole = whole_scene();
    let (Ok(strips_frame), Ok(whole_frame)) = (draw(candidate, &strips), draw(candidate, &whole))
    else {
        return decided(
            SamplerKind::Unknown,
            "it could not draw the strip or whole-pixel scenes",
        );
    };
    if !right_size(&strips_frame, &strips) || !right_size(&whole_frame, &whole) {
        return Err("returned a frame of the wrong size".to_owned());
    }
    let middle: Vec<(u32, u32)> = STRIPS_MIDDLE
        .flat_map(|y| STRIPS_MIDDLE.map(move |x| (x, y)))
        .collect();
    let filled = middle.iter().filter(|&&p| drawn(&strips_frame, p)).count();
    let any_strip = strips_frame.coverage.iter().any(|&c| c > 0);
    let any_whole = whole_frame.coverage.iter().any(|&c| c > 0);
    if filled == middle.len() {
        decided(
            SamplerKind::Point,
            "it fills every pixel of a mesh of strips 1/8 px high, and draws at most one sliver off the 1/8 lattice",
        )
    } else if !any_strip && any_whole {
        decided(
            SamplerKind::Area,
            "it draws a triangle over whole pixels but no strip of a mesh of strips 1/8 px high (no strip covers more than 1/8 of a pixel), and no sliver",
        )
    } else {
        Ok(Sampler {
            kind: SamplerKind::Unknown,
            evidence: format!(
                "it draws {touched} of 4 slivers, {filled} of the {} middle pixels of a mesh of strips, and {} whole-pixel triangle",
                middle.len(),
                if any_whole { "the" } else { "not the" }
            ),
        })
    }
}

/// For a candidate that refuses single-sample scenes (`why`): an
/// antialiased half-covered pixel.
fn decide_antialiased(candidate: &dyn Rasterizer, why: &str) -> Result<Sampler, String> {
    let scene = antialiased_scene();
    match draw(candidate, &scene) {
        Ok(f) if f.samples == 0 && fractional(&f) => Ok(Sampler {
            kind: SamplerKind::Area,
            evidence: format!(
                "it draws no single-sample scene ({why}), and answers an antialiased half-covered pixel with resolved coverage only (no samples)"
            ),
        }),
        Ok(f) if f.samples == 0 && nothing(&f) => Ok(Sampler {
            kind: SamplerKind::Unknown,
            evidence: format!(
                "it draws no single-sample scene ({why}), and answers an antialiased pixel half covered by a triangle with nothing: zero coverage in every pixel (it draws nothing)"
            ),
        }),
        Ok(_) => Ok(Sampler {
            kind: SamplerKind::Unknown,
            evidence: format!(
                "it draws no single-sample scene ({why}); its antialiased frames have sample slots"
            ),
        }),
        Err(e) => Err(format!("it draws no single-sample scene ({why}), and {e}")),
    }
}
