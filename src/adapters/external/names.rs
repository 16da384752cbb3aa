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
/// also as `NAME=external…` (then called NAME), or `None` for any other,
/// and for one whose command cannot be split (an unterminated quote: the
/// preflight says why, [`super::preflight::preflight`]).
pub fn by_name(arg: &str) -> Option<Box<dyn Rasterizer>> {
    let (name, spec) = split_name(arg).unwrap_or((arg, arg));
    let (persistent, words) = command_of(spec).ok()??;
    let (program, args) = words.split_first()?;
    Some(Box::new(External::new(
        name,
        program.clone(),
        args.to_vec(),
        persistent,
    )))
}

/// Whether `spec` (`external:…` or `external-persistent:…`, no name) runs
/// its program persistently, and the program with its arguments, split as
/// a shell would ([`words`]); `Ok(None)` for any other spec, `Err` for a
/// command that cannot be split.
pub(super) fn command_of(spec: &str) -> Result<Option<(bool, Vec<String>)>, String> {
    let (persistent, command) = if let Some(rest) = spec.strip_prefix("external-persistent:") {
        (true, rest)
    } else if let Some(rest) = spec.strip_prefix("external:") {
        (false, rest)
    } else {
        return Ok(None);
    };
    Ok(Some((persistent, words(command)?)))
}

/// `command` split into words as a POSIX shell splits a simple command
/// (SPEC.md §12): at unquoted whitespace; `'…'` keeps everything inside as
/// written; `"…"` keeps everything, a backslash escaping only `"`, `$`, a
/// backquote, a backslash and a line break; an unquoted backslash keeps
/// the next character. Nothing is expanded: no variables, no globbing, no
/// `~`. An unterminated quote, or a lone backslash at the end, is an error.
pub(super) fn words(command: &str) -> Result<Vec<String>, String> {
    let mut words = Vec::new();
    let mut word: Option<String> = None;
    let mut chars = command.chars();
    let unterminated = |quote: char| {
        format!(
            "the command {:?} has an unterminated {quote} quote; close it, or escape it \
             with \\",
            shorten(command)
        )
    };
    while let Some(c) = chars.next() {
        match c {
            c if c.is_whitespace() => words.extend(word.take()),
            '\'' => {
                let w = word.get_or_insert_with(String::new);
                loop {
                    match chars.next() {
                        Some('\'') => break,
                        Some(c) => w.push(c),
                        None => return Err(unterminated('\'')),
                    }
                }
            }
            '"' => {
                let w = word.get_or_insert_with(String::new);
                loop {
                    match chars.next() {
                        Some('"') => break,
                        Some('\\') => match chars.next() {
                            Some(c @ ('"' | '\\' | '$' | '`')) => w.push(c),
                            Some('\n') => {}
                            Some(c) => {
                                w.push('\\');
                                w.push(c);
                            }
                            None => return Err(unterminated('"')),
                        },
                        Some(c) => w.push(c),
                        None => return Err(unterminated('"')),
                    }
                }
            }
            '\\' => match chars.next() {
                Some('\n') => {}
                Some(c) => word.get_or_insert_with(String::new).push(c),
                None => {
                    return Err(format!(
                        "the command {:?} ends with a lone \\; escape it as \\\\",
                        shorten(command)
                    ))
                }
            },
            c => word.get_or_insert_with(String::new).push(c),
        }
    }
    words.extend(word);
    Ok(words)
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

    #[test]
    fn commands_split_as_a_shell_splits_them() {
        let split = |c: &str| words(c).unwrap();
        assert_eq!(split("  prog  -a   b "), ["prog", "-a", "b"]);
        assert_eq!(
            split("python3 '/my dir/r.py' --name \"a b\""),
            ["python3", "/my dir/r.py", "--name", "a b"]
        );
        assert_eq!(split("a\\ b c"), ["a b", "c"]);
        assert_eq!(split("'it''s' x"), ["its", "x"]);
        assert_eq!(
            split("'a\\b' \"a\\b\" \"\\\"\\$\\\\\""),
            ["a\\b", "a\\b", "\"$\\"]
        );
        // Empty quotes are a word; nothing is expanded.
        assert_eq!(split("p '' \"\""), ["p", "", ""]);
        assert_eq!(split("p $HOME *.json ~"), ["p", "$HOME", "*.json", "~"]);
        assert_eq!(split("x=\"1 2\"y"), ["x=1 2y"]);
        assert!(split("").is_empty());
        for bad in ["prog 'open", "prog \"open", "prog \\"] {
            let error = words(bad).unwrap_err();
            assert!(error.contains("the command"), "{bad}: {error}");
        }
        assert!(words("p 'x").unwrap_err().contains("unterminated ' quote"));
        assert_eq!(
            command_of("external-persistent:p 'a b'"),
            Ok(Some((true, vec!["p".to_owned(), "a b".to_owned()])))
        );
        assert_eq!(command_of("production"), Ok(None));
        assert!(command_of("external:p \"").is_err());
    }
}
