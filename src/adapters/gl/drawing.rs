//! One scene set up in the shared context: its vertex stream uploaded, its
//! framebuffer of float attachments made; cleared, drawn and deleted.

use glow::HasContext;

use super::context::{gl_error, GlContext};
use crate::adapters::gpu::{self, VERTEX_FLOATS};
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Cull, Interpolation, Scene};

impl GlContext {
    /// Sets a scene up: uploads its vertex stream into a vertex array and
    /// buffer of its own, and makes a framebuffer of `P × Q` float
    /// attachments (the count, then the channel groups).
    pub(super) unsafe fn set_up<'a>(
        &self,
        scene: &Scene,
        plan: &'a Plan,
        bits: u32,
    ) -> Result<Drawing<'a>, RasterError> {
        let (tw, th) = gpu::target_size(scene, self.max_side, &self.renderer)?;
        let groups = gpu::groups(plan);
        let gpu::Stream { vertices, runs } =
            gpu::Stream::new(scene, &gpu::Placement::at_centres(bits, (tw, th)));
        let gl = &self.gl;
        let _ = gl_error(gl);

        let mut drawing = Drawing {
            plan,
            canvas: (scene.canvas.width, scene.canvas.height),
            target: (tw, th),
            cull: scene.rules.cull,
            runs,
            vao: gl.create_vertex_array().map_err(|e| self.failed(&e))?,
            vbo: None,
            fbo: None,
            renderbuffers: Vec::with_capacity(1 + groups),
        };
        if let Err(e) = self.make(&mut drawing, &vertices, groups) {
            self.delete(&drawing);
            return Err(e);
        }
        Ok(drawing)
    }

    /// Makes the vertex buffer (filled with `vertices`) and the framebuffer
    /// of `drawing`; what is made before a failure is left for
    /// [`GlContext::delete`].
    pub(super) unsafe fn make(
        &self,
        drawing: &mut Drawing,
        vertices: &[f32],
        groups: usize,
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
        let (tw, th) = drawing.target;
        for k in 0..=groups {
            let rb = gl.create_renderbuffer().map_err(|e| self.failed(&e))?;
            drawing.renderbuffers.push(rb);
            gl.bind_renderbuffer(glow::RENDERBUFFER, Some(rb));
            let format = if k == 0 { glow::R32F } else { glow::RGBA32F };
            gl.renderbuffer_storage(glow::RENDERBUFFER, format, tw as i32, th as i32);
            gl.framebuffer_renderbuffer(
                glow::FRAMEBUFFER,
                glow::COLOR_ATTACHMENT0 + k as u32,
                glow::RENDERBUFFER,
                Some(rb),
            );
        }
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        if status != glow::FRAMEBUFFER_COMPLETE {
            return Err(self.failed(&format!(
                "float framebuffer {tw}×{th} incomplete ({status:#x})"
            )));
        }
        let buffers: Vec<u32> = (0..=groups as u32)
            .map(|k| glow::COLOR_ATTACHMENT0 + k)
            .collect();
        gl.draw_buffers(&buffers);
        self.check("setting up")
    }

    /// Binds `drawing`'s framebuffer, in which its draw buffers are kept.
    pub(super) unsafe fn bind_framebuffer(&self, drawing: &Drawing) {
        self.gl.bind_framebuffer(glow::FRAMEBUFFER, drawing.fbo);
    }

    /// Clears every attachment of `drawing`.
    pub(super) unsafe fn clear(&self, drawing: &Drawing) {
        let gl = &self.gl;
        self.bind_framebuffer(drawing);
        gl.disable(glow::SCISSOR_TEST);
        for k in 0..drawing.renderbuffers.len() as u32 {
            gl.clear_buffer_f32_slice(glow::COLOR, k, &[0.0; 4]);
        }
    }

    /// Issues `drawing`'s draw calls into its attachments as they stand:
    /// the viewport, scissor, blending and culling its scene asks for (the
    /// context's state is every case's, so it is set each time), then one
    /// `glDrawArrays` per run of triangles. Returns without waiting.
    pub(super) unsafe fn draw(&self, drawing: &Drawing) {
        let gl = &self.gl;
        let ((w, h), (tw, th)) = (drawing.canvas, drawing.target);
        self.bind_framebuffer(drawing);
        gl.viewport(0, 0, tw as i32, th as i32);
        gl.enable(glow::SCISSOR_TEST);
        gl.scissor(0, (th - h) as i32, w as i32, h as i32);
        gl.disable(glow::BLEND);
        gl.enable_draw_buffer(glow::BLEND, 0);
        match drawing.cull {
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
        gl.bind_vertex_array(Some(drawing.vao));
        for run in &drawing.runs {
            // The adapter refuses lines and polygons (`accepted`).
            let gpu::Draw::Triangles(mode) = run.draw else {
                continue;
            };
            let (a, b) = (run.first, run.end);
            let program = match mode {
                Interpolation::Perspective => self.programs[0],
                Interpolation::Linear => self.programs[1],
                Interpolation::Flat => self.programs[2],
            };
            gl.use_program(Some(program));
            // Vertex counts are bounded by the primitive limit (SPEC §8).
            gl.draw_arrays(glow::TRIANGLES, a as i32, (b - a) as i32);
        }
        gl.bind_vertex_array(None);
    }

    /// Deletes `drawing`'s objects.
    pub(super) unsafe fn delete(&self, drawing: &Drawing) {
        let gl = &self.gl;
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        if let Some(fbo) = drawing.fbo {
            gl.delete_framebuffer(fbo);
        }
        for &rb in &drawing.renderbuffers {
            gl.delete_renderbuffer(rb);
        }
        if let Some(vbo) = drawing.vbo {
            gl.delete_buffer(vbo);
        }
        gl.delete_vertex_array(drawing.vao);
    }
}

/// One scene set up in the shared context: its vertex stream in a vertex
/// array and buffer of its own, and its framebuffer of float attachments,
/// so that it can be cleared, drawn and read back again and again while
/// other cases use the context in between.
pub(super) struct Drawing<'a> {
    pub(super) plan: &'a Plan,
    pub(super) canvas: (u32, u32),
    /// The attachments' power-of-two size.
    pub(super) target: (u32, u32),
    pub(super) cull: Cull,
    /// The runs of consecutive vertices (first, end) of one interpolation
    /// mode: one draw call each.
    pub(super) runs: Vec<gpu::Run>,
    pub(super) vao: glow::VertexArray,
    pub(super) vbo: Option<glow::Buffer>,
    pub(super) fbo: Option<glow::Framebuffer>,
    /// The count's, then the channel groups'.
    pub(super) renderbuffers: Vec<glow::Renderbuffer>,
}

pub(super) fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}
