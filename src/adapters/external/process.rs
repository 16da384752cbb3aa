//! The processes of external programs: waiting for one within a deadline,
//! killing it with its process group, reading its stdout within a bound,
//! and keeping the tail of its stderr for the messages that quote it.

use std::io::Read;
use std::process::{Child, ExitStatus};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

use super::limits::{PIPE_GRACE, STDERR_KEEP, STDERR_QUOTE_CHARS, STDERR_QUOTE_LINES};
use crate::rasterizer::RasterError;

pub(super) fn exit_description(status: ExitStatus) -> String {
    if let Some(code) = status.code() {
        return format!("exited with status {code}");
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            return format!("killed by signal {signal}");
        }
    }
    format!("exited: {status}")
}

/// Polls until the child exits or the deadline passes; `None` on timeout.
pub(super) fn wait_until(child: &mut Child, deadline: Instant) -> Option<ExitStatus> {
    wait_until_or(child, deadline, || false)
}

/// Polls until the child exits, the deadline passes or `stop` says so;
/// `None` unless it exited.
pub(super) fn wait_until_or(
    child: &mut Child,
    deadline: Instant,
    mut stop: impl FnMut() -> bool,
) -> Option<ExitStatus> {
    let mut pause = Duration::from_micros(200);
    loop {
        if stop() {
            return None;
        }
        match child.try_wait() {
            Ok(Some(status)) => {
                crate::stop::unregister(child.id());
                return Some(status);
            }
            Ok(None) => {}
            // Cannot be waited for: treat as exited, the caller kills it.
            Err(_) => return None,
        }
        let now = Instant::now();
        if now >= deadline {
            return None;
        }
        thread::sleep(pause.min(deadline - now));
        pause = (pause * 2).min(Duration::from_millis(10));
    }
}

/// Kills a child and reaps it.
pub(super) fn kill(child: &mut Child) {
    crate::stop::unregister(child.id());
    let _ = child.kill();
    let _ = child.wait();
}

extern "C" {
    /// POSIX `kill(2)`, from the C library std already links.
    #[link_name = "kill"]
    pub(super) fn posix_kill(pid: i32, signal: i32) -> i32;
}

pub(super) const SIGKILL: i32 = 9;

/// Kills every process of the child's group (it leads one of its own:
/// `process_group(0)`), then the child itself, and reaps it. Called right
/// after the child exits or instead of waiting for it: its group id stays
/// taken while any member lives, so the signal reaches only its group.
pub(super) fn kill_group(child: &mut Child) {
    if let Ok(pgid) = i32::try_from(child.id()) {
        if pgid > 1 {
            // SAFETY: kill(2) takes plain integers and touches no memory.
            unsafe {
                posix_kill(-pgid, SIGKILL);
            }
        }
    }
    kill(child);
}

/// Joins the threads that end within `grace` (they end once the pipes they
/// serve close); a thread still blocked then (a process that left its group
/// holds its pipe) is left to end by itself.
pub(super) fn join_within(threads: Vec<JoinHandle<()>>, grace: Duration) {
    let deadline = Instant::now() + grace;
    for thread in threads {
        while !thread.is_finished() && Instant::now() < deadline {
            thread::sleep(Duration::from_millis(1));
        }
        if thread.is_finished() {
            let _ = thread.join();
        }
    }
}

/// Why a program's stdout was not read to the end.
pub(super) enum Output {
    /// More bytes than the limit (`RASTERCHECK_EXTERNAL_MAX_OUTPUT`).
    TooLong,
    Read(std::io::Error),
}

/// Reads to the end, or stops after `max` bytes.
pub(super) fn read_bounded(stdout: impl Read, max: u64) -> Result<Vec<u8>, Output> {
    let mut bytes = Vec::new();
    stdout
        .take(max.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(Output::Read)?;
    if bytes.len() as u64 > max {
        return Err(Output::TooLong);
    }
    Ok(bytes)
}

/// A failure, with what the program said on stderr since byte `mark`.
pub(super) fn failed(why: String, stderr: &StderrTail, mark: u64) -> RasterError {
    stderr.wait_closed(PIPE_GRACE.min(Duration::from_millis(200)));
    match stderr.since(mark) {
        Some(tail) => RasterError::Failed(format!("{why}; stderr: {tail}")),
        None => RasterError::Failed(format!("{why}; nothing on stderr")),
    }
}

/// The end of a program's stderr, collected by a thread.
#[derive(Clone)]
pub(super) struct StderrTail(pub(super) Arc<(Mutex<TailState>, Condvar)>);

#[derive(Default)]
pub(super) struct TailState {
    /// The last bytes read (at most `2 * STDERR_KEEP`).
    pub(super) bytes: Vec<u8>,
    /// Bytes read in all, so that callers can mark a position.
    pub(super) written: u64,
    pub(super) closed: bool,
}

impl StderrTail {
    /// Starts the thread that reads it, returned to be joined.
    pub(super) fn collect(
        stderr: Option<std::process::ChildStderr>,
    ) -> (StderrTail, Option<JoinHandle<()>>) {
        let tail = StderrTail(Arc::new((Mutex::new(TailState::default()), Condvar::new())));
        let Some(mut stderr) = stderr else {
            tail.0 .0.lock().unwrap().closed = true;
            return (tail, None);
        };
        let shared = tail.clone();
        let thread = thread::spawn(move || {
            let mut buffer = [0u8; 8192];
            loop {
                let n = stderr.read(&mut buffer).unwrap_or(0);
                let (state, changed) = &*shared.0;
                let mut state = state.lock().unwrap_or_else(|e| e.into_inner());
                if n == 0 {
                    state.closed = true;
                    changed.notify_all();
                    return;
                }
                state.bytes.extend_from_slice(&buffer[..n]);
                state.written += n as u64;
                if state.bytes.len() > 2 * STDERR_KEEP {
                    let cut = state.bytes.len() - STDERR_KEEP;
                    state.bytes.drain(..cut);
                }
            }
        });
        (tail, Some(thread))
    }

    pub(super) fn written(&self) -> u64 {
        self.0 .0.lock().unwrap_or_else(|e| e.into_inner()).written
    }

    /// Waits (at most `limit`) for the program to close its stderr.
    pub(super) fn wait_closed(&self, limit: Duration) {
        let (state, changed) = &*self.0;
        let state = state.lock().unwrap_or_else(|e| e.into_inner());
        let _ = changed.wait_timeout_while(state, limit, |s| !s.closed);
    }

    /// The last lines written since byte `mark`, or `None` if there are none.
    pub(super) fn since(&self, mark: u64) -> Option<String> {
        let state = self.0 .0.lock().unwrap_or_else(|e| e.into_inner());
        let new = state
            .written
            .saturating_sub(mark)
            .min(state.bytes.len() as u64) as usize;
        let bytes = &state.bytes[state.bytes.len() - new..];
        let text = String::from_utf8_lossy(bytes);
        let text = text.trim_end();
        if text.trim().is_empty() {
            return None;
        }
        let lines: Vec<&str> = text.lines().collect();
        let mut tail = lines[lines.len().saturating_sub(STDERR_QUOTE_LINES)..].join("\n");
        let chars = tail.chars().count();
        if chars > STDERR_QUOTE_CHARS {
            tail = tail.chars().skip(chars - STDERR_QUOTE_CHARS).collect();
            tail.insert(0, '…');
        } else if lines.len() > STDERR_QUOTE_LINES {
            tail.insert_str(0, "…\n");
        }
        Some(tail)
    }
}
