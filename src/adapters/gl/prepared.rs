//! A scene set up once and cleared, drawn and read back phase by phase:
//! what the bench times as the driver's own draw.

use glow::HasContext;

use super::accepted::accepted;
use super::context::{with_context, GlContext};
use super::drawing::Drawing;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Prepared, RasterError};
use crate::scene::Scene;

/// A scene set up in the shared context, to be cleared, drawn and read back
/// again and again: the bench's view of the driver's own draw. The context
/// is locked and made current for each phase, not held between them, so
/// that a whole call (the bench's own, or another case's) can run in
/// between; the scene's objects are its own, untouched by it, and deleted
/// when it is dropped.
struct PreparedGl<'a> {
    drawing: Drawing<'a>,
}

/// Sets `scene` up, its upload finished (`glFinish`) before it returns.
pub(super) fn prepare<'a>(
    scene: &Scene,
    plan: &'a Plan,
    softpipe: bool,
) -> Result<Box<dyn Prepared + 'a>, RasterError> {
    let (bits, depth) = accepted(scene, plan, softpipe)?;
    let drawing = with_context(|gl| {
        gl.insist_on_softpipe(softpipe)?;
        // SAFETY: GL calls on the context current on this thread.
        unsafe {
            let drawing = gl.set_up(scene, plan, bits, depth)?;
            gl.gl.finish();
            Ok(drawing)
        }
    })?;
    Ok(Box::new(PreparedGl { drawing }))
}

impl PreparedGl<'_> {
    /// Runs one phase on the drawing, with the context current.
    fn phase<T>(
        &self,
        f: impl FnOnce(&GlContext, &Drawing) -> Result<T, RasterError>,
    ) -> Result<T, RasterError> {
        with_context(|gl| f(gl, &self.drawing))
    }
}

impl Prepared for PreparedGl<'_> {
    /// Clears every attachment, and waits (`glFinish`).
    fn clear(&mut self) -> Result<(), RasterError> {
        // SAFETY: GL calls on the context current on this thread.
        self.phase(|gl, drawing| unsafe {
            gl.clear(drawing);
            gl.gl.finish();
            gl.check("clearing")
        })
    }

    /// The draw calls into the attachments as they stand (no clear), and
    /// `glFinish`: the state the draw needs is set too, as the context is
    /// shared, but nothing is uploaded or read.
    fn draw(&mut self) -> Result<(), RasterError> {
        // SAFETY: GL calls on the context current on this thread.
        self.phase(|gl, drawing| unsafe {
            gl.draw(drawing);
            gl.gl.finish();
            gl.check("drawing")
        })
    }

    /// Reads the attachments back as a whole call does (`glReadPixels`
    /// waits for any drawing still pending).
    fn read_back(&mut self) -> Result<Frame, RasterError> {
        // SAFETY: GL calls on the context current on this thread, with
        // buffers sized to what is read.
        self.phase(|gl, drawing| unsafe { gl.read_back(drawing) })
    }
}

impl Drop for PreparedGl<'_> {
    fn drop(&mut self) {
        // SAFETY: deleting the drawing's own objects, the context current.
        let _ = self.phase(|gl, drawing| {
            unsafe { gl.delete(drawing) };
            Ok(())
        });
    }
}
