//! Antialiasing in production (SPEC.md §14.2): supersampling at the plan's
//! offsets, adaptive sampling of edge pixels only, and the methods measured
//! beside it.

use super::Method;

/// The antialiasing methods that are rasterizers of their own.
pub fn methods() -> Vec<Method> {
    Vec::new()
}
