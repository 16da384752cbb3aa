//! `plots/*.svg`: accuracy charts, computed from the report model alone (so
//! they work for any rasterizer) and written as standalone SVG:
//!
//! - `aa-error-by-family.svg`: per family, the distribution of each
//!   rasterizer's antialiasing error (edge RMS of resolved − exact area);
//! - `interpolation-ulp-by-family.svg`: per family, the distribution of
//!   each rasterizer's interpolation error in ulp (largest over channels);
//! - `aa-error-vs-samples-<rasterizer>.svg`: for a rasterizer with
//!   samples, antialiasing error against samples per pixel, one line per
//!   sample pattern;
//! - `time-error-vs-samples-<rasterizer>.svg`: for a rasterizer with
//!   moving scenes, time-coverage error against time samples, one line per
//!   time pattern.
//!
//! A chart without data is not drawn; one whose every value is 0 neither,
//! and [`notes`] says so instead.
//!
//! `all.rs` lists the charts, drawn by `by_family.rs` and `by_samples.rs`
//! from what `data.rs` reads of the report, as `charts.rs` lays them out in
//! `svg.rs`'s primitives; each is a [`Plot`] (`plot.rs`).

mod all;
mod by_family;
mod by_samples;
pub mod charts;
mod data;
mod plot;
pub mod svg;

pub use all::{notes, plots, write};
pub use plot::{Plot, FOLDER};

#[cfg(test)]
mod tests;
