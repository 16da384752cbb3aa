//! What the GPU-API adapters (`vulkan`, `lavapipe`, `gl`) share: the
//! vertex stream they upload (`stream.rs`), the shifts of shifted passes
//! (`passes.rs`), the draws of time passes (`time.rs`), a real depth
//! attachment's state and read-back (`depth.rs`), the WGSL of the two
//! Vulkan adapters (`wgsl.rs`), what a driver cannot be handed of a
//! clip-space scene (`clip.rs`), what they draw and the target size
//! (`acceptance.rs`), the channels they write (`channels.rs`), the
//! viewport a screen-space scene is drawn through (`view.rs`), and
//! Mesa's environment noise quieted where they start it (`mesa_noise.rs`).
//!
//! Positions are snapped exactly to the case's grid, rounded once to f32,
//! and mapped to clip space over a power-of-two viewport `(x0, y0, P, Q)`
//! enclosing the target and the scene (`view.rs`), on which the mapping
//! and the viewport transform back are exact in f32:
//! `x_ndc = 2(x − x0)/P − 1`, `y_ndc = 1 − 2(y − y0)/Q` (y down on screen), sent as
//! `(x_ndc·w, y_ndc·w, w/2, w)` so the driver's perspective division sees
//! the vertex's w.

mod acceptance;
mod channels;
#[cfg(any(feature = "vulkan", feature = "gl"))]
mod clip;
#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) mod depth;
mod mesa_noise;
mod passes;
#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) mod points;
mod stream;
#[cfg(any(feature = "vulkan", feature = "gl"))]
mod time;
mod view;
#[cfg(any(feature = "lavapipe", feature = "vulkan"))]
pub(crate) mod wgsl;

#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) use clip::clip_space_refusal;
#[cfg_attr(not(feature = "vulkan"), allow(unused_imports))]
pub(crate) use passes::shifts;
#[allow(unused_imports)] // `Run` is the gl adapter's
pub(crate) use stream::{Draw, Placement, Run, Stream, VERTEX_FLOATS};
#[cfg(any(feature = "vulkan", feature = "gl"))]
pub(crate) use time::time_draws;

#[cfg_attr(not(any(feature = "lavapipe", feature = "gl")), allow(unused_imports))]
pub(crate) use acceptance::{capabilities, snapping_bits, target_size};
#[allow(unused_imports)] // not every adapter reads each
pub(crate) use channels::{groups, CHANNELS, GROUPS, MAX_ATTRIBUTES};
pub(crate) use mesa_noise::quiet_mesa;
#[allow(unused_imports)] // not every adapter reads each
pub(crate) use view::{clipped_at, screen_view, View, ViewLimits};
