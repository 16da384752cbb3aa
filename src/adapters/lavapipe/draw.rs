//! Drawing one scene on lavapipe: a [`Drawing`] set up once (the vertex
//! stream uploaded, targets of the canvas's power-of-two size made,
//! single-sample or 4× MSAA, and the pipelines chosen), whose passes are
//! then recorded to clear the targets, draw into them, or both, and whose
//! targets are read back (a 4× target with each sample spread to its own
//! texel first). [`Gpu::render`] records it all in one command buffer and
//! submits, waits for and reads back once; `prepared.rs` runs the phases
//! one submission each. The pipelines are `pipelines.rs`'s; decoding the
//! bytes is `readback.rs`'s.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

use super::super::gpu::{self, VERTEX_FLOATS};
use super::device::Gpu;
use super::readback::{self, copy_out, read_rows};
use super::unpack::{Unpack, MSAA};

/// The error scopes of one submission's work, open from before its first
/// command (or buffer) is made until it has been waited for.
pub(super) struct Scopes {
    // Dropped (and so popped) in this order on an early return, the
    // reverse of how they were pushed.
    oom: wgpu::ErrorScopeGuard,
    scope: wgpu::ErrorScopeGuard,
}

impl Scopes {
    pub(super) fn open(device: &wgpu::Device) -> Scopes {
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        Scopes { oom, scope }
    }

    /// Closes the scopes, with what they caught as the error.
    fn close(self) -> Result<(), RasterError> {
        if let Some(e) = pollster::block_on(self.oom.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: out of memory: {e}")));
        }
        if let Some(e) = pollster::block_on(self.scope.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: wgpu error: {e}")));
        }
        Ok(())
    }
}

/// What recording the passes does to the targets.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Passes {
    /// Clears them and draws nothing.
    Clear,
    /// Draws into them as they stand.
    Draw,
    /// Clears them, then draws: the whole call's one frame.
    ClearAndDraw,
}

/// One scene set up on the device: its vertex stream uploaded, its targets
/// made, and the pipeline of every run of triangles in every channel group
/// chosen, so that its passes can be recorded again and again.
pub(super) struct Drawing<'a> {
    device: wgpu::Device,
    queue: wgpu::Queue,
    plan: &'a Plan,
    vertex_buffer: wgpu::Buffer,
    /// Per channel group, the pipeline of each run of triangles and the
    /// run's vertices (first, end).
    passes: Vec<Vec<(wgpu::RenderPipeline, u32, u32)>>,
    /// The additive count, and the channel groups.
    count: wgpu::Texture,
    values: Vec<wgpu::Texture>,
    count_format: wgpu::TextureFormat,
    canvas: (u32, u32),
    /// 1, or [`MSAA`] for an antialiased scene, whose samples `unpack`
    /// spreads out before they are read back.
    samples: u32,
    unpack: Option<Unpack>,
}

/// The mapped-to-be buffers one read-back copies the targets into, and the
/// size of the image they hold (4× wider than the canvas under MSAA).
pub(super) struct ReadBack {
    count: (wgpu::Buffer, u32),
    values: Vec<(wgpu::Buffer, u32)>,
    size: (u32, u32),
}

impl Gpu {
    /// Sets a scene up: uploads its vertex stream (written into the
    /// queue, so copied by the next submission), makes its targets
    /// (single-sample, or 4× multisampled for an antialiased plan, whose
    /// offsets are Vulkan's standard 4×, checked by the caller), and
    /// chooses its pipelines. Call within [`Scopes`].
    pub(super) fn set_up<'a>(
        &mut self,
        scene: &Scene,
        plan: &'a Plan,
        bits: u32,
    ) -> Result<Drawing<'a>, RasterError> {
        let samples = if plan.antialias.is_some() { MSAA } else { 1 };
        let (w, h) = (scene.canvas.width, scene.canvas.height);
        let (tw, th) = gpu::target_size(scene, self.max_side, "the lavapipe adapter")?;
        if samples > 1 {
            self.check_msaa(scene, plan)?;
        }
        let groups = gpu::groups(plan);
        let gpu::Stream { vertices, runs, .. } = gpu::Stream::new(
            scene,
            &gpu::Placement::at_centres(bits, gpu::View::target((tw, th))),
        );

        let vertex_buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("vertices"),
            size: (vertices.len().max(VERTEX_FLOATS) * 4) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        if !vertices.is_empty() {
            self.queue
                .write_buffer(&vertex_buffer, 0, f32_bytes(&vertices).as_slice());
        }
        let (count_format, value_format, usage) = if samples == 1 {
            let copy = wgpu::TextureUsages::COPY_SRC;
            (self.count_format, wgpu::TextureFormat::Rgba32Float, copy)
        } else {
            let binding = wgpu::TextureUsages::TEXTURE_BINDING;
            (self.msaa.count, self.msaa.values, binding)
        };
        let count = target(&self.device, count_format, (tw, th), samples, usage);
        let values = (0..groups)
            .map(|_| target(&self.device, value_format, (tw, th), samples, usage))
            .collect();
        let cull = scene.rules.cull;
        let passes = (0..groups)
            .map(|g| {
                // The adapter refuses lines and polygons (`accepted`).
                runs.iter()
                    .filter_map(|run| match run.draw {
                        gpu::Draw::Triangles(mode) => {
                            Some((self.pipeline(mode, g, cull, samples), run.first, run.end))
                        }
                        _ => None,
                    })
                    .collect()
            })
            .collect();
        let unpack = (samples > 1).then(|| self.unpack().clone());
        Ok(Drawing {
            device: self.device.clone(),
            queue: self.queue.clone(),
            plan,
            vertex_buffer,
            passes,
            count,
            values,
            count_format,
            canvas: (w, h),
            samples,
            unpack,
        })
    }

    /// Why an antialiased scene cannot be drawn here, if it cannot: its
    /// samples are read back through a target 4× wider than the canvas, and
    /// where the adapter multisamples no four-channel f32 format the
    /// channels hold primitive + 1 only, and only up to 2048.
    fn check_msaa(&self, scene: &Scene, plan: &Plan) -> Result<(), RasterError> {
        let w = scene.canvas.width;
        if u64::from(w) * u64::from(MSAA) > u64::from(self.max_side) {
            return Err(RasterError::Unsupported(format!(
                "canvas width {w}: its {MSAA} samples per pixel are read back through a target \
                 {MSAA}× wider, and the lavapipe adapter draws at most {}",
                self.max_side
            )));
        }
        if !self.msaa.exact_values() {
            if plan.interpolates() {
                return Err(RasterError::Unsupported(format!(
                    "depth and attributes under MSAA: the adapter multisamples no \
                     four-channel f32 format, and {:?} holds them to 11 bits",
                    self.msaa.values
                )));
            }
            if scene.triangles().count() > 2047 {
                return Err(RasterError::Unsupported(format!(
                    "over 2047 triangles under MSAA: primitive + 1 is read back in {:?}, \
                     exact only up to 2048",
                    self.msaa.values
                )));
            }
        }
        Ok(())
    }

    /// Draws a scene and reads the canvas back: the set-up, the clearing
    /// draw and the read-back recorded in one command buffer, submitted,
    /// waited for and read back once.
    pub(super) fn render(
        &mut self,
        scene: &Scene,
        plan: &Plan,
        bits: u32,
    ) -> Result<Frame, RasterError> {
        let scopes = Scopes::open(&self.device);
        let drawing = self.set_up(scene, plan, bits)?;
        let mut encoder = drawing.encoder();
        drawing.record(&mut encoder, Passes::ClearAndDraw);
        let read_back = drawing.record_read_back(&mut encoder);
        drawing.finish(scopes, encoder, Some(&read_back))?;
        drawing.decode(&read_back)
    }
}

impl Drawing<'_> {
    pub(super) fn encoder(&self) -> wgpu::CommandEncoder {
        self.device.create_command_encoder(&Default::default())
    }

    /// Records one render pass per channel group (the count target too, in
    /// group 0), scissored to the canvas, that clears the targets, draws
    /// the scene's runs of triangles into them, or both.
    pub(super) fn record(&self, encoder: &mut wgpu::CommandEncoder, passes: Passes) {
        let load = if passes == Passes::Draw {
            wgpu::LoadOp::Load
        } else {
            wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT)
        };
        for (g, (value, runs)) in self.values.iter().zip(&self.passes).enumerate() {
            let count_view = self.count.create_view(&Default::default());
            let value_view = value.create_view(&Default::default());
            let attachments = if g == 0 {
                vec![attachment(&count_view, load), attachment(&value_view, load)]
            } else {
                vec![attachment(&value_view, load)]
            };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("rastercheck lavapipe"),
                color_attachments: &attachments,
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            if passes == Passes::Clear {
                continue;
            }
            pass.set_scissor_rect(0, 0, self.canvas.0, self.canvas.1);
            pass.set_vertex_buffer(0, self.vertex_buffer.slice(..));
            for (pipeline, a, b) in runs {
                pass.set_pipeline(pipeline);
                pass.draw(*a..*b, 0..1);
            }
        }
    }

    /// Records the copies of the canvas out of the targets into mappable
    /// buffers. A 4× target is first spread over a non-multisampled one 4×
    /// wider (texel (4x + s, y) holds sample s of pixel (x, y), which is
    /// slot 4·p + s of the frame), and that is copied.
    pub(super) fn record_read_back(&self, encoder: &mut wgpu::CommandEncoder) -> ReadBack {
        let Some(unpack) = &self.unpack else {
            let count_texel = self.count_format.block_copy_size(None).unwrap_or(4);
            let copy = |texture, texel, encoder: &mut _| {
                copy_out(&self.device, encoder, texture, texel, self.canvas)
            };
            return ReadBack {
                count: copy(&self.count, count_texel, encoder),
                values: self.values.iter().map(|t| copy(t, 16, encoder)).collect(),
                size: self.canvas,
            };
        };
        let wide = (self.canvas.0 * self.samples, self.canvas.1);
        let mut spread = |source: &wgpu::Texture, format, pipeline: &wgpu::RenderPipeline| {
            let copy = wgpu::TextureUsages::COPY_SRC;
            let spread = target(&self.device, format, wide, 1, copy);
            let source_view = source.create_view(&Default::default());
            let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("rastercheck lavapipe unpack"),
                layout: &unpack.layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&source_view),
                }],
            });
            let spread_view = spread.create_view(&Default::default());
            let clear = wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT);
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("rastercheck lavapipe unpack"),
                color_attachments: &[attachment(&spread_view, clear)],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.draw(0..3, 0..1);
            drop(pass);
            let texel = if format == wgpu::TextureFormat::R32Float {
                4
            } else {
                16
            };
            copy_out(&self.device, encoder, &spread, texel, wide)
        };
        ReadBack {
            count: spread(&self.count, wgpu::TextureFormat::R32Float, &unpack.single),
            values: self
                .values
                .iter()
                .map(|v| spread(v, wgpu::TextureFormat::Rgba32Float, &unpack.quad))
                .collect(),
            size: wide,
        }
    }

    /// Submits the recorded commands, maps the read-back buffers if any,
    /// waits for the device, and reports what the error scopes caught.
    pub(super) fn finish(
        &self,
        scopes: Scopes,
        encoder: wgpu::CommandEncoder,
        read_back: Option<&ReadBack>,
    ) -> Result<(), RasterError> {
        self.queue.submit([encoder.finish()]);
        for (buffer, _) in read_back
            .iter()
            .flat_map(|r| std::iter::once(&r.count).chain(&r.values))
        {
            buffer.map_async(wgpu::MapMode::Read, .., |_| {});
        }
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RasterError::Failed(format!("lavapipe: waiting for the frame: {e}")))?;
        scopes.close()
    }

    /// The frame a finished read-back holds: counts, last primitives and
    /// channels, box-resolved under MSAA. A count beyond what its format
    /// holds exactly is an error.
    pub(super) fn decode(&self, read_back: &ReadBack) -> Result<Frame, RasterError> {
        let (w, h) = self.canvas;
        let count_texel = if self.samples == 1 {
            self.count_format.block_copy_size(None).unwrap_or(4) as usize
        } else {
            4
        };
        let count_bytes = read_rows(&read_back.count, count_texel, read_back.size)?;
        let counts = if self.samples == 1 {
            readback::counts(&count_bytes, self.count_format)
        } else {
            readback::floats(&count_bytes)
        };
        let channels = readback::channels(&read_back.values, read_back.size)?;

        let format = self.count_format;
        if self.samples == 1 {
            let mut frame = Frame::new(w, h, self.plan.depth, self.plan.attributes);
            let half = format != wgpu::TextureFormat::R32Float;
            readback::fill(&mut frame, &counts, &channels, "sample", |c| {
                (half && c >= 2048.0).then(|| {
                    "lavapipe: over 2048 triangles cover one sample; the R16Float count saturates"
                        .to_owned()
                })
            })?;
            return Ok(frame);
        }
        let mut frame = Frame::for_plan(w, h, self.plan);
        let limit = if format == wgpu::TextureFormat::R32Float {
            65535.0
        } else {
            2047.0
        };
        readback::fill(&mut frame, &counts, &channels, "slot", |c| {
            (c > limit).then(|| {
                format!(
                    "lavapipe: {c} triangles cover one sample; the {format:?} count is \
                     exact only up to 2048"
                )
            })
        })?;
        frame.resolve();
        Ok(frame)
    }
}

/// A `width × height` render target of `samples` samples, usable as
/// `usage` too.
fn target(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    (width, height): (u32, u32),
    sample_count: u32,
    usage: wgpu::TextureUsages,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some("target"),
        size: wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | usage,
        view_formats: &[],
    })
}

/// A colour attachment loaded with `load` and stored.
fn attachment(
    view: &wgpu::TextureView,
    load: wgpu::LoadOp<wgpu::Color>,
) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations {
            load,
            store: wgpu::StoreOp::Store,
        },
    })
}

fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}
