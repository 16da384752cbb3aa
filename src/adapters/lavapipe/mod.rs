//! `lavapipe`: Mesa's Vulkan rasterizer on the CPU, through wgpu's Vulkan
//! backend (cargo feature `lavapipe`). What is drawn and how it is read
//! back, its rules and 4× MSAA:
//! [`docs/drivers/lavapipe.md`](../../../docs/drivers/lavapipe.md).
//!
//! A scene passes `adapter.rs` (the [`Rasterizer`](crate::rasterizer::Rasterizer)),
//! `refusals.rs` (what wgpu lets it draw), `shared.rs` (the device, made
//! once by `device.rs`), `draw.rs` (set up, cleared and drawn with
//! `pipelines.rs`' pipelines and `shaders.rs`' WGSL, a 4× target spread
//! out by `unpack.rs`), then `readback.rs`; `prepared.rs` is the same for
//! the bench, one submission at a time.

mod adapter;
mod device;
mod draw;
mod pipelines;
mod prepared;
mod readback;
mod refusals;
mod shaders;
mod shared;
mod unpack;

pub use adapter::{Lavapipe, NAME};
pub use refusals::{standard_4x_refusal, STANDARD_4X};
pub use shared::{adapter_description, msaa_formats};
