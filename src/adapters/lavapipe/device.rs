//! lavapipe's device: finding Mesa's CPU Vulkan adapter through wgpu,
//! creating the one device every case shares, and choosing the render
//! target formats it can blend and multisample. Drawing is `draw.rs`'s.

use std::collections::HashMap;

use crate::adapters::gpu;
use crate::scene::{Cull, Interpolation};

use super::unpack::Unpack;

/// What to install when no adapter is found.
const INSTALL_HINT: &str =
    "install mesa-vulkan-drivers libvulkan1 (Debian/Ubuntu) so that wgpu finds the lavapipe CPU adapter";

/// The device every case shares, with its formats, limits and the
/// shader modules and pipelines compiled so far.
pub(super) struct Gpu {
    pub(super) device: wgpu::Device,
    pub(super) queue: wgpu::Queue,
    pub(super) description: String,
    pub(super) count_format: wgpu::TextureFormat,
    pub(super) max_side: u32,
    pub(super) msaa: MsaaFormats,
    /// Shader modules by interpolation mode and per-sample interpolation.
    pub(super) modules: HashMap<(Interpolation, bool), wgpu::ShaderModule>,
    /// Pipelines by interpolation mode, channel group, culling and samples.
    pub(super) pipelines: HashMap<(Interpolation, usize, Cull, u32), wgpu::RenderPipeline>,
    /// The pass that spreads a 4× target's samples over a 4× wider one,
    /// by unpacked format.
    pub(super) unpack: Option<Unpack>,
}

/// The multisampled (4×) render-target formats.
#[derive(Clone, Copy, Debug)]
pub(super) struct MsaaFormats {
    /// The additive count: `R32Float` where the adapter multisamples and
    /// blends it, else `R16Float` (core WebGPU; exact up to 2048).
    pub(super) count: wgpu::TextureFormat,
    /// The channel groups: `Rgba32Float` where the adapter multisamples it,
    /// else `Rgba16Float` (core WebGPU), which holds primitive + 1 exactly
    /// up to 2048 and no depth or attribute to the suite's bound.
    pub(super) values: wgpu::TextureFormat,
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
    pub(super) fn exact_values(&self) -> bool {
        self.values == wgpu::TextureFormat::Rgba32Float
    }
}

impl Gpu {
    pub(super) fn new() -> Result<Gpu, String> {
        gpu::quiet_mesa();
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::VULKAN;
        let instance = wgpu::Instance::new(desc);
        // lavapipe among the adapters when it is there (another CPU driver,
        // such as SwiftShader given to the loader, may come first); else
        // the fallback adapter, said to be no lavapipe below.
        let named_lavapipe = |a: &wgpu::Adapter| {
            let info = a.get_info();
            [&info.name, &info.driver]
                .iter()
                .any(|s| s.contains("llvmpipe") || s.contains("lavapipe"))
        };
        let adapters = pollster::block_on(instance.enumerate_adapters(wgpu::Backends::VULKAN));
        let adapter = match adapters.into_iter().find(named_lavapipe) {
            Some(adapter) => adapter,
            None => pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
                force_fallback_adapter: true,
                ..Default::default()
            }))
            .map_err(|e| format!("no Vulkan adapter: {INSTALL_HINT} ({e})"))?,
        };
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
}
