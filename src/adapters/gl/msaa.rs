//! Drawing into the driver's multisampled targets, and reading each
//! sample back.
//!
//! Two layouts draw one pass into an N-sample framebuffer (float
//! multisample textures with fixed sample locations, a multisample
//! stencil renderbuffer for polygons):
//!
//! - **native MSAA**, for an antialiased case whose pattern is exactly the
//!   driver's positions of some count (`samples.rs`): the scene unshifted,
//!   driver sample i read into the plan slot at the same offset;
//! - **rectangle lines** (`lines.rs`), for a single-sample case: llvmpipe
//!   draws GL's multisample lines (rectangles, GL 4.6 §14.5.4) only into
//!   multisampled targets, so the scene is shifted by position_j − (½, ½)
//!   for one driver sample j on the 1/256 grid, which brings each pixel's
//!   centre onto the pixel's sample j (the driver samples there, not at
//!   the centre: the opposite of a shifted pass's shift), and sample j
//!   alone is read, into the pixel's one slot.
//!
//! Per-sample read-back: for each attachment and each sample read, a
//! full-screen triangle whose fragment shader `texelFetch`es that sample
//! of the multisample texture into a single-sample `RGBA32F` copy of the
//! framebuffer's size, which `glReadPixels` reads as it reads a
//! single-sample drawing.

use glow::HasContext;

use super::context::GlContext;
use super::drawing::Drawing;
use super::passes::{Layout, Pass, Reading, DRIVER_BITS};
use super::samples::DriverSamples;
use crate::adapters::gpu;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;
use dashu_int::IBig;
use dashu_ratio::RBig;

/// One pass of the scene at the pixel centres into a `count`-sample
/// target: driver sample i is read into slot `slots[i]`.
pub(super) fn native(
    scene: &Scene,
    bits: u32,
    (tile, view): ((u32, u32), gpu::View),
    count: u32,
    slots: &[usize],
) -> Layout {
    let reading = Reading::Samples {
        samples: count,
        read: slots
            .iter()
            .enumerate()
            .map(|(i, &slot)| (i as u32, slot))
            .collect(),
    };
    let mut layout = Layout::new(tile, reading);
    let stream = layout.push(gpu::Stream::new(
        scene,
        &gpu::Placement::at_centres(bits, view),
    ));
    layout.passes.push(Pass {
        origin: (0, 0),
        stream,
        pixel: None,
    });
    layout
}

/// One pass of a single-sample scene into a multisampled target, shifted
/// so that one driver sample lies on each pixel centre, that sample read:
/// how rectangle lines are drawn. Or why not: no multisampling, vertices
/// finer than the driver's grid, no sample on it.
pub(super) fn at_one_sample(
    scene: &Scene,
    plan: &Plan,
    bits: u32,
    (tile, view): ((u32, u32), gpu::View),
    offered: &[DriverSamples],
) -> Result<Layout, RasterError> {
    let unsupported = |why: String| Err(RasterError::Unsupported(why));
    if plan.antialias.is_some() || plan.samples_per_pixel != 1 {
        return unsupported("rectangle lines in an antialiased scene".to_owned());
    }
    if bits > DRIVER_BITS {
        return unsupported(format!(
            "rectangle lines with subpixel_bits {bits}: they are drawn shifted onto a \
             driver sample, and Mesa rounds vertices to {DRIVER_BITS} bits, ties to even, \
             which a shift does not commute with"
        ));
    }
    let Some((driver, j, [x, y])) = offered.iter().find_map(|driver| {
        (0..driver.positions.len()).find_map(|j| Some((driver, j, driver.on_grid(j, DRIVER_BITS)?)))
    }) else {
        return unsupported(
            "rectangle lines: the driver offers no multisampling with a sample on its \
             1/256 grid"
                .to_owned(),
        );
    };
    let unit = 1i64 << DRIVER_BITS;
    // Driver sample j of pixel (x, y) lies at (x, y) + p_j: moving the
    // scene by p_j − (½, ½) brings the pixel's centre onto it.
    let shift = [x, y].map(|c| RBig::from_parts(IBig::from(c - unit / 2), (unit as u64).into()));
    let place = gpu::Placement {
        shift,
        ..gpu::Placement::at_centres(bits, view)
    };
    let reading = Reading::Samples {
        samples: driver.count,
        read: vec![(j as u32, 0)],
    };
    let mut layout = Layout::new(tile, reading);
    let stream = layout.push(gpu::Stream::new(scene, &place));
    layout.passes.push(Pass {
        origin: (0, 0),
        stream,
        pixel: None,
    });
    Ok(layout)
}

impl GlContext {
    /// Makes `drawing`'s attachments multisampled: `groups + 1` float
    /// textures of `samples` samples with fixed locations (the count's,
    /// then the groups'), a stencil renderbuffer of as many where it
    /// `stencils`, and the single-sample copy the samples are fetched into
    /// (its renderbuffer the last of `drawing`'s).
    pub(super) unsafe fn make_multisampled(
        &self,
        drawing: &mut Drawing,
        groups: usize,
        stencils: bool,
    ) -> Result<(), RasterError> {
        let gl = &self.gl;
        let (fw, fh) = drawing.size;
        let samples = drawing.samples as i32;
        for k in 0..=groups {
            let texture = gl.create_texture().map_err(|e| self.failed(&e))?;
            drawing.textures.push(texture);
            gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, Some(texture));
            let format = if k == 0 { glow::R32F } else { glow::RGBA32F };
            gl.tex_image_2d_multisample(
                glow::TEXTURE_2D_MULTISAMPLE,
                samples,
                format as i32,
                fw as i32,
                fh as i32,
                true,
            );
            gl.framebuffer_texture_2d(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0 + k as u32,
                glow::TEXTURE_2D_MULTISAMPLE,
                Some(texture),
                0,
            );
        }
        gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, None);
        if stencils {
            let rb = gl.create_renderbuffer().map_err(|e| self.failed(&e))?;
            drawing.stencil = Some(rb);
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            gl.renderbuffer_storage_multisample(
                glow::RENDERBUFFER,
                samples,
                glow::DEPTH24_STENCIL8,
                fw as i32,
                fh as i32,
            );
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::DEPTH_STENCIL_ATTACHMENT,
                glow::RENDERBUFFER,
                Some(rb),
            );
        }
        let copy = gl.create_framebuffer().map_err(|e| self.failed(&e))?;
        drawing.copy = Some(copy);
        let rb = gl.create_renderbuffer().map_err(|e| self.failed(&e))?;
        drawing.renderbuffers.push(rb);
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
        gl.renderbuffer_storage(glow::RENDERBUFFER, glow::RGBA32F, fw as i32, fh as i32);
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(copy));
        gl.framebuffer_renderbuffer(
            glow::FRAMEBUFFER,
            glow::COLOR_ATTACHMENT0,
            glow::RENDERBUFFER,
            Some(rb),
        );
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        gl.bind_framebuffer(glow::FRAMEBUFFER, drawing.fbo);
        if status != glow::FRAMEBUFFER_COMPLETE {
            return Err(self.failed(&format!("copy framebuffer incomplete ({status:#x})")));
        }
        Ok(())
    }

    /// Copies sample `sample` of attachment `k` into the copy framebuffer,
    /// which is left bound for reading (its attachment 0).
    pub(super) unsafe fn fetch_sample(&self, drawing: &Drawing, k: usize, sample: u32) {
        let gl = &self.gl;
        let (fw, fh) = drawing.size;
        gl.bind_framebuffer(glow::FRAMEBUFFER, drawing.copy);
        gl.draw_buffers(&[glow::COLOR_ATTACHMENT0]);
        gl.disable(glow::SCISSOR_TEST);
        gl.disable(glow::BLEND);
        gl.disable(glow::STENCIL_TEST);
        gl.disable(glow::CULL_FACE);
        gl.color_mask(true, true, true, true);
        gl.viewport(0, 0, fw as i32, fh as i32);
        gl.use_program(Some(self.fetch.program));
        gl.active_texture(glow::TEXTURE0);
        gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, Some(drawing.textures[k]));
        gl.uniform_1_i32(self.fetch.source.as_ref(), 0);
        gl.uniform_1_i32(self.fetch.sample.as_ref(), sample as i32);
        gl.bind_vertex_array(Some(self.fetch.vao));
        gl.draw_arrays(glow::TRIANGLES, 0, 3);
        gl.bind_vertex_array(None);
        gl.bind_texture(glow::TEXTURE_2D_MULTISAMPLE, None);
        gl.read_buffer(glow::COLOR_ATTACHMENT0);
    }
}
