//! Rasterizer names on the command line: each `-r` resolved through the
//! registry, with "did you mean" for a mistyped one, and the names given to
//! external programs (`-r NAME=external…`) checked.

use super::exit::Exit;
use crate::adapters::external;
use crate::rasterizer::Rasterizer;
use crate::registry::{self, Missing};

/// The prefixes that run an external program, for "did you mean".
const EXTERNAL_PREFIXES: [&str; 2] = ["external", "external-persistent"];

/// The error for a name that makes no rasterizer: a built-in one this build
/// lacks (and the feature that has it), or one suggestion by edit distance,
/// and where to find them all.
pub(crate) fn unknown_rasterizer(name: &str) -> String {
    if let Err(Missing::NotCompiled { feature }) = registry::resolve(name) {
        return format!(
            "rasterizer {name:?} is not compiled into this build (cargo feature `{feature}`: build with --features {feature})"
        );
    }
    let list = "`rastercheck rasterizers` lists them";
    match suggestion(name) {
        Some(meant) => format!("unknown rasterizer {name:?}; did you mean {meant:?}? ({list})"),
        None => format!("unknown rasterizer {name:?}; {list}"),
    }
}

/// What a mistyped `-r` most likely meant: `NAME=external-persistent:PROGRAM`
/// for `NAME=PROGRAM`, the external prefix spelled right, or the nearest
/// built-in name.
fn suggestion(name: &str) -> Option<String> {
    if let Some((called, program)) = name.split_once('=') {
        let program = program.trim();
        if external::check_name(called).is_ok()
            && !program.is_empty()
            && !program.starts_with("external")
        {
            return Some(format!("{called}=external-persistent:{program}"));
        }
    }
    if let Some((prefix, program)) = name.split_once(':') {
        let meant = crate::scene::case::closest(prefix, &EXTERNAL_PREFIXES);
        if let Some(meant) = meant.filter(|m| *m != prefix && !program.trim().is_empty()) {
            return Some(format!("{meant}:{program}"));
        }
    }
    registry::suggestion(name).map(str::to_owned)
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
        let Some((name, _)) = external::split_name(arg) else {
            continue;
        };
        external::check_name(name).map_err(refuse)?;
        if registry::names().contains(&name) {
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
    environment_for(name)?;
    // First: a command that cannot be split, or a hello that breaks the
    // protocol, is said as such, not as an unknown name.
    startable(name)?;
    registry::by_name(name).ok_or_else(|| {
        eprintln!("error: {}", unknown_rasterizer(name));
        Exit::BadInput
    })
}

/// An external program that cannot start (`adapters::external::preflight`):
/// `Err` (already printed, once, before any case runs) when it cannot.
pub(crate) fn startable(name: &str) -> Result<(), Exit> {
    external::preflight(name).map_err(|e| {
        eprintln!("error: -r {name}: {e}");
        Exit::BadInput
    })
}

/// Bad usage in the environment a rasterizer reads (an external program's
/// `RASTERCHECK_EXTERNAL_TIMEOUT`): `Err` (already printed) when malformed.
pub(crate) fn environment_for(name: &str) -> Result<(), Exit> {
    let name = external::split_name(name).map_or(name, |(_, spec)| spec);
    if !name.trim_start().starts_with("external") {
        return Ok(());
    }
    external::check_environment().map_err(|e| {
        eprintln!("error: {e}");
        Exit::BadInput
    })
}

/// The named rasterizers; `Err` (already printed) on an unknown name.
pub(crate) fn rasterizers_named(names: &[String]) -> Result<Vec<Box<dyn Rasterizer>>, Exit> {
    check_names(names)?;
    names.iter().map(|name| rasterizer_named(name)).collect()
}
