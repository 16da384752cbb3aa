//! The conformance matrix: every case through a list of rasterizers, one
//! row per rasterizer and one column per case family, with findings
//! computed from the results, as markdown (and into README.md between the
//! markers `<!-- matrix:begin -->` and `<!-- matrix:end -->`).
//!
//! A rasterizer that cannot start (not compiled into this build, no driver,
//! a program that will not run) is a row that says "not available" and
//! why; it is never dropped.
//!
//! What the findings say about a row's sampler and tie rule is `probe`'s
//! decision ([`Diagnosis`](crate::explore::probe::Diagnosis)), never
//! a guess from the counts: overdraw is blamed on closed edges only when
//! probe finds closed edges, and on an any-coverage or area sampler when
//! probe finds one. The counts say how much; the diagnosis says why.
//!
//! A matrix is built in `build.rs` (rows from the registry, cases through
//! the runner, probe's diagnosis per row) into the types of `table.rs`;
//! `findings.rs` says what the counts mean, `markdown.rs` writes it all.

pub mod build;
pub mod findings;
pub mod markdown;
pub mod table;

pub use build::{build, check_available, rasterizer};
pub use findings::LONG_LINE;
pub use markdown::{replace_block, BEGIN, END};
pub use table::{family, Cell, Matrix, Row};
