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
//! - [`reference`]: the exact oracle. [`production`]: the fast fixed-point
//!   rasterizer. [`mutants`]: production with one deliberate bug each.
//! - [`frame`]: what every rasterizer returns.
//! - [`metrics`]: coverage, watertightness and interpolation error.
//! - [`suite`]: discovery and running; [`golden`] and [`report`]: outputs;
//!   [`baseline`]: recorded metrics that later runs must not get worse than.

pub mod adapters;
pub mod baseline;
pub mod bench;
pub mod deadline;
pub mod frame;
pub mod fuzz;
pub mod golden;
pub mod matrix;
pub mod metrics;
pub mod mutants;
pub mod plan;
pub mod probe;
pub mod production;
pub mod rasterizer;
pub mod reference;
pub mod report;
pub mod runner;
pub mod scene;
pub mod suite;

pub use frame::Frame;
pub use plan::Plan;
pub use rasterizer::{Capabilities, RasterError, Rasterizer};
pub use scene::{parse_case, CaseError, Limits, Scene};
