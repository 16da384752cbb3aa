//! Polygons in production (SPEC.md §14.1): scanline fill with an edge table
//! and an active edge table, and the other polygon methods measured beside
//! it.

use super::fixed::{EdgeInt, Format};
use super::Method;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::{Polygon, Scene};

/// Draws polygon `index` of the scene into `frame`.
pub fn draw<E: EdgeInt>(
    _scene: &Scene,
    _plan: &Plan,
    _format: Format,
    _index: usize,
    _polygon: &Polygon,
    _frame: &mut Frame,
) -> Result<(), RasterError> {
    Err(RasterError::Unsupported(
        "polygons are not drawn by production yet".to_owned(),
    ))
}

/// The polygon methods that are rasterizers of their own.
pub fn methods() -> Vec<Method> {
    Vec::new()
}
