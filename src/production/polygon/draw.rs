//! Production's polygon path: a polygon of a scene drawn by scanline fill,
//! once per sample of the pixel, each into its slot.

use super::contour::{nudge, snapped};
use super::scanline::{self, Samples};
use crate::frame::Frame;
use crate::plan::Plan;
use crate::production::fixed::{EdgeInt, Format};
use crate::rasterizer::RasterError;
use crate::scene::{Polygon, Scene};

/// Draws polygon `index` of the scene into `frame`: one scanline fill per
/// sample of the pixel, each into its slot.
///
/// `E` is the caller's edge-function width; the scanline carries its one
/// product per edge in i128 and steps in i64 whatever it is (see
/// [`Walk`](super::scanline::Walk)).
pub fn draw<E: EdgeInt>(
    scene: &Scene,
    plan: &Plan,
    format: Format,
    index: usize,
    polygon: &Polygon,
    frame: &mut Frame,
) -> Result<(), RasterError> {
    let nudge = nudge(scene)?;
    let contours = snapped(scene, format, polygon)?;
    let one = format.one();
    match &plan.antialias {
        None => {
            let half = format.centre(0).0;
            let samples = Samples {
                one,
                offset: [half, half],
                slot: 0,
                nudge,
            };
            scanline::fill(
                &contours,
                polygon.fill,
                &samples,
                scene.canvas,
                frame,
                index,
            );
        }
        Some(sample_plan) => {
            // Sample s of pixel p lies at p + offsets[s]·2^-position_bits:
            // an integer in the format only when it is at least as fine.
            let Some(shift) = format.frac_bits.checked_sub(sample_plan.position_bits) else {
                return Err(RasterError::Failed(format!(
                    "the fixed-point format has {} fraction bits, fewer than the {} of the sample positions",
                    format.frac_bits, sample_plan.position_bits
                )));
            };
            if frame.samples as usize != sample_plan.offsets.len() {
                return Err(RasterError::Failed(format!(
                    "the frame holds {} samples per pixel, the plan {}",
                    frame.samples,
                    sample_plan.offsets.len()
                )));
            }
            // Adaptive sampling (only pixels an edge touches) is not worth
            // it here: a span already costs one write per sample, so every
            // slot is filled by its own scanline pass, adaptive or not, and
            // the result is the same.
            for (slot, offset) in sample_plan.offsets.iter().enumerate() {
                let samples = Samples {
                    one,
                    offset: offset.map(|o| i64::from(o) << shift),
                    slot,
                    nudge,
                };
                scanline::fill(
                    &contours,
                    polygon.fill,
                    &samples,
                    scene.canvas,
                    frame,
                    index,
                );
            }
        }
    }
    Ok(())
}
