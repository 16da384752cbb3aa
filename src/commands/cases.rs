//! The case paths a command is given: `cases` by default, discovered with
//! what was skipped and what could not be found printed.

use std::path::PathBuf;

use super::console::outln;
use crate::harness::case_list::CaseList;
use crate::harness::discover::{self, Discovery};

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
pub(crate) fn discover(paths: Vec<PathBuf>) -> (Discovery, bool) {
    printed(discover::discover(&default_paths(paths)))
}

/// [`discover`] with the cases held compactly (`run`).
pub(crate) fn discover_list(paths: Vec<PathBuf>) -> (Discovery<CaseList>, bool) {
    printed(discover::discover_list(&default_paths(paths)))
}

/// What was skipped and what could not be found, printed.
fn printed<C>(found: Discovery<C>) -> (Discovery<C>, bool) {
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

/// "did you mean" for a `--family` no case found has: the nearest family
/// among the cases found, if one is plausibly meant.
pub(crate) fn family_hint<'a>(
    family: &str,
    ids: impl IntoIterator<Item = &'a str>,
) -> Option<String> {
    let families: std::collections::BTreeSet<&str> = ids
        .into_iter()
        .filter_map(|id| id.split_once('/').map(|(f, _)| f))
        .collect();
    let families: Vec<&str> = families.into_iter().collect();
    if families.contains(&family) {
        return None;
    }
    let near = crate::scene::case::closest(family, &families)?;
    Some(format!(
        "no case is of family {family:?}; did you mean {near:?}?"
    ))
}
