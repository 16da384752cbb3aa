//! Whether an external program can be started at all, checked once before
//! a run: a program that is not there, or is not executable, or a
//! persistent one whose hello is malformed, is one clear error (bad usage,
//! exit 2), not the same error for every case.

use std::io;
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::time::Instant;

use super::adapter::External;
use super::hello;
use super::limits::{max_output_from_env, timeout_from_env, HELLO_WAIT};
use super::messages::shorten;
use super::names::{command_of, split_name};
use super::worker::Worker;

/// Why the program an `external:…` or `external-persistent:…` name (also
/// as `NAME=external…`) runs cannot be started, if it cannot: a path that
/// names no file, a directory, a file no one may execute, or a bare name
/// found on no `PATH` entry, as `exec` would find it. `Ok` for every other
/// name. A program that is found and still fails to start (a script whose
/// interpreter is missing) is an error for each case, as before.
///
/// A persistent program is then started once, and its first line read as
/// the run would read it (SPEC.md §12.7): a hello that breaks §12.7 (an
/// unknown key or word, a value of the wrong type) is refused here, naming
/// its JSON path, and no case is sent. The process is ended at once; a
/// program that writes nothing within the hello's wait (version 1) costs
/// that wait.
pub fn preflight(arg: &str) -> Result<(), String> {
    let spec = split_name(arg).map_or(arg, |(_, spec)| spec);
    let Some((persistent, words)) = command_of(spec)? else {
        return Ok(());
    };
    let Some(program) = words.first() else {
        return Ok(());
    };
    found(program)?;
    if persistent {
        hello_of(program, &words[1..])?;
    }
    Ok(())
}

/// Starts the program once and reads its first line: `Err` when it is a
/// hello that breaks §12.7. A program that cannot start, or writes no
/// hello, is left to the run (each case then says why).
fn hello_of(program: &str, args: &[String]) -> Result<(), String> {
    let external = External::new(program, program.to_owned(), args.to_vec(), true);
    let (Ok(timeout), Ok(max_output)) = (timeout_from_env(), max_output_from_env()) else {
        return Ok(());
    };
    let Ok(child) = external.start() else {
        return Ok(());
    };
    let mut worker = Worker::start(child, max_output);
    worker.await_hello(Instant::now() + HELLO_WAIT.min(timeout));
    worker.end(true);
    match worker.hello.take() {
        Some(Err(why)) => Err(format!(
            "{}: its hello is not a hello of SPEC.md §12.7: {why}",
            shorten(program)
        )),
        Some(Ok(_)) => {
            let mut command = vec![program.to_owned()];
            command.extend_from_slice(args);
            hello::remember(&command);
            Ok(())
        }
        None => Ok(()),
    }
}

/// Whether `program` names an executable file, as `exec` would find it.
fn found(program: &str) -> Result<(), String> {
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
