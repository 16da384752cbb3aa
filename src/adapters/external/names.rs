//! The names that run an external program: `external:…`,
//! `external-persistent:…`, and `NAME=external…`, read into an adapter.

use super::adapter::External;
use super::messages::shorten;
use crate::rasterizer::Rasterizer;

/// Whether `spec` runs an external program (`external:…` or
/// `external-persistent:…`).
fn is_external(spec: &str) -> bool {
    spec.starts_with("external:") || spec.starts_with("external-persistent:")
}

/// `NAME=external:…` or `NAME=external-persistent:…` split into the name
/// reports use and the program's spec; `None` for any other argument. Only
/// the first `=` counts, and only when what follows it starts a spec, so a
/// command whose arguments hold `=` is left whole (`external:prog --a=b`
/// is no name).
pub fn split_name(arg: &str) -> Option<(&str, &str)> {
    if is_external(arg) {
        return None;
    }
    let (name, spec) = arg.split_once('=')?;
    is_external(spec).then_some((name, spec))
}

/// Why `name` cannot name an external program: empty, with whitespace, or
/// with `:` or `=` (which would read as a spec).
pub fn check_name(name: &str) -> Result<(), String> {
    if name.is_empty() {
        return Err("an empty rasterizer name in NAME=external…; give a name before the =".into());
    }
    if name
        .chars()
        .any(|c| c.is_whitespace() || c == ':' || c == '=')
    {
        return Err(format!(
            "rasterizer name {:?} has whitespace, ':' or '='; a name is one word",
            shorten(name)
        ));
    }
    Ok(())
}

/// The adapter for `external:...` and `external-persistent:...` names,
/// also as `NAME=external…` (then called NAME), or `None` for any other.
pub fn by_name(arg: &str) -> Option<Box<dyn Rasterizer>> {
    let (name, spec) = split_name(arg).unwrap_or((arg, arg));
    let (persistent, words) = command_of(spec)?;
    let (program, args) = words.split_first()?;
    Some(Box::new(External::new(
        name,
        program.clone(),
        args.to_vec(),
        persistent,
    )))
}

/// Whether `spec` (`external:…` or `external-persistent:…`, no name) runs
/// its program persistently, and the program with its arguments; `None`
/// for any other spec.
pub(super) fn command_of(spec: &str) -> Option<(bool, Vec<String>)> {
    let (persistent, command) = if let Some(rest) = spec.strip_prefix("external-persistent:") {
        (true, rest)
    } else if let Some(rest) = spec.strip_prefix("external:") {
        (false, rest)
    } else {
        return None;
    };
    Some((
        persistent,
        command.split_whitespace().map(str::to_owned).collect(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_split_only_before_a_spec() {
        assert_eq!(
            split_name("lava=external-persistent:prog --a=b"),
            Some(("lava", "external-persistent:prog --a=b"))
        );
        assert_eq!(split_name("x=external:prog"), Some(("x", "external:prog")));
        // An argument that is a spec is never split, whatever `=` it holds.
        assert_eq!(split_name("external:prog --name=external:y"), None);
        // `RUN=RECORDED` of baseline check is no name.
        assert_eq!(split_name("production=reference"), None);
        assert!(check_name("lava").is_ok());
        for bad in ["", "a b", "a:b", "tab\there"] {
            assert!(check_name(bad).is_err(), "{bad:?}");
        }
    }
}
