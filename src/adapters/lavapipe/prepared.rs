//! lavapipe's prepared path: one scene set up once ([`Gpu::set_up`], the
//! same conversion, upload, targets and pipelines as a whole call's), then
//! cleared, drawn and read back one submission at a time, each waited for,
//! so that `rastercheck bench` can time the driver's draw apart from the
//! adapter's work around it. Every scene `rasterize` draws is covered,
//! antialiased ones too (their samples are spread out in the read-back).
//!
//! The shared device's mutex is taken for each phase, not held between
//! them, so that a whole call on the same device (the bench's own, or
//! another case's) can run between two phases; the prepared scene's
//! buffers and targets are its own, untouched by it.

use std::sync::Mutex;

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Prepared, RasterError};
use crate::scene::Scene;

use super::device::Gpu;
use super::draw::{Drawing, Passes, Scopes};
use super::refusals::accepted;
use super::shared::{gpu, lock};

/// A scene set up on the shared device, to be cleared, drawn and read back
/// again and again.
pub(super) struct PreparedLavapipe<'a> {
    gpu: &'static Mutex<Gpu>,
    drawing: Drawing<'a>,
}

/// Sets `scene` up and waits until its vertex stream is uploaded, so that
/// no later phase copies it.
pub(super) fn prepare<'a>(
    scene: &Scene,
    plan: &'a Plan,
) -> Result<PreparedLavapipe<'a>, RasterError> {
    let bits = accepted(scene, plan)?;
    let gpu = gpu().map_err(|why| RasterError::Failed(why.clone()))?;
    let drawing = {
        let mut device = lock(gpu);
        let scopes = Scopes::open(&device.device);
        let drawing = device.set_up(scene, plan, bits)?;
        // The upload was written into the queue; an empty submission
        // carries it out.
        drawing.finish(scopes, drawing.encoder(), None)?;
        drawing
    };
    Ok(PreparedLavapipe { gpu, drawing })
}

impl PreparedLavapipe<'_> {
    /// Records the passes `passes` asks for, submits them and waits.
    fn submit(&self, passes: Passes) -> Result<(), RasterError> {
        let device = lock(self.gpu);
        let scopes = Scopes::open(&device.device);
        let mut encoder = self.drawing.encoder();
        self.drawing.record(&mut encoder, passes);
        self.drawing.finish(scopes, encoder, None)
    }
}

impl Prepared for PreparedLavapipe<'_> {
    /// One submission of render passes that clear every target and draw
    /// nothing.
    fn clear(&mut self) -> Result<(), RasterError> {
        self.submit(Passes::Clear)
    }

    /// One submission of the render passes that draw every run of
    /// triangles into the targets as they stand (`LoadOp::Load`), and the
    /// wait for the device to finish them.
    fn draw(&mut self) -> Result<(), RasterError> {
        self.submit(Passes::Draw)
    }

    /// One submission of the copies out (after spreading a 4× target's
    /// samples), waited for, mapped and decoded as a whole call's frame is.
    fn read_back(&mut self) -> Result<Frame, RasterError> {
        let device = lock(self.gpu);
        let scopes = Scopes::open(&device.device);
        let mut encoder = self.drawing.encoder();
        let read_back = self.drawing.record_read_back(&mut encoder);
        self.drawing.finish(scopes, encoder, Some(&read_back))?;
        self.drawing.decode(&read_back)
    }
}
