//! Foils: deliberately inexact rasterizers built from production, to show
//! what the exact reference catches that a looser check would not. They are
//! not candidates for correctness; each documents where it departs from
//! SPEC.md.

pub mod dda;
pub mod float_edges;

pub use dda::{DdaF32, DdaF64};
pub use float_edges::{FloatF32, FloatF64};
