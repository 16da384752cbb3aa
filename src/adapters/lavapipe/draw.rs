//! Drawing one frame on lavapipe: the vertex stream uploaded, one render
//! pass per channel group into targets of the canvas's power-of-two size
//! (single-sample, or 4× MSAA with each sample spread to its own texel),
//! everything recorded in one command buffer, submitted, waited for and
//! read back once. The pipelines are `pipelines.rs`'s; decoding the bytes
//! is `readback.rs`'s.

use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Cull, Interpolation, Scene};

use super::super::gpu::{self, VERTEX_FLOATS};
use super::device::Gpu;
use super::readback::{self, copy_out, read_rows};

/// One frame's work on the device: its error scopes, open from before the
/// first buffer is made until everything is read back, and its vertices.
struct Work {
    device: wgpu::Device,
    // Dropped (and so popped) in this order on an early return, the
    // reverse of how they were pushed.
    oom: wgpu::ErrorScopeGuard,
    scope: wgpu::ErrorScopeGuard,
    vertex_buffer: wgpu::Buffer,
}

impl Work {
    /// Opens the error scopes and uploads the vertex stream.
    fn begin(gpu: &Gpu, vertices: &[f32]) -> Work {
        let device = gpu.device.clone();
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let vertex_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("vertices"),
            size: (vertices.len().max(VERTEX_FLOATS) * 4) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        if !vertices.is_empty() {
            gpu.queue
                .write_buffer(&vertex_buffer, 0, f32_bytes(vertices).as_slice());
        }
        Work {
            device,
            oom,
            scope,
            vertex_buffer,
        }
    }

    /// A `width × height` render target of `samples` samples, usable as
    /// `usage` too.
    fn target(
        &self,
        format: wgpu::TextureFormat,
        (width, height): (u32, u32),
        sample_count: u32,
        usage: wgpu::TextureUsages,
    ) -> wgpu::Texture {
        self.device.create_texture(&wgpu::TextureDescriptor {
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

    /// Submits the recorded commands, maps the readback buffers, waits for
    /// the device, and reports what the error scopes caught.
    fn finish(
        self,
        queue: &wgpu::Queue,
        encoder: wgpu::CommandEncoder,
        readbacks: &[&(wgpu::Buffer, u32)],
    ) -> Result<(), RasterError> {
        queue.submit([encoder.finish()]);
        for (buffer, _) in readbacks {
            buffer.map_async(wgpu::MapMode::Read, .., |_| {});
        }
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RasterError::Failed(format!("lavapipe: waiting for the frame: {e}")))?;
        if let Some(e) = pollster::block_on(self.oom.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: out of memory: {e}")));
        }
        if let Some(e) = pollster::block_on(self.scope.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: wgpu error: {e}")));
        }
        Ok(())
    }
}

impl Gpu {
    /// A command encoder with one render pass recorded per channel group
    /// over the scene's runs of triangles (the count target too, in group
    /// 0), into `samples`-sample targets cleared first, scissored to the
    /// canvas.
    fn record_groups(
        &mut self,
        work: &Work,
        (count, values): (&wgpu::Texture, &[wgpu::Texture]),
        runs: &[(Interpolation, u32, u32)],
        (cull, samples): (Cull, u32),
        (w, h): (u32, u32),
    ) -> wgpu::CommandEncoder {
        let mut encoder = work.device.create_command_encoder(&Default::default());
        for (g, value) in values.iter().enumerate() {
            let pipelines: Vec<(wgpu::RenderPipeline, u32, u32)> = runs
                .iter()
                .map(|&(mode, a, b)| (self.pipeline(mode, g, cull, samples), a, b))
                .collect();
            let count_view = count.create_view(&Default::default());
            let value_view = value.create_view(&Default::default());
            let attachments = if g == 0 {
                vec![cleared(&count_view), cleared(&value_view)]
            } else {
                vec![cleared(&value_view)]
            };
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("rastercheck lavapipe"),
                color_attachments: &attachments,
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_scissor_rect(0, 0, w, h);
            pass.set_vertex_buffer(0, work.vertex_buffer.slice(..));
            for (pipeline, a, b) in &pipelines {
                pass.set_pipeline(pipeline);
                pass.draw(*a..*b, 0..1);
            }
        }
        encoder
    }

    /// Draws a single-sample scene and reads the canvas back.
    pub(super) fn render(
        &mut self,
        scene: &Scene,
        plan: &Plan,
        bits: u32,
    ) -> Result<Frame, RasterError> {
        let (w, h) = (scene.canvas.width, scene.canvas.height);
        let (tw, th) = gpu::target_size(scene, self.max_side, "the lavapipe adapter")?;
        let groups = gpu::groups(plan);
        let (vertices, runs) = gpu::vertex_stream(scene, bits, (tw, th));

        let work = Work::begin(self, &vertices);
        let copy = wgpu::TextureUsages::COPY_SRC;
        let count = work.target(self.count_format, (tw, th), 1, copy);
        let values: Vec<wgpu::Texture> = (0..groups)
            .map(|_| work.target(wgpu::TextureFormat::Rgba32Float, (tw, th), 1, copy))
            .collect();

        let cull = (scene.rules.cull, 1);
        let mut encoder = self.record_groups(&work, (&count, &values), &runs, cull, (w, h));
        let readback = |texture: &wgpu::Texture, texel: u32, encoder: &mut wgpu::CommandEncoder| {
            copy_out(&work.device, encoder, texture, texel, (w, h))
        };
        let count_texel = self.count_format.block_copy_size(None).unwrap_or(4);
        let count_buffer = readback(&count, count_texel, &mut encoder);
        let value_buffers: Vec<_> = values
            .iter()
            .map(|t| readback(t, 16, &mut encoder))
            .collect();
        let mapped: Vec<_> = std::iter::once(&count_buffer)
            .chain(&value_buffers)
            .collect();
        work.finish(&self.queue, encoder, &mapped)?;

        let count_bytes = read_rows(&count_buffer, count_texel as usize, (w, h))?;
        let counts = readback::counts(&count_bytes, self.count_format);
        let channels = readback::channels(&value_buffers, (w, h))?;

        let mut frame = Frame::new(w, h, plan.depth, plan.attributes);
        let half = self.count_format != wgpu::TextureFormat::R32Float;
        readback::fill(&mut frame, &counts, &channels, "sample", |c| {
            (half && c >= 2048.0).then(|| {
                "lavapipe: over 2048 triangles cover one sample; the R16Float count saturates"
                    .to_owned()
            })
        })?;
        Ok(frame)
    }

    /// Draws an antialiased scene into 4× multisampled targets (the plan's
    /// offsets are Vulkan's standard 4×, checked by the caller), spreads
    /// each target's samples over a non-multisampled target 4× wider
    /// (texel (4x + s, y) holds sample s of pixel (x, y), which is slot
    /// 4·p + s of the frame), reads those back, and box-resolves.
    pub(super) fn render_msaa(
        &mut self,
        scene: &Scene,
        plan: &Plan,
        bits: u32,
    ) -> Result<Frame, RasterError> {
        const N: u32 = 4;
        let (w, h) = (scene.canvas.width, scene.canvas.height);
        let (tw, th) = gpu::target_size(scene, self.max_side, "the lavapipe adapter")?;
        if u64::from(w) * u64::from(N) > u64::from(self.max_side) {
            return Err(RasterError::Unsupported(format!(
                "canvas width {w}: its {N} samples per pixel are read back through a target \
                 {N}× wider, and the lavapipe adapter draws at most {}",
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
        let groups = gpu::groups(plan);
        let (vertices, runs) = gpu::vertex_stream(scene, bits, (tw, th));

        let work = Work::begin(self, &vertices);
        let binding = wgpu::TextureUsages::TEXTURE_BINDING;
        let count = work.target(self.msaa.count, (tw, th), N, binding);
        let values: Vec<wgpu::Texture> = (0..groups)
            .map(|_| work.target(self.msaa.values, (tw, th), N, binding))
            .collect();

        let cull = (scene.rules.cull, N);
        let mut encoder = self.record_groups(&work, (&count, &values), &runs, cull, (w, h));

        // Each sample to its own texel: (4x + s, y).
        let unpack = self.unpack();
        let wide = (w * N, h);
        let copy = wgpu::TextureUsages::COPY_SRC;
        let mut spread = |source: &wgpu::Texture, format, pipeline: &wgpu::RenderPipeline| {
            let target = work.target(format, wide, 1, copy);
            let source_view = source.create_view(&Default::default());
            let bind_group = work.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("rastercheck lavapipe unpack"),
                layout: &unpack.layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&source_view),
                }],
            });
            let target_view = target.create_view(&Default::default());
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("rastercheck lavapipe unpack"),
                color_attachments: &[cleared(&target_view)],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.draw(0..3, 0..1);
            drop(pass);
            target
        };
        let count_wide = spread(&count, wgpu::TextureFormat::R32Float, &unpack.single);
        let values_wide: Vec<wgpu::Texture> = values
            .iter()
            .map(|v| spread(v, wgpu::TextureFormat::Rgba32Float, &unpack.quad))
            .collect();
        let count_buffer = copy_out(&work.device, &mut encoder, &count_wide, 4, wide);
        let value_buffers: Vec<_> = values_wide
            .iter()
            .map(|t| copy_out(&work.device, &mut encoder, t, 16, wide))
            .collect();
        let mapped: Vec<_> = std::iter::once(&count_buffer)
            .chain(&value_buffers)
            .collect();
        work.finish(&self.queue, encoder, &mapped)?;

        let counts = readback::floats(&read_rows(&count_buffer, 4, wide)?);
        let channels = readback::channels(&value_buffers, wide)?;

        let mut frame = Frame::for_plan(w, h, plan);
        let count_limit = if self.msaa.count == wgpu::TextureFormat::R32Float {
            65535.0
        } else {
            2047.0
        };
        let count_format = self.msaa.count;
        readback::fill(&mut frame, &counts, &channels, "slot", |c| {
            (c > count_limit).then(|| {
                format!(
                    "lavapipe: {c} triangles cover one sample; the {count_format:?} count is \
                     exact only up to 2048"
                )
            })
        })?;
        frame.resolve();
        Ok(frame)
    }
}

/// A colour attachment cleared to 0 and stored.
fn cleared(view: &wgpu::TextureView) -> Option<wgpu::RenderPassColorAttachment<'_>> {
    Some(wgpu::RenderPassColorAttachment {
        view,
        depth_slice: None,
        resolve_target: None,
        ops: wgpu::Operations {
            load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
            store: wgpu::StoreOp::Store,
        },
    })
}

fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}
