//! Reading a drawing's tiles back into a [`Frame`]: pass s fills sample
//! slot s of every pixel (`p · N + s`); an antialiased frame is then box
//! resolved.

use glow::HasContext;

use super::context::GlContext;
use super::drawing::Drawing;
use crate::frame::Frame;
use crate::rasterizer::RasterError;

impl GlContext {
    /// Reads each pass's canvas (the top `W × H` of its tile) back,
    /// flipping the rows, into its slot of a frame: the counts, the last
    /// primitives, and where covered the depth and attributes.
    /// `glReadPixels` waits for the drawing.
    pub(super) unsafe fn read_back(&self, drawing: &Drawing) -> Result<Frame, RasterError> {
        let (w, h) = drawing.canvas;
        let plan = drawing.plan;
        let mut frame = Frame::for_plan(w, h, plan);
        let samples = drawing.passes.len();
        for (s, pass) in drawing.passes.iter().enumerate() {
            let (ox, oy) = pass.origin;
            let rect = (ox, oy + drawing.target.1 - h);
            self.read_pass(drawing, rect, &mut frame, s, samples)?;
        }
        if plan.antialias.is_some() {
            frame.resolve();
        }
        Ok(frame)
    }

    /// Reads the canvas whose lower-left window corner is `corner` into
    /// slot `slot` of each of `frame`'s pixels (`samples` per pixel).
    unsafe fn read_pass(
        &self,
        drawing: &Drawing,
        corner: (u32, u32),
        frame: &mut Frame,
        slot: usize,
        samples: usize,
    ) -> Result<(), RasterError> {
        let gl = &self.gl;
        let (w, h) = drawing.canvas;
        let groups = drawing.renderbuffers.len() as u32 - 1;
        self.bind_framebuffer(drawing);
        let n = w as usize * h as usize;
        let read = |k: u32, components: usize| -> Vec<f32> {
            let mut bytes = vec![0u8; n * components * 4];
            gl.read_buffer(glow::COLOR_ATTACHMENT0 + k);
            gl.read_pixels(
                corner.0 as i32,
                corner.1 as i32,
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

        let channel = |c: usize, i: usize| values[c / 4][i * 4 + c % 4];
        for (i, &c) in counts.iter().enumerate() {
            if c.fract() != 0.0 || !(0.0..=65535.0).contains(&c) {
                return Err(self.failed(&format!(
                    "coverage count {c} read back at pixel {i}, sample {slot}"
                )));
            }
            let at = i * samples + slot;
            frame.coverage[at] = c as u16;
            frame.last[at] = channel(0, i) as u32;
            if c > 0.0 {
                if let Some(depth) = &mut frame.depth {
                    depth[at] = f64::from(channel(1, i));
                }
                for (k, a) in frame.attributes.iter_mut().enumerate() {
                    a[at] = f64::from(channel(2 + k, i));
                }
            }
        }
        Ok(())
    }
}
