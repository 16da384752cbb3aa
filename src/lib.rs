//! rastercheck: a conformance and accuracy test suite for rasterizers, with
//! an exact reference rasterizer.
//!
//! Data flows one way (see ARCHITECTURE.md):
//!
//! ```text
//! case file → scene → plan → rasterizer → frame → metrics → report
//! ```
//!
//! - [`scene`]: the model every rasterizer shares: exact numbers, rules,
//!   primitives; read from JSON with errors that name the file and path.
//! - [`plan`]: the stages a scene needs, and nothing more.
//! - The rasterizers, behind one trait ([`rasterizer`]): [`reference`], the
//!   exact oracle; [`production`], the fast fixed-point rasterizer (with its
//!   foils and mutants); [`adapters`], third-party rasterizers.
//! - [`frame`]: what every rasterizer returns.
//! - [`metrics`]: coverage, watertightness, interpolation, antialiasing and
//!   time-coverage error, and the verdicts.
//! - [`harness`]: finding and running cases, golden files, baselines.
//! - [`report`]: report.json and everything written from it.
//! - On top: [`registry`] (every rasterizer name, and how to make it),
//!   [`commands`], [`explore`] (fuzz, probe, the conformance matrix) and
//!   [`bench`].
//!
//! [`deadline`] is the per-case time limit that the long loops of every
//! stage poll; [`stop`] is how SIGINT and SIGTERM stop a run (the runner
//! polls it, external programs register their children with it).

pub mod adapters;
pub mod bench;
pub mod commands;
pub mod deadline;
pub mod explore;
pub mod frame;
pub mod harness;
pub mod metrics;
pub mod plan;
pub mod production;
pub mod rasterizer;
pub mod reference;
pub mod registry;
pub mod report;
pub mod scene;
pub mod stop;

pub use frame::Frame;
pub use plan::Plan;
pub use rasterizer::{Capabilities, RasterError, Rasterizer};
pub use scene::{parse_case, CaseError, Limits, Scene};
