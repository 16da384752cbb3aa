//! `lavapipe`: Mesa's Vulkan rasterizer on the CPU, driven through wgpu
//! (cargo feature `lavapipe`; system packages `mesa-vulkan-drivers` and
//! `libvulkan1`).
//!
//! # What is drawn, and how it is read back
//!
//! A case's triangles are drawn in scene order, with no depth test, into
//! float render targets, and read back into a [`Frame`]:
//!
//! - **count** (`R32Float`, additive blending `1 + dst`; `R16Float` where the
//!   adapter lacks `FLOAT32_BLENDABLE`, exact up to 2048 covers a sample):
//!   how many triangles cover each sample;
//! - **channel groups** (`Rgba32Float`, no blending, so the last triangle in
//!   submission order wins, as Vulkan's primitive order guarantees): the
//!   channels `[primitive + 1, depth, attribute 0, …, attribute 15]` four at
//!   a time. Group 0 (primitive, depth, attributes 0 and 1) is drawn in the
//!   same pass as the count; every further group of four attributes is drawn
//!   by one more pass over the same triangles. Everything is recorded in one
//!   command buffer and read back once.
//!
//! The primitive index (+ 1, exact in f32 up to 2^24) is a `flat` varying and
//! doubles as the coverage marker of the last writer. Depth is the case's `z`
//! as a `linear` (screen-space, `noperspective`) varying, not the depth buffer,
//! so no depth-range mapping touches it (SPEC.md §5: z is screen-space
//! linear). Attributes are varyings with the case's `@interpolate`:
//! `perspective`, `linear`, or `flat` (the first vertex provokes, Vulkan's
//! default and the case's rule). Consecutive triangles of one interpolation
//! mode share one draw call.
//!
//! # Positions: exact to the 8-bit grid
//!
//! Each coordinate is snapped to the case's `subpixel_bits` (ties to even,
//! the reference's own snapping) and rounded to f32 (exact for b ≤ 8). The
//! render targets are `P × Q` texels, P and Q the powers of two at or above
//! the canvas width and height; only the canvas (scissor `W × H` at the
//! origin) is drawn and copied back. With a power-of-two viewport the NDC
//! mapping
//!
//! ```text
//! x_ndc = x · 2/P − 1,   y_ndc = 1 − y · 2/Q      (y down on screen)
//! clip  = (x_ndc · w, y_ndc · w, w / 2, w)
//! ```
//!
//! and the viewport transform back (`x = (x_ndc + 1) · P/2`, wgpu flips y) are
//! exact in f32 for every snapped coordinate |x|, |y| ≤ 2^15 with b ≤ 8 (the
//! values span at most 24 significant bits). The only float step is the
//! perspective division (x_ndc·w)/w when w ≠ 1, at most an ulp or so, which
//! the driver's snap to 1/256 absorbs unless a coordinate uses all 24 bits
//! (|x| near 2^15). Clip z = w/2 keeps every vertex inside the depth range,
//! so only the x and y planes (and the driver's guard band) can clip.
//!
//! lavapipe then snaps to its own `subPixelPrecisionBits` = 8: cases with
//! b > 8 are snapped twice (to b, then to 8 bits), and show it; cases with
//! `subpixel_bits: null` are unsupported.
//!
//! The viewport is the whole `P × Q` target, so the driver clips at x = 0,
//! y = 0, x = P and y = Q (at the canvas's own right and bottom borders only
//! when W and H are powers of two). Mesa 22.3's lavapipe clips there rather
//! than rasterizing off-screen vertices in a guard band, and re-snaps the
//! vertices clipping makes: an edge from an off-screen vertex moves by up to
//! a subpixel and its on-screen tie samples can change hands
//! (`tests/lavapipe.rs` shows it). That is the driver's behaviour, reported
//! as found.
//!
//! # Rules
//!
//! - **Fill rule**: the driver's own (top-left). The case's rule is not
//!   faked: a case under another rule reports lavapipe's departures from it.
//! - **Culling**: `front_face = Ccw` with `cull: ccw` → cull the front face,
//!   `cull: cw` → cull the back face. WebGPU reads the winding in framebuffer
//!   coordinates (y down), the same orientation as the case's (SPEC.md §2):
//!   (0,0), (1,0), (0,1) is clockwise in both. w > 0, so the division keeps
//!   the winding.
//! - **Lines**: unsupported (wgpu draws only 1-px lines, with no rule to
//!   choose). **Polygons**: unsupported (the harness refuses them).
//!
//! # Antialiasing: 4× MSAA, read back sample by sample
//!
//! An antialiased scene is drawn only when its plan's offsets are exactly
//! Vulkan's standard 4× locations ([`STANDARD_4X`] at the plan's
//! `position_bits`; the offsets are checked, not the pattern's name): wgpu
//! exposes 4× MSAA at the standard positions only, so every other count or
//! pattern is unsupported, with that reason. The same passes as above draw
//! into 4× multisampled targets (`count: 4`): the count in `R32Float`
//! where the adapter multisamples and blends it (through
//! `TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` and `FLOAT32_BLENDABLE`; else
//! core `R16Float`, exact up to 2048 covers a sample), the channel groups in
//! `Rgba32Float` where the adapter multisamples it (else core `Rgba16Float`:
//! primitive + 1 exact up to 2048, more triangles refused, and depth and
//! attributes refused as they would not meet the bound). Mesa 22.3's
//! lavapipe takes the f32 formats. Depth and the non-flat attributes are
//! varyings with the `sample` qualifier, so the fragment shader runs once
//! per sample and interpolates at the sample's own position; blending and
//! the last-writer-wins channels are per sample anyway.
//!
//! A second pass per target spreads the samples out: a full-target triangle
//! over a non-multisampled `R32Float` / `Rgba32Float` target 4× wider,
//! whose texel (4x + s, y) is `textureLoad(t, (x, y), s)`. Vulkan's sample
//! index s is standard location s, which is the frame's slot s, so the
//! wide target read row by row is the frame's slot order (`4·p + s`).
//! Then the frame is box-resolved ([`Frame::resolve`]). Canvases wider
//! than a quarter of the largest texture are unsupported.
//!
//! What lavapipe does with it (`tests/lavapipe.rs`): its mask equals the
//! exact reference's sample by sample on every bundled standard 4×
//! triangle case, and a tiny square on standard location i lights slot i
//! only. Depth and linear and flat attributes are within the bound per
//! sample; perspective attributes are not: Mesa 22.3 divides Σλ·a/w at the
//! sample by Σλ/w at the pixel centre, a driver bug the check reports.
//!
//! One device is created on first use and shared by every case (creating it
//! takes a while); a mutex serialises the cases that use it. Compiled
//! pipelines are kept, keyed by interpolation mode, channel group and culling.
//!
//! # Set up once, drawn again and again
//!
//! A scene is set up once (its vertex stream converted and uploaded, its
//! targets made, its pipelines chosen) and then cleared, drawn and read
//! back. `rasterize` records all of it in one command buffer;
//! [`Rasterizer::prepare`] hands the set-up scene to the bench, which
//! clears, draws (submission to fence) and reads back one submission at a
//! time, and so times lavapipe's own draw apart. Both paths share every
//! step, so the frame the bench judges is the one a case's run draws.

//!
//! # The rooms
//!
//! - this file: the [`Rasterizer`] impl, what lavapipe can draw and why it
//!   refuses the rest, and the shared device;
//! - `device.rs`: finding lavapipe, creating the device, choosing formats;
//! - `pipelines.rs` and `shaders.rs`: the render pipelines and their WGSL;
//! - `draw.rs`: one scene set up on the device, its passes (clearing,
//!   drawing, single-sample and 4× MSAA) and its read-back;
//! - `prepared.rs`: the same scene cleared, drawn and read back one
//!   submission at a time, for the bench to time the draw apart;
//! - `readback.rs`: copying targets out and decoding them into a [`Frame`].

mod device;
mod draw;
mod pipelines;
mod prepared;
mod readback;
mod shaders;

use std::sync::{Mutex, MutexGuard, OnceLock};

use crate::frame::Frame;
use crate::plan::{Plan, SamplePlan};
use crate::rasterizer::{refuse_last_provoking, Capabilities, Prepared, RasterError, Rasterizer};
use crate::scene::{FillRule, Scene};

use super::gpu;
use device::Gpu;

/// The name on the command line and in reports.
pub const NAME: &str = "lavapipe";

/// Mesa's lavapipe, through wgpu's Vulkan backend.
pub struct Lavapipe;

impl Rasterizer for Lavapipe {
    fn name(&self) -> &str {
        NAME
    }

    fn capabilities(&self) -> Capabilities {
        gpu::capabilities(true)
    }

    /// Vulkan's, as the `vulkan` adapter says: the driver chooses, and
    /// lavapipe follows top-left.
    fn fixed_fill_rule(&self) -> Option<FillRule> {
        Some(FillRule::TopLeft)
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let bits = accepted(scene, plan)?;
        let gpu = gpu().map_err(|why| RasterError::Failed(why.clone()))?;
        lock(gpu).render(scene, plan, bits)
    }

    /// Everything `rasterize` draws, set up once: see `prepared.rs`.
    fn prepare<'a>(
        &'a self,
        scene: &'a Scene,
        plan: &'a Plan,
    ) -> Option<Result<Box<dyn Prepared + 'a>, RasterError>> {
        Some(prepared::prepare(scene, plan).map(|p| Box::new(p) as Box<dyn Prepared + 'a>))
    }
}

/// The subpixel bits lavapipe snaps the scene to, or why it cannot draw it:
/// samples other than Vulkan's standard 4×, a line, unsnapped geometry or
/// too many attributes.
fn accepted(scene: &Scene, plan: &Plan) -> Result<u32, RasterError> {
    if scene.has_points() {
        return Err(RasterError::Unsupported(
            "the wgpu adapter draws no points (wgpu has only 1-pixel points, no size)".to_owned(),
        ));
    }
    if let Some(aa) = &plan.antialias {
        if let Some(why) = standard_4x_refusal(aa) {
            return Err(RasterError::Unsupported(why));
        }
    } else if plan.samples_per_pixel != 1 {
        return Err(RasterError::Unsupported(format!(
            "{} samples per pixel without a sample pattern",
            plan.samples_per_pixel
        )));
    }
    refuse_last_provoking(
        scene,
        "the wgpu adapter (wgpu has no choice of provoking vertex)",
    )?;
    gpu::snapping_bits(
        scene,
        plan,
        |_| {
            Some("wgpu draws only 1-pixel lines, with no choice of the case's line rule".to_owned())
        },
        "lavapipe",
    )
}

/// Vulkan's standard 4× sample locations (`standardSampleLocations`), in
/// 1/16 pixel from the pixel's top-left corner, y down, in Vulkan's sample
/// order: sample index i of the driver is slot i of the frame.
pub const STANDARD_4X: [[u32; 2]; 4] = [[6, 2], [14, 6], [2, 10], [10, 14]];

/// Why lavapipe cannot draw these samples, if it cannot: wgpu asks the
/// driver for 4× MSAA at its standard locations and nothing else, so the
/// plan's offsets must be exactly [`STANDARD_4X`] at its position bits
/// (the offsets are checked, not the pattern's name).
pub fn standard_4x_refusal(aa: &SamplePlan) -> Option<String> {
    let standard = aa.position_bits.checked_sub(4).map(|shift| {
        STANDARD_4X
            .iter()
            .map(|p| p.map(|c| c << shift))
            .collect::<Vec<_>>()
    });
    if standard.as_deref() == Some(aa.offsets.as_slice()) {
        return None;
    }
    Some(format!(
        "{} samples per pixel, not at Vulkan's standard 4x locations: \
         wgpu exposes 4x MSAA at the standard positions only",
        aa.offsets.len()
    ))
}

/// The multisampled formats this adapter draws 4× MSAA into, as
/// "count FORMAT, values FORMAT", or why it cannot.
pub fn msaa_formats() -> Result<String, String> {
    let gpu = lock(gpu()?);
    Ok(format!(
        "count {:?}, values {:?}",
        gpu.msaa.count, gpu.msaa.values
    ))
}

/// The adapter wgpu found, as "name (driver, driver info)", or why none was
/// found. Creates the shared device on first use.
pub fn adapter_description() -> Result<String, String> {
    Ok(lock(gpu()?).description.clone())
}

fn gpu() -> Result<&'static Mutex<Gpu>, &'static String> {
    static GPU: OnceLock<Result<Mutex<Gpu>, String>> = OnceLock::new();
    GPU.get_or_init(|| Gpu::new().map(Mutex::new)).as_ref()
}

/// The shared device, for one case (or one phase of a prepared scene) at a
/// time; a case that panicked holding it leaves it usable.
fn lock(gpu: &'static Mutex<Gpu>) -> MutexGuard<'static, Gpu> {
    gpu.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_ndc_mapping_is_exact_for_snapped_coordinates() {
        // x · 2/P − 1 and back, for 8-bit coordinates across the whole range.
        for p in [1u32, 8, 1024, 16384] {
            let s = 2.0 / p as f32;
            for x in [
                -32768.0f32,
                -32768.0 + 1.0 / 256.0,
                -0.00390625,
                0.5,
                1023.5,
                32768.0 - 1.0 / 256.0,
            ] {
                let ndc = x * s - 1.0;
                assert_eq!(f64::from(ndc), f64::from(x) * 2.0 / f64::from(p) - 1.0);
                assert_eq!((ndc + 1.0) * (p as f32 / 2.0), x);
            }
        }
    }
}
