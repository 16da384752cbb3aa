//! The commands: each `rastercheck` subcommand as a library function, so
//! that the binary, the tests and any other front end run the same code.
//!
//! `src/main.rs` only parses the command line (the argument types live here,
//! derived with clap) and turns an [`Exit`] into the process's exit code.
//! A command reads its cases (`cases.rs`) and rasterizers (`names.rs`,
//! through the registry), runs them (harness), and writes what the user
//! sees: console lines (`console.rs`), files through [`crate::report`].

pub mod baseline;
pub mod bench;
pub mod bless;
pub mod cases;
pub mod console;
pub mod diff;
pub mod docs;
pub mod exit;
pub mod fuzz;
pub mod limits;
pub mod matrix;
pub mod merge;
pub mod names;
pub mod probe;
pub mod rasterizers;
pub mod run;
pub mod show;
pub mod values;

pub use exit::Exit;
pub use limits::LimitArgs;
pub use rasterizers::list_rasterizers;
pub use values::MAX_THREADS;
