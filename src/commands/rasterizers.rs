//! `rastercheck rasterizers`: every name `--rasterizer` accepts, with what
//! it is, read from the registry.

use super::console::outln;
use super::exit::Exit;
use crate::registry::{self, Kind};

/// `rastercheck rasterizers`: the built-in names with their kind and
/// description (those whose cargo feature this build lacks said so), then
/// the forms that run an external program.
pub fn list_rasterizers() -> Exit {
    let width = registry::ENTRIES
        .iter()
        .map(|e| e.name.len())
        .chain(registry::EXTERNAL_FORMS.iter().map(|(form, _)| form.len()))
        .max()
        .unwrap_or(0);
    for e in registry::ENTRIES {
        let missing = match e.feature {
            Some(feature) if !e.compiled() => {
                format!(" (not in this build: cargo feature `{feature}`)")
            }
            _ => String::new(),
        };
        outln!(
            "{:width$}  {}: {}{missing}",
            e.name,
            e.kind.name(),
            e.description
        );
    }
    outln!();
    outln!("and any program speaking the protocol of SPEC.md §12:");
    for (form, description) in registry::EXTERNAL_FORMS {
        outln!("{form:width$}  {}: {description}", Kind::External.name());
    }
    Exit::Pass
}
