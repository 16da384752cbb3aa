//! Reading a drawing's tiles back into a [`Frame`]: pass s fills sample
//! slot s of every pixel (`p · N + s`), or a multisampled drawing's
//! samples each fill the slot they are read into (`msaa.rs` fetches each
//! one into a single-sample copy first), an antialiased frame then box
//! resolved; or, for time passes, the one tile's counts over the M·N
//! tests are each pixel's time coverage.

use glow::HasContext;

use super::context::GlContext;
use super::drawing::Drawing;
use super::passes::Reading;
use crate::adapters::gpu::depth::stored_value;
use crate::frame::Frame;
use crate::rasterizer::RasterError;

impl GlContext {
    /// Reads each pass's canvas (the top `W × H` of its tile) back,
    /// flipping the rows, into its slot of a frame: the counts, the last
    /// primitives, and where covered the depth and attributes; or the time
    /// coverage. `glReadPixels` waits for the drawing.
    pub(super) unsafe fn read_back(&self, drawing: &Drawing) -> Result<Frame, RasterError> {
        let (w, h) = drawing.canvas;
        let corner = |origin: (u32, u32)| (origin.0, origin.1 + drawing.target.1 - h);
        if let Reading::Time { tests } = drawing.reading {
            let counts = self.read_canvas(drawing, corner((0, 0)), 0, 1, None);
            self.check("drawing and reading back")?;
            let limit = 16_777_216.0;
            let time = counts
                .iter()
                .enumerate()
                .map(|(i, &c)| {
                    self.count(c, limit, i, None)
                        .map(|c| f64::from(c) / f64::from(tests))
                })
                .collect::<Result<Vec<f64>, RasterError>>()?;
            return Ok(Frame {
                method: Some("time passes"),
                ..Frame::time_only(w, h, time)
            });
        }
        let plan = drawing.plan;
        let mut frame = Frame::for_plan(w, h, plan);
        let samples = frame.samples as usize;
        match &drawing.reading {
            Reading::Samples { read, .. } => {
                for &(sample, slot) in read {
                    let at = (corner((0, 0)), Some(sample));
                    self.read_pass(drawing, at, &mut frame, slot, samples)?;
                }
            }
            _ => {
                for (s, pass) in drawing.passes.iter().enumerate() {
                    let at = (corner(pass.origin), None);
                    self.read_pass(drawing, at, &mut frame, s, samples)?;
                }
            }
        }
        let native = matches!(drawing.reading, Reading::Samples { .. });
        frame.method = match (native, plan.antialias.is_some()) {
            (true, true) => Some("native MSAA"),
            (true, false) => Some("one sample of a multisampled target"),
            (false, true) => Some("shifted passes"),
            (false, false) => None,
        };
        if plan.antialias.is_some() {
            frame.resolve();
        }
        Ok(frame)
    }

    /// Attachment `k`'s canvas whose lower-left window corner is `corner`,
    /// `components` floats a texel, its rows flipped (y down); of a
    /// multisampled drawing, its sample `sample`, fetched first.
    unsafe fn read_canvas(
        &self,
        drawing: &Drawing,
        corner: (u32, u32),
        k: u32,
        components: usize,
        sample: Option<u32>,
    ) -> Vec<f32> {
        let gl = &self.gl;
        let (w, h) = drawing.canvas;
        let n = w as usize * h as usize;
        match sample {
            Some(sample) => self.fetch_sample(drawing, k as usize, sample),
            None => {
                self.bind_framebuffer(drawing);
                gl.read_buffer(glow::COLOR_ATTACHMENT0 + k);
            }
        }
        let mut bytes = vec![0u8; n * components * 4];
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
    }

    /// A count read back, checked: a whole number of covers, at most
    /// `limit`.
    fn count(
        &self,
        c: f32,
        limit: f32,
        pixel: usize,
        slot: Option<usize>,
    ) -> Result<f32, RasterError> {
        if c.fract() != 0.0 || !(0.0..=limit).contains(&c) {
            let slot = slot.map_or(String::new(), |s| format!(", sample {s}"));
            return Err(self.failed(&format!(
                "coverage count {c} read back at pixel {pixel}{slot}"
            )));
        }
        Ok(c)
    }

    /// Reads the canvas whose lower-left window corner is `corner` (of a
    /// multisampled drawing, its sample given) into slot `slot` of each of
    /// `frame`'s pixels (`samples` per pixel). With a depth attachment
    /// (single-sample only, `depth.rs`) a covered sample's depth is the
    /// attachment's stored value, not the depth channel.
    unsafe fn read_pass(
        &self,
        drawing: &Drawing,
        (corner, sample): ((u32, u32), Option<u32>),
        frame: &mut Frame,
        slot: usize,
        samples: usize,
    ) -> Result<(), RasterError> {
        let groups = drawing.attachments as u32 - 1;
        let counts = self.read_canvas(drawing, corner, 0, 1, sample);
        let values: Vec<Vec<f32>> = (1..=groups)
            .map(|k| self.read_canvas(drawing, corner, k, 4, sample))
            .collect();
        let stored: Option<Vec<f64>> = match (&drawing.depth, &frame.depth) {
            (Some(target), Some(_)) => {
                debug_assert!(sample.is_none(), "a depth attachment is single-sample");
                let words = self.read_depth(drawing, target, corner);
                Some(
                    words
                        .into_iter()
                        .map(|w| stored_value(target.format, w))
                        .collect(),
                )
            }
            _ => None,
        };
        self.check("drawing and reading back")?;

        let channel = |c: usize, i: usize| values[c / 4][i * 4 + c % 4];
        for (i, &c) in counts.iter().enumerate() {
            let c = self.count(c, 65535.0, i, Some(slot))?;
            let at = i * samples + slot;
            frame.coverage[at] = c as u16;
            frame.last[at] = channel(0, i) as u32;
            if c > 0.0 {
                if let Some(depth) = &mut frame.depth {
                    depth[at] = match &stored {
                        Some(stored) => stored[i],
                        None => f64::from(channel(1, i)),
                    };
                }
                for (k, a) in frame.attributes.iter_mut().enumerate() {
                    a[at] = f64::from(channel(2 + k, i));
                }
            }
        }
        Ok(())
    }
}
