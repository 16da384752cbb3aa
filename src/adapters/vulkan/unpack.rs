//! Reading a multisampled target back sample by sample: a pass that draws
//! one triangle over a single-sample target n times wider than the canvas,
//! whose texel (n·x + s, y) loads sample s of pixel (x, y) of the
//! multisampled target (`shaders::unpack_spirv`). Vulkan's sample index s
//! is the frame's slot s (the caller checks the device's locations), so
//! the wide target read row by row is the frame's slot order (n·p + s).
//! The render pass, pipeline layout and pipelines are made on first use
//! and kept.

use std::collections::HashMap;

use ash::vk;

use super::pipelines::{destroy_kept, graphics_pipeline, shader_module};
use super::shaders;

/// The kept objects of the read-back pass, destroyed with their owner.
pub(super) struct Unpack {
    device: ash::Device,
    pub set_layout: vk::DescriptorSetLayout,
    pub layout: vk::PipelineLayout,
    passes: HashMap<vk::Format, vk::RenderPass>,
    /// By sample count, and whether the source is a depth attachment.
    modules: HashMap<(u32, bool), vk::ShaderModule>,
    pipelines: HashMap<(vk::Format, u32, bool), vk::Pipeline>,
}

impl Unpack {
    pub(super) fn new(device: &ash::Device) -> Result<Unpack, String> {
        let bindings = [vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::SAMPLED_IMAGE)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
        let info = vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings);
        // SAFETY: valid create infos; destroyed in Drop.
        unsafe {
            let set_layout = device
                .create_descriptor_set_layout(&info, None)
                .map_err(|e| format!("creating a descriptor set layout: {e}"))?;
            let layouts = [set_layout];
            let info = vk::PipelineLayoutCreateInfo::default().set_layouts(&layouts);
            let layout = match device.create_pipeline_layout(&info, None) {
                Ok(layout) => layout,
                Err(e) => {
                    device.destroy_descriptor_set_layout(set_layout, None);
                    return Err(format!("creating a pipeline layout: {e}"));
                }
            };
            Ok(Unpack {
                device: device.clone(),
                set_layout,
                layout,
                passes: HashMap::new(),
                modules: HashMap::new(),
                pipelines: HashMap::new(),
            })
        }
    }

    /// The render pass of one single-sample `format` target, left for
    /// copying out.
    pub(super) fn render_pass(&mut self, format: vk::Format) -> Result<vk::RenderPass, String> {
        if let Some(&pass) = self.passes.get(&format) {
            return Ok(pass);
        }
        let attachments = [vk::AttachmentDescription::default()
            .format(format)
            .samples(vk::SampleCountFlags::TYPE_1)
            .load_op(vk::AttachmentLoadOp::DONT_CARE)
            .store_op(vk::AttachmentStoreOp::STORE)
            .initial_layout(vk::ImageLayout::UNDEFINED)
            .final_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)];
        let refs = [vk::AttachmentReference {
            attachment: 0,
            layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        }];
        let subpasses = [vk::SubpassDescription::default()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&refs)];
        let dependencies = [vk::SubpassDependency {
            src_subpass: 0,
            dst_subpass: vk::SUBPASS_EXTERNAL,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            dst_stage_mask: vk::PipelineStageFlags::TRANSFER,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::TRANSFER_READ,
            dependency_flags: vk::DependencyFlags::empty(),
        }];
        let info = vk::RenderPassCreateInfo::default()
            .attachments(&attachments)
            .subpasses(&subpasses)
            .dependencies(&dependencies);
        // SAFETY: a valid device and create info.
        let pass = unsafe { self.device.create_render_pass(&info, None) }
            .map_err(|e| format!("creating the read-back render pass: {e}"))?;
        self.passes.insert(format, pass);
        Ok(pass)
    }

    /// The pipeline that spreads an `n`-sample target (a depth attachment
    /// when `depth`, read as a depth texture) into `format`.
    pub(super) fn pipeline(
        &mut self,
        format: vk::Format,
        n: u32,
        depth: bool,
    ) -> Result<vk::Pipeline, String> {
        if let Some(&pipeline) = self.pipelines.get(&(format, n, depth)) {
            return Ok(pipeline);
        }
        let render_pass = self.render_pass(format)?;
        let module = match self.modules.get(&(n, depth)) {
            Some(&module) => module,
            None => {
                let module = shader_module(&self.device, &shaders::unpack_spirv(n, depth)?)?;
                self.modules.insert((n, depth), module);
                module
            }
        };
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default();
        let assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let raster = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .line_width(1.0);
        let multisample = vk::PipelineMultisampleStateCreateInfo::default()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1);
        let blends = [vk::PipelineColorBlendAttachmentState::default()
            .color_write_mask(vk::ColorComponentFlags::RGBA)];
        let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blends);
        let info = vk::GraphicsPipelineCreateInfo::default()
            .vertex_input_state(&vertex_input)
            .input_assembly_state(&assembly)
            .rasterization_state(&raster)
            .multisample_state(&multisample)
            .color_blend_state(&blend)
            .layout(self.layout)
            .render_pass(render_pass);
        let pipeline = graphics_pipeline(&self.device, module, info)
            .map_err(|e| format!("creating the read-back pipeline: {e}"))?;
        self.pipelines.insert((format, n, depth), pipeline);
        Ok(pipeline)
    }
}

impl Drop for Unpack {
    fn drop(&mut self) {
        // SAFETY: the device is idle, and nothing else holds these objects.
        unsafe {
            destroy_kept(
                &self.device,
                self.pipelines.values(),
                self.modules.values(),
                self.passes.values(),
                self.layout,
            );
            self.device
                .destroy_descriptor_set_layout(self.set_layout, None);
        }
    }
}
