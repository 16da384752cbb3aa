//! `gl` and `softpipe`: Mesa's OpenGL rasterizers on the CPU (llvmpipe, or
//! softpipe with `GALLIUM_DRIVER=softpipe`), driven through EGL on the
//! surfaceless platform with glow (cargo feature `gl`). What is drawn and
//! how it is read back, the driver's rules, antialiasing, motion and the
//! one context per process: [`docs/drivers/gl.md`](../../../docs/drivers/gl.md).
//!
//! A scene passes `adapter.rs` (the [`Rasterizer`](crate::rasterizer::Rasterizer)),
//! `accepted.rs` (what GL draws, and why not the rest; `conservative.rs`
//! refuses conservative cases naming the extensions), `context.rs` (the
//! shared EGL context), `passes.rs` / `time.rs` / `msaa.rs` (the passes it
//! is drawn in), `draw.rs` (set up, cleared and drawn into a `drawing.rs`,
//! with `depth.rs`'s attachment), then `readback.rs`; `prepared.rs` is the
//! same for the bench, phase by phase. `debug.rs` keeps the API record
//! (what KHR_debug said of the calls); `invalid_call.rs` makes a call it
//! must catch, for the test that shows it does.

mod accepted;
mod adapter;
mod clip;
mod conservative;
mod context;
mod debug;
mod depth;
mod draw;
mod drawing;
mod driver;
mod fetch;
mod invalid_call;
mod lines;
mod msaa;
mod offset_clamp;
mod passes;
mod prepared;
mod readback;
mod samples;
mod shaders;
mod time;

pub use adapter::{Gl, NAME, SOFTPIPE};
pub use driver::{driver_multisampling, renderer_description, DriverMultisampling};
pub use invalid_call::{invalid_call_record, INVALID_CALL_ERROR};
