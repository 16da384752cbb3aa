//! The harness: from case files on disk to one outcome per case.
//!
//! - [`suite`]: finding case files, reading them, running one case through
//!   the reference and the candidates, and judging the golden file.
//! - [`oracle`]: the reference's answer for a case and what the exact
//!   rationals say beyond its frame, computed once for every candidate.
//! - [`runner`]: many cases at once: selection, parallel execution, limits,
//!   outcomes in a fixed order.
//! - [`golden`]: the blessed reference outputs (EXR) and their comparison.
//! - [`baseline`]: recorded metrics that later runs must not get worse than.
//! - [`profile`]: declared conventions (`run --profile`): a profiled
//!   rasterizer judged under the fill rule its profile declares.
//! - [`matrix`]: every case through several rasterizers, as a conformance
//!   matrix with findings.
//! - [`diagnosis`]: how a rasterizer samples and breaks ties, as `probe`
//!   decides it, in the words both the profile and the matrix use.

pub mod baseline;
pub mod diagnosis;
pub mod golden;
pub mod matrix;
pub mod oracle;
pub mod profile;
pub mod runner;
pub mod suite;
