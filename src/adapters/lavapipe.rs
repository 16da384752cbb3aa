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
//!   choose). **MSAA**: not yet.
//!
//! One device is created on first use and shared by every case (creating it
//! takes a while); a mutex serialises the cases that use it. Compiled
//! pipelines are kept, keyed by interpolation mode, channel group and culling.

use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

use crate::frame::Frame;
use crate::plan::Plan;
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
            antialias: false,
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        if plan.samples_per_pixel != 1 {
            return Err(RasterError::Unsupported(
                "multisampling is not wired to lavapipe yet".to_owned(),
            ));
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
        gpu.render(scene, plan, bits)
    }
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
    modules: HashMap<Interpolation, wgpu::ShaderModule>,
    pipelines: HashMap<(Interpolation, usize, Cull), wgpu::RenderPipeline>,
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
        let limits = adapter.limits();
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("rastercheck lavapipe"),
            required_features: if blendable {
                wgpu::Features::FLOAT32_BLENDABLE
            } else {
                wgpu::Features::empty()
            },
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
            modules: HashMap::new(),
            pipelines: HashMap::new(),
        })
    }

    fn module(&mut self, mode: Interpolation) -> &wgpu::ShaderModule {
        let device = &self.device;
        self.modules.entry(mode).or_insert_with(|| {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("rastercheck lavapipe"),
                source: wgpu::ShaderSource::Wgsl(shader(mode).into()),
            })
        })
    }

    fn pipeline(&mut self, mode: Interpolation, group: usize, cull: Cull) -> wgpu::RenderPipeline {
        if let Some(p) = self.pipelines.get(&(mode, group, cull)) {
            return p.clone();
        }
        let module = self.module(mode).clone();
        let attributes: Vec<wgpu::VertexAttribute> = (0..VERTEX_FLOATS / 4)
            .map(|i| wgpu::VertexAttribute {
                format: wgpu::VertexFormat::Float32x4,
                offset: (i * 16) as u64,
                shader_location: i as u32,
            })
            .collect();
        let value_target = Some(wgpu::ColorTargetState {
            format: wgpu::TextureFormat::Rgba32Float,
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
                    format: self.count_format,
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
                multisample: wgpu::MultisampleState::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(&entry),
                    compilation_options: Default::default(),
                    targets: &targets,
                }),
                multiview_mask: None,
                cache: None,
            });
        self.pipelines.insert((mode, group, cull), pipeline.clone());
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
        for (g, value) in values.iter().enumerate() {
            let pipelines: Vec<(wgpu::RenderPipeline, u32, u32)> = runs
                .iter()
                .map(|&(mode, a, b)| (self.pipeline(mode, g, scene.rules.cull), a, b))
                .collect();
            let count_view = count.create_view(&Default::default());
            let value_view = value.create_view(&Default::default());
            let attachment = |view| {
                Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })
            };
            let attachments = if g == 0 {
                vec![attachment(&count_view), attachment(&value_view)]
            } else {
                vec![attachment(&value_view)]
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
        let readback = |texture: &wgpu::Texture, texel: u32, encoder: &mut wgpu::CommandEncoder| {
            let row = (w * texel).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
            let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("readback"),
                size: u64::from(row) * u64::from(h),
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
                        rows_per_image: Some(h),
                    },
                },
                wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
            );
            (buffer, row)
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
/// the additive count target).
fn shader(mode: Interpolation) -> String {
    let qualifier = mode.name();
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
    @location(1) @interpolate(linear) depth: f32,
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
