//! A real depth attachment (SPEC.md §18), for the scenes whose depth
//! format is not `exact` or that give a polygon offset
//! (`gpu::depth::target` says which and what; it refuses polygons).
//!
//! # The attachment and its state
//!
//! - **Format**: a renderbuffer of `GL_DEPTH_COMPONENT16`,
//!   `GL_DEPTH_COMPONENT24` or `GL_DEPTH_COMPONENT32F` (unorm16, unorm24,
//!   float32), checked to hold exactly that many depth bits
//!   (`GL_RENDERBUFFER_DEPTH_SIZE`): GL lets a driver store a format with
//!   more, which would hide the quantization judged.
//! - **Test**: on, `glDepthFunc(GL_ALWAYS)` with writes on, so that the
//!   last primitive in submission order keeps its depth, as the colour
//!   channels keep its values; cleared (to 1) with the colour targets.
//! - **Offset**: `GL_POLYGON_OFFSET_FILL` only (lines and points are never
//!   offset, SPEC.md §18.2), `glPolygonOffset(slope, constant)` (GL's
//!   factor and units), or `glPolygonOffsetClamp(slope, constant, clamp)`
//!   (GL 4.6, ARB/EXT_polygon_offset_clamp) when the clamp is not 0; a
//!   context without it refuses such a case.
//! - **Screen space**: the position's z is the case's z (`gpu::Stream`);
//!   the context's clip control is already `GL_ZERO_TO_ONE` (`clip.rs`),
//!   so z_ndc is the window depth under `glDepthRange(0, 1)`, and
//!   `GL_DEPTH_CLAMP` is on (`clip::Stage`): no near or far clipping, the
//!   depth (offset first) clamped to [0, 1], the format's clamp. A context
//!   without clip control refuses such a case.
//! - **Clip space**: the viewport's depth range and `depth: clamp` as
//!   `clip.rs` sets them for every clip-space case.
//!
//! Everything is set before a scene's draws and put back after them
//! (depth test and offset off, offset 0): the context is every case's.
//!
//! # Read-back
//!
//! The stored values, never a conversion of them to float (a unorm24
//! value near 1 is within an f32 ulp of its neighbours): unorm16 as
//! `GL_UNSIGNED_SHORT` (the integer k itself), unorm24 as
//! `GL_UNSIGNED_INT` (GL widens k/(2^24 − 1) to 32 bits; k is recovered
//! exactly, [`unorm24_of_u32`]), float32 as `GL_FLOAT` (the bits). Rows
//! come back bottom-up and are flipped, as the colour targets' are;
//! `gpu::depth::stored_value` turns each word into the depth the frame
//! reports.
//!
//! Only single-sample targets have one: a multisampled depth attachment
//! cannot be read back sample by sample without a conversion to float,
//! so scenes with a depth attachment are antialiased by shifted passes
//! (never the driver's MSAA), and rectangle lines, drawn into a
//! multisampled target, are refused beside one.

use glow::HasContext;

use super::context::GlContext;
use super::drawing::Drawing;
use crate::adapters::gpu::depth::DepthTarget;
use crate::rasterizer::RasterError;
use crate::scene::{DepthFormat, Scene};

/// The renderbuffer format of a depth format, and the depth bits it must
/// have.
fn internal_format(format: DepthFormat) -> (u32, i32) {
    match format {
        DepthFormat::Unorm16 => (glow::DEPTH_COMPONENT16, 16),
        DepthFormat::Unorm24 => (glow::DEPTH_COMPONENT24, 24),
        // `exact` never has an attachment (`gpu::depth::target`).
        DepthFormat::Float32 | DepthFormat::Exact => (glow::DEPTH_COMPONENT32F, 32),
    }
}

/// The 24-bit integer k that GL's `GL_UNSIGNED_INT` read-back of a
/// unorm24 depth widens to `u`: the integer nearest u·(2^24 − 1)/(2^32 − 1),
/// exactly, in integers. Any widening within 127 of the exact
/// k·(2^32 − 1)/(2^24 − 1) (the grid step is 256.00002 words) gives k back.
pub(crate) fn unorm24_of_u32(u: u32) -> u32 {
    const D24: u64 = (1 << 24) - 1;
    const D32: u64 = (1 << 32) - 1;
    // ⌊(2u·D24 + D32) / (2·D32)⌋ = ⌊u·D24/D32 + ½⌋; below 2^58.
    ((2 * u64::from(u) * D24 + D32) / (2 * D32)) as u32
}

impl GlContext {
    /// Why this context cannot give `scene` the attachment `target`
    /// asks for, if it cannot.
    pub(super) fn depth_refusal(&self, scene: &Scene, target: &DepthTarget) -> Option<String> {
        if scene.viewport.is_none() && !self.clip.zero_to_one {
            return Some(
                "a depth attachment in screen space needs glClipControl (GL 4.5, \
                 ARB_clip_control): without GL_ZERO_TO_ONE the case's z would be \
                 remapped from [−1, 1]"
                    .to_owned(),
            );
        }
        match target.bias {
            Some([_, _, clamp]) if clamp != 0.0 && self.offset_clamp.is_none() => Some(format!(
                "depth_bias.clamp {clamp}: {} offers no glPolygonOffsetClamp (GL 4.6, \
                 ARB_polygon_offset_clamp, EXT_polygon_offset_clamp)",
                self.renderer
            )),
            _ => None,
        }
    }

    /// Makes `drawing`'s depth renderbuffer of its target's format and
    /// attaches it, or fails where the driver stores the format with
    /// other than its bits.
    pub(super) unsafe fn make_depth(&self, drawing: &mut Drawing) -> Result<(), RasterError> {
        let Some(target) = drawing.depth else {
            return Ok(());
        };
        let gl = &self.gl;
        let (fw, fh) = drawing.size;
        let rb = gl.create_renderbuffer().map_err(|e| self.failed(&e))?;
        drawing.depth_buffer = Some(rb);
        let (format, bits) = internal_format(target.format);
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
        gl.renderbuffer_storage(glow::RENDERBUFFER, format, fw as i32, fh as i32);
        gl.framebuffer_renderbuffer(
            glow::FRAMEBUFFER,
            glow::DEPTH_ATTACHMENT,
            glow::RENDERBUFFER,
            Some(rb),
        );
        let stored =
            gl.get_renderbuffer_parameter_i32(glow::RENDERBUFFER, glow::RENDERBUFFER_DEPTH_SIZE);
        if stored != bits {
            return Err(RasterError::Unsupported(format!(
                "depth_format {}: {} stores it with {stored} depth bits, not {bits}",
                target.format.name(),
                self.renderer
            )));
        }
        Ok(())
    }

    /// Turns the depth test (always passing, writes on) and the polygon
    /// offset on for `drawing`'s draws, where it has an attachment.
    pub(super) unsafe fn set_depth_state(&self, drawing: &Drawing) {
        let Some(target) = drawing.depth else {
            return;
        };
        let gl = &self.gl;
        gl.enable(glow::DEPTH_TEST);
        gl.depth_func(glow::ALWAYS);
        gl.depth_mask(true);
        if let Some([constant, slope, clamp]) = target.bias {
            gl.enable(glow::POLYGON_OFFSET_FILL);
            match self.offset_clamp {
                Some(offset_clamp) if clamp != 0.0 => offset_clamp(slope, constant, clamp),
                _ => gl.polygon_offset(slope, constant),
            }
        }
    }

    /// Puts back what [`GlContext::set_depth_state`] and the screen-space
    /// depth clamp changed: no depth test, no offset, no clamp.
    pub(super) unsafe fn reset_depth_state(&self) {
        let gl = &self.gl;
        gl.disable(glow::DEPTH_TEST);
        gl.depth_func(glow::LESS);
        gl.disable(glow::POLYGON_OFFSET_FILL);
        // GL 4.6: glPolygonOffset(f, u) is glPolygonOffsetClamp(f, u, 0).
        gl.polygon_offset(0.0, 0.0);
        gl.disable(glow::DEPTH_CLAMP);
    }

    /// The stored depth words of the canvas whose lower-left window corner
    /// is `corner`, rows flipped (y down): unorm k, or float32 bits.
    pub(super) unsafe fn read_depth(
        &self,
        drawing: &Drawing,
        target: &DepthTarget,
        corner: (u32, u32),
    ) -> Vec<u32> {
        let gl = &self.gl;
        let (w, h) = (drawing.canvas.0 as usize, drawing.canvas.1 as usize);
        self.bind_framebuffer(drawing);
        let (kind, size) = match target.format {
            DepthFormat::Unorm16 => (glow::UNSIGNED_SHORT, 2),
            DepthFormat::Unorm24 => (glow::UNSIGNED_INT, 4),
            DepthFormat::Float32 | DepthFormat::Exact => (glow::FLOAT, 4),
        };
        // GL_PACK_ALIGNMENT is 4 (`context.rs`): rows start on 4 bytes.
        let stride = (w * size).next_multiple_of(4);
        let mut bytes = vec![0u8; stride * h];
        gl.read_pixels(
            corner.0 as i32,
            corner.1 as i32,
            w as i32,
            h as i32,
            glow::DEPTH_COMPONENT,
            kind,
            glow::PixelPackData::Slice(Some(&mut bytes)),
        );
        let mut out = Vec::with_capacity(w * h);
        for y in (0..h).rev() {
            let row = &bytes[y * stride..y * stride + w * size];
            out.extend(row.chunks_exact(size).map(|b| match target.format {
                DepthFormat::Unorm16 => u32::from(u16::from_le_bytes([b[0], b[1]])),
                DepthFormat::Unorm24 => {
                    unorm24_of_u32(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                }
                _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            }));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// k comes back from its exact widening, Mesa's bit replication
    /// (k << 8 | k >> 16) and anything within 127 words, and not from a
    /// word half a step away.
    #[test]
    fn unorm24_words_give_k_back() {
        const D24: u64 = (1 << 24) - 1;
        const D32: u64 = (1 << 32) - 1;
        for k in [
            0u32,
            1,
            2,
            255,
            65535,
            65536,
            1 << 23,
            (1 << 24) - 2,
            (1 << 24) - 1,
        ] {
            let exact = (u64::from(k) * D32 + D24 / 2) / D24;
            assert_eq!(unorm24_of_u32(exact as u32), k, "{k}");
            assert_eq!(unorm24_of_u32((k << 8) | (k >> 16)), k, "{k}");
            if k > 0 {
                assert_eq!(unorm24_of_u32(exact as u32 - 127), k, "{k}");
                assert_eq!(unorm24_of_u32(exact as u32 - 129), k - 1, "{k}");
            }
            if k < (1 << 24) - 1 {
                assert_eq!(unorm24_of_u32(exact as u32 + 127), k, "{k}");
                assert_eq!(unorm24_of_u32(exact as u32 + 129), k + 1, "{k}");
            }
        }
        assert_eq!(unorm24_of_u32(u32::MAX), (1 << 24) - 1);
    }
}
