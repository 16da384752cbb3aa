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

use crate::rasterizer::Rasterizer;

/// The names of the built-in adapters compiled into this binary.
pub fn names() -> Vec<&'static str> {
    #[allow(unused_mut)]
    let mut names = Vec::new();
    names
}

/// A built-in adapter by name; `external:PROGRAM` is handled by the caller.
pub fn by_name(name: &str) -> Option<Box<dyn Rasterizer>> {
    let _ = name;
    None
}
