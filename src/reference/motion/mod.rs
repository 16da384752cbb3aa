//! Exact time coverage of moving primitives, with a certified bound
//! (SPEC.md §15.2).
//!
//! A moving vertex is linear in the instant τ, so every quantity whose sign
//! decides whether a primitive covers a sample (edge functions, twice the
//! area, a line's side conditions) is a polynomial of degree ≤ 2 in τ with
//! integer coefficients on the grid (`motion/quadratic.rs`). Between their
//! real roots coverage is constant and is decided exactly at one rational
//! instant (`motion/measure.rs`); rational roots are exact points, and
//! irrational ones are isolated between rationals by an integer square root
//! and left undecided, which is the bound. The per-instant decisions are
//! §3 and §4.4 written out again (`motion/moving.rs`).
//!
//! Static primitives are drawn once by the static reference
//! (`coverage_under`): they cover a sample for the whole shutter or not at
//! all, and every kind of primitive may be static.
//!
//! What this module does not do: decide inside an isolating interval (it
//! is narrowed instead), or use a float anywhere but the final rounding of
//! [`frame`].
//!
//! `coverage.rs` gives each pixel's value, `point_coverage.rs` one
//! primitive's at one point, both through `sample.rs`; `certified.rs` is
//! what they return, `frame.rs` the frame rounded from it.

mod certified;
mod coverage;
mod frame;
mod measure;
mod moving;
mod point_coverage;
mod quadratic;
mod sample;

pub use certified::{max_bound, Certified};
pub use coverage::{time_coverage, time_coverage_from, time_coverage_with};
pub use frame::{frame, frame_of};
#[doc(hidden)]
pub use moving::Mutation;
pub use point_coverage::{point_coverage, point_coverage_with};
