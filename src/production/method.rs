//! A production method that is a rasterizer of its own, by its
//! command-line name (what [`methods`](super::catalog::methods) lists).

use crate::rasterizer::Rasterizer;

/// A production method that is a rasterizer of its own (a polygon fill, an
/// antialiasing method), by its command-line name.
pub struct Method {
    pub name: &'static str,
    pub make: fn() -> Box<dyn Rasterizer>,
}
