//! Third-party rasterizers behind the one [`Rasterizer`] trait: external
//! programs speaking the protocol of SPEC.md, and built-in adapters for real
//! libraries and drivers. Each built-in adapter sits behind a cargo feature,
//! so that the core stays lean; an adapter whose library or driver is
//! missing on a machine says so when asked to draw (`RasterError::Failed`
//! with the reason), never passes silently.
//!
//! Adapters translate a scene into the library's own input and read its
//! output back into a [`Frame`](crate::frame::Frame). A scene they cannot
//! express (a line rule, attributes, a fill rule they cannot change) is
//! `RasterError::Unsupported`, reported as such and never as a pass or
//! failure.
//!
//! Each adapter is made by name through `crate::registry`, one row each.

#[cfg(feature = "euc")]
pub mod euc;
pub mod external;
#[cfg(any(
    feature = "tiny-skia",
    feature = "euc",
    feature = "vello",
    feature = "lavapipe",
    feature = "gl",
    feature = "vulkan"
))]
mod float_input;
#[cfg(feature = "gl")]
pub mod gl;
#[cfg(any(feature = "lavapipe", feature = "gl", feature = "vulkan"))]
mod gpu;
#[cfg(feature = "lavapipe")]
pub mod lavapipe;
#[cfg(feature = "tiny-skia")]
pub mod tiny_skia;
#[cfg(feature = "vello")]
pub mod vello;
#[cfg(feature = "vulkan")]
pub mod vulkan;
