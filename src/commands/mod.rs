//! The commands: each `rastercheck` subcommand as a library function, so
//! that the binary, the tests and any other front end run the same code.
//!
//! `src/main.rs` only parses the command line (the argument types live here,
//! derived with clap) and turns an [`Exit`] into the process's exit code.
//! Each command reads cases (harness), runs rasterizers, and writes what the
//! user sees: console lines here, files through [`crate::report`].

use console::outln;
use std::path::PathBuf;

use crate::harness::suite;
use crate::rasterizer::Rasterizer;

pub mod baseline;
pub mod bench;
pub mod bless;
pub mod console;
pub mod diff;
pub mod fuzz;
pub mod limits;
pub mod matrix;
pub mod probe;
pub mod run;
pub mod show;

pub use limits::LimitArgs;

/// How a command ended, as SPEC.md §9 maps it to an exit code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exit {
    /// 0: everything judged passes.
    Pass,
    /// 1: something failed.
    Fail,
    /// 2: bad input or bad usage, or a case over a resource limit.
    BadInput,
    /// 3: nothing was judged: every selected case unsupported by every
    /// candidate, or a selection that matched no case.
    NothingJudged,
    /// 128 + the signal (130: SIGINT, 143: SIGTERM): the run was stopped
    /// and its report is partial (`crate::stop`).
    Interrupted(i32),
}

impl Exit {
    /// The process exit code.
    pub fn code(self) -> u8 {
        match self {
            Exit::Pass => 0,
            Exit::Fail => 1,
            Exit::BadInput => 2,
            Exit::NothingJudged => 3,
            Exit::Interrupted(signal) => crate::stop::exit_code(signal),
        }
    }
}

/// The most worker threads `--threads` accepts (README: "Exit codes").
pub const MAX_THREADS: usize = 256;

/// A `--threads` value: 0 (one per core) to [`MAX_THREADS`]. More threads
/// than that only cost memory and time (16 000 took minutes).
pub(crate) fn threads(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(n) if n <= MAX_THREADS => Ok(n),
        _ => Err(format!(
            "expected a number of threads from 0 (one per core) to {MAX_THREADS}, got {:?}",
            shorten(text)
        )),
    }
}

/// `text` cut to about 80 characters, for echoing in a message.
pub(crate) fn shorten(text: &str) -> String {
    crate::adapters::external::shorten(text)
}

/// The case paths given, or `cases` when none is.
pub(crate) fn default_paths(paths: Vec<PathBuf>) -> Vec<PathBuf> {
    if paths.is_empty() {
        vec![PathBuf::from("cases")]
    } else {
        paths
    }
}

/// Discovers cases, printing what was skipped and what could not be found;
/// the flag says whether something could not be found.
pub(crate) fn discover(paths: Vec<PathBuf>) -> (suite::Discovery, bool) {
    let found = suite::discover(&default_paths(paths));
    for dir in &found.skipped {
        outln!(
            "note: skipping {} (negative tests; name it explicitly to check it)",
            dir.display()
        );
    }
    for error in &found.errors {
        eprintln!("error: {error}");
    }
    let bad = !found.errors.is_empty();
    (found, bad)
}

/// The error for a name that is no rasterizer, listing the known ones.
pub(crate) fn unknown_rasterizer(name: &str) -> String {
    format!(
        "unknown rasterizer {name:?}; known: {}",
        suite::rasterizer_names().join(", ")
    )
}

/// Checks the names given as `-r NAME=external…` (SPEC.md §12): each one
/// word, not a bundled rasterizer's, and given once among `args`. `Err`
/// (already printed) otherwise: bad usage.
pub(crate) fn check_names(args: &[String]) -> Result<(), Exit> {
    let refuse = |why: String| {
        eprintln!("error: {why}");
        Exit::BadInput
    };
    let mut seen: Vec<&str> = Vec::new();
    for arg in args {
        let Some((name, _)) = crate::adapters::external::split_name(arg) else {
            continue;
        };
        crate::adapters::external::check_name(name).map_err(refuse)?;
        if suite::rasterizer_names().contains(&name) {
            return Err(refuse(format!(
                "rasterizer name {name:?} is a bundled rasterizer's; choose another"
            )));
        }
        if seen.contains(&name) {
            return Err(refuse(format!(
                "rasterizer name {name:?} is given to two -r; give each its own"
            )));
        }
        seen.push(name);
    }
    Ok(())
}

/// The named rasterizer; `Err` (already printed) when there is none, or
/// when the environment it reads is malformed.
pub(crate) fn rasterizer_named(name: &str) -> Result<Box<dyn Rasterizer>, Exit> {
    check_names(&[name.to_owned()])?;
    let found = suite::rasterizer(name).ok_or_else(|| {
        eprintln!("error: {}", unknown_rasterizer(name));
        Exit::BadInput
    })?;
    environment_for(name)?;
    startable(name)?;
    Ok(found)
}

/// Bad usage in the environment a rasterizer reads (an external program's
/// `RASTERCHECK_EXTERNAL_TIMEOUT`): `Err` (already printed) when malformed.
pub(crate) fn environment_for(name: &str) -> Result<(), Exit> {
    let name = crate::adapters::external::split_name(name).map_or(name, |(_, spec)| spec);
    if !name.trim_start().starts_with("external") {
        return Ok(());
    }
    crate::adapters::external::check_environment().map_err(|e| {
        eprintln!("error: {e}");
        Exit::BadInput
    })
}

/// An external program that cannot start (`adapters::external::preflight`):
/// `Err` (already printed, once, before any case runs) when it cannot.
pub(crate) fn startable(name: &str) -> Result<(), Exit> {
    crate::adapters::external::preflight(name).map_err(|e| {
        eprintln!("error: -r {name}: {e}");
        Exit::BadInput
    })
}

/// The named rasterizers; `Err` (already printed) on an unknown name.
pub(crate) fn rasterizers_named(names: &[String]) -> Result<Vec<Box<dyn Rasterizer>>, Exit> {
    check_names(names)?;
    names.iter().map(|name| rasterizer_named(name)).collect()
}

/// `rastercheck rasterizers`: the names `--rasterizer` accepts.
pub fn list_rasterizers() -> Exit {
    for name in suite::rasterizer_names() {
        outln!("{name}");
    }
    Exit::Pass
}
