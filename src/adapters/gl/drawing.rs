//! One scene set up in the shared context: the passes' vertex streams in a
//! vertex array and buffer of its own, and its framebuffer of float
//! attachments (and a stencil or depth buffer where it needs one), as
//! `draw.rs` makes, clears, draws and deletes it.

use super::clip::Stage;
use super::passes::{Pass, Reading};
use crate::adapters::gpu;
use crate::adapters::gpu::depth::DepthTarget;
use crate::plan::Plan;
use crate::scene::Cull;

/// One scene set up in the shared context: its passes' vertex streams in a
/// vertex array and buffer of its own, and its framebuffer of float
/// attachments, so that it can be cleared, drawn and read back again and
/// again while other cases use the context in between.
pub(super) struct Drawing<'a> {
    pub(super) plan: &'a Plan,
    pub(super) canvas: (u32, u32),
    /// Each pass's tile: the power-of-two size the canvas is drawn in.
    pub(super) target: (u32, u32),
    /// The viewport of a screen-space scene, in its tile's pixels
    /// (`gpu/view.rs`).
    pub(super) view: gpu::View,
    /// The framebuffer's size: every tile.
    pub(super) size: (u32, u32),
    pub(super) cull: Cull,
    /// The provoking vertex, and a clip-space scene's viewport, depth range
    /// and clamp (`clip.rs`).
    pub(super) stage: Stage,
    /// Each stream's runs, indexing the vertex buffer.
    pub(super) streams: Vec<Vec<gpu::Run>>,
    /// Each stream's viewport corner: the view's, moved by its shift.
    pub(super) corners: Vec<[f32; 2]>,
    /// One pass per tile (one sample slot, slot order), or one per time
    /// test, each scissored to its pixel.
    pub(super) passes: Vec<Pass>,
    pub(super) reading: Reading,
    /// Samples a pixel of the target has; 0: single-sample.
    pub(super) samples: u32,
    pub(super) vao: glow::VertexArray,
    pub(super) vbo: Option<glow::Buffer>,
    pub(super) fbo: Option<glow::Framebuffer>,
    /// Colour attachments: the count's, then the channel groups'.
    pub(super) attachments: usize,
    /// The attachments (single-sample), or the copy's (multisampled).
    pub(super) renderbuffers: Vec<glow::Renderbuffer>,
    /// The attachments (multisampled).
    pub(super) textures: Vec<glow::Texture>,
    /// Depth and stencil, for scenes with polygons.
    pub(super) stencil: Option<glow::Renderbuffer>,
    /// The depth attachment's format and offset, for scenes that need one
    /// (`depth.rs`; never with polygons).
    pub(super) depth: Option<DepthTarget>,
    /// The depth attachment (single-sample).
    pub(super) depth_buffer: Option<glow::Renderbuffer>,
    /// The single-sample framebuffer a multisampled drawing's samples
    /// are fetched into, one at a time, to be read.
    pub(super) copy: Option<glow::Framebuffer>,
}
