//! lavapipe's render pipelines: the shader modules and pipelines that draw
//! the count and the channel groups (one per interpolation mode, channel
//! group, culling and sample count, compiled on first use and kept), and
//! the pass that spreads a 4× target's samples out. The WGSL is
//! `shaders.rs`'s; recording the passes is `draw.rs`'s.

use crate::scene::{Cull, Interpolation};

use super::super::gpu::wgsl;
use super::super::gpu::VERTEX_FLOATS;
use super::device::Gpu;
use super::shaders::shader;
use super::unpack::{Unpack, MSAA};

impl Gpu {
    fn module(&mut self, mode: Interpolation, per_sample: bool) -> &wgpu::ShaderModule {
        let device = &self.device;
        self.modules.entry((mode, per_sample)).or_insert_with(|| {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("rastercheck lavapipe"),
                source: wgpu::ShaderSource::Wgsl(shader(mode, per_sample).into()),
            })
        })
    }

    /// The pipeline drawing channel group `group` (and the count, for group
    /// 0) into `samples`-sample targets (1, or 4 for MSAA).
    pub(super) fn pipeline(
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

    /// The unpacking pass, built on first use.
    pub(super) fn unpack(&mut self) -> &Unpack {
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
                source: wgpu::ShaderSource::Wgsl(wgsl::unpack(MSAA, false).into()),
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
}
