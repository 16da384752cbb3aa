//! One scene set up in the shared context: its passes' vertex streams
//! uploaded, its framebuffer of float attachments (and a stencil buffer
//! where it has polygons) made; cleared, drawn and deleted.
//!
//! Each run of the stream is drawn with the state its kind needs:
//!
//! - **triangles**: colour on, the case's culling, no stencil test;
//! - **lines**: colour on, `GL_LINES` at the run's width (never culled);
//! - **stencil** (a polygon's fan): colour writes off, no culling, the
//!   stencil test always passing; nonzero counts the winding, front faces
//!   `GL_INCR_WRAP` and back faces `GL_DECR_WRAP`; even-odd `GL_INVERT`s,
//!   so that bit 0 is the parity;
//! - **cover** (the polygon's box): colour on, no culling, drawn where the
//!   stencil is not 0 (mask `0xFF`, nonzero) or where bit 0 is set (mask
//!   `0x01`, even-odd), and every stencil sample under it set back to 0.

use glow::HasContext;

use super::clip::Stage;
use super::context::{gl_error, GlContext};
use super::drawing::Drawing;
use super::passes::{self, DRIVER_BITS};
use super::{lines, msaa, samples, shaders, time};
use crate::adapters::gpu::depth::DepthTarget;
use crate::adapters::gpu::{self, VERTEX_FLOATS};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Cull, Interpolation, PolygonFill, Scene};

impl GlContext {
    /// A scene's tile (the target) and the viewport its screen-space
    /// positions are placed on in it (`gpu/view.rs`), at the case's `bits`:
    /// what [`GlContext::set_up`] draws through and the adapter's
    /// `screen_viewport` reports.
    pub(super) fn placed(
        &self,
        scene: &Scene,
        bits: u32,
    ) -> Result<((u32, u32), gpu::View), RasterError> {
        let tile = gpu::target_size(scene, self.max_side, &self.renderer)?;
        let limits = self.clip.screen_limits(tile, self.max_side);
        let view = gpu::screen_view(scene, bits, bits.max(DRIVER_BITS), tile, &limits);
        Ok((tile, view))
    }

    /// Sets a scene up: uploads its passes' vertex streams into a vertex
    /// array and buffer of its own, and makes a framebuffer of float
    /// attachments (the count, then the channel groups) holding a `P × Q`
    /// tile per pass, and the depth attachment `depth` asks for
    /// (`depth.rs`).
    pub(super) unsafe fn set_up<'a>(
        &self,
        scene: &Scene,
        plan: &'a Plan,
        bits: u32,
        depth: Option<DepthTarget>,
    ) -> Result<Drawing<'a>, RasterError> {
        if let Some(why) = self.clip.refusal(scene) {
            return Err(RasterError::Unsupported(why));
        }
        if let Some(why) = depth.and_then(|t| self.depth_refusal(scene, &t)) {
            return Err(RasterError::Unsupported(why));
        }
        let (tile, view) = self.placed(scene, bits)?;
        let groups = gpu::groups(plan);
        let layout = self.layout(scene, plan, bits, (tile, view), depth.is_some())?;
        let stencils = layout.stencils();
        let off_the_integers = layout.corners.iter().flatten().any(|c| c.fract() != 0.0);
        if off_the_integers && scene.viewport.is_none() && !self.clip.float_viewports {
            return Err(RasterError::Unsupported(
                "shifted passes move the viewport by a fraction of a pixel, which needs \
                 glViewportIndexedf (GL 4.1, ARB_viewport_array): the context offers \
                 neither"
                    .to_owned(),
            ));
        }
        let passes::Layout {
            vertices,
            streams,
            corners,
            passes,
            size,
            reading,
        } = layout;
        let gl = &self.gl;
        let _ = gl_error(gl);

        let mut drawing = Drawing {
            plan,
            canvas: (scene.canvas.width, scene.canvas.height),
            target: tile,
            view,
            size,
            cull: scene.rules.cull,
            stage: Stage::of(scene),
            streams,
            corners,
            passes,
            samples: reading.target_samples(),
            reading,
            vao: gl.create_vertex_array().map_err(|e| self.failed(&e))?,
            vbo: None,
            fbo: None,
            attachments: 1 + groups,
            renderbuffers: Vec::with_capacity(1 + groups),
            textures: Vec::new(),
            stencil: None,
            depth,
            depth_buffer: None,
            copy: None,
        };
        if let Err(e) = self.make(&mut drawing, &vertices, groups, stencils) {
            self.delete(&drawing);
            return Err(e);
        }
        Ok(drawing)
    }

    /// How `scene` is drawn: by time passes if it moves; into a
    /// multisampled target, one sample read, if it has rectangle lines
    /// (refused with a depth attachment, which is single-sample:
    /// `depth.rs`); by native MSAA if its sample pattern is exactly the
    /// driver's, it has no line (llvmpipe draws every line of a
    /// multisampled target as a rectangle) and no depth attachment; else
    /// by shifted passes (one, without antialiasing).
    unsafe fn layout(
        &self,
        scene: &Scene,
        plan: &Plan,
        bits: u32,
        placed: ((u32, u32), gpu::View),
        depth: bool,
    ) -> Result<passes::Layout, RasterError> {
        if let Some(motion) = &plan.motion {
            return time::layout(scene, plan, motion, bits, placed);
        }
        if lines::has_rectangles(scene) {
            if depth {
                return Err(RasterError::Unsupported(
                    "rectangle lines with a depth attachment: they are drawn into a \
                     multisampled target, whose depth cannot be read back sample by \
                     sample without a conversion to float"
                        .to_owned(),
                ));
            }
            return msaa::at_one_sample(scene, plan, bits, placed, &self.offered);
        }
        if let Some(aa) = plan.antialias.as_ref().filter(|_| !depth) {
            if let Some((count, slots)) = samples::native(aa, &self.offered) {
                if !lines::has_lines(scene) {
                    return Ok(msaa::native(scene, bits, placed, count, &slots));
                }
            }
        }
        passes::layout(scene, plan, bits, placed, self.max_side)
    }

    /// Makes the vertex buffer (filled with `vertices`) and the framebuffer
    /// of `drawing`, with a stencil buffer where it `stencils`; what is made
    /// before a failure is left for [`GlContext::delete`].
    unsafe fn make(
        &self,
        drawing: &mut Drawing,
        vertices: &[f32],
        groups: usize,
        stencils: bool,
    ) -> Result<(), RasterError> {
        let gl = &self.gl;
        gl.bind_vertex_array(Some(drawing.vao));
        let vbo = gl.create_buffer().map_err(|e| self.failed(&e))?;
        drawing.vbo = Some(vbo);
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        for i in 0..VERTEX_FLOATS / 4 {
            gl.enable_vertex_attrib_array(i as u32);
            gl.vertex_attrib_pointer_f32(
                i as u32,
                4,
                glow::FLOAT,
                false,
                (VERTEX_FLOATS * 4) as i32,
                (i * 16) as i32,
            );
        }
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, &f32_bytes(vertices), glow::STATIC_DRAW);
        gl.bind_vertex_array(None);

        let fbo = gl.create_framebuffer().map_err(|e| self.failed(&e))?;
        drawing.fbo = Some(fbo);
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        let (fw, fh) = drawing.size;
        if drawing.samples > 0 {
            self.make_multisampled(drawing, groups, stencils)?;
        } else {
            self.make_single_sampled(drawing, groups, stencils);
            self.make_depth(drawing)?;
        }
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        if status != glow::FRAMEBUFFER_COMPLETE {
            return Err(self.failed(&format!(
                "float framebuffer {fw}×{fh} ({} samples) incomplete ({status:#x})",
                drawing.samples
            )));
        }
        if drawing.samples > 0 {
            let granted = gl.get_parameter_i32(glow::SAMPLES);
            if granted != drawing.samples as i32 {
                return Err(self.failed(&format!(
                    "asked for {} samples a pixel, the framebuffer has {granted}",
                    drawing.samples
                )));
            }
        }
        let buffers: Vec<u32> = (0..=groups as u32)
            .map(|k| glow::COLOR_ATTACHMENT0 + k)
            .collect();
        gl.draw_buffers(&buffers);
        self.check("setting up")
    }

    /// Makes single-sample attachments: `groups + 1` float renderbuffers
    /// (the count's, then the groups'), and a stencil one where it
    /// `stencils`.
    unsafe fn make_single_sampled(&self, drawing: &mut Drawing, groups: usize, stencils: bool) {
        let gl = &self.gl;
        let (fw, fh) = drawing.size;
        for k in 0..=groups {
            let Ok(rb) = gl.create_renderbuffer() else {
                return;
            };
            drawing.renderbuffers.push(rb);
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            let format = if k == 0 { glow::R32F } else { glow::RGBA32F };
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, fw as i32, fh as i32);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0 + k as u32,
                glow::RENDERBUFFER,
                Some(rb),
            );
        }
        if stencils {
            let Ok(rb) = gl.create_renderbuffer() else {
                return;
            };
            drawing.stencil = Some(rb);
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            let format = glow::DEPTH24_STENCIL8;
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, fw as i32, fh as i32);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::DEPTH_STENCIL_ATTACHMENT,
                glow::RENDERBUFFER,
                Some(rb),
            );
        }
    }

    /// Binds `drawing`'s framebuffer, in which its draw buffers are kept.
    pub(super) unsafe fn bind_framebuffer(&self, drawing: &Drawing) {
        self.gl.bind_framebuffer(glow::FRAMEBUFFER, drawing.fbo);
    }

    /// Clears every attachment of `drawing`, the stencil to 0, the depth
    /// to 1.
    pub(super) unsafe fn clear(&self, drawing: &Drawing) {
        let gl = &self.gl;
        self.bind_framebuffer(drawing);
        gl.disable(glow::SCISSOR_TEST);
        gl.color_mask(true, true, true, true);
        for k in 0..drawing.attachments as u32 {
            gl.clear_buffer_f32_slice(glow::COLOR, k, &[0.0; 4]);
        }
        if drawing.stencil.is_some() {
            gl.stencil_mask(0xFF);
            gl.clear_buffer_depth_stencil(glow::DEPTH_STENCIL, 0, 1.0, 0);
        }
        if drawing.depth.is_some() {
            gl.depth_mask(true);
            gl.clear_buffer_f32_slice(glow::DEPTH, 0, &[1.0]);
        }
    }

    /// Issues `drawing`'s draw calls into its attachments as they stand:
    /// per pass, its tile's viewport (its corner moved by the pass's
    /// shift) and the canvas's scissor in it (or its
    /// one pixel's, for a time pass), then one `glDrawArrays` per run of its
    /// stream, with the state the run needs (the
    /// context's state is every case's, so it is set each time, and the
    /// depth state put back after). Returns without waiting.
    pub(super) unsafe fn draw(&self, drawing: &Drawing) {
        let gl = &self.gl;
        let ((w, h), (tw, th)) = (drawing.canvas, drawing.target);
        self.bind_framebuffer(drawing);
        gl.enable(glow::SCISSOR_TEST);
        gl.disable(glow::BLEND);
        gl.enable_draw_buffer(glow::BLEND, 0);
        gl.stencil_mask(0xFF);
        self.set_depth_state(drawing);
        gl.bind_vertex_array(Some(drawing.vao));
        for pass in &drawing.passes {
            let (ox, oy) = pass.origin;
            let corner = drawing.corners[pass.stream];
            drawing.stage.set(
                gl,
                self.provoking,
                pass.origin,
                (tw, th),
                (drawing.view, corner),
            );
            match pass.pixel {
                // Canvas row y is window row Q − 1 − y of the tile.
                Some((x, y)) => gl.scissor((ox + x) as i32, (oy + th - 1 - y) as i32, 1, 1),
                None => gl.scissor(ox as i32, (oy + th - h) as i32, w as i32, h as i32),
            }
            for run in &drawing.streams[pass.stream] {
                let mode = self.set_state(run.draw, drawing.cull);
                // Vertex counts are bounded by the primitive limit (SPEC §8).
                gl.draw_arrays(mode, run.first as i32, (run.end - run.first) as i32);
            }
        }
        gl.color_mask(true, true, true, true);
        gl.disable(glow::STENCIL_TEST);
        self.reset_depth_state();
        gl.bind_vertex_array(None);
    }

    /// Sets the state a run of `draw` is drawn with (the module's list),
    /// and returns its primitive mode.
    unsafe fn set_state(&self, draw: gpu::Draw, cull: Cull) -> u32 {
        let gl = &self.gl;
        let program = |mode| match mode {
            Interpolation::Perspective => self.programs[0],
            Interpolation::Linear => self.programs[1],
            Interpolation::Flat => self.programs[2],
        };
        match draw {
            gpu::Draw::Triangles(mode) => {
                gl.color_mask(true, true, true, true);
                gl.disable(glow::STENCIL_TEST);
                set_cull(gl, cull);
                gl.use_program(Some(program(mode)));
                glow::TRIANGLES
            }
            gpu::Draw::Lines {
                width,
                interpolation,
                ..
            } => {
                gl.color_mask(true, true, true, true);
                gl.disable(glow::STENCIL_TEST);
                gl.disable(glow::CULL_FACE);
                gl.line_width(width);
                gl.use_program(Some(program(interpolation)));
                glow::LINES
            }
            gpu::Draw::Points { size } => {
                gl.color_mask(true, true, true, true);
                gl.disable(glow::STENCIL_TEST);
                gl.disable(glow::CULL_FACE);
                // The vertex shader's `gl_PointSize`, from the run's size
                // (`POINT_SIZE_UNIFORM`); glow has no `glPointSize`.
                gl.enable(glow::PROGRAM_POINT_SIZE);
                let flat = program(Interpolation::Flat);
                gl.use_program(Some(flat));
                let at = gl.get_uniform_location(flat, shaders::POINT_SIZE_UNIFORM);
                gl.uniform_1_f32(at.as_ref(), size);
                glow::POINTS
            }
            gpu::Draw::Stencil(fill) => {
                gl.color_mask(false, false, false, false);
                gl.enable(glow::STENCIL_TEST);
                gl.disable(glow::CULL_FACE);
                gl.stencil_func(glow::ALWAYS, 0, 0xFF);
                match fill {
                    PolygonFill::NonZero => {
                        gl.stencil_op_separate(
                            glow::FRONT,
                            glow::KEEP,
                            glow::KEEP,
                            glow::INCR_WRAP,
                        );
                        gl.stencil_op_separate(glow::BACK, glow::KEEP, glow::KEEP, glow::DECR_WRAP);
                    }
                    PolygonFill::EvenOdd => gl.stencil_op(glow::KEEP, glow::KEEP, glow::INVERT),
                }
                gl.use_program(Some(program(Interpolation::Linear)));
                glow::TRIANGLES
            }
            gpu::Draw::Cover(fill) => {
                gl.color_mask(true, true, true, true);
                gl.enable(glow::STENCIL_TEST);
                gl.disable(glow::CULL_FACE);
                let mask = match fill {
                    PolygonFill::NonZero => 0xFF,
                    PolygonFill::EvenOdd => 0x01,
                };
                gl.stencil_func(glow::NOTEQUAL, 0, mask);
                gl.stencil_op(glow::ZERO, glow::ZERO, glow::ZERO);
                gl.use_program(Some(program(Interpolation::Linear)));
                glow::TRIANGLES
            }
        }
    }

    /// Deletes `drawing`'s objects.
    pub(super) unsafe fn delete(&self, drawing: &Drawing) {
        let gl = &self.gl;
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        if let Some(fbo) = drawing.fbo {
            gl.delete_framebuffer(fbo);
        }
        if let Some(copy) = drawing.copy {
            gl.delete_framebuffer(copy);
        }
        for &rb in drawing
            .renderbuffers
            .iter()
            .chain(&drawing.stencil)
            .chain(&drawing.depth_buffer)
        {
            gl.delete_renderbuffer(rb);
        }
        for &texture in &drawing.textures {
            gl.delete_texture(texture);
        }
        if let Some(vbo) = drawing.vbo {
            gl.delete_buffer(vbo);
        }
        gl.delete_vertex_array(drawing.vao);
    }
}

/// The case's culling: GL reads the winding in window coordinates (y up)
/// and the read-back flips the rows, so the winding seen is the case's
/// (the module's notes); `glFrontFace(GL_CCW)`.
unsafe fn set_cull(gl: &glow::Context, cull: Cull) {
    match cull {
        Cull::None => gl.disable(glow::CULL_FACE),
        Cull::Clockwise => {
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::BACK);
        }
        Cull::CounterClockwise => {
            gl.enable(glow::CULL_FACE);
            gl.cull_face(glow::FRONT);
        }
    }
}

pub(super) fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}
