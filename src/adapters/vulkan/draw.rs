//! Drawing one scene: its passes' vertex streams uploaded into one buffer,
//! targets of the canvas's power-of-two size made, every pass recorded in
//! one command buffer (each cleared, drawn, and copied out into its own
//! part of a host-visible buffer), submitted, waited for, and decoded into
//! the frame: pass s fills sample slot s of every pixel.
//!
//! Everything made here is destroyed when the [`Drawing`] drops, on every
//! path, failures included.

use ash::vk;

use super::super::float_input::f32_of;
use super::super::gpu::{self, Placement, Stream, View, VERTEX_FLOATS};
use super::device::{depth_attachment, Device};
use super::pipelines::{Pipelines, Stage, COUNT_FORMAT, VALUE_FORMAT};
use super::unpack::Unpack;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

/// What one scene needs on the device; destroyed on drop.
struct Drawing<'d> {
    gpu: &'d Device,
    images: Vec<(vk::Image, vk::ImageView, vk::DeviceMemory)>,
    buffers: Vec<(vk::Buffer, vk::DeviceMemory)>,
    framebuffers: Vec<vk::Framebuffer>,
    descriptors: vk::DescriptorPool,
    pool: vk::CommandPool,
    fence: vk::Fence,
}

/// What one scene's command buffer draws: every placement's stream, and
/// each render pass's draws, as (scissor, stream). Pass s's read-back
/// fills slot s of every pixel ([`slots`]), or one pass's counts make a
/// moving scene's time coverage ([`time`]).
pub(super) struct Job {
    pub streams: Vec<Stream>,
    pub passes: Vec<Vec<(vk::Rect2D, usize)>>,
    /// Samples per pixel of the targets: 1, or the count of native
    /// multisampling (one pass, read back sample by sample).
    pub samples: u32,
    /// The viewport a screen-space scene's streams are placed on
    /// (`gpu/view.rs`), every placement's, each drawn with its corner moved
    /// by the placement's shift (`Stream::viewport_corner`).
    pub view: View,
}

impl Job {
    /// One pass per placement, each drawn over the whole canvas, through
    /// `view`, the placements' viewport.
    pub(super) fn per_placement(scene: &Scene, placements: &[Placement], view: View) -> Job {
        let canvas = rect(0, 0, scene.canvas.width, scene.canvas.height);
        Job {
            streams: placements.iter().map(|p| Stream::new(scene, p)).collect(),
            passes: (0..placements.len()).map(|i| vec![(canvas, i)]).collect(),
            samples: 1,
            view,
        }
    }
}

/// The viewport: a clip-space scene's own (SPEC.md §16.1, y down as
/// Vulkan's; `vulkan/mod.rs` checked that its values are f32 and within
/// the device's bounds), else `view`, the rectangle enclosing the target
/// and the scene onto which the stream's screen-space positions map
/// exactly (`gpu/view.rs`, which kept it within the device's
/// `maxViewportDimensions` and `viewportBoundsRange`, with a pixel to
/// spare), its corner at `corner`: the view's moved by the stream's shift
/// (`Stream::viewport_corner`), so that every shifted pass is clipped at
/// the one rectangle `view` is in the case's coordinates. SwiftShader and
/// Mesa report `viewportSubPixelBits` 0 but take the corner as the float
/// it is (SwiftShader's `X0 = x + width/2` in `Renderer.cpp`, Mesa's
/// viewport scale and translate): the bundled antialiased cases drawn by
/// shifted passes, and `tests/vulkan.rs`, hold them to it. The scissor,
/// at the canvas, bounds what is drawn.
fn viewport(scene: &Scene, view: View, corner: [f32; 2]) -> vk::Viewport {
    match &scene.viewport {
        Some(v) => vk::Viewport {
            x: f32_of(&v.x),
            y: f32_of(&v.y),
            width: f32_of(&v.width),
            height: f32_of(&v.height),
            min_depth: f32_of(&v.min_depth),
            max_depth: f32_of(&v.max_depth),
        },
        None => vk::Viewport {
            x: corner[0],
            y: corner[1],
            width: view.size.0 as f32,
            height: view.size.1 as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        },
    }
}

/// A scissor rectangle.
pub(super) fn rect(x: u32, y: u32, width: u32, height: u32) -> vk::Rect2D {
    vk::Rect2D {
        offset: vk::Offset2D {
            x: x as i32,
            y: y as i32,
        },
        extent: vk::Extent2D { width, height },
    }
}

/// Records and runs a job, and returns what each pass read back: its
/// counts, then its channel groups (see [`layout`]).
pub(super) fn render(
    gpu: &Device,
    pipelines: &mut Pipelines,
    unpack: &mut Unpack,
    scene: &Scene,
    plan: &Plan,
    job: &Job,
) -> Result<Vec<u8>, RasterError> {
    let failed = |e: String| RasterError::Failed(format!("vulkan: {e}"));
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let target = gpu::target_size(scene, gpu.offers.max_side, "this Vulkan device")?;
    let groups = gpu::groups(plan);
    let depth = Stage::of(scene).depth;
    let mut drawing = Drawing {
        gpu,
        images: Vec::new(),
        buffers: Vec::new(),
        framebuffers: Vec::new(),
        descriptors: vk::DescriptorPool::null(),
        pool: vk::CommandPool::null(),
        fence: vk::Fence::null(),
    };

    // Every stream, one after another in one vertex buffer.
    let streams = &job.streams;
    let vertices: Vec<f32> = streams
        .iter()
        .flat_map(|s| s.vertices.iter().copied())
        .collect();
    let vertex_bytes = (vertices.len().max(VERTEX_FLOATS) * 4) as u64;
    let (vertex_buffer, vertex_memory) = drawing
        .buffer(vertex_bytes, vk::BufferUsageFlags::VERTEX_BUFFER)
        .map_err(failed)?;
    // SAFETY: host-visible, coherent memory of at least this size.
    unsafe { write(gpu, vertex_memory, &vertices) }.map_err(failed)?;

    // Under native multisampling the one pass is read back through targets
    // n times wider: n "pixels" a pixel, in slot order.
    let n = job.samples;
    let pixels = u64::from(w) * u64::from(h) * u64::from(n);
    let (count_bytes, pass_bytes) = layout(pixels as usize, groups, depth.is_some());
    let (count_bytes, pass_bytes) = (count_bytes as u64, pass_bytes as u64);
    let read_bytes = pass_bytes * job.passes.len() as u64;
    let (read_buffer, read_memory) = drawing
        .buffer(read_bytes, vk::BufferUsageFlags::TRANSFER_DST)
        .map_err(failed)?;

    let render_pass = pipelines.render_pass(groups, n, depth).map_err(failed)?;
    let read_from = if n == 1 {
        vk::ImageUsageFlags::TRANSFER_SRC
    } else {
        vk::ImageUsageFlags::SAMPLED
    };
    let colour = vk::ImageUsageFlags::COLOR_ATTACHMENT | read_from;
    let formats: Vec<vk::Format> = std::iter::once(COUNT_FORMAT)
        .chain(std::iter::repeat_n(VALUE_FORMAT, groups))
        .collect();
    let mut views = Vec::with_capacity(groups + 2);
    for &format in &formats {
        views.push(drawing.image(format, target, colour, n).map_err(failed)?);
    }
    // The stencil, or the depth attachment, read back as the colour
    // targets are (copied out, or sampled by the read-back pass).
    let (last_format, last_usage) = match depth.and_then(depth_attachment) {
        Some((format, _)) => (format, read_from),
        None => (gpu.offers.stencil_format, vk::ImageUsageFlags::empty()),
    };
    let usage = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT | last_usage;
    views.push(
        drawing
            .image(last_format, target, usage, n)
            .map_err(failed)?,
    );
    let framebuffer = drawing
        .framebuffer(render_pass, &views, target)
        .map_err(failed)?;

    // Under multisampling: a wide single-sample target per attachment,
    // and the descriptor set that lets the read-back pass sample it.
    let mut spreads = Vec::new();
    if n > 1 {
        let wide = (w * n, h);
        // The depth attachment, read as a depth texture into an R32 target.
        let read = if depth.is_some() {
            &views[..]
        } else {
            &views[..=groups]
        };
        let sets = drawing.descriptor_sets(unpack, read).map_err(failed)?;
        let sources = formats
            .iter()
            .map(|&f| (f, false))
            .chain(depth.map(|_| (COUNT_FORMAT, true)));
        for (i, (format, is_depth)) in sources.enumerate() {
            let usage = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC;
            let view = drawing.image(format, wide, usage, 1).map_err(failed)?;
            let image = drawing.images.last().map(|i| i.0).unwrap_or_default();
            let pass = unpack.render_pass(format).map_err(failed)?;
            let pipeline = unpack.pipeline(format, n, is_depth).map_err(failed)?;
            let framebuffer = drawing.framebuffer(pass, &[view], wide).map_err(failed)?;
            spreads.push((pass, pipeline, framebuffer, sets[i], image));
        }
    }

    // Each stream's place in the vertex buffer and the pipelines of its
    // runs, chosen before recording.
    let mut placed = Vec::with_capacity(streams.len());
    let mut base = 0u64;
    let stage =
        Stage::asked(scene, gpu.offers.conservative.as_ref()).map_err(RasterError::Unsupported)?;
    for stream in streams {
        let mut runs = Vec::with_capacity(stream.runs.len());
        for run in &stream.runs {
            let pipeline = pipelines
                .pipeline(run.draw, scene.rules.cull, stage, groups, n)
                .map_err(failed)?;
            runs.push((pipeline, run.first, run.end));
        }
        placed.push((base, runs));
        base += (stream.vertices.len() * 4) as u64;
    }

    // SAFETY: every handle recorded is alive until the fence is waited for
    // and the drawing dropped.
    unsafe {
        let d = &gpu.device;
        let info = vk::CommandPoolCreateInfo::default().queue_family_index(gpu.family);
        drawing.pool = d
            .create_command_pool(&info, None)
            .map_err(|e| failed(e.to_string()))?;
        let info = vk::CommandBufferAllocateInfo::default()
            .command_pool(drawing.pool)
            .level(vk::CommandBufferLevel::PRIMARY)
            .command_buffer_count(1);
        let cb = d
            .allocate_command_buffers(&info)
            .map_err(|e| failed(e.to_string()))?[0];
        let begin = vk::CommandBufferBeginInfo::default()
            .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
        d.begin_command_buffer(cb, &begin)
            .map_err(|e| failed(e.to_string()))?;
        let mut clears = vec![vk::ClearValue::default(); groups + 1];
        clears.push(vk::ClearValue {
            depth_stencil: vk::ClearDepthStencilValue {
                depth: 0.0,
                stencil: 0,
            },
        });
        for (s, draws) in job.passes.iter().enumerate() {
            let begin = vk::RenderPassBeginInfo::default()
                .render_pass(render_pass)
                .framebuffer(framebuffer)
                .render_area(vk::Rect2D {
                    offset: vk::Offset2D { x: 0, y: 0 },
                    extent: vk::Extent2D {
                        width: target.0,
                        height: target.1,
                    },
                })
                .clear_values(&clears);
            d.cmd_begin_render_pass(cb, &begin, vk::SubpassContents::INLINE);
            let mut bound = vk::Pipeline::null();
            for &(scissor, stream) in draws {
                let (offset, runs) = &placed[stream];
                let corner = streams[stream].viewport_corner;
                d.cmd_set_viewport(cb, 0, &[viewport(scene, job.view, corner)]);
                d.cmd_set_scissor(cb, 0, &[scissor]);
                d.cmd_bind_vertex_buffers(cb, 0, &[vertex_buffer], &[*offset]);
                for &(pipeline, first, end) in runs {
                    if pipeline != bound {
                        d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, pipeline);
                        bound = pipeline;
                    }
                    d.cmd_draw(cb, end - first, 1, first, 0);
                }
            }
            d.cmd_end_render_pass(cb);
            let mut at = pass_bytes * s as u64;
            let copy_aspect = |image, width, at, aspect_mask| {
                let region = vk::BufferImageCopy {
                    buffer_offset: at,
                    buffer_row_length: 0,
                    buffer_image_height: 0,
                    image_subresource: vk::ImageSubresourceLayers {
                        aspect_mask,
                        mip_level: 0,
                        base_array_layer: 0,
                        layer_count: 1,
                    },
                    image_offset: vk::Offset3D { x: 0, y: 0, z: 0 },
                    image_extent: vk::Extent3D {
                        width,
                        height: h,
                        depth: 1,
                    },
                };
                let layout = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
                d.cmd_copy_image_to_buffer(cb, image, layout, read_buffer, &[region]);
            };
            let copy =
                |image, width, at| copy_aspect(image, width, at, vk::ImageAspectFlags::COLOR);
            if n == 1 {
                for (i, &(image, _, _)) in drawing.images[..=groups].iter().enumerate() {
                    copy(image, w, at);
                    at += if i == 0 { count_bytes } else { pixels * 16 };
                }
                if depth.is_some() {
                    let image = drawing.images[groups + 1].0;
                    copy_aspect(image, w, at, vk::ImageAspectFlags::DEPTH);
                }
                continue;
            }
            let wide = rect(0, 0, w * n, h);
            for (i, &(pass, pipeline, framebuffer, set, image)) in spreads.iter().enumerate() {
                let begin = vk::RenderPassBeginInfo::default()
                    .render_pass(pass)
                    .framebuffer(framebuffer)
                    .render_area(wide);
                d.cmd_begin_render_pass(cb, &begin, vk::SubpassContents::INLINE);
                let viewport = vk::Viewport {
                    x: 0.0,
                    y: 0.0,
                    width: (w * n) as f32,
                    height: h as f32,
                    min_depth: 0.0,
                    max_depth: 1.0,
                };
                d.cmd_set_viewport(cb, 0, &[viewport]);
                d.cmd_set_scissor(cb, 0, &[wide]);
                d.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, pipeline);
                d.cmd_bind_descriptor_sets(
                    cb,
                    vk::PipelineBindPoint::GRAPHICS,
                    unpack.layout,
                    0,
                    &[set],
                    &[],
                );
                d.cmd_draw(cb, 3, 1, 0, 0);
                d.cmd_end_render_pass(cb);
                copy(image, w * n, at);
                at += if i == 0 { count_bytes } else { pixels * 16 };
            }
        }
        let to_host = vk::MemoryBarrier::default()
            .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(vk::AccessFlags::HOST_READ);
        d.cmd_pipeline_barrier(
            cb,
            vk::PipelineStageFlags::TRANSFER,
            vk::PipelineStageFlags::HOST,
            vk::DependencyFlags::empty(),
            &[to_host],
            &[],
            &[],
        );
        d.end_command_buffer(cb)
            .map_err(|e| failed(e.to_string()))?;
        drawing.fence = d
            .create_fence(&vk::FenceCreateInfo::default(), None)
            .map_err(|e| failed(e.to_string()))?;
        let buffers = [cb];
        let submit = vk::SubmitInfo::default().command_buffers(&buffers);
        d.queue_submit(gpu.queue, &[submit], drawing.fence)
            .map_err(|e| failed(format!("submitting: {e}")))?;
        d.wait_for_fences(&[drawing.fence], true, u64::MAX)
            .map_err(|e| failed(format!("waiting for the frame: {e}")))?;
    }

    // SAFETY: the fence is signalled: the copies are done and visible.
    unsafe { read(gpu, read_memory, read_bytes) }.map_err(failed)
}

/// The bytes of one pass's counts, and of the whole pass (counts, then
/// each channel group, then the depth attachment's texels, 2 or 4 bytes
/// each, when there is one), in the read-back buffer: every copy starts on
/// a multiple of 16 bytes, the largest texel.
fn layout(pixels: usize, groups: usize, depth: bool) -> (usize, usize) {
    let count = (pixels * 4).next_multiple_of(16);
    let depth = if depth { count } else { 0 };
    (count, count + pixels * 16 * groups + depth)
}

/// The f32 at byte `at`.
fn float(bytes: &[u8], at: usize) -> f32 {
    f32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
}

/// Pixel p's stored depth in a depth copy at byte `at`: a `D16_UNORM`
/// texel's 2 bytes, or an `X8_D24_UNORM_PACK32` or `D32_SFLOAT` texel's 4.
fn stored(bytes: &[u8], at: usize, p: usize, format: crate::scene::DepthFormat) -> u32 {
    if format.unorm_bits() == Some(16) {
        let at = at + p * 2;
        u32::from(u16::from_le_bytes([bytes[at], bytes[at + 1]]))
    } else {
        let at = at + p * 4;
        u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
    }
}

/// A count read back, checked: a whole number of covers, at most `limit`.
fn count(bytes: &[u8], at: usize, limit: f32, p: usize) -> Result<f32, RasterError> {
    let count = float(bytes, at);
    if count.fract() != 0.0 || !(0.0..=limit).contains(&count) {
        return Err(RasterError::Failed(format!(
            "vulkan: coverage count {count} read back at pixel {p}"
        )));
    }
    Ok(count)
}

/// The frame whose slot s of each pixel pass s read back, or, under
/// native multisampling (`job.samples` > 1), whose slots the one pass's
/// wide targets hold in order; box-resolved when the scene antialiases.
pub(super) fn slots(
    bytes: &[u8],
    scene: &Scene,
    plan: &Plan,
    job: &Job,
) -> Result<Frame, RasterError> {
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let mut frame = Frame::for_plan(w, h, plan);
    let slots = frame.samples as usize;
    let pixels = w as usize * h as usize * job.samples as usize;
    let groups = gpu::groups(plan);
    let depth = Stage::of(scene).depth;
    let (count_bytes, pass_bytes) = layout(pixels, groups, depth.is_some());
    let depth_at = count_bytes + pixels * 16 * groups;
    let float = |at: usize| float(bytes, at);
    for s in 0..job.passes.len() {
        let base = s * pass_bytes;
        for p in 0..pixels {
            let slot = if job.samples > 1 { p } else { p * slots + s };
            let count = count(bytes, base + p * 4, 65535.0, p)?;
            let channel = |c: usize| {
                let (g, k) = (c / 4, c % 4);
                float(base + count_bytes + g * pixels * 16 + p * 16 + k * 4)
            };
            frame.coverage[slot] = count as u16;
            frame.last[slot] = channel(0) as u32;
            if count > 0.0 {
                if let Some(values) = &mut frame.depth {
                    values[slot] = match depth {
                        // Sampled by the read-back pass: a float.
                        Some(format) if job.samples > 1 => {
                            gpu::depth::sampled_value(format, float(base + depth_at + p * 4))
                        }
                        Some(format) => gpu::depth::stored_value(
                            format,
                            stored(bytes, base + depth_at, p, format),
                        ),
                        None => f64::from(channel(1)),
                    };
                }
                for (k, a) in frame.attributes.iter_mut().enumerate() {
                    a[slot] = f64::from(channel(2 + k));
                }
            }
        }
    }
    if plan.antialias.is_some() {
        frame.resolve();
        frame.method = Some(if job.samples > 1 {
            "native MSAA"
        } else {
            "shifted passes"
        });
    }
    Ok(frame)
}

/// The time coverage of a moving scene from its one pass's counts: each
/// pixel's covered tests over its `tests` tests.
pub(super) fn time(bytes: &[u8], scene: &Scene, tests: u32) -> Result<Frame, RasterError> {
    let (w, h) = (scene.canvas.width, scene.canvas.height);
    let time = (0..w as usize * h as usize)
        .map(|p| Ok(f64::from(count(bytes, p * 4, 16_777_216.0, p)?) / f64::from(tests)))
        .collect::<Result<Vec<f64>, RasterError>>()?;
    Ok(Frame {
        method: Some("time passes"),
        ..Frame::time_only(w, h, time)
    })
}

impl Drawing<'_> {
    /// A host-visible, coherent buffer of `size` bytes.
    fn buffer(
        &mut self,
        size: u64,
        usage: vk::BufferUsageFlags,
    ) -> Result<(vk::Buffer, vk::DeviceMemory), String> {
        let d = &self.gpu.device;
        let info = vk::BufferCreateInfo::default()
            .size(size)
            .usage(usage)
            .sharing_mode(vk::SharingMode::EXCLUSIVE);
        // SAFETY: valid create infos; what is made is kept for Drop.
        unsafe {
            let buffer = d.create_buffer(&info, None).map_err(|e| e.to_string())?;
            let needs = d.get_buffer_memory_requirements(buffer);
            let host =
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
            let memory = match self.memory(needs, host) {
                Ok(memory) => memory,
                Err(e) => {
                    d.destroy_buffer(buffer, None);
                    return Err(e);
                }
            };
            self.buffers.push((buffer, memory));
            d.bind_buffer_memory(buffer, memory, 0)
                .map_err(|e| e.to_string())?;
            Ok((buffer, memory))
        }
    }

    /// A `size` 2D image of `format` in device memory, and its view.
    fn image(
        &mut self,
        format: vk::Format,
        (width, height): (u32, u32),
        usage: vk::ImageUsageFlags,
        samples: u32,
    ) -> Result<vk::ImageView, String> {
        let d = &self.gpu.device;
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D {
                width,
                height,
                depth: 1,
            })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::from_raw(samples))
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        let aspect = if usage.contains(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT) {
            match format {
                vk::Format::S8_UINT => vk::ImageAspectFlags::STENCIL,
                vk::Format::D16_UNORM
                | vk::Format::X8_D24_UNORM_PACK32
                | vk::Format::D32_SFLOAT => vk::ImageAspectFlags::DEPTH,
                _ => vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL,
            }
        } else {
            vk::ImageAspectFlags::COLOR
        };
        // SAFETY: valid create infos; what is made is kept for Drop.
        unsafe {
            let image = d.create_image(&info, None).map_err(|e| e.to_string())?;
            let needs = d.get_image_memory_requirements(image);
            let memory = match self.memory(needs, vk::MemoryPropertyFlags::DEVICE_LOCAL) {
                Ok(memory) => memory,
                Err(e) => {
                    d.destroy_image(image, None);
                    return Err(e);
                }
            };
            self.images.push((image, vk::ImageView::null(), memory));
            d.bind_image_memory(image, memory, 0)
                .map_err(|e| e.to_string())?;
            let view = vk::ImageViewCreateInfo::default()
                .image(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: aspect,
                    base_mip_level: 0,
                    level_count: 1,
                    base_array_layer: 0,
                    layer_count: 1,
                });
            let view = d
                .create_image_view(&view, None)
                .map_err(|e| e.to_string())?;
            if let Some(last) = self.images.last_mut() {
                last.1 = view;
            }
            Ok(view)
        }
    }

    /// A framebuffer of `views` of `size`.
    fn framebuffer(
        &mut self,
        render_pass: vk::RenderPass,
        views: &[vk::ImageView],
        (width, height): (u32, u32),
    ) -> Result<vk::Framebuffer, String> {
        let info = vk::FramebufferCreateInfo::default()
            .render_pass(render_pass)
            .attachments(views)
            .width(width)
            .height(height)
            .layers(1);
        // SAFETY: valid views of images at least this size.
        let framebuffer = unsafe { self.gpu.device.create_framebuffer(&info, None) }
            .map_err(|e| e.to_string())?;
        self.framebuffers.push(framebuffer);
        Ok(framebuffer)
    }

    /// One descriptor set per multisampled view, for the read-back pass.
    fn descriptor_sets(
        &mut self,
        unpack: &Unpack,
        views: &[vk::ImageView],
    ) -> Result<Vec<vk::DescriptorSet>, String> {
        let d = &self.gpu.device;
        let sizes = [vk::DescriptorPoolSize {
            ty: vk::DescriptorType::SAMPLED_IMAGE,
            descriptor_count: views.len() as u32,
        }];
        let info = vk::DescriptorPoolCreateInfo::default()
            .max_sets(views.len() as u32)
            .pool_sizes(&sizes);
        // SAFETY: valid create infos; the pool is destroyed in Drop, and
        // the views outlive the sets.
        unsafe {
            self.descriptors = d
                .create_descriptor_pool(&info, None)
                .map_err(|e| e.to_string())?;
            let layouts = vec![unpack.set_layout; views.len()];
            let info = vk::DescriptorSetAllocateInfo::default()
                .descriptor_pool(self.descriptors)
                .set_layouts(&layouts);
            let sets = d
                .allocate_descriptor_sets(&info)
                .map_err(|e| e.to_string())?;
            for (&set, &view) in sets.iter().zip(views) {
                let images = [vk::DescriptorImageInfo {
                    sampler: vk::Sampler::null(),
                    image_view: view,
                    image_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                }];
                let write = vk::WriteDescriptorSet::default()
                    .dst_set(set)
                    .dst_binding(0)
                    .descriptor_type(vk::DescriptorType::SAMPLED_IMAGE)
                    .image_info(&images);
                d.update_descriptor_sets(&[write], &[]);
            }
            Ok(sets)
        }
    }

    unsafe fn memory(
        &self,
        needs: vk::MemoryRequirements,
        flags: vk::MemoryPropertyFlags,
    ) -> Result<vk::DeviceMemory, String> {
        let index = self
            .gpu
            .memory_type(needs.memory_type_bits, flags)
            .or_else(|| {
                self.gpu
                    .memory_type(needs.memory_type_bits, vk::MemoryPropertyFlags::empty())
            })
            .ok_or("no memory type fits")?;
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(needs.size)
            .memory_type_index(index);
        self.gpu
            .device
            .allocate_memory(&info, None)
            .map_err(|e| format!("allocating {} bytes: {e}", needs.size))
    }
}

/// Copies `values` into host-visible memory.
unsafe fn write(gpu: &Device, memory: vk::DeviceMemory, values: &[f32]) -> Result<(), String> {
    if values.is_empty() {
        return Ok(());
    }
    let bytes = std::mem::size_of_val(values);
    let to = gpu
        .device
        .map_memory(memory, 0, bytes as u64, vk::MemoryMapFlags::empty())
        .map_err(|e| e.to_string())?;
    std::ptr::copy_nonoverlapping(values.as_ptr().cast::<u8>(), to.cast::<u8>(), bytes);
    gpu.device.unmap_memory(memory);
    Ok(())
}

/// The first `size` bytes of host-visible memory.
unsafe fn read(gpu: &Device, memory: vk::DeviceMemory, size: u64) -> Result<Vec<u8>, String> {
    let from = gpu
        .device
        .map_memory(memory, 0, size, vk::MemoryMapFlags::empty())
        .map_err(|e| e.to_string())?;
    let bytes = std::slice::from_raw_parts(from.cast::<u8>(), size as usize).to_vec();
    gpu.device.unmap_memory(memory);
    Ok(bytes)
}

impl Drop for Drawing<'_> {
    fn drop(&mut self) {
        let d = &self.gpu.device;
        // SAFETY: the submission (if any) is waited for; on an early
        // return, wait for the device before destroying what it may use.
        unsafe {
            let _ = d.device_wait_idle();
            if self.fence != vk::Fence::null() {
                d.destroy_fence(self.fence, None);
            }
            if self.pool != vk::CommandPool::null() {
                d.destroy_command_pool(self.pool, None);
            }
            for &framebuffer in &self.framebuffers {
                d.destroy_framebuffer(framebuffer, None);
            }
            if self.descriptors != vk::DescriptorPool::null() {
                d.destroy_descriptor_pool(self.descriptors, None);
            }
            for &(image, view, memory) in &self.images {
                if view != vk::ImageView::null() {
                    d.destroy_image_view(view, None);
                }
                d.destroy_image(image, None);
                d.free_memory(memory, None);
            }
            for &(buffer, memory) in &self.buffers {
                d.destroy_buffer(buffer, None);
                d.free_memory(memory, None);
            }
        }
    }
}
