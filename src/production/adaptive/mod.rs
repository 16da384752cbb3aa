//! Two antialiasing methods measured beside production's own sampling and
//! built on it: `refine.rs` (`adaptive-refine`, a pixel decided from a
//! quarter of its samples when they agree; inexact) and `resolve.rs`
//! (`adaptive-resolve`, counts instead of masks, resolved bit for bit as
//! full supersampling's box resolve).

pub mod refine;
pub mod resolve;

pub use refine::AdaptiveRefine;
pub use resolve::AdaptiveResolve;
