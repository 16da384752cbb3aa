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

use crate::rasterizer::Rasterizer;

/// The names of the built-in adapters compiled into this binary.
#[allow(clippy::vec_init_then_push)] // each push is behind its own feature
pub fn names() -> Vec<&'static str> {
    #[allow(unused_mut)]
    let mut names = Vec::new();
    #[cfg(feature = "vulkan")]
    names.extend([vulkan::NAME, vulkan::PASSES_NAME]);
    #[cfg(feature = "lavapipe")]
    names.push(lavapipe::NAME);
    #[cfg(feature = "gl")]
    names.extend([gl::NAME, gl::SOFTPIPE]);
    #[cfg(feature = "tiny-skia")]
    names.push("tiny-skia");
    #[cfg(feature = "euc")]
    names.push("euc");
    #[cfg(feature = "vello")]
    names.push("vello-cpu");
    names
}

/// A built-in adapter by name, or an external program:
/// `external:PROGRAM [ARGS]` and `external-persistent:PROGRAM [ARGS]`
/// (split on whitespace; SPEC.md §12).
pub fn by_name(name: &str) -> Option<Box<dyn Rasterizer>> {
    #[cfg(feature = "vulkan")]
    if name == vulkan::NAME || name == vulkan::PASSES_NAME {
        let passes_only = name == vulkan::PASSES_NAME;
        return Some(Box::new(vulkan::Vulkan { passes_only }));
    }
    #[cfg(feature = "lavapipe")]
    if name == lavapipe::NAME {
        return Some(Box::new(lavapipe::Lavapipe));
    }
    #[cfg(feature = "gl")]
    if name == gl::NAME {
        return Some(Box::new(gl::Gl { softpipe: false }));
    }
    #[cfg(feature = "gl")]
    if name == gl::SOFTPIPE {
        return Some(Box::new(gl::Gl { softpipe: true }));
    }
    match name {
        #[cfg(feature = "tiny-skia")]
        "tiny-skia" => return Some(Box::new(tiny_skia::TinySkia)),
        #[cfg(feature = "euc")]
        "euc" => return Some(Box::new(euc::Euc)),
        #[cfg(feature = "vello")]
        "vello-cpu" => return Some(Box::new(vello::VelloCpu)),
        _ => {}
    }
    if let Some(external) = external::by_name(name) {
        return Some(external);
    }
    None
}
