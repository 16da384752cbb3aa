//! Greedy shrinking of a failing scene to a small one that fails the same
//! check: the loop over passes, the evaluation budget, and the simplicity
//! keys that make every accepted step smaller. The passes live beside it:
//! `cut.rs` (fewer things), `settings.rs` (simpler declarations) and
//! `moves.rs` (simpler numbers).
//!
//! `greedy.rs` runs the passes over the state of `state.rs`; the moves
//! toward simpler numbers use the keys of `values.rs`.

mod cut;
mod greedy;
mod moves;
mod settings;
mod state;
mod values;

pub use greedy::shrink;
pub use state::{Shrunk, SHRINK_BUDGET};
