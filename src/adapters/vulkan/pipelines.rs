//! The render passes and graphics pipelines, made on first use and kept.
//!
//! One render pass per number of channel groups: the count (`R32_SFLOAT`,
//! additive blending), the groups (`R32G32B32A32_SFLOAT`, no blending: the
//! last primitive in submission order wins, as Vulkan's primitive order
//! guarantees) and a stencil attachment, all cleared on load and left for
//! copying out. One pipeline per run state ([`Draw`]), culling and group
//! count:
//!
//! - triangles: the case's culling, front face counter-clockwise;
//! - lines: the line mode the rule maps to (`vulkan/mod.rs`), the line's
//!   width, never culled;
//! - a polygon's stencil fan: no colour written, every face counted into
//!   the stencil (nonzero: front faces increment and back faces decrement,
//!   wrapping; even-odd: invert);
//! - its cover: colour written where the stencil fills (nonzero: any bit;
//!   even-odd: the low bit), and the stencil cleared behind it.

use std::collections::HashMap;

use ash::vk;

use super::super::gpu::{self, Draw, VERTEX_FLOATS};
use super::conservative::{Ask, ConservativeOffers};
use super::device::{depth_attachment, Device};
use super::shaders;
use crate::scene::{
    Cull, DepthFormat, DepthMode, Interpolation, LineRule, PolygonFill, ProvokingVertex, Scene,
};

/// The count's format and the channel groups'.
pub(super) const COUNT_FORMAT: vk::Format = vk::Format::R32_SFLOAT;
pub(super) const VALUE_FORMAT: vk::Format = vk::Format::R32G32B32A32_SFLOAT;

/// What a pipeline is made for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Key {
    draw: DrawKey,
    cull: Cull,
    stage: Stage,
    groups: usize,
    samples: u32,
}

/// The vertex post-processing and depth state a scene asks for (SPEC.md
/// §16, §18), kept in the pipeline: which vertex provokes, whether depth
/// is clamped rather than clipped, and the depth attachment and polygon
/// offset. `vulkan/mod.rs` refuses what the device lacks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub(super) struct Stage {
    /// `provoking_vertex: last`: VK_EXT_provoking_vertex's LAST_VERTEX.
    pub provoking_last: bool,
    /// `depth: clamp`, or a screen-space scene with a depth attachment
    /// (whose depth is the position's z, never clipped):
    /// depthClampEnable, and depthClipEnable false.
    pub depth_clamp: bool,
    /// A depth attachment of this format (`gpu/depth.rs`): the depth test
    /// always passes and writes, so the last primitive's depth stays.
    pub depth: Option<DepthFormat>,
    /// Polygon offset `[constant, slope, clamp]`, their f32 bits.
    pub bias: Option<[u32; 3]>,
    /// Conservative rasterization (`conservative.rs`): its create info
    /// chained into the rasterization state.
    pub conservative: Option<Ask>,
}

impl Stage {
    /// What the pipelines drawing `scene` on a device offering
    /// `conservative` are asked for: [`Stage::of`], with the conservative
    /// state ([`super::conservative::ask`]) beside the depth attachment,
    /// or why the device cannot draw it conservatively.
    pub(super) fn asked(
        scene: &Scene,
        conservative: Option<&ConservativeOffers>,
    ) -> Result<Stage, String> {
        Ok(Stage {
            conservative: super::conservative::ask(scene, conservative)?,
            ..Stage::of(scene)
        })
    }

    pub(super) fn of(scene: &Scene) -> Stage {
        let requested = gpu::depth::requested(scene);
        let depth = requested.map(|t| t.format);
        let clamp = scene.rules.clip.depth == DepthMode::Clamp;
        Stage {
            provoking_last: scene.rules.provoking_vertex == ProvokingVertex::Last,
            depth_clamp: if scene.in_clip_space() {
                clamp
            } else {
                depth.is_some()
            },
            depth,
            bias: requested.and_then(|t| t.bias).map(|b| b.map(f32::to_bits)),
            conservative: None,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum DrawKey {
    Triangles(Interpolation),
    Lines(LineRule, u32, Interpolation),
    /// Points of a size (its f32 bits).
    Points(u32),
    Stencil(PolygonFill),
    Cover(PolygonFill),
}

/// The kept render passes and pipelines, destroyed with their owner.
pub(super) struct Pipelines {
    device: ash::Device,
    layout: vk::PipelineLayout,
    /// By groups, samples and depth attachment.
    passes: HashMap<(usize, u32, Option<DepthFormat>), vk::RenderPass>,
    /// By interpolation, groups, per-sample, and point size (f32 bits).
    modules: HashMap<(Interpolation, usize, bool, Option<u32>), vk::ShaderModule>,
    pipelines: HashMap<Key, vk::Pipeline>,
    stencil_format: vk::Format,
    independent_blend: bool,
}

impl Pipelines {
    pub(super) fn new(gpu: &Device) -> Result<Pipelines, String> {
        let info = vk::PipelineLayoutCreateInfo::default();
        // SAFETY: a valid device and create info.
        let layout = unsafe { gpu.device.create_pipeline_layout(&info, None) }
            .map_err(|e| format!("creating a pipeline layout: {e}"))?;
        Ok(Pipelines {
            device: gpu.device.clone(),
            layout,
            passes: HashMap::new(),
            modules: HashMap::new(),
            pipelines: HashMap::new(),
            stencil_format: gpu.offers.stencil_format,
            independent_blend: gpu.offers.independent_blend,
        })
    }

    /// The render pass of `groups` channel groups at `samples` samples
    /// per pixel: single-sample targets are left for copying out,
    /// multisampled ones for the read-back pass to sample. Its last
    /// attachment is the stencil, or the `depth` attachment, stored and
    /// left as the colour targets are.
    pub(super) fn render_pass(
        &mut self,
        groups: usize,
        samples: u32,
        depth: Option<DepthFormat>,
    ) -> Result<vk::RenderPass, String> {
        if let Some(&pass) = self.passes.get(&(groups, samples, depth)) {
            return Ok(pass);
        }
        let count = vk::SampleCountFlags::from_raw(samples);
        let left = if samples == 1 {
            vk::ImageLayout::TRANSFER_SRC_OPTIMAL
        } else {
            vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL
        };
        let colour = |format| {
            vk::AttachmentDescription::default()
                .format(format)
                .samples(count)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::STORE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(left)
        };
        let mut attachments = vec![colour(COUNT_FORMAT)];
        attachments.extend((0..groups).map(|_| colour(VALUE_FORMAT)));
        let last = match depth.and_then(depth_attachment) {
            Some((format, _)) => vk::AttachmentDescription::default()
                .format(format)
                .samples(count)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::STORE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(left),
            None => vk::AttachmentDescription::default()
                .format(self.stencil_format)
                .samples(count)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::DONT_CARE)
                .stencil_load_op(vk::AttachmentLoadOp::CLEAR)
                .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        };
        attachments.push(last);
        let colour_refs: Vec<vk::AttachmentReference> = (0..=groups as u32)
            .map(|i| vk::AttachmentReference {
                attachment: i,
                layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
            })
            .collect();
        let stencil_ref = vk::AttachmentReference {
            attachment: groups as u32 + 1,
            layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
        };
        let subpasses = [vk::SubpassDescription::default()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&colour_refs)
            .depth_stencil_attachment(&stencil_ref)];
        let attachment_stages = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT
            | vk::PipelineStageFlags::EARLY_FRAGMENT_TESTS
            | vk::PipelineStageFlags::LATE_FRAGMENT_TESTS;
        let attachment_access = vk::AccessFlags::COLOR_ATTACHMENT_WRITE
            | vk::AccessFlags::COLOR_ATTACHMENT_READ
            | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE
            | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ;
        // The previous pass's copies read the targets before this pass
        // clears them; this pass's copies wait for its drawing.
        let dependencies = [
            vk::SubpassDependency {
                src_subpass: vk::SUBPASS_EXTERNAL,
                dst_subpass: 0,
                src_stage_mask: vk::PipelineStageFlags::TRANSFER | attachment_stages,
                dst_stage_mask: attachment_stages,
                src_access_mask: vk::AccessFlags::TRANSFER_READ | attachment_access,
                dst_access_mask: attachment_access,
                dependency_flags: vk::DependencyFlags::empty(),
            },
            vk::SubpassDependency {
                src_subpass: 0,
                dst_subpass: vk::SUBPASS_EXTERNAL,
                src_stage_mask: attachment_stages,
                dst_stage_mask: vk::PipelineStageFlags::TRANSFER
                    | vk::PipelineStageFlags::FRAGMENT_SHADER,
                src_access_mask: attachment_access,
                dst_access_mask: vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::SHADER_READ,
                dependency_flags: vk::DependencyFlags::empty(),
            },
        ];
        let info = vk::RenderPassCreateInfo::default()
            .attachments(&attachments)
            .subpasses(&subpasses)
            .dependencies(&dependencies);
        // SAFETY: a valid device and create info.
        let pass = unsafe { self.device.create_render_pass(&info, None) }
            .map_err(|e| format!("creating a render pass: {e}"))?;
        self.passes.insert((groups, samples, depth), pass);
        Ok(pass)
    }

    /// The pipeline of a run drawn as `draw`, under `cull` and `stage`,
    /// into `groups` channel groups of `samples` samples per pixel.
    pub(super) fn pipeline(
        &mut self,
        draw: Draw,
        cull: Cull,
        stage: Stage,
        groups: usize,
        samples: u32,
    ) -> Result<vk::Pipeline, String> {
        let key = Key {
            draw: match draw {
                Draw::Triangles(mode) => DrawKey::Triangles(mode),
                Draw::Lines {
                    rule,
                    width,
                    interpolation,
                } => DrawKey::Lines(rule, width.to_bits(), interpolation),
                Draw::Points { size } => DrawKey::Points(size.to_bits()),
                Draw::Stencil(fill) => DrawKey::Stencil(fill),
                Draw::Cover(fill) => DrawKey::Cover(fill),
            },
            cull: match draw {
                Draw::Triangles(_) => cull,
                _ => Cull::None,
            },
            stage,
            groups,
            samples,
        };
        if let Some(&pipeline) = self.pipelines.get(&key) {
            return Ok(pipeline);
        }
        let pipeline = self.make(key)?;
        self.pipelines.insert(key, pipeline);
        Ok(pipeline)
    }

    fn module(
        &mut self,
        mode: Interpolation,
        groups: usize,
        per_sample: bool,
        point_size: Option<u32>,
    ) -> Result<vk::ShaderModule, String> {
        let key = (mode, groups, per_sample, point_size);
        if let Some(&module) = self.modules.get(&key) {
            return Ok(module);
        }
        let size = point_size.map(f32::from_bits);
        let words = shaders::spirv(mode, groups, per_sample, size)?;
        let module = shader_module(&self.device, &words)?;
        self.modules.insert(key, module);
        Ok(module)
    }

    fn make(&mut self, key: Key) -> Result<vk::Pipeline, String> {
        let mode = match key.draw {
            DrawKey::Triangles(mode) | DrawKey::Lines(_, _, mode) => mode,
            // A point's one vertex gives every sample its values.
            DrawKey::Points(_) => Interpolation::Flat,
            DrawKey::Stencil(_) | DrawKey::Cover(_) => Interpolation::Linear,
        };
        let point_size = match key.draw {
            DrawKey::Points(size) => Some(size),
            _ => None,
        };
        let module = self.module(mode, key.groups, key.samples > 1, point_size)?;
        let render_pass = self.render_pass(key.groups, key.samples, key.stage.depth)?;
        let bindings = [vk::VertexInputBindingDescription {
            binding: 0,
            stride: (VERTEX_FLOATS * 4) as u32,
            input_rate: vk::VertexInputRate::VERTEX,
        }];
        let attributes: Vec<vk::VertexInputAttributeDescription> = (0..VERTEX_FLOATS as u32 / 4)
            .map(|i| vk::VertexInputAttributeDescription {
                location: i,
                binding: 0,
                format: vk::Format::R32G32B32A32_SFLOAT,
                offset: i * 16,
            })
            .collect();
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&bindings)
            .vertex_attribute_descriptions(&attributes);
        let assembly =
            vk::PipelineInputAssemblyStateCreateInfo::default().topology(match key.draw {
                DrawKey::Lines(..) => vk::PrimitiveTopology::LINE_LIST,
                DrawKey::Points(_) => vk::PrimitiveTopology::POINT_LIST,
                _ => vk::PrimitiveTopology::TRIANGLE_LIST,
            });
        let cull_mode = match key.cull {
            Cull::None => vk::CullModeFlags::NONE,
            Cull::Clockwise => vk::CullModeFlags::BACK,
            Cull::CounterClockwise => vk::CullModeFlags::FRONT,
        };
        let (width, line_mode) = match key.draw {
            DrawKey::Lines(rule, width, _) => (f32::from_bits(width), Some(line_mode(rule))),
            _ => (1.0, None),
        };
        let mut line_state = vk::PipelineRasterizationLineStateCreateInfoKHR::default()
            .line_rasterization_mode(line_mode.unwrap_or_default());
        let mut raster = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(cull_mode)
            .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
            .line_width(width);
        if line_mode.is_some_and(|m| m != vk::LineRasterizationModeKHR::DEFAULT) {
            raster = raster.push_next(&mut line_state);
        }
        let mut provoking = vk::PipelineRasterizationProvokingVertexStateCreateInfoEXT::default()
            .provoking_vertex_mode(vk::ProvokingVertexModeEXT::LAST_VERTEX);
        if key.stage.provoking_last {
            raster = raster.push_next(&mut provoking);
        }
        let mut depth_clip = vk::PipelineRasterizationDepthClipStateCreateInfoEXT::default()
            .depth_clip_enable(false);
        if key.stage.depth_clamp {
            raster = raster.depth_clamp_enable(true).push_next(&mut depth_clip);
        }
        let mut conservative = key.stage.conservative.map(|ask| ask.create_info());
        if let Some(state) = &mut conservative {
            raster = raster.push_next(state);
        }
        if let Some([constant, slope, clamp]) = key.stage.bias {
            raster = raster
                .depth_bias_enable(true)
                .depth_bias_constant_factor(f32::from_bits(constant))
                .depth_bias_slope_factor(f32::from_bits(slope))
                .depth_bias_clamp(f32::from_bits(clamp));
        }
        let multisample = vk::PipelineMultisampleStateCreateInfo::default()
            .rasterization_samples(vk::SampleCountFlags::from_raw(key.samples));
        let always = vk::StencilOpState {
            fail_op: vk::StencilOp::KEEP,
            pass_op: vk::StencilOp::KEEP,
            depth_fail_op: vk::StencilOp::KEEP,
            compare_op: vk::CompareOp::ALWAYS,
            compare_mask: 0xff,
            write_mask: 0xff,
            reference: 0,
        };
        let (front, back, stencil_test) = match key.draw {
            DrawKey::Stencil(PolygonFill::NonZero) => (
                vk::StencilOpState {
                    pass_op: vk::StencilOp::INCREMENT_AND_WRAP,
                    ..always
                },
                vk::StencilOpState {
                    pass_op: vk::StencilOp::DECREMENT_AND_WRAP,
                    ..always
                },
                true,
            ),
            DrawKey::Stencil(PolygonFill::EvenOdd) => {
                let invert = vk::StencilOpState {
                    pass_op: vk::StencilOp::INVERT,
                    ..always
                };
                (invert, invert, true)
            }
            DrawKey::Cover(fill) => {
                let cover = vk::StencilOpState {
                    pass_op: vk::StencilOp::ZERO,
                    compare_op: vk::CompareOp::NOT_EQUAL,
                    compare_mask: if fill == PolygonFill::EvenOdd {
                        0x01
                    } else {
                        0xff
                    },
                    ..always
                };
                (cover, cover, true)
            }
            _ => (always, always, false),
        };
        // A depth attachment: every fragment passes and writes (a write
        // needs the test enabled), so the last primitive's depth stays.
        let depth_stencil = vk::PipelineDepthStencilStateCreateInfo::default()
            .depth_test_enable(key.stage.depth.is_some())
            .depth_write_enable(key.stage.depth.is_some())
            .depth_compare_op(vk::CompareOp::ALWAYS)
            .stencil_test_enable(stencil_test)
            .front(front)
            .back(back);
        let writes = if matches!(key.draw, DrawKey::Stencil(_)) {
            vk::ColorComponentFlags::empty()
        } else {
            vk::ColorComponentFlags::RGBA
        };
        // The count blends, the values beside it do not: two blend states
        // in one pipeline, which only `independentBlend` allows.
        if key.groups > 0 && !self.independent_blend {
            return Err(
                "the device lacks independentBlend, needed to count coverage while writing values beside it"
                    .to_owned(),
            );
        }
        let mut blends = vec![vk::PipelineColorBlendAttachmentState::default()
            .blend_enable(true)
            .src_color_blend_factor(vk::BlendFactor::ONE)
            .dst_color_blend_factor(vk::BlendFactor::ONE)
            .color_blend_op(vk::BlendOp::ADD)
            .src_alpha_blend_factor(vk::BlendFactor::ONE)
            .dst_alpha_blend_factor(vk::BlendFactor::ONE)
            .alpha_blend_op(vk::BlendOp::ADD)
            .color_write_mask(writes)];
        blends
            .extend((0..key.groups).map(|_| {
                vk::PipelineColorBlendAttachmentState::default().color_write_mask(writes)
            }));
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blends);
        let info = vk::GraphicsPipelineCreateInfo::default()
            .vertex_input_state(&vertex_input)
            .input_assembly_state(&assembly)
            .rasterization_state(&raster)
            .multisample_state(&multisample)
            .depth_stencil_state(&depth_stencil)
            .color_blend_state(&blend)
            .layout(self.layout)
            .render_pass(render_pass);
        graphics_pipeline(&self.device, module, info)
            .map_err(|e| format!("creating a pipeline for {key:?}: {e}"))
    }
}

/// A shader module of naga's SPIR-V.
pub(super) fn shader_module(
    device: &ash::Device,
    words: &[u32],
) -> Result<vk::ShaderModule, String> {
    let info = vk::ShaderModuleCreateInfo::default().code(words);
    // SAFETY: valid SPIR-V from naga.
    unsafe { device.create_shader_module(&info, None) }
        .map_err(|e| format!("creating a shader module: {e}"))
}

/// A graphics pipeline of subpass 0 from `info`'s states, with `module`'s
/// `vs` and `fs` as its stages and one viewport and scissor, set when it
/// draws (the state every pipeline of this adapter shares).
pub(super) fn graphics_pipeline(
    device: &ash::Device,
    module: vk::ShaderModule,
    info: vk::GraphicsPipelineCreateInfo<'_>,
) -> Result<vk::Pipeline, vk::Result> {
    let stages = [
        vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::VERTEX)
            .module(module)
            .name(c"vs"),
        vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::FRAGMENT)
            .module(module)
            .name(c"fs"),
    ];
    let viewport = vk::PipelineViewportStateCreateInfo::default()
        .viewport_count(1)
        .scissor_count(1);
    let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
    let info = info
        .stages(&stages)
        .viewport_state(&viewport)
        .dynamic_state(&dynamic)
        .subpass(0);
    // SAFETY: every state `info` points at lives until this call returns.
    let pipelines =
        unsafe { device.create_graphics_pipelines(vk::PipelineCache::null(), &[info], None) }
            .map_err(|(_, e)| e)?;
    Ok(pipelines[0])
}

/// Destroys kept pipelines, shader modules and render passes, then their
/// pipeline layout.
///
/// # Safety
/// The device is idle, and nothing else holds these objects.
pub(super) unsafe fn destroy_kept<'a>(
    device: &ash::Device,
    pipelines: impl Iterator<Item = &'a vk::Pipeline>,
    modules: impl Iterator<Item = &'a vk::ShaderModule>,
    passes: impl Iterator<Item = &'a vk::RenderPass>,
    layout: vk::PipelineLayout,
) {
    for &p in pipelines {
        device.destroy_pipeline(p, None);
    }
    for &m in modules {
        device.destroy_shader_module(m, None);
    }
    for &p in passes {
        device.destroy_render_pass(p, None);
    }
    device.destroy_pipeline_layout(layout, None);
}

/// The line mode a line rule maps to (`vulkan/mod.rs` refuses the rules a
/// device cannot draw first): `diamond-exit` is BRESENHAM, `rectangle`
/// RECTANGULAR, `parallelogram` DEFAULT on a device without `strictLines`.
fn line_mode(rule: LineRule) -> vk::LineRasterizationModeKHR {
    match rule {
        LineRule::DiamondExit => vk::LineRasterizationModeKHR::BRESENHAM,
        LineRule::Rectangle => vk::LineRasterizationModeKHR::RECTANGULAR,
        LineRule::Parallelogram | LineRule::Midpoint => vk::LineRasterizationModeKHR::DEFAULT,
    }
}

impl Drop for Pipelines {
    fn drop(&mut self) {
        // SAFETY: the device is idle (every submission is waited for), and
        // nothing else holds these objects.
        unsafe {
            destroy_kept(
                &self.device,
                self.pipelines.values(),
                self.modules.values(),
                self.passes.values(),
                self.layout,
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapters::vulkan::conservative::h100;
    use crate::scene::{parse_case, Limits};

    fn case(name: &str) -> Scene {
        let path = format!(
            "{}/cases/conservative/{name}.json",
            env!("CARGO_MANIFEST_DIR")
        );
        let text = std::fs::read_to_string(&path).expect("the case file");
        parse_case(&text, &path, &Limits::default()).expect("a valid case")
    }

    /// The conservative depth cases (SPEC.md §19.9) ask the device for
    /// what an ordinary depth case asks (the depth attachment of the
    /// case's format, clamped to the viewport's [0, 1] and written by
    /// every fragment, its polygon offset; under `exact`, no attachment:
    /// the fragment's z) with the conservative state beside it. No device
    /// here offers the extension, so this is what is asked, never drawn.
    #[test]
    fn a_conservative_depth_case_asks_for_depth_and_the_conservative_state() {
        let offers = h100();
        let attached = [
            ("depth_inside", None, None),
            ("depth_touch_extrapolated", None, None),
            ("depth_band_grown", None, None),
            ("depth_last_writer", None, None),
            ("depth_degenerate_provoking", None, None),
            ("depth_under", None, None),
            ("depth_clamp_unorm16", Some(DepthFormat::Unorm16), None),
            (
                "depth_clamp_float32_below",
                Some(DepthFormat::Float32),
                None,
            ),
            (
                "depth_offset_unorm16",
                Some(DepthFormat::Unorm16),
                Some([4.0f32.to_bits(), 0, 0]),
            ),
        ];
        for (name, format, bias) in attached {
            let scene = case(name);
            assert!(scene.has_depth, "{name}");
            let stage = Stage::asked(&scene, Some(&offers)).unwrap();
            assert_eq!(stage.depth, format, "{name}");
            assert_eq!(stage.depth_clamp, format.is_some(), "{name}");
            assert_eq!(stage.bias, bias, "{name}");
            let ask = stage.conservative.expect(name);
            let under = name == "depth_under";
            assert_eq!(ask.underestimate, under, "{name}");
            let extra = f32::from_bits(ask.extra);
            let expected = match name {
                // u = 1/4: the largest 2^-8 step at most 1/4 − 2^-9.
                "depth_band_grown" | "depth_last_writer" => 63.0 / 256.0,
                _ => 0.0,
            };
            assert_eq!(extra, expected, "{name}");
            assert_eq!(
                ask.create_info().conservative_rasterization_mode,
                if under {
                    vk::ConservativeRasterizationModeEXT::UNDERESTIMATE
                } else {
                    vk::ConservativeRasterizationModeEXT::OVERESTIMATE
                },
                "{name}"
            );
            // The device's declaration no longer refuses the case for
            // its depth (SPEC.md §19.9).
            let support = super::super::conservative::support_for(&scene, Some(&offers));
            assert!(support.depth, "{name}");
            assert_eq!(support.refuses_depth(true), None, "{name}");
        }
        // Without the extension the device's reason still comes first.
        let scene = case("depth_inside");
        let why = Stage::asked(&scene, None).unwrap_err();
        assert!(
            why.contains("offers no VK_EXT_conservative_rasterization"),
            "{why}"
        );
    }
}
