//! Truncation to whole pixels: does the rasterizer draw a vertex at 2.625
//! at 2 and one at 14.875 at 14 (⌊x⌋, as two real 2D libraries do)?
//!
//! Two squares on an 18 × 18 canvas, each two triangles with their
//! vertices at fractions of a pixel: [2.625, 6.375]² and [10.875,
//! 14.875]². Their edges lie a whole number of pixels plus a fraction
//! that no sample centre shares, and at truncated vertices every edge lies
//! on a pixel boundary: no tie rule is asked either way. A rasterizer that
//! truncates draws exactly the reference's frame of the truncated squares
//! (pixels 2..5 and 10..13 on both axes); an exact point sampler draws 3..5
//! and 11..14, one that rounds to whole pixels 3..5 and 11..14, one that
//! rounds up 3..6 and 11..14, an any-coverage one 2..6 and 10..14. The
//! probe runs on every sampler; where a sample position was found off the
//! centre, the squares are moved for it as the other probes' scenes are
//! (a sample at the corner (1, 1) would otherwise draw them shifted by
//! half a pixel, as truncation does), and at the centre otherwise (a
//! rasterizer that truncates finds no sample position: the position
//! probe's triangles are smaller than a pixel).

use serde_json::Value;

use super::diagnosis::{Eighths, CENTRE};
use super::infer::draw_for;
use super::scenes::{mesh_scene, tri};
use crate::plan::Plan;
use crate::rasterizer::Rasterizer;
use crate::reference;
use crate::scene::{Number, Scene};

/// The squares, as (low, high) corners on both axes.
const SQUARES: [(f64, f64); 2] = [(2.625, 6.375), (10.875, 14.875)];

/// What the scene is, in the words a finding gives.
pub const MEASURED_ON: &str = "two squares [2.625, 6.375]² and [10.875, 14.875]² on an 18 × 18 canvas: drawn as the reference draws them at ⌊x⌋, ⌊y⌋ (pixels 2..5 and 10..13)";

fn square((lo, hi): (f64, f64)) -> [Value; 2] {
    [
        tri([(lo, lo), (hi, lo), (hi, hi)]),
        tri([(lo, lo), (hi, hi), (lo, hi)]),
    ]
}

fn scene() -> Scene {
    let triangles = SQUARES.iter().flat_map(|&s| square(s)).collect();
    mesh_scene("probe_truncation", 18, 18, 8, triangles)
}

/// The scene with every coordinate truncated, exactly.
fn truncated(scene: &Scene) -> Scene {
    let mut s = scene.clone();
    for v in s.primitives.iter_mut().flat_map(|p| p.vertices_mut()) {
        for c in [&mut v.x, &mut v.y] {
            *c = Number::from_rbig(dashu_ratio::RBig::from(c.as_rbig().floor()));
        }
    }
    s
}

/// Whether the candidate truncates vertices to whole pixels: its frame of
/// the squares is drawn where the reference draws them truncated, pixel
/// for pixel (drawn or not), and not where it draws them as written.
/// `None` when it could not draw the scene.
pub(super) fn truncates(candidate: &dyn Rasterizer, offset: Option<Eighths>) -> Option<bool> {
    let s = scene();
    let frame = draw_for(candidate, &s, offset.unwrap_or(CENTRE)).ok()?;
    if frame.samples != 1 || frame.sample_count() != s.canvas.pixel_count() {
        return None;
    }
    let plan = Plan::for_scene(&s);
    let drawn =
        |f: &crate::frame::Frame| -> Vec<bool> { f.coverage.iter().map(|&c| c > 0).collect() };
    let theirs = drawn(&frame);
    let at_floor = drawn(&reference::render(&truncated(&s), &plan));
    let as_written = drawn(&reference::render(&s, &plan));
    Some(theirs == at_floor && theirs != as_written)
}
