//! Reading a drawing's attachments back into a [`Frame`].

use glow::HasContext;

use super::context::GlContext;
use super::drawing::Drawing;
use crate::frame::Frame;
use crate::rasterizer::RasterError;

impl GlContext {
    /// Reads the canvas (the top `W × H` of the attachments) back, flipping
    /// the rows, into a frame: the counts, the last primitives, and where
    /// covered the depth and attributes. `glReadPixels` waits for the
    /// drawing.
    pub(super) unsafe fn read_back(&self, drawing: &Drawing) -> Result<Frame, RasterError> {
        let gl = &self.gl;
        let ((w, h), th) = (drawing.canvas, drawing.target.1);
        let groups = drawing.renderbuffers.len() as u32 - 1;
        self.bind_framebuffer(drawing);
        let n = w as usize * h as usize;
        let read = |k: u32, components: usize| -> Vec<f32> {
            let mut bytes = vec![0u8; n * components * 4];
            gl.read_buffer(glow::COLOR_ATTACHMENT0 + k);
            gl.read_pixels(
                0,
                (th - h) as i32,
                w as i32,
                h as i32,
                if components == 1 {
                    glow::RED
                } else {
                    glow::RGBA
                },
                glow::FLOAT,
                glow::PixelPackData::Slice(Some(&mut bytes)),
            );
            let row = w as usize * components;
            let mut out = Vec::with_capacity(n * components);
            for y in (0..h as usize).rev() {
                out.extend(
                    bytes[y * row * 4..(y + 1) * row * 4]
                        .chunks_exact(4)
                        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                );
            }
            out
        };
        let counts = read(0, 1);
        let values: Vec<Vec<f32>> = (1..=groups).map(|k| read(k, 4)).collect();
        self.check("drawing and reading back")?;

        let plan = drawing.plan;
        let mut frame = Frame::new(w, h, plan.depth, plan.attributes);
        let channel = |c: usize, i: usize| values[c / 4][i * 4 + c % 4];
        for i in 0..n {
            let c = counts[i];
            if c.fract() != 0.0 || !(0.0..=65535.0).contains(&c) {
                return Err(self.failed(&format!("coverage count {c} read back at sample {i}")));
            }
            frame.coverage[i] = c as u16;
            frame.last[i] = channel(0, i) as u32;
            if c > 0.0 {
                if let Some(depth) = &mut frame.depth {
                    depth[i] = f64::from(channel(1, i));
                }
                for (k, a) in frame.attributes.iter_mut().enumerate() {
                    a[i] = f64::from(channel(2 + k, i));
                }
            }
        }
        Ok(frame)
    }
}
