//! Exploring a rasterizer beyond the bundled cases.
//!
//! - [`fuzz`]: random and adversarial scenes, each judged against the
//!   reference, and a failure shrunk to a minimal case file.
//! - [`probe`]: what conventions a rasterizer follows, found from its frames
//!   alone, and the profile `run --profile` judges it by.
//! - [`matrix`]: every case through several rasterizers, as a conformance
//!   matrix whose findings say what probe found.

pub mod fuzz;
pub mod matrix;
pub mod probe;
