//! One process of a persistent adapter (SPEC.md §12.4, §12.7): started in
//! its own process group, fed one request a line, and read until the line
//! that answers the request in flight; under version 2 by its id, stray
//! and late lines skipped and counted.

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read};
use std::process::{Child, ChildStdin, ExitStatus};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

use serde_json::Value;

use super::envelope::{Envelope, Id};
use super::hello::{self, Hello};
use super::limits::{MAX_SKIPPED_LINES, OWED_IDS, PIPE_GRACE};
use super::messages::shorten;
use super::process::*;
use super::protocol::Outgoing;

/// What a persistent exchange got instead of a line.
pub(super) enum Exchange {
    TimedOut,
    /// Too many lines that were not the answer (v2).
    Flood,
    /// The process closed its stdout (it exited, most likely).
    Closed,
    /// A malformed hello came in place of the answer (v1), saying why.
    Late(String),
    /// v2: a line shaped as an answer (§12.2's fields) carried no `id`,
    /// shown here shortened: the program does not echo ids.
    NoId(String),
    Broken(Output),
}

/// One process of a persistent adapter.
pub(super) struct Worker {
    pub(super) child: Child,
    /// Lines to write to its stdin, by a thread, so that a program that
    /// stops reading cannot block rastercheck past the time limit.
    pub(super) requests: Option<Sender<Outgoing>>,
    pub(super) lines: Receiver<Result<String, Output>>,
    pub(super) stderr: StderrTail,
    /// The threads that write its stdin and read its stdout and stderr.
    pub(super) threads: Vec<JoinHandle<()>>,
    pub(super) reaped: bool,
    /// What its first line declared, if it was a hello (SPEC.md §12.7),
    /// or why that hello was refused.
    pub(super) hello: Option<Result<Hello, String>>,
    /// A first line read while waiting for a hello that was none: the
    /// first line the first exchange reads.
    pub(super) pending: Option<Result<String, Output>>,
    /// Whether any line was read from it yet.
    pub(super) heard: bool,
    /// Whether a moving case has waited for its hello once more
    /// ([`Worker::await_late_hello`]).
    pub(super) rewaited: bool,
    /// v2: ids of requests that timed out, whose late answers are dropped.
    pub(super) owed: VecDeque<String>,
    /// v2: timeouts since its last answer.
    pub(super) timeouts_in_a_row: u32,
}

/// What a v2 exchange skipped on the way to its answer.
#[derive(Default)]
pub(super) struct Skipped {
    /// Lines that answer no request of this process: not JSON, no id, an
    /// unknown id.
    pub(super) strays: usize,
    /// Answers to earlier requests that timed out.
    pub(super) late: usize,
    pub(super) bytes: u64,
    /// The first stray line, shortened.
    pub(super) first: Option<String>,
    /// The id of the first stray line shaped as an answer (§12.2's
    /// fields) whose id is neither the request's nor an owed one, quoted.
    pub(super) wrong_id: Option<String>,
}

impl Skipped {
    pub(super) fn describe(&self) -> String {
        let mut parts = Vec::new();
        if self.strays > 0 {
            parts.push(format!(
                "{} stray line{} on stdout (the first: {:?})",
                self.strays,
                if self.strays == 1 { "" } else { "s" },
                self.first.as_deref().unwrap_or("")
            ));
        }
        if self.late > 0 {
            parts.push(format!(
                "{} late answer{} to earlier requests, dropped",
                self.late,
                if self.late == 1 { "" } else { "s" }
            ));
        }
        parts.join(", ")
    }
}

impl Worker {
    pub(super) fn start(mut child: Child, max_output: u64) -> Worker {
        let (stderr, stderr_thread) = StderrTail::collect(child.stderr.take());
        let stdin: ChildStdin = child.stdin.take().expect("stdin is piped");
        let (requests, to_write) = mpsc::channel::<Outgoing>();
        let writer = thread::spawn(move || {
            let mut stdin = stdin;
            for request in to_write {
                if request.write_to(&mut stdin).is_err() {
                    break;
                }
            }
        });
        let stdout = child.stdout.take().expect("stdout is piped");
        let (send, lines) = mpsc::channel();
        let reader = thread::spawn(move || {
            let mut stdout = BufReader::new(stdout);
            loop {
                let line = read_line(&mut stdout, max_output);
                let stop = !matches!(line, Ok(Some(_)));
                let Some(line) = line.transpose() else { break };
                if send.send(line).is_err() || stop {
                    break;
                }
            }
        });
        let mut threads = vec![writer, reader];
        threads.extend(stderr_thread);
        Worker {
            child,
            requests: Some(requests),
            lines,
            stderr,
            threads,
            reaped: false,
            hello: None,
            pending: None,
            heard: false,
            rewaited: false,
            owed: VecDeque::new(),
            timeouts_in_a_row: 0,
        }
    }

    /// Waits until `deadline` for the first line, and keeps it as the
    /// process's hello if it is one; any other line is left for the first
    /// exchange. A program that says nothing by then speaks v1 (a hello
    /// that comes later, as its first line, is still read: §12.7).
    pub(super) fn await_hello(&mut self, deadline: Instant) {
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            match self.lines.recv_timeout(left) {
                Ok(Ok(line)) if line.trim().is_empty() => continue,
                Ok(Ok(line)) => {
                    if !self.take_hello(&line) {
                        self.pending = Some(Ok(line));
                    }
                    return;
                }
                Ok(Err(e)) => {
                    self.pending = Some(Err(e));
                    return;
                }
                Err(_) => return,
            }
        }
    }

    /// A hello that came after the first wait, before the next request: read
    /// now, so that it holds for that request (SPEC.md §12.7). A process
    /// that has written nothing yet is waited for up to `wait` more, once
    /// in its life (a moving case goes only to a program whose hello
    /// declares motion, §12.8: a program slow to start would otherwise lose
    /// it as a version 1 one would); otherwise only what it has written is
    /// looked at.
    pub(super) fn await_late_hello(&mut self, wait: Duration) {
        if self.heard || self.pending.is_some() {
            return;
        }
        let wait = if self.rewaited { Duration::ZERO } else { wait };
        self.rewaited |= !wait.is_zero();
        self.await_hello(Instant::now() + wait);
    }

    /// Reads `line` as the hello if it is the first line and one.
    pub(super) fn take_hello(&mut self, line: &str) -> bool {
        if self.heard {
            return false;
        }
        self.heard = true;
        // A version 1 program's first line is its first answer: looked at
        // for a `hello` key only, not parsed into a tree (issue 36).
        if !Envelope::read(line).is_some_and(|e| e.hello) {
            return false;
        }
        match serde_json::from_str::<Value>(line) {
            Ok(value) if hello::is_hello(&value) => {
                self.hello = Some(Hello::parse(&value));
                true
            }
            _ => false,
        }
    }

    /// Whether it declared version 2 in its hello.
    pub(super) fn speaks_v2(&self) -> bool {
        matches!(&self.hello, Some(Ok(h)) if h.protocol >= 2)
    }

    /// Remembers the id of a request that timed out.
    pub(super) fn owe(&mut self, id: String) {
        self.timeouts_in_a_row += 1;
        if self.owed.len() == OWED_IDS {
            self.owed.pop_front();
        }
        self.owed.push_back(id);
    }

    /// The next line (the one kept from the hello's wait first).
    pub(super) fn next_line(
        &mut self,
        deadline: Instant,
    ) -> Result<Result<String, Output>, Exchange> {
        if let Some(line) = self.pending.take() {
            return Ok(line);
        }
        let left = deadline.saturating_duration_since(Instant::now());
        match self.lines.recv_timeout(left) {
            Ok(line) => Ok(line),
            Err(RecvTimeoutError::Timeout) => Err(Exchange::TimedOut),
            Err(RecvTimeoutError::Disconnected) => Err(Exchange::Closed),
        }
    }

    /// Sends a v2 request and reads lines until the one whose `id` is
    /// `id`: the answer. Every other line is skipped and counted: a late
    /// answer to a request that timed out, or a stray (an answer under
    /// another id is noted in [`Skipped::wrong_id`]); a line shaped as an
    /// answer with no id at all ends the exchange at once
    /// ([`Exchange::NoId`]: the program does not echo ids). Past
    /// [`MAX_SKIPPED_LINES`] lines or `max_output` bytes skipped, gives up.
    pub(super) fn exchange_v2(
        &mut self,
        request: Outgoing,
        id: &str,
        deadline: Instant,
        max_output: u64,
    ) -> (Result<String, Exchange>, Skipped) {
        if let Some(requests) = &self.requests {
            let _ = requests.send(request);
        }
        let mut skipped = Skipped::default();
        loop {
            let line = match self.next_line(deadline) {
                Ok(Ok(line)) => line,
                Ok(Err(e)) => return (Err(Exchange::Broken(e)), skipped),
                Err(e) => return (Err(e), skipped),
            };
            if line.trim().is_empty() {
                continue;
            }
            // Its id and shape only: the answer is read into a frame later.
            let envelope = Envelope::read(&line);
            let got = envelope.as_ref().and_then(Envelope::id_text);
            match got {
                Some(got) if got == id => {
                    self.timeouts_in_a_row = 0;
                    return (Ok(line), skipped);
                }
                Some(got) if self.owed.iter().any(|o| o == got) => {
                    self.owed.retain(|o| o != got);
                    self.timeouts_in_a_row = 0;
                    skipped.late += 1;
                }
                _ => {
                    match envelope.as_ref().filter(|e| e.answer).map(|e| &e.id) {
                        Some(Id::Missing | Id::Null) => {
                            return (Err(Exchange::NoId(shorten(&line))), skipped)
                        }
                        Some(Id::Text(other)) => {
                            let other = format!("{:?}", shorten(other));
                            skipped.wrong_id.get_or_insert(other);
                        }
                        Some(Id::Other(other)) => {
                            skipped.wrong_id.get_or_insert(shorten(other));
                        }
                        None => {}
                    }
                    skipped.strays += 1;
                    skipped.first.get_or_insert_with(|| shorten(&line));
                }
            }
            skipped.bytes += line.len() as u64;
            if skipped.strays + skipped.late > MAX_SKIPPED_LINES || skipped.bytes > max_output {
                return (Err(Exchange::Flood), skipped);
            }
        }
    }

    /// Joins its threads, once its group is gone and its pipes closed.
    pub(super) fn join(&mut self) {
        join_within(std::mem::take(&mut self.threads), PIPE_GRACE);
    }

    /// Sends a request line and waits for the next non-blank line.
    pub(super) fn exchange(
        &mut self,
        request: Outgoing,
        deadline: Instant,
    ) -> Result<String, Exchange> {
        if let Some(requests) = &self.requests {
            // A send fails only when the writer stopped (the pipe broke);
            // the read below then finds the output closed.
            let _ = requests.send(request);
        }
        loop {
            match self.next_line(deadline)? {
                Ok(line) if line.trim().is_empty() => continue,
                // A hello that came after the wait: its capabilities and
                // version hold from the next request on.
                Ok(line) if self.take_hello(&line) => continue,
                Ok(line) => return Ok(line),
                Err(e) => return Err(Exchange::Broken(e)),
            }
        }
    }

    pub(super) fn say_bye(&mut self) {
        if let Some(requests) = self.requests.take() {
            let _ = requests.send(Outgoing::Line(b"{\"bye\": true}\n"));
            // Dropping the sender closes stdin once the line is written.
        }
    }

    /// Ends the process: killed at once, or first given a moment to exit by
    /// itself (it closed its output). Returns its exit status if it exited
    /// by itself.
    pub(super) fn end(&mut self, kill_now: bool) -> Option<ExitStatus> {
        self.requests = None;
        self.reaped = true;
        let status = if kill_now {
            None
        } else {
            wait_until(&mut self.child, Instant::now() + PIPE_GRACE)
        };
        kill_group(&mut self.child);
        self.join();
        status
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        if !self.reaped {
            self.requests = None;
            kill_group(&mut self.child);
            self.join();
        }
    }
}

/// One line of at most `max` bytes (without its line break), or `None` at
/// the end of the output.
pub(super) fn read_line(stdout: &mut impl BufRead, max: u64) -> Result<Option<String>, Output> {
    let mut bytes = Vec::new();
    let n = stdout
        .take(max.saturating_add(2))
        .read_until(b'\n', &mut bytes)
        .map_err(Output::Read)?;
    if n == 0 {
        return Ok(None);
    }
    if bytes.last() == Some(&b'\n') {
        bytes.pop();
        if bytes.last() == Some(&b'\r') {
            bytes.pop();
        }
    }
    if bytes.len() as u64 > max {
        return Err(Output::TooLong);
    }
    String::from_utf8(bytes)
        .map(Some)
        .map_err(|e| Output::Read(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))
}
