//! The adapter's multisampled targets: their sample count, and the
//! unpacking pass that spreads their samples out to be read back.

/// Samples per pixel of an antialiased scene: Vulkan's standard 4×.
pub(super) const MSAA: u32 = 4;

/// The unpacking pass's pipelines and their bind group layout.
#[derive(Clone)]
pub(super) struct Unpack {
    pub(super) layout: wgpu::BindGroupLayout,
    /// Into `R32Float` (counts) and `Rgba32Float` (channel groups).
    pub(super) single: wgpu::RenderPipeline,
    pub(super) quad: wgpu::RenderPipeline,
}
