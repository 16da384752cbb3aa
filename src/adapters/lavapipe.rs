//! `lavapipe`: Mesa's Vulkan rasterizer on the CPU, driven through wgpu
//! (cargo feature `lavapipe`; system packages `mesa-vulkan-drivers` and
//! `libvulkan1`).
//!
//! # What is drawn, and how it is read back
//!
//! A case's triangles are drawn in scene order, with no depth test, into
//! float render targets, and read back into a [`Frame`]:
//!
//! - **count** (`R32Float`, additive blending `1 + dst`; `R16Float` where the
//!   adapter lacks `FLOAT32_BLENDABLE`, exact up to 2048 covers a sample):
//!   how many triangles cover each sample;
//! - **channel groups** (`Rgba32Float`, no blending, so the last triangle in
//!   submission order wins, as Vulkan's primitive order guarantees): the
//!   channels `[primitive + 1, depth, attribute 0, …, attribute 15]` four at
//!   a time. Group 0 (primitive, depth, attributes 0 and 1) is drawn in the
//!   same pass as the count; every further group of four attributes is drawn
//!   by one more pass over the same triangles. Everything is recorded in one
//!   command buffer and read back once.
//!
//! The primitive index (+ 1, exact in f32 up to 2^24) is a `flat` varying and
//! doubles as the coverage marker of the last writer. Depth is the case's `z`
//! as a `linear` (screen-space, `noperspective`) varying, not the depth buffer,
//! so no depth-range mapping touches it (SPEC.md §5: z is screen-space
//! linear). Attributes are varyings with the case's `@interpolate`:
//! `perspective`, `linear`, or `flat` (the first vertex provokes, Vulkan's
//! default and the case's rule). Consecutive triangles of one interpolation
//! mode share one draw call.
//!
//! # Positions: exact to the 8-bit grid
//!
//! Each coordinate is snapped to the case's `subpixel_bits` (ties to even,
//! the reference's own snapping) and rounded to f32 (exact for b ≤ 8). The
//! render targets are `P × Q` texels, P and Q the powers of two at or above
//! the canvas width and height; only the canvas (scissor `W × H` at the
//! origin) is drawn and copied back. With a power-of-two viewport the NDC
//! mapping
//!
//! ```text
//! x_ndc = x · 2/P − 1,   y_ndc = 1 − y · 2/Q      (y down on screen)
//! clip  = (x_ndc · w, y_ndc · w, w / 2, w)
//! ```
//!
//! and the viewport transform back (`x = (x_ndc + 1) · P/2`, wgpu flips y) are
//! exact in f32 for every snapped coordinate |x|, |y| ≤ 2^15 with b ≤ 8 (the
//! values span at most 24 significant bits). The only float step is the
//! perspective division (x_ndc·w)/w when w ≠ 1, at most an ulp or so, which
//! the driver's snap to 1/256 absorbs unless a coordinate uses all 24 bits
//! (|x| near 2^15). Clip z = w/2 keeps every vertex inside the depth range,
//! so only the x and y planes (and the driver's guard band) can clip.
//!
//! lavapipe then snaps to its own `subPixelPrecisionBits` = 8: cases with
//! b > 8 are snapped twice (to b, then to 8 bits), and show it; cases with
//! `subpixel_bits: null` are unsupported.
//!
//! The viewport is the whole `P × Q` target, so the driver clips at x = 0,
//! y = 0, x = P and y = Q (at the canvas's own right and bottom borders only
//! when W and H are powers of two). Mesa 22.3's lavapipe clips there rather
//! than rasterizing off-screen vertices in a guard band, and re-snaps the
//! vertices clipping makes: an edge from an off-screen vertex moves by up to
//! a subpixel and its on-screen tie samples can change hands
//! (`tests/lavapipe.rs` shows it). That is the driver's behaviour, reported
//! as found.
//!
//! # Rules
//!
//! - **Fill rule**: the driver's own (top-left). The case's rule is not
//!   faked: a case under another rule reports lavapipe's departures from it.
//! - **Culling**: `front_face = Ccw` with `cull: ccw` → cull the front face,
//!   `cull: cw` → cull the back face. WebGPU reads the winding in framebuffer
//!   coordinates (y down), the same orientation as the case's (SPEC.md §2):
//!   (0,0), (1,0), (0,1) is clockwise in both. w > 0, so the division keeps
//!   the winding.
//! - **Lines**: unsupported (wgpu draws only 1-px lines, with no rule to
//!   choose). **Polygons**: unsupported (the harness refuses them).
//!
//! # Antialiasing: 4× MSAA, read back sample by sample
//!
//! An antialiased scene is drawn only when its plan's offsets are exactly
//! Vulkan's standard 4× locations ([`STANDARD_4X`] at the plan's
//! `position_bits`; the offsets are checked, not the pattern's name): wgpu
//! exposes 4× MSAA at the standard positions only, so every other count or
//! pattern is unsupported, with that reason. The same passes as above draw
//! into 4× multisampled targets (`count: 4`): the count in `R32Float`
//! where the adapter multisamples and blends it (through
//! `TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` and `FLOAT32_BLENDABLE`; else
//! core `R16Float`, exact up to 2048 covers a sample), the channel groups in
//! `Rgba32Float` where the adapter multisamples it (else core `Rgba16Float`:
//! primitive + 1 exact up to 2048, more triangles refused, and depth and
//! attributes refused as they would not meet the bound). Mesa 22.3's
//! lavapipe takes the f32 formats. Depth and the non-flat attributes are
//! varyings with the `sample` qualifier, so the fragment shader runs once
//! per sample and interpolates at the sample's own position; blending and
//! the last-writer-wins channels are per sample anyway.
//!
//! A second pass per target spreads the samples out: a full-target triangle
//! over a non-multisampled `R32Float` / `Rgba32Float` target 4× wider,
//! whose texel (4x + s, y) is `textureLoad(t, (x, y), s)`. Vulkan's sample
//! index s is standard location s, which is the frame's slot s, so the
//! wide target read row by row is the frame's slot order (`4·p + s`).
//! Then the frame is box-resolved ([`Frame::resolve`]). Canvases wider
//! than a quarter of the largest texture are unsupported.
//!
//! What lavapipe does with it (`tests/lavapipe.rs`): its mask equals the
//! exact reference's sample by sample on every bundled standard 4×
//! triangle case, and a tiny square on standard location i lights slot i
//! only. Depth and linear and flat attributes are within the bound per
//! sample; perspective attributes are not: Mesa 22.3 divides Σλ·a/w at the
//! sample by Σλ/w at the pixel centre, a driver bug the check reports.
//!
//! One device is created on first use and shared by every case (creating it
//! takes a while); a mutex serialises the cases that use it. Compiled
//! pipelines are kept, keyed by interpolation mode, channel group and culling.

use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

use crate::frame::Frame;
use crate::plan::{Plan, SamplePlan};
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{Cull, Interpolation, Primitive, Scene};

/// The name on the command line and in reports.
pub const NAME: &str = "lavapipe";

/// What to install when no adapter is found.
const INSTALL_HINT: &str =
    "install mesa-vulkan-drivers libvulkan1 (Debian/Ubuntu) so that wgpu finds the lavapipe CPU adapter";

use super::gpu::{self, GROUPS, MAX_ATTRIBUTES, VERTEX_FLOATS};

/// Mesa's lavapipe, through wgpu's Vulkan backend.
pub struct Lavapipe;

impl Rasterizer for Lavapipe {
    fn name(&self) -> &str {
        NAME
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            triangles: true,
            ideal_geometry: false,
            attributes: true,
            depth: true,
            polygons: false,
            antialias: true,
            motion_blur: false,
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if let Some(aa) = &plan.antialias {
            if let Some(why) = standard_4x_refusal(aa) {
                return Err(RasterError::Unsupported(why));
            }
        } else if plan.samples_per_pixel != 1 {
            return Err(RasterError::Unsupported(format!(
                "{} samples per pixel without a sample pattern",
                plan.samples_per_pixel
            )));
        }
        if scene
            .primitives
            .iter()
            .any(|p| matches!(p, Primitive::Line(_)))
        {
            return Err(RasterError::Unsupported(
                "lines: wgpu draws only 1-pixel lines, with no choice of the case's line rule"
                    .to_owned(),
            ));
        }
        let Some(bits) = scene.rules.subpixel_bits else {
            return Err(RasterError::Unsupported(
                "unsnapped geometry (subpixel_bits: null): lavapipe snaps to 8 subpixel bits"
                    .to_owned(),
            ));
        };
        if plan.attributes > MAX_ATTRIBUTES {
            return Err(RasterError::Unsupported(format!(
                "{} attributes (this adapter carries at most {MAX_ATTRIBUTES})",
                plan.attributes
            )));
        }
        let gpu = gpu().map_err(|why| RasterError::Failed(why.clone()))?;
        let mut gpu = gpu.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        if plan.antialias.is_some() {
            gpu.render_msaa(scene, plan, bits)
        } else {
            gpu.render(scene, plan, bits)
        }
    }
}

/// Vulkan's standard 4× sample locations (`standardSampleLocations`), in
/// 1/16 pixel from the pixel's top-left corner, y down, in Vulkan's sample
/// order: sample index i of the driver is slot i of the frame.
pub const STANDARD_4X: [[u32; 2]; 4] = [[6, 2], [14, 6], [2, 10], [10, 14]];

/// Why lavapipe cannot draw these samples, if it cannot: wgpu asks the
/// driver for 4× MSAA at its standard locations and nothing else, so the
/// plan's offsets must be exactly [`STANDARD_4X`] at its position bits
/// (the offsets are checked, not the pattern's name).
pub fn standard_4x_refusal(aa: &SamplePlan) -> Option<String> {
    let standard = aa.position_bits.checked_sub(4).map(|shift| {
        STANDARD_4X
            .iter()
            .map(|p| p.map(|c| c << shift))
            .collect::<Vec<_>>()
    });
    if standard.as_deref() == Some(aa.offsets.as_slice()) {
        return None;
    }
    Some(format!(
        "{} samples per pixel, not at Vulkan's standard 4x locations: \
         wgpu exposes 4x MSAA at the standard positions only",
        aa.offsets.len()
    ))
}

/// The multisampled formats this adapter draws 4× MSAA into, as
/// "count FORMAT, values FORMAT", or why it cannot.
pub fn msaa_formats() -> Result<String, String> {
    let gpu = gpu()?;
    let gpu = gpu.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Ok(format!(
        "count {:?}, values {:?}",
        gpu.msaa.count, gpu.msaa.values
    ))
}

/// The adapter wgpu found, as "name (driver, driver info)", or why none was
/// found. Creates the shared device on first use.
pub fn adapter_description() -> Result<String, String> {
    let gpu = gpu()?;
    let gpu = gpu.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    Ok(gpu.description.clone())
}

fn gpu() -> Result<&'static Mutex<Gpu>, &'static String> {
    static GPU: OnceLock<Result<Mutex<Gpu>, String>> = OnceLock::new();
    GPU.get_or_init(|| Gpu::new().map(Mutex::new)).as_ref()
}

struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    description: String,
    count_format: wgpu::TextureFormat,
    max_side: u32,
    msaa: MsaaFormats,
    /// Shader modules by interpolation mode and per-sample interpolation.
    modules: HashMap<(Interpolation, bool), wgpu::ShaderModule>,
    /// Pipelines by interpolation mode, channel group, culling and samples.
    pipelines: HashMap<(Interpolation, usize, Cull, u32), wgpu::RenderPipeline>,
    /// The pass that spreads a 4× target's samples over a 4× wider one,
    /// by unpacked format.
    unpack: Option<Unpack>,
}

/// The multisampled (4×) render-target formats.
#[derive(Clone, Copy, Debug)]
struct MsaaFormats {
    /// The additive count: `R32Float` where the adapter multisamples and
    /// blends it, else `R16Float` (core WebGPU; exact up to 2048).
    count: wgpu::TextureFormat,
    /// The channel groups: `Rgba32Float` where the adapter multisamples it,
    /// else `Rgba16Float` (core WebGPU), which holds primitive + 1 exactly
    /// up to 2048 and no depth or attribute to the suite's bound.
    values: wgpu::TextureFormat,
}

impl MsaaFormats {
    /// The best formats the adapter supports at 4×. Without
    /// `TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES` only core WebGPU's
    /// multisampled formats are allowed, whatever the adapter says.
    fn choose(adapter: &wgpu::Adapter, specific: bool, blendable: bool) -> MsaaFormats {
        use wgpu::TextureFormatFeatureFlags as F;
        let has = |format, flags: F| {
            specific
                && adapter
                    .get_texture_format_features(format)
                    .flags
                    .contains(flags)
        };
        MsaaFormats {
            count: if blendable
                && has(
                    wgpu::TextureFormat::R32Float,
                    F::MULTISAMPLE_X4 | F::BLENDABLE,
                ) {
                wgpu::TextureFormat::R32Float
            } else {
                wgpu::TextureFormat::R16Float
            },
            values: if has(wgpu::TextureFormat::Rgba32Float, F::MULTISAMPLE_X4) {
                wgpu::TextureFormat::Rgba32Float
            } else {
                wgpu::TextureFormat::Rgba16Float
            },
        }
    }

    /// Whether the channel groups hold f32.
    fn exact_values(&self) -> bool {
        self.values == wgpu::TextureFormat::Rgba32Float
    }
}

/// The unpacking pass's pipelines and their bind group layout.
struct Unpack {
    layout: wgpu::BindGroupLayout,
    /// Into `R32Float` (counts) and `Rgba32Float` (channel groups).
    single: wgpu::RenderPipeline,
    quad: wgpu::RenderPipeline,
}

impl Gpu {
    fn new() -> Result<Gpu, String> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::VULKAN;
        let instance = wgpu::Instance::new(desc);
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            force_fallback_adapter: true,
            ..Default::default()
        }))
        .map_err(|e| format!("no Vulkan adapter: {INSTALL_HINT} ({e})"))?;
        let info = adapter.get_info();
        let description = format!("{} ({}, {})", info.name, info.driver, info.driver_info);
        let is_lavapipe = [&info.name, &info.driver]
            .iter()
            .any(|s| s.contains("llvmpipe") || s.contains("lavapipe"));
        if !is_lavapipe {
            return Err(format!(
                "no lavapipe adapter: the CPU Vulkan adapter found is {description}; {INSTALL_HINT}"
            ));
        }
        let blendable = adapter
            .features()
            .contains(wgpu::Features::FLOAT32_BLENDABLE);
        let specific = adapter
            .features()
            .contains(wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES);
        let mut required_features = wgpu::Features::empty();
        if blendable {
            required_features |= wgpu::Features::FLOAT32_BLENDABLE;
        }
        if specific {
            required_features |= wgpu::Features::TEXTURE_ADAPTER_SPECIFIC_FORMAT_FEATURES;
        }
        let msaa = MsaaFormats::choose(&adapter, specific, blendable);
        let limits = adapter.limits();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("rastercheck lavapipe"),
            required_features,
            required_limits: limits.clone(),
            ..Default::default()
        }))
        .map_err(|e| format!("lavapipe found ({description}) but its device failed: {e}"))?;
        Ok(Gpu {
            device,
            queue,
            description,
            count_format: if blendable {
                wgpu::TextureFormat::R32Float
            } else {
                wgpu::TextureFormat::R16Float
            },
            max_side: limits.max_texture_dimension_2d,
            msaa,
            modules: HashMap::new(),
            pipelines: HashMap::new(),
            unpack: None,
        })
    }

    fn module(&mut self, mode: Interpolation, per_sample: bool) -> &wgpu::ShaderModule {
        let device = &self.device;
        self.modules.entry((mode, per_sample)).or_insert_with(|| {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("rastercheck lavapipe"),
                source: wgpu::ShaderSource::Wgsl(shader(mode, per_sample).into()),
            })
        })
    }

    /// Records one render pass per channel group over the scene's runs of
    /// triangles (the count target too, in group 0), into `samples`-sample
    /// targets cleared first, scissored to the canvas.
    fn record_groups(
        &mut self,
        encoder: &mut wgpu::CommandEncoder,
        (count, values): (&wgpu::Texture, &[wgpu::Texture]),
        runs: &[(Interpolation, u32, u32)],
        (cull, samples): (Cull, u32),
        vertex_buffer: &wgpu::Buffer,
        (w, h): (u32, u32),
    ) {
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
            pass.set_vertex_buffer(0, vertex_buffer.slice(..));
            for (pipeline, a, b) in &pipelines {
                pass.set_pipeline(pipeline);
                pass.draw(*a..*b, 0..1);
            }
        }
    }

    /// The pipeline drawing channel group `group` (and the count, for group
    /// 0) into `samples`-sample targets (1, or 4 for MSAA).
    fn pipeline(
        &mut self,
        mode: Interpolation,
        group: usize,
        cull: Cull,
        samples: u32,
    ) -> wgpu::RenderPipeline {
        if let Some(p) = self.pipelines.get(&(mode, group, cull, samples)) {
            return p.clone();
        }
        let (count_format, value_format) = if samples == 1 {
            (self.count_format, wgpu::TextureFormat::Rgba32Float)
        } else {
            (self.msaa.count, self.msaa.values)
        };
        let module = self.module(mode, samples > 1).clone();
        let attributes: Vec<wgpu::VertexAttribute> = (0..VERTEX_FLOATS / 4)
            .map(|i| wgpu::VertexAttribute {
                format: wgpu::VertexFormat::Float32x4,
                offset: (i * 16) as u64,
                shader_location: i as u32,
            })
            .collect();
        let value_target = Some(wgpu::ColorTargetState {
            format: value_format,
            blend: None,
            write_mask: wgpu::ColorWrites::ALL,
        });
        let targets = if group == 0 {
            let add = wgpu::BlendComponent {
                src_factor: wgpu::BlendFactor::One,
                dst_factor: wgpu::BlendFactor::One,
                operation: wgpu::BlendOperation::Add,
            };
            vec![
                Some(wgpu::ColorTargetState {
                    format: count_format,
                    blend: Some(wgpu::BlendState {
                        color: add,
                        alpha: add,
                    }),
                    write_mask: wgpu::ColorWrites::ALL,
                }),
                value_target,
            ]
        } else {
            vec![value_target]
        };
        let entry = format!("fs_{group}");
        let pipeline = self
            .device
            .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("rastercheck lavapipe"),
                layout: None,
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some("vs"),
                    compilation_options: Default::default(),
                    buffers: &[Some(wgpu::VertexBufferLayout {
                        array_stride: (VERTEX_FLOATS * 4) as u64,
                        step_mode: wgpu::VertexStepMode::Vertex,
                        attributes: &attributes,
                    })],
                },
                primitive: wgpu::PrimitiveState {
                    topology: wgpu::PrimitiveTopology::TriangleList,
                    front_face: wgpu::FrontFace::Ccw,
                    cull_mode: match cull {
                        Cull::None => None,
                        Cull::CounterClockwise => Some(wgpu::Face::Front),
                        Cull::Clockwise => Some(wgpu::Face::Back),
                    },
                    ..Default::default()
                },
                depth_stencil: None,
                multisample: wgpu::MultisampleState {
                    count: samples,
                    ..Default::default()
                },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(&entry),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: None,
            });
        self.pipelines
            .insert((mode, group, cull, samples), pipeline.clone());
        pipeline
    }

    fn render(&mut self, scene: &Scene, plan: &Plan, bits: u32) -> Result<Frame, RasterError> {
        let (w, h) = (scene.canvas.width, scene.canvas.height);
        let (tw, th) = gpu::target_size(scene, self.max_side, "the lavapipe adapter")?;
        let groups = gpu::groups(plan);
        let (vertices, runs) = gpu::vertex_stream(scene, bits, (tw, th));

        let device = self.device.clone();
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let vertex_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("vertices"),
            size: (vertices.len().max(VERTEX_FLOATS) * 4) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        if !vertices.is_empty() {
            self.queue
                .write_buffer(&vertex_buffer, 0, f32_bytes(&vertices).as_slice());
        }
        let target = |format: wgpu::TextureFormat| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some("target"),
                size: wgpu::Extent3d {
                    width: tw,
                    height: th,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            })
        };
        let count = target(self.count_format);
        let values: Vec<wgpu::Texture> = (0..groups)
            .map(|_| target(wgpu::TextureFormat::Rgba32Float))
            .collect();

        let mut encoder = device.create_command_encoder(&Default::default());
        self.record_groups(
            &mut encoder,
            (&count, &values),
            &runs,
            (scene.rules.cull, 1),
            &vertex_buffer,
            (w, h),
        );
        let readback = |texture: &wgpu::Texture, texel: u32, encoder: &mut wgpu::CommandEncoder| {
            copy_out(&device, encoder, texture, texel, (w, h))
        };
        let count_texel = self.count_format.block_copy_size(None).unwrap_or(4);
        let count_buffer = readback(&count, count_texel, &mut encoder);
        let value_buffers: Vec<_> = values
            .iter()
            .map(|t| readback(t, 16, &mut encoder))
            .collect();
        self.queue.submit([encoder.finish()]);
        for (buffer, _) in std::iter::once(&count_buffer).chain(&value_buffers) {
            buffer.map_async(wgpu::MapMode::Read, .., |_| {});
        }
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RasterError::Failed(format!("lavapipe: waiting for the frame: {e}")))?;
        if let Some(e) = pollster::block_on(oom.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: out of memory: {e}")));
        }
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: wgpu error: {e}")));
        }

        let n = w as usize * h as usize;
        let read = |(buffer, row): &(wgpu::Buffer, u32), texel: usize| {
            let view = buffer
                .get_mapped_range(..)
                .map_err(|e| RasterError::Failed(format!("lavapipe: reading back: {e}")))?;
            let mut out = Vec::with_capacity(n * texel / 4);
            for y in 0..h as usize {
                let start = y * *row as usize;
                out.extend_from_slice(&view[start..start + w as usize * texel]);
            }
            Ok::<Vec<u8>, RasterError>(out)
        };
        let count_bytes = read(&count_buffer, count_texel as usize)?;
        let counts: Vec<f32> = if self.count_format == wgpu::TextureFormat::R32Float {
            count_bytes
                .chunks_exact(4)
                .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect()
        } else {
            count_bytes
                .chunks_exact(2)
                .map(|b| f16_to_f32(u16::from_le_bytes([b[0], b[1]])))
                .collect()
        };
        let mut channels: Vec<Vec<f32>> = vec![Vec::with_capacity(n); groups * 4];
        for (g, buffer) in value_buffers.iter().enumerate() {
            let bytes = read(buffer, 16)?;
            for (k, b) in bytes.chunks_exact(4).enumerate() {
                channels[g * 4 + k % 4].push(f32::from_le_bytes([b[0], b[1], b[2], b[3]]));
            }
        }

        let mut frame = Frame::new(w, h, plan.depth, plan.attributes);
        for i in 0..n {
            let c = counts[i];
            if c.fract() != 0.0 || !(0.0..=65535.0).contains(&c) {
                return Err(RasterError::Failed(format!(
                    "lavapipe: coverage count {c} read back at sample {i}"
                )));
            }
            if self.count_format != wgpu::TextureFormat::R32Float && c >= 2048.0 {
                return Err(RasterError::Failed(
                    "lavapipe: over 2048 triangles cover one sample; the R16Float count saturates"
                        .to_owned(),
                ));
            }
            frame.coverage[i] = c as u16;
            frame.last[i] = channels[0][i] as u32;
            if c > 0.0 {
                if let Some(depth) = &mut frame.depth {
                    depth[i] = f64::from(channels[1][i]);
                }
                for (k, a) in frame.attributes.iter_mut().enumerate() {
                    a[i] = f64::from(channels[2 + k][i]);
                }
            }
        }
        Ok(frame)
    }
}

impl Gpu {
    /// The unpacking pass, built on first use.
    fn unpack(&mut self) -> &Unpack {
        let device = &self.device;
        self.unpack.get_or_insert_with(|| {
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("rastercheck lavapipe unpack"),
                entries: &[wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::FRAGMENT,
                    ty: wgpu::BindingType::Texture {
                        sample_type: wgpu::TextureSampleType::Float { filterable: false },
                        view_dimension: wgpu::TextureViewDimension::D2,
                        multisampled: true,
                    },
                    count: None,
                }],
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("rastercheck lavapipe unpack"),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            });
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("rastercheck lavapipe unpack"),
                source: wgpu::ShaderSource::Wgsl(UNPACK_SHADER.into()),
            });
            let pipeline = |format: wgpu::TextureFormat| {
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some("rastercheck lavapipe unpack"),
                    layout: Some(&pipeline_layout),
                    vertex: wgpu::VertexState {
                        module: &module,
                        entry_point: Some("vs"),
                        compilation_options: Default::default(),
                        buffers: &[],
                    },
                    primitive: wgpu::PrimitiveState::default(),
                    depth_stencil: None,
                    multisample: wgpu::MultisampleState::default(),
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some("fs"),
                        compilation_options: Default::default(),
                        targets: &[Some(wgpu::ColorTargetState {
                            format,
                            blend: None,
                            write_mask: wgpu::ColorWrites::ALL,
                        })],
                    }),
                    multiview_mask: None,
                    cache: None,
                })
            };
            Unpack {
                single: pipeline(wgpu::TextureFormat::R32Float),
                quad: pipeline(wgpu::TextureFormat::Rgba32Float),
                layout,
            }
        })
    }

    /// Draws an antialiased scene into 4× multisampled targets (the plan's
    /// offsets are Vulkan's standard 4×, checked by the caller), spreads
    /// each target's samples over a non-multisampled target 4× wider
    /// (texel (4x + s, y) holds sample s of pixel (x, y), which is slot
    /// 4·p + s of the frame), reads those back, and box-resolves.
    fn render_msaa(&mut self, scene: &Scene, plan: &Plan, bits: u32) -> Result<Frame, RasterError> {
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

        let device = self.device.clone();
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let vertex_buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("vertices"),
            size: (vertices.len().max(VERTEX_FLOATS) * 4) as u64,
            usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        if !vertices.is_empty() {
            self.queue
                .write_buffer(&vertex_buffer, 0, f32_bytes(&vertices).as_slice());
        }
        let texture = |format, (width, height), sample_count, usage| {
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
        };
        let binding = wgpu::TextureUsages::TEXTURE_BINDING;
        let count = texture(self.msaa.count, (tw, th), N, binding);
        let values: Vec<wgpu::Texture> = (0..groups)
            .map(|_| texture(self.msaa.values, (tw, th), N, binding))
            .collect();

        let mut encoder = device.create_command_encoder(&Default::default());
        self.record_groups(
            &mut encoder,
            (&count, &values),
            &runs,
            (scene.rules.cull, N),
            &vertex_buffer,
            (w, h),
        );

        // Each sample to its own texel: (4x + s, y).
        let unpack = self.unpack();
        let wide = (w * N, h);
        let copy = wgpu::TextureUsages::COPY_SRC;
        let mut spread = |source: &wgpu::Texture, format, pipeline: &wgpu::RenderPipeline| {
            let target = texture(format, wide, 1, copy);
            let source_view = source.create_view(&Default::default());
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
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
        let count_buffer = copy_out(&device, &mut encoder, &count_wide, 4, wide);
        let value_buffers: Vec<_> = values_wide
            .iter()
            .map(|t| copy_out(&device, &mut encoder, t, 16, wide))
            .collect();
        self.queue.submit([encoder.finish()]);
        for (buffer, _) in std::iter::once(&count_buffer).chain(&value_buffers) {
            buffer.map_async(wgpu::MapMode::Read, .., |_| {});
        }
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| RasterError::Failed(format!("lavapipe: waiting for the frame: {e}")))?;
        if let Some(e) = pollster::block_on(oom.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: out of memory: {e}")));
        }
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(RasterError::Failed(format!("lavapipe: wgpu error: {e}")));
        }

        let counts = floats(&read_rows(&count_buffer, 4, wide)?);
        let mut channels: Vec<Vec<f32>> = vec![Vec::with_capacity(counts.len()); groups * 4];
        for (g, buffer) in value_buffers.iter().enumerate() {
            for (k, v) in floats(&read_rows(buffer, 16, wide)?)
                .into_iter()
                .enumerate()
            {
                channels[g * 4 + k % 4].push(v);
            }
        }

        let mut frame = Frame::for_plan(w, h, plan);
        let count_limit = if self.msaa.count == wgpu::TextureFormat::R32Float {
            65535.0
        } else {
            2047.0
        };
        for (i, &c) in counts.iter().enumerate() {
            if c.fract() != 0.0 || !(0.0..=65535.0).contains(&c) {
                return Err(RasterError::Failed(format!(
                    "lavapipe: coverage count {c} read back at slot {i}"
                )));
            }
            if c > count_limit {
                return Err(RasterError::Failed(format!(
                    "lavapipe: {c} triangles cover one sample; the {:?} count is exact only \
                     up to 2048",
                    self.msaa.count
                )));
            }
            frame.coverage[i] = c as u16;
            frame.last[i] = channels[0][i] as u32;
            if c > 0.0 {
                if let Some(depth) = &mut frame.depth {
                    depth[i] = f64::from(channels[1][i]);
                }
                for (k, a) in frame.attributes.iter_mut().enumerate() {
                    a[i] = f64::from(channels[2 + k][i]);
                }
            }
        }
        frame.resolve();
        Ok(frame)
    }
}

/// Spreads sample s of pixel (x, y) of a 4× multisampled float target to
/// texel (4x + s, y): `textureLoad` with Vulkan's sample index s, which is
/// the standard location s.
const UNPACK_SHADER: &str = "
@group(0) @binding(0) var source: texture_multisampled_2d<f32>;

@vertex
fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    // (-1, -1), (3, -1), (-1, 3): one triangle over the whole target.
    return vec4<f32>(f32(i32(i & 1u) * 4 - 1), f32(i32(i >> 1u) * 4 - 1), 0.0, 1.0);
}

@fragment
fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
    let texel = vec2<i32>(floor(p.xy));
    return textureLoad(source, vec2<i32>(texel.x / 4, texel.y), texel.x % 4);
}
";

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

/// Records a copy of a `width × height` texture of `texel`-byte texels into
/// a mappable buffer; returns the buffer and its padded row length.
fn copy_out(
    device: &wgpu::Device,
    encoder: &mut wgpu::CommandEncoder,
    texture: &wgpu::Texture,
    texel: u32,
    (width, height): (u32, u32),
) -> (wgpu::Buffer, u32) {
    let row = (width * texel).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: u64::from(row) * u64::from(height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(row),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
    );
    (buffer, row)
}

/// The rows of a mapped readback buffer without their padding.
fn read_rows(
    (buffer, row): &(wgpu::Buffer, u32),
    texel: usize,
    (width, height): (u32, u32),
) -> Result<Vec<u8>, RasterError> {
    let view = buffer
        .get_mapped_range(..)
        .map_err(|e| RasterError::Failed(format!("lavapipe: reading back: {e}")))?;
    let mut out = Vec::with_capacity(width as usize * height as usize * texel);
    for y in 0..height as usize {
        let start = y * *row as usize;
        out.extend_from_slice(&view[start..start + width as usize * texel]);
    }
    Ok(out)
}

fn floats(bytes: &[u8]) -> Vec<f32> {
    bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}

fn f32_bytes(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

/// IEEE binary16 to f32 (the count target where f32 blending is missing).
fn f16_to_f32(bits: u16) -> f32 {
    let sign = if bits & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exponent = i32::from((bits >> 10) & 0x1f);
    let mantissa = f32::from(bits & 0x3ff);
    sign * match exponent {
        0 => mantissa * 2f32.powi(-24),
        31 => f32::INFINITY,
        e => (1.0 + mantissa / 1024.0) * 2f32.powi(e - 15),
    }
}

/// The WGSL for one interpolation mode: a pass-through vertex shader, and one
/// fragment entry point per group of four channels (`fs_0` also writes 1 to
/// the additive count target). `per_sample` interpolates depth and the
/// non-flat attributes at each sample's own position (`@interpolate(…,
/// sample)`, which also runs the fragment shader once per sample).
fn shader(mode: Interpolation, per_sample: bool) -> String {
    let qualifier = match (mode, per_sample) {
        (Interpolation::Flat, _) | (_, false) => mode.name().to_owned(),
        (_, true) => format!("{}, sample", mode.name()),
    };
    let depth = if per_sample {
        "linear, sample"
    } else {
        "linear"
    };
    let mut channels = vec!["v.prim".to_owned(), "v.depth".to_owned()];
    for k in 0..MAX_ATTRIBUTES {
        channels.push(format!("v.a{}.{}", k / 4, ["x", "y", "z", "w"][k % 4]));
    }
    while channels.len() < GROUPS * 4 {
        channels.push("0.0".to_owned());
    }
    let mut wgsl = format!(
        "struct VertexIn {{
    @location(0) position: vec4<f32>,
    @location(1) info: vec4<f32>,
    @location(2) a0: vec4<f32>,
    @location(3) a1: vec4<f32>,
    @location(4) a2: vec4<f32>,
    @location(5) a3: vec4<f32>,
}}

struct Varyings {{
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) prim: f32,
    @location(1) @interpolate({depth}) depth: f32,
    @location(2) @interpolate({qualifier}) a0: vec4<f32>,
    @location(3) @interpolate({qualifier}) a1: vec4<f32>,
    @location(4) @interpolate({qualifier}) a2: vec4<f32>,
    @location(5) @interpolate({qualifier}) a3: vec4<f32>,
}}

@vertex
fn vs(v: VertexIn) -> Varyings {{
    return Varyings(v.position, v.info.x, v.info.y, v.a0, v.a1, v.a2, v.a3);
}}

struct First {{
    @location(0) count: f32,
    @location(1) values: vec4<f32>,
}}

@fragment
fn fs_0(v: Varyings) -> First {{
    return First(1.0, vec4<f32>({}, {}, {}, {}));
}}
",
        channels[0], channels[1], channels[2], channels[3]
    );
    for g in 1..GROUPS {
        let c = &channels[g * 4..g * 4 + 4];
        wgsl.push_str(&format!(
            "
@fragment
fn fs_{g}(v: Varyings) -> @location(0) vec4<f32> {{
    return vec4<f32>({}, {}, {}, {});
}}
",
            c[0], c[1], c[2], c[3]
        ));
    }
    wgsl
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_floats_decode() {
        assert_eq!(f16_to_f32(0x0000), 0.0);
        assert_eq!(f16_to_f32(0x3c00), 1.0);
        assert_eq!(f16_to_f32(0x4000), 2.0);
        assert_eq!(f16_to_f32(0x6800), 2048.0);
    }

    #[test]
    fn the_ndc_mapping_is_exact_for_snapped_coordinates() {
        // x · 2/P − 1 and back, for 8-bit coordinates across the whole range.
        for p in [1u32, 8, 1024, 16384] {
            let s = 2.0 / p as f32;
            for x in [
                -32768.0f32,
                -32768.0 + 1.0 / 256.0,
                -0.00390625,
                0.5,
                1023.5,
                32768.0 - 1.0 / 256.0,
            ] {
                let ndc = x * s - 1.0;
                assert_eq!(f64::from(ndc), f64::from(x) * 2.0 / f64::from(p) - 1.0);
                assert_eq!((ndc + 1.0) * (p as f32 / 2.0), x);
            }
        }
    }
}
