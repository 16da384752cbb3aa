//! The limits an external program runs under: its time and output per
//! case (set from the environment), and the waits and buffers of its
//! processes.

use std::time::Duration;

use super::messages::shorten;

/// How long a fresh persistent process is given to write its hello before
/// the first request is sent to it (it is sent at once when a line comes
/// sooner). A program that writes none is v1, and pays this once per run
/// (per thread that starts one at the same time): once a process has
/// written no hello, the next ones are not waited for.
pub(super) const HELLO_WAIT: Duration = Duration::from_secs(1);

/// The most lines a v2 exchange skips (stray lines, late answers) before
/// the process is judged to flood and is killed; their bytes count against
/// the output limit too.
pub(super) const MAX_SKIPPED_LINES: usize = 1000;

/// How long a look for what a persistent process wrote unasked
/// ([`Worker::unread`](super::worker::Worker::unread)) waits for the end of
/// a line whose bytes it found in the pipe: a blank line is forgiven, and
/// anything else is a program out of step.
pub(super) const UNREAD_GRACE: Duration = Duration::from_millis(200);

/// How long a version 1 process still running after its answer, or
/// before its next request, is waited for to fall asleep (waiting for its
/// next request) or to write, so that a line it writes after its answer is
/// not taken for the next answer ([`Worker::unread`](super::worker::Worker::unread)).
/// A process that runs on past it (a thread that never sleeps) is not
/// waited for again: its version 1 answers are matched by order alone.
pub(super) const SETTLE_WAIT: Duration = Duration::from_secs(1);

/// How many ids of requests that timed out a v2 process remembers, so
/// that their late answers are told apart from stray lines.
pub(super) const OWED_IDS: usize = 64;

/// The environment variable that sets the per-case time limit, in seconds.
pub const TIMEOUT_ENV: &str = "RASTERCHECK_EXTERNAL_TIMEOUT";

/// The per-case time limit when the environment does not set one.
pub const DEFAULT_TIMEOUT: Duration = Duration::from_secs(30);

/// The environment variable that sets how many bytes a program may write to
/// stdout for one case (one-shot) or in one line (persistent).
pub const MAX_OUTPUT_ENV: &str = "RASTERCHECK_EXTERNAL_MAX_OUTPUT";

/// The output limit when the environment does not set one: 256 MiB.
pub const DEFAULT_MAX_OUTPUT: u64 = 256 << 20;

/// How long a persistent process may take to exit after `{"bye": true}`.
pub(super) const BYE_GRACE: Duration = Duration::from_secs(2);

/// How long the output pipes may stay open after the process has exited
/// (a grandchild holding them) before rastercheck stops waiting for them.
pub(super) const PIPE_GRACE: Duration = Duration::from_millis(500);

/// How much of a program's stderr is kept, and how much is quoted.
pub(super) const STDERR_KEEP: usize = 64 * 1024;
pub(super) const STDERR_QUOTE_CHARS: usize = 1500;
pub(super) const STDERR_QUOTE_LINES: usize = 12;

/// Checks the environment external programs read (`TIMEOUT_ENV`,
/// `MAX_OUTPUT_ENV`): a
/// malformed value is bad usage, said before any case runs.
pub fn check_environment() -> Result<(), String> {
    timeout_from_env()?;
    max_output_from_env().map(|_| ())
}

pub(super) fn timeout_from_env() -> Result<Duration, String> {
    match std::env::var(TIMEOUT_ENV) {
        Err(std::env::VarError::NotPresent) => Ok(DEFAULT_TIMEOUT),
        Err(std::env::VarError::NotUnicode(text)) => Err(format!(
            "{TIMEOUT_ENV}={:?} is not a positive number of seconds",
            shorten(&text.to_string_lossy())
        )),
        Ok(text) => text
            .trim()
            .parse::<f64>()
            .ok()
            .filter(|s| s.is_finite() && *s > 0.0 && *s < 1e9)
            .map(Duration::from_secs_f64)
            .ok_or_else(|| {
                format!(
                    "{TIMEOUT_ENV}={:?} is not a positive number of seconds",
                    shorten(&text)
                )
            }),
    }
}

pub(super) fn max_output_from_env() -> Result<u64, String> {
    match std::env::var(MAX_OUTPUT_ENV) {
        Err(_) => Ok(DEFAULT_MAX_OUTPUT),
        Ok(text) => text
            .trim()
            .parse::<u64>()
            .ok()
            .filter(|&n| n > 0)
            .ok_or_else(|| {
                format!(
                    "{MAX_OUTPUT_ENV}={:?} is not a positive number of bytes",
                    shorten(&text)
                )
            }),
    }
}
