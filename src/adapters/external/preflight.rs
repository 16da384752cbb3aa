//! Whether an external program can be started at all, checked once before
//! a run: a program that is not there, or is not executable, is one clear
//! error (bad usage, exit 2), not the same error for every case.

use std::io;
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

use super::names::{command_of, split_name};

/// Why the program an `external:…` or `external-persistent:…` name (also
/// as `NAME=external…`) runs cannot be started, if it cannot: a path that
/// names no file, a directory, a file no one may execute, or a bare name
/// found on no `PATH` entry, as `exec` would find it. `Ok` for every other
/// name. A program that is found and still fails to start (a script whose
/// interpreter is missing) is an error for each case, as before.
pub fn preflight(arg: &str) -> Result<(), String> {
    let spec = split_name(arg).map_or(arg, |(_, spec)| spec);
    let Some((_, words)) = command_of(spec) else {
        return Ok(());
    };
    let Some(program) = words.first() else {
        return Ok(());
    };
    let why = if program.contains('/') {
        match executable(Path::new(program)) {
            Ok(()) => return Ok(()),
            Err(why) => why,
        }
    } else {
        let path = std::env::var_os("PATH").unwrap_or_default();
        let mut refused = None;
        for dir in std::env::split_paths(&path) {
            let dir = if dir.as_os_str().is_empty() {
                PathBuf::from(".")
            } else {
                dir
            };
            match executable(&dir.join(program)) {
                Ok(()) => return Ok(()),
                Err(why) if refused.is_none() && !why.starts_with(NOT_FOUND) => refused = Some(why),
                Err(_) => {}
            }
        }
        refused.unwrap_or_else(|| format!("{NOT_FOUND} (not found on PATH)"))
    };
    Err(format!("cannot start {program}: {why}"))
}

/// What the system says of a path that names nothing.
const NOT_FOUND: &str = "No such file or directory";

/// Whether `path` is a file someone may execute, or why not.
fn executable(path: &Path) -> Result<(), String> {
    let metadata = std::fs::metadata(path).map_err(|e| describe(&e))?;
    if metadata.is_dir() {
        return Err("Is a directory, not a program".to_owned());
    }
    if metadata.permissions().mode() & 0o111 == 0 {
        return Err("Permission denied (the file is not executable)".to_owned());
    }
    Ok(())
}

/// An I/O error as the system words it, without its error number.
fn describe(e: &io::Error) -> String {
    if e.kind() == io::ErrorKind::NotFound {
        return NOT_FOUND.to_owned();
    }
    let text = e.to_string();
    match text.find(" (os error ") {
        Some(at) => text[..at].to_owned(),
        None => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_program_that_is_not_there_or_not_executable_is_refused() {
        assert_eq!(preflight("production"), Ok(()));
        assert_eq!(preflight("external:sh -c true"), Ok(()));
        assert_eq!(preflight("x=external-persistent:/bin/sh"), Ok(()));
        assert_eq!(
            preflight("external:./no/such/program --fast"),
            Err("cannot start ./no/such/program: No such file or directory".to_owned())
        );
        assert_eq!(
            preflight("x=external-persistent:no-such-program-here"),
            Err(
                "cannot start no-such-program-here: No such file or directory \
                 (not found on PATH)"
                    .to_owned()
            )
        );
        let err = preflight("external:/").unwrap_err();
        assert!(err.contains("Is a directory"), "{err}");
    }
}
