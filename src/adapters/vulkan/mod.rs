//! `vulkan`: any installed Vulkan driver, through raw Vulkan (ash), not
//! wgpu's portable subset (cargo feature `vulkan`; system package
//! `libvulkan1` and a driver: `mesa-vulkan-drivers` for lavapipe). Which
//! device, what is drawn and how it is read back, its rules, antialiasing
//! and motion: [`docs/drivers/vulkan.md`](../../../docs/drivers/vulkan.md).
//!
//! A scene passes `adapter.rs` (the [`Rasterizer`](crate::rasterizer::Rasterizer)),
//! `refusals.rs` (what the device draws, and why not the rest, with
//! `conservative.rs` for VK_EXT_conservative_rasterization), `native.rs`
//! (natively multisampled or by shifted passes), `shared.rs` (the device
//! and pipelines, made once: `device.rs`, `pipelines.rs`, `shaders.rs`),
//! then `draw.rs` (recorded, submitted, read back, decoded, with
//! `unpack.rs` for a multisampled target). `messenger.rs` keeps the API
//! record (what the validation layer said of the calls); `invalid_call.rs`
//! makes a call it must catch, for the test that shows it does.

mod adapter;
mod conservative;
mod device;
mod draw;
mod invalid_call;
mod messenger;
mod native;
mod pipelines;
mod refusals;
mod shaders;
mod shared;
mod unpack;

pub use adapter::{Vulkan, NAME, PASSES_NAME};
pub use invalid_call::{invalid_call_record, INVALID_CALL_VUID};
pub use messenger::ask_for_validation;
pub use shared::{device_description, device_description_of};
