//! One process of a persistent adapter (SPEC.md §12.4, §12.7): started in
//! its own process group, fed one request a line, and read until the line
//! that answers the request in flight; under version 2 by its id, stray
//! and late lines skipped and counted. Its stdout is read one line at a
//! time (the reader waits while a line is unread, and the program on its
//! full pipe), and what it wrote that no exchange has read yet can be
//! looked at ([`Worker::unread`]): the sign of a program out of step.

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read};
use std::os::fd::{AsFd, AsRawFd, OwnedFd};
use std::process::{Child, ChildStdin, ExitStatus};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender, TryRecvError};
use std::sync::Arc;
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

use serde_json::Value;

use super::envelope::{Envelope, Id};
use super::hello::{self, Hello};
use super::limits::{MAX_SKIPPED_LINES, OWED_IDS, PIPE_GRACE, SETTLE_WAIT, UNREAD_GRACE};
use super::messages::shorten;
use super::process::*;
use super::protocol::Outgoing;
use super::running::running;

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
    /// Requests sent to it: 0 for a fresh process.
    pub(super) sent: u64,
    /// How much of its stdout the reader has taken from the pipe and
    /// handed on.
    flow: Arc<Flow>,
    /// Its stdout's pipe (a duplicate of the reader's descriptor), to
    /// look for bytes written and not yet read.
    pipe: Option<OwnedFd>,
    /// v1: whether it ran on past [`SETTLE_WAIT`] once (it is not waited
    /// for again).
    restless: bool,
}

/// The bytes of a process's stdout its reader thread has taken from the
/// pipe, and those it has handed on as lines (counted before the line is
/// handed on): the difference is a line the reader is reading.
#[derive(Default)]
struct Flow {
    from_pipe: AtomicU64,
    handed: AtomicU64,
}

/// A process's stdout, counting the bytes read from it into [`Flow`].
struct Counted<R> {
    inner: R,
    flow: Arc<Flow>,
}

impl<R: Read> Read for Counted<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.flow.from_pipe.fetch_add(n as u64, Ordering::SeqCst);
        Ok(n)
    }
}

/// What a process wrote that no exchange has read yet (blank lines aside).
pub(super) enum Unread {
    Nothing,
    /// A line (or why it could not be read).
    Line(Result<String, Output>),
    /// Bytes of a line not yet ended, after [`UNREAD_GRACE`].
    Bytes,
}

/// How many bytes wait in the pipe `fd` (`FIONREAD`); 0 when it cannot say.
fn bytes_in_pipe(fd: &OwnedFd) -> u64 {
    let mut n: libc::c_int = 0;
    // SAFETY: FIONREAD writes one int through the pointer, which lives
    // across the call; the descriptor is open while `fd` is.
    let ok = unsafe { libc::ioctl(fd.as_raw_fd(), libc::FIONREAD, &mut n as *mut libc::c_int) };
    if ok == 0 {
        u64::try_from(n).unwrap_or(0)
    } else {
        0
    }
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
        let pipe = stdout.as_fd().try_clone_to_owned().ok();
        let flow = Arc::new(Flow::default());
        // No line waits in the channel: the reader holds the next one until
        // it is taken, and the program then waits on its full pipe, so that
        // what a program writes while no request is in flight costs one
        // line (at most the output limit), never more.
        let (send, lines) = mpsc::sync_channel(0);
        let counted = Counted {
            inner: stdout,
            flow: flow.clone(),
        };
        let handed = flow.clone();
        let reader = thread::spawn(move || {
            let mut stdout = BufReader::new(counted);
            loop {
                let mut consumed = 0;
                let line = read_line(&mut stdout, max_output, &mut consumed);
                handed.handed.fetch_add(consumed, Ordering::SeqCst);
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
            sent: 0,
            flow,
            pipe,
            restless: false,
        }
    }

    /// Whether the process has exited (or cannot be waited for): an idle
    /// one is then not reused.
    pub(super) fn exited(&mut self) -> bool {
        !matches!(self.child.try_wait(), Ok(None))
    }

    /// Why this idle process is not to be sent the next request, if it is
    /// not: it has exited, or, having been sent requests, it wrote a line
    /// that none asked for while it was idle (a late answer to a request
    /// that timed out aside, under version 2, dropped by its id). Under
    /// version 1, whose answers carry no id, bytes of a line not yet ended
    /// count too: nothing may come but the answer to the next request.
    pub(super) fn unfit(&mut self) -> Option<String> {
        if self.exited() {
            return Some("it exited".to_owned());
        }
        if self.sent == 0 {
            return None;
        }
        loop {
            match self.unread() {
                Unread::Nothing => return None,
                Unread::Bytes if self.speaks_v2() => return None,
                Unread::Bytes => return Some("it was writing a line no request asked for".into()),
                Unread::Line(Err(_)) => return Some("its output broke".to_owned()),
                Unread::Line(Ok(line)) => {
                    let value = serde_json::from_str::<Value>(&line).ok();
                    let id = value
                        .as_ref()
                        .and_then(|v| v.get("id"))
                        .and_then(Value::as_str);
                    match id {
                        Some(id) if self.speaks_v2() && self.owed.iter().any(|o| o == id) => {
                            self.owed.retain(|o| o != id);
                            self.timeouts_in_a_row = 0;
                        }
                        _ => {
                            return Some(format!(
                                "it wrote a line no request asked for: {:?}",
                                shorten(&line)
                            ))
                        }
                    }
                }
            }
        }
    }

    /// How long to wait for a line: [`UNREAD_GRACE`] when bytes are in
    /// its pipe or in the reader (a line on its way), else none.
    fn unread_wait(&self) -> Duration {
        let in_pipe = self.pipe.as_ref().map_or(0, bytes_in_pipe);
        let in_reader =
            self.flow.from_pipe.load(Ordering::SeqCst) > self.flow.handed.load(Ordering::SeqCst);
        if in_pipe > 0 || in_reader {
            UNREAD_GRACE
        } else {
            Duration::ZERO
        }
    }

    /// Version 1: waits while it runs with nothing written, up to
    /// [`SETTLE_WAIT`]. Its answers carry no id: a line written after an
    /// answer (a second line for one request) is told from the next answer
    /// only by coming first, and a program may be between its two writes
    /// (or not yet scheduled) when the first one is read. Looked at in
    /// this order: whether it runs, then whether bytes wait, so that bytes
    /// written before it fell asleep are seen.
    fn settle(&mut self) {
        if self.restless || self.speaks_v2() || self.pending.is_some() {
            return;
        }
        let end = Instant::now() + SETTLE_WAIT;
        while running(self.child.id()) == Some(true) && self.unread_wait().is_zero() {
            if Instant::now() >= end {
                self.restless = true;
                return;
            }
            thread::sleep(Duration::from_micros(200));
        }
    }

    /// What it wrote that no exchange has read yet, blank lines skipped: a
    /// line already read (kept from the hello's wait, or handed on by the
    /// reader), or bytes still in its pipe or in the reader, waited for
    /// [`UNREAD_GRACE`] to end their line. Looked at upstream first (the
    /// pipe, then the reader, then the channel), so that a byte moving on
    /// between two looks is seen by the later one.
    pub(super) fn unread(&mut self) -> Unread {
        self.settle();
        let mut wait = self.unread_wait();
        loop {
            let line = match self.pending.take() {
                Some(line) => Ok(line),
                None if wait.is_zero() => self.lines.try_recv(),
                None => self.lines.recv_timeout(wait).map_err(|e| match e {
                    RecvTimeoutError::Timeout => TryRecvError::Empty,
                    RecvTimeoutError::Disconnected => TryRecvError::Disconnected,
                }),
            };
            match line {
                Ok(Ok(line)) if line.trim().is_empty() => {
                    // A blank line: what follows it is looked at anew.
                    wait = self.unread_wait();
                }
                Ok(line) => return Unread::Line(line),
                Err(TryRecvError::Empty) if !wait.is_zero() => return Unread::Bytes,
                Err(_) => return Unread::Nothing,
            }
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
        self.sent += 1;
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

    /// Joins its threads, once its group is gone and its pipes closed
    /// (nothing more is read from it).
    pub(super) fn join(&mut self) {
        self.stop_reading();
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
        self.sent += 1;
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

    /// Lets the reader go: a line it holds for the channel is dropped, and
    /// it ends once the pipe closes.
    fn stop_reading(&mut self) {
        drop(std::mem::replace(&mut self.lines, mpsc::sync_channel(0).1));
        self.pipe = None;
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
/// the end of the output; the bytes it took are added to `consumed`.
fn read_line(
    stdout: &mut impl BufRead,
    max: u64,
    consumed: &mut u64,
) -> Result<Option<String>, Output> {
    let mut bytes = Vec::new();
    let read = stdout
        .take(max.saturating_add(2))
        .read_until(b'\n', &mut bytes);
    *consumed += bytes.len() as u64;
    let n = read.map_err(Output::Read)?;
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
