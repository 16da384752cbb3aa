//! Rasterizers in other processes, in any language, speaking the protocol
//! of SPEC.md §12: the scene goes out as one JSON request, the covered
//! pixels of each primitive come back as one JSON response, and rastercheck
//! composes the [`Frame`] itself, in primitive order.
//!
//! - `external:PROGRAM [ARGS]`: one process per case; the request on its
//!   stdin, the response on its stdout.
//! - `external-persistent:PROGRAM [ARGS]`: JSON Lines; a process is started
//!   once per thread that needs one and reused for every later case, so a
//!   driver is initialised once per run. `{"bye": true}` ends it.
//!
//! A program that crashes, hangs (past `RASTERCHECK_EXTERNAL_TIMEOUT`
//! seconds, 30 by default, or past the case's `--case-timeout` deadline
//! when that comes first), prints something that is not a response or more
//! than `RASTERCHECK_EXTERNAL_MAX_OUTPUT` bytes (256 MiB by default), or
//! cannot be started is a [`RasterError::Failed`] for that case, with the
//! tail of its stderr (the last 64 KiB are kept, the rest is read and
//! dropped); the run goes on.
//!
//! Every program runs in a process group of its own. The whole group is
//! killed when the program overstays, when a one-shot case is done, and when
//! a persistent process is retired or the adapter is dropped at the end of
//! the run, so nothing it started outlives its case (or the run), and the
//! threads that feed and read its pipes end with it. Every process started
//! here is waited for: never left running or as a zombie.
//!
//! Protocol v2 (SPEC.md §12.7), persistent mode: a program whose first
//! line is a hello of version 2 gets an `id` in every request and must
//! echo it. The answer is the line with the id in flight; a late answer to
//! a request that timed out is dropped, any other line is a stray (an
//! error for the case in flight only), so no answer is ever matched to
//! another case. A timed-out process is kept, unless the next request
//! times out too: then it is stuck, killed, and that case is sent once
//! more to a fresh process. The hello's capabilities (`hello.rs`) refuse
//! cases before they are sent. `NAME=external…` names the adapter.
//!
//! This file holds the processes: starting them, feeding them, timing
//! them out and reaping them. `protocol.rs` holds the messages: the
//! request, and reading a response into a frame; `hello.rs` the hello.

mod hello;
mod protocol;

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::process::CommandExt;
use std::process::{Child, ChildStdin, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Condvar, Mutex};
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

use serde_json::Value;

use crate::deadline;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::Scene;

use hello::Hello;
use protocol::parse_response;
pub use protocol::{frame_from_response, request, request_v2};

/// The protocol's name and version, sent in every request of v1.
pub const PROTOCOL: &str = "rastercheck-external/1";

/// Version 2 (SPEC.md §12.7): the program's hello, ids in every request
/// and answer.
pub const PROTOCOL_V2: &str = "rastercheck-external/2";

/// How long a fresh persistent process is given to write its hello before
/// the first request is sent to it (it is sent at once when a line comes
/// sooner). A program that writes none is v1, and pays this once per run
/// (per thread that starts one at the same time): once a process has
/// written no hello, the next ones are not waited for.
const HELLO_WAIT: Duration = Duration::from_secs(1);

/// The most lines a v2 exchange skips (stray lines, late answers) before
/// the process is judged to flood and is killed; their bytes count against
/// the output limit too.
const MAX_SKIPPED_LINES: usize = 1000;

/// How many ids of requests that timed out a v2 process remembers, so
/// that their late answers are told apart from stray lines.
const OWED_IDS: usize = 64;

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
const BYE_GRACE: Duration = Duration::from_secs(2);

/// How long the output pipes may stay open after the process has exited
/// (a grandchild holding them) before rastercheck stops waiting for them.
const PIPE_GRACE: Duration = Duration::from_millis(500);

/// How much of a program's stderr is kept, and how much is quoted.
const STDERR_KEEP: usize = 64 * 1024;
const STDERR_QUOTE_CHARS: usize = 1500;
const STDERR_QUOTE_LINES: usize = 12;

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
    let (persistent, command) = if let Some(rest) = spec.strip_prefix("external-persistent:") {
        (true, rest)
    } else if let Some(rest) = spec.strip_prefix("external:") {
        (false, rest)
    } else {
        return None;
    };
    let words: Vec<String> = command.split_whitespace().map(str::to_owned).collect();
    let (program, args) = words.split_first()?;
    Some(Box::new(External::new(
        name,
        program.clone(),
        args.to_vec(),
        persistent,
    )))
}

/// A rasterizer that is another program.
pub struct External {
    name: String,
    program: String,
    args: Vec<String>,
    /// The per-case time limit, or why the environment's value is refused.
    timeout: Result<Duration, String>,
    /// The most bytes read from stdout per response, or why the
    /// environment's value is refused.
    max_output: Result<u64, String>,
    /// Idle processes of a persistent adapter; `None` in one-shot mode.
    pool: Option<Mutex<Vec<Worker>>>,
    /// The id of the next v2 request (unique in the adapter's life).
    next_id: AtomicU64,
    /// Whether a process of this program wrote no hello: later processes
    /// are not waited for (a hello that comes later is still read).
    said_no_hello: AtomicBool,
}

impl External {
    /// `name` is what reports call it; the program and its arguments are
    /// run as given, in rastercheck's working directory.
    pub fn new(name: &str, program: String, args: Vec<String>, persistent: bool) -> External {
        External {
            name: name.to_owned(),
            program,
            args,
            timeout: timeout_from_env(),
            max_output: max_output_from_env(),
            pool: persistent.then(|| Mutex::new(Vec::new())),
            next_id: AtomicU64::new(1),
            said_no_hello: AtomicBool::new(false),
        }
    }

    /// The same adapter with another per-case time limit (the environment's
    /// `RASTERCHECK_EXTERNAL_TIMEOUT` is the default).
    pub fn with_timeout(mut self, timeout: Duration) -> External {
        self.timeout = Ok(timeout);
        self
    }

    /// The same adapter with another output limit in bytes (the
    /// environment's `RASTERCHECK_EXTERNAL_MAX_OUTPUT` is the default).
    pub fn with_max_output(mut self, bytes: u64) -> External {
        self.max_output = Ok(bytes);
        self
    }

    fn command(&self) -> Command {
        let mut command = Command::new(&self.program);
        command
            .args(&self.args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            // A group of its own, so that what it starts can be killed with it.
            .process_group(0);
        command
    }

    fn start(&self) -> Result<Child, RasterError> {
        let child = self
            .command()
            .spawn()
            .map_err(|e| RasterError::Failed(format!("cannot start {:?}: {e}", self.program)))?;
        // Killed on SIGINT or SIGTERM; forgotten when reaped (`wait_until`, `kill`).
        crate::stop::register(child.id());
        Ok(child)
    }

    /// One process for this case: request on stdin, response on stdout.
    /// Whatever happens, its whole process group is killed before this
    /// returns, and the threads that fed and read it are joined.
    fn one_shot(
        &self,
        request: Vec<u8>,
        timeout: Duration,
        max_output: u64,
    ) -> Result<Value, RasterError> {
        let deadline = Instant::now() + timeout;
        let mut child = self.start()?;
        let (stderr, stderr_thread) = StderrTail::collect(child.stderr.take());
        let mut stdin = child.stdin.take().expect("stdin is piped");
        // Written from a thread: a program may print before reading it all.
        let writer = thread::spawn(move || {
            let _ = stdin.write_all(&request);
        });
        let stdout = child.stdout.take().expect("stdout is piped");
        let (send, output) = mpsc::channel();
        let reader = thread::spawn(move || {
            let _ = send.send(read_bounded(stdout, max_output));
        });
        let mut threads = vec![writer, reader];
        threads.extend(stderr_thread);
        // Waits for the exit, the deadline, or output over the limit.
        let mut got = None;
        let status = wait_until_or(&mut child, deadline, || {
            if got.is_none() {
                got = output.try_recv().ok();
            }
            matches!(got, Some(Err(Output::TooLong)))
        });
        let too_long = || {
            format!(
                "wrote more than {max_output} bytes to stdout (the limit is \
                 {MAX_OUTPUT_ENV}, in bytes)"
            )
        };
        let result = match status {
            None if got.is_some() => Err(format!("{}; it was killed", too_long())),
            None => Err(format!("timed out after {}", seconds(timeout))),
            Some(status) if !status.success() => Err(exit_description(status)),
            Some(_) => Ok(()),
        };
        // The case is done: nothing the program started outlives it.
        kill_group(&mut child);
        let result = result.and_then(|()| {
            let got = match got.take() {
                Some(got) => got,
                None => output.recv_timeout(PIPE_GRACE).map_err(|_| {
                    "exited, but its output stayed open (a process it started that left \
                     its process group holds it)"
                        .to_owned()
                })?,
            };
            match got {
                Ok(bytes) => parse_response(&bytes),
                Err(Output::TooLong) => Err(too_long()),
                Err(Output::Read(e)) => Err(format!("reading its output: {e}")),
            }
        });
        let result = result.map_err(|why| failed(why, &stderr, 0));
        join_within(threads, PIPE_GRACE);
        result
    }

    /// A line to a process of the pool, and a line back. The request is
    /// written in the version the process speaks: v2 (an id, the answer
    /// found by it) when its first line was a hello of version 2, else v1.
    fn persistent(
        &self,
        pool: &Mutex<Vec<Worker>>,
        scene: &Scene,
        plan: &Plan,
        timeout: Duration,
        max_output: u64,
        retried: bool,
    ) -> Result<Value, RasterError> {
        let deadline = Instant::now() + timeout;
        let idle = pool.lock().unwrap_or_else(|e| e.into_inner()).pop();
        let mut worker = match idle {
            Some(worker) => worker,
            None => {
                let mut worker = Worker::start(self.start()?, max_output);
                if !self.said_no_hello.load(Ordering::Relaxed) {
                    worker.await_hello(Instant::now() + HELLO_WAIT.min(timeout));
                    if worker.hello.is_none() {
                        self.said_no_hello.store(true, Ordering::Relaxed);
                    }
                }
                worker
            }
        };
        let mark = worker.stderr.written();
        if let Some(Err(why)) = &worker.hello {
            let why = format!("its hello is not a hello of SPEC.md §12.7: {why}");
            worker.end(true);
            return Err(failed(why, &worker.stderr, mark));
        }
        if let Some(Ok(hello)) = &worker.hello {
            if let Some(why) = hello.refuses(scene, plan) {
                // Never sent: the program said it cannot draw it.
                pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
                return Err(RasterError::Unsupported(why));
            }
        }
        if worker.speaks_v2() {
            return match self
                .persistent_v2(pool, worker, scene, plan, deadline, timeout, max_output)
            {
                Ok(result) => result,
                // The process was stuck on an earlier case, and is gone:
                // this case is sent once more, to a fresh one, with a
                // fresh time limit (within the case's deadline).
                Err(_) if !retried => {
                    let timeout = match (self.timeout.clone(), deadline::remaining()) {
                        (Ok(t), Some(left)) => t.min(left),
                        (Ok(t), None) => t,
                        (Err(why), _) => return Err(RasterError::Failed(why)),
                    };
                    self.persistent(pool, scene, plan, timeout, max_output, true)
                }
                Err(why) => Err(why),
            };
        }
        let mut request =
            serde_json::to_vec(&request(scene, plan)).expect("a JSON value serializes");
        request.push(b'\n');
        let line = worker.exchange(request, deadline);
        let result = match line {
            Ok(line) => parse_response(line.as_bytes()).map_err(|why| (why, true)),
            Err(Exchange::TimedOut | Exchange::Flood) => {
                Err((format!("timed out after {}", seconds(timeout)), true))
            }
            Err(Exchange::Closed) => Err(("closed its output".to_owned(), false)),
            Err(Exchange::Broken(Output::Read(e))) => {
                Err((format!("reading its output: {e}"), true))
            }
            Err(Exchange::Broken(Output::TooLong)) => Err((
                format!(
                    "wrote more than {max_output} bytes to stdout in one line (the limit \
                     is {MAX_OUTPUT_ENV}, in bytes); it was killed"
                ),
                true,
            )),
        };
        match result {
            Ok(value) => {
                pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
                Ok(value)
            }
            Err((why, kill_now)) => {
                // The stream is out of step, or the process is gone: it is
                // not used again, and a later case starts a fresh one.
                let why = match worker.end(kill_now) {
                    Some(status) if !kill_now => format!("{why}: {}", exit_description(status)),
                    _ => why,
                };
                Err(failed(why, &worker.stderr, mark))
            }
        }
    }

    /// A v2 exchange (SPEC.md §12.7): the answer is the line that carries
    /// the request's id. Stray lines make this case a protocol error and
    /// nothing else; late answers to requests that timed out are dropped;
    /// a timeout keeps the process unless it is its second in a row: the
    /// process is then stuck on the earlier request, and is killed;
    /// `Err` says so, for the caller to send the case to a fresh process.
    #[allow(clippy::too_many_arguments)]
    fn persistent_v2(
        &self,
        pool: &Mutex<Vec<Worker>>,
        mut worker: Worker,
        scene: &Scene,
        plan: &Plan,
        deadline: Instant,
        timeout: Duration,
        max_output: u64,
    ) -> Result<Result<Value, RasterError>, RasterError> {
        let id = format!(
            "{}#{}",
            scene.name,
            self.next_id.fetch_add(1, Ordering::Relaxed)
        );
        let mark = worker.stderr.written();
        let mut request =
            serde_json::to_vec(&request_v2(scene, plan, &id)).expect("a JSON value serializes");
        request.push(b'\n');
        let (answer, skipped) = worker.exchange_v2(request, &id, deadline, max_output);
        let keep = |worker: Worker| pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
        let strays = skipped.describe();
        let (why, kill_now) = match answer {
            Ok(value) if skipped.strays == 0 => {
                keep(worker);
                return Ok(Ok(value));
            }
            Ok(_) => {
                let why = format!(
                    "protocol error: before its answer (id {id:?}) it wrote {strays}; the \
                     answer was read and not judged, and the next case is read by its own id"
                );
                let err = failed(why, &worker.stderr, mark);
                keep(worker);
                return Ok(Err(err));
            }
            Err(Exchange::TimedOut) => {
                worker.owe(id.clone());
                let why = format!(
                    "timed out after {} with no answer to id {id:?}{}",
                    seconds(timeout),
                    if skipped.strays + skipped.late > 0 {
                        format!(" ({strays})")
                    } else {
                        String::new()
                    }
                );
                if worker.timeouts_in_a_row < 2 {
                    // It may only be slow: kept, and its late answer is
                    // dropped by its id when it comes.
                    let err = failed(
                        format!("{why}; the process is kept (a late answer is dropped by its id)"),
                        &worker.stderr,
                        mark,
                    );
                    keep(worker);
                    return Ok(Err(err));
                }
                // Nothing since its last timeout: stuck on that request.
                let why = format!(
                    "{why}, nor to the earlier request it timed out on: it is stuck, and \
                     was killed"
                );
                worker.end(true);
                return Err(failed(why, &worker.stderr, mark));
            }
            Err(Exchange::Flood) => (
                format!(
                    "{strays} without answering id {id:?}, more than {MAX_SKIPPED_LINES} lines \
                     or {max_output} bytes ({MAX_OUTPUT_ENV}); it was killed"
                ),
                true,
            ),
            Err(Exchange::Closed) => ("closed its output".to_owned(), false),
            Err(Exchange::Broken(Output::Read(e))) => (format!("reading its output: {e}"), true),
            Err(Exchange::Broken(Output::TooLong)) => (
                format!(
                    "wrote more than {max_output} bytes to stdout in one line (the limit \
                     is {MAX_OUTPUT_ENV}, in bytes); it was killed"
                ),
                true,
            ),
        };
        let why = match worker.end(kill_now) {
            Some(status) if !kill_now => format!("{why}: {}", exit_description(status)),
            _ => why,
        };
        Ok(Err(failed(why, &worker.stderr, mark)))
    }
}

impl Rasterizer for External {
    fn name(&self) -> &str {
        &self.name
    }

    /// Everything: the program says what it does not do, case by case.
    fn capabilities(&self) -> Capabilities {
        // The program says itself what it cannot do (`unsupported`).
        // The protocol does not carry moving vertices yet (SPEC.md §12).
        Capabilities {
            motion_blur: false,
            ..Capabilities::everything()
        }
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        let mut timeout = self.timeout.clone().map_err(RasterError::Failed)?;
        let max_output = self.max_output.clone().map_err(RasterError::Failed)?;
        // The case's deadline (`--case-timeout`) stops the program too; the
        // runner then judges the case over the limit.
        if let Some(left) = deadline::remaining() {
            timeout = timeout.min(left);
        }
        let response = match &self.pool {
            None => {
                let request =
                    serde_json::to_vec(&request(scene, plan)).expect("a JSON value serializes");
                self.one_shot(request, timeout, max_output)?
            }
            Some(pool) => self.persistent(pool, scene, plan, timeout, max_output, false)?,
        };
        frame_from_response(&response, scene, plan)
    }
}

impl Drop for External {
    fn drop(&mut self) {
        let Some(pool) = &self.pool else { return };
        let mut workers = std::mem::take(&mut *pool.lock().unwrap_or_else(|e| e.into_inner()));
        // Say goodbye to all first, so that they shut down together.
        for worker in &mut workers {
            worker.say_bye();
        }
        let deadline = Instant::now() + BYE_GRACE;
        for worker in &mut workers {
            if wait_until(&mut worker.child, deadline).is_none() {
                kill(&mut worker.child);
            }
            // What it started goes with it.
            kill_group(&mut worker.child);
            worker.reaped = true;
        }
        for worker in &mut workers {
            worker.join();
        }
    }
}

/// Checks the environment external programs read (`TIMEOUT_ENV`,
/// `MAX_OUTPUT_ENV`): a
/// malformed value is bad usage, said before any case runs.
pub fn check_environment() -> Result<(), String> {
    timeout_from_env()?;
    max_output_from_env().map(|_| ())
}

/// `text` cut to about 80 characters (with `…` and the full length when
/// cut), for echoing a value in a message.
pub fn shorten(text: &str) -> String {
    const MAX: usize = 80;
    if text.chars().count() <= MAX {
        return text.to_owned();
    }
    let head: String = text.chars().take(MAX).collect();
    format!("{head}… ({} bytes)", text.len())
}

fn timeout_from_env() -> Result<Duration, String> {
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

fn max_output_from_env() -> Result<u64, String> {
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

fn seconds(d: Duration) -> String {
    format!("{} s", d.as_secs_f64())
}

fn exit_description(status: ExitStatus) -> String {
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
fn wait_until(child: &mut Child, deadline: Instant) -> Option<ExitStatus> {
    wait_until_or(child, deadline, || false)
}

/// Polls until the child exits, the deadline passes or `stop` says so;
/// `None` unless it exited.
fn wait_until_or(
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
fn kill(child: &mut Child) {
    crate::stop::unregister(child.id());
    let _ = child.kill();
    let _ = child.wait();
}

extern "C" {
    /// POSIX `kill(2)`, from the C library std already links.
    #[link_name = "kill"]
    fn posix_kill(pid: i32, signal: i32) -> i32;
}

const SIGKILL: i32 = 9;

/// Kills every process of the child's group (it leads one of its own:
/// `process_group(0)`), then the child itself, and reaps it. Called right
/// after the child exits or instead of waiting for it: its group id stays
/// taken while any member lives, so the signal reaches only its group.
fn kill_group(child: &mut Child) {
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
fn join_within(threads: Vec<JoinHandle<()>>, grace: Duration) {
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
enum Output {
    /// More bytes than the limit (`RASTERCHECK_EXTERNAL_MAX_OUTPUT`).
    TooLong,
    Read(std::io::Error),
}

/// Reads to the end, or stops after `max` bytes.
fn read_bounded(stdout: impl Read, max: u64) -> Result<Vec<u8>, Output> {
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
fn failed(why: String, stderr: &StderrTail, mark: u64) -> RasterError {
    stderr.wait_closed(PIPE_GRACE.min(Duration::from_millis(200)));
    match stderr.since(mark) {
        Some(tail) => RasterError::Failed(format!("{why}; stderr: {tail}")),
        None => RasterError::Failed(format!("{why}; nothing on stderr")),
    }
}

// ---------------------------------------------------------------------------
// Processes.

/// What a persistent exchange got instead of a line.
enum Exchange {
    TimedOut,
    /// Too many lines that were not the answer (v2).
    Flood,
    /// The process closed its stdout (it exited, most likely).
    Closed,
    Broken(Output),
}

/// One process of a persistent adapter.
struct Worker {
    child: Child,
    /// Lines to write to its stdin, by a thread, so that a program that
    /// stops reading cannot block rastercheck past the time limit.
    requests: Option<Sender<Vec<u8>>>,
    lines: Receiver<Result<String, Output>>,
    stderr: StderrTail,
    /// The threads that write its stdin and read its stdout and stderr.
    threads: Vec<JoinHandle<()>>,
    reaped: bool,
    /// What its first line declared, if it was a hello (SPEC.md §12.7),
    /// or why that hello was refused.
    hello: Option<Result<Hello, String>>,
    /// A first line read while waiting for a hello that was none: the
    /// first line the first exchange reads.
    pending: Option<Result<String, Output>>,
    /// Whether any line was read from it yet.
    heard: bool,
    /// v2: ids of requests that timed out, whose late answers are dropped.
    owed: VecDeque<String>,
    /// v2: timeouts since its last answer.
    timeouts_in_a_row: u32,
}

/// What a v2 exchange skipped on the way to its answer.
#[derive(Default)]
struct Skipped {
    /// Lines that answer no request of this process: not JSON, no id, an
    /// unknown id.
    strays: usize,
    /// Answers to earlier requests that timed out.
    late: usize,
    bytes: u64,
    /// The first stray line, shortened.
    first: Option<String>,
}

impl Skipped {
    fn describe(&self) -> String {
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
    fn start(mut child: Child, max_output: u64) -> Worker {
        let (stderr, stderr_thread) = StderrTail::collect(child.stderr.take());
        let stdin: ChildStdin = child.stdin.take().expect("stdin is piped");
        let (requests, to_write) = mpsc::channel::<Vec<u8>>();
        let writer = thread::spawn(move || {
            let mut stdin = stdin;
            for request in to_write {
                if stdin
                    .write_all(&request)
                    .and_then(|()| stdin.flush())
                    .is_err()
                {
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
            owed: VecDeque::new(),
            timeouts_in_a_row: 0,
        }
    }

    /// Waits until `deadline` for the first line, and keeps it as the
    /// process's hello if it is one; any other line is left for the first
    /// exchange. A program that says nothing by then speaks v1 (a hello
    /// that comes later, as its first line, is still read: §12.7).
    fn await_hello(&mut self, deadline: Instant) {
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

    /// Reads `line` as the hello if it is the first line and one.
    fn take_hello(&mut self, line: &str) -> bool {
        if self.heard {
            return false;
        }
        self.heard = true;
        match serde_json::from_str::<Value>(line) {
            Ok(value) if hello::is_hello(&value) => {
                self.hello = Some(Hello::parse(&value));
                true
            }
            _ => false,
        }
    }

    /// Whether it declared version 2 in its hello.
    fn speaks_v2(&self) -> bool {
        matches!(&self.hello, Some(Ok(h)) if h.protocol >= 2)
    }

    /// Remembers the id of a request that timed out.
    fn owe(&mut self, id: String) {
        self.timeouts_in_a_row += 1;
        if self.owed.len() == OWED_IDS {
            self.owed.pop_front();
        }
        self.owed.push_back(id);
    }

    /// The next line (the one kept from the hello's wait first).
    fn next_line(&mut self, deadline: Instant) -> Result<Result<String, Output>, Exchange> {
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
    /// answer to a request that timed out, or a stray. Past
    /// [`MAX_SKIPPED_LINES`] lines or `max_output` bytes skipped, gives up.
    fn exchange_v2(
        &mut self,
        request: Vec<u8>,
        id: &str,
        deadline: Instant,
        max_output: u64,
    ) -> (Result<Value, Exchange>, Skipped) {
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
            let value = serde_json::from_str::<Value>(&line).ok();
            let got = value
                .as_ref()
                .and_then(|v| v.get("id"))
                .and_then(Value::as_str);
            match got {
                Some(got) if got == id => {
                    self.timeouts_in_a_row = 0;
                    return (Ok(value.expect("it parsed")), skipped);
                }
                Some(got) if self.owed.iter().any(|o| o == got) => {
                    self.owed.retain(|o| o != got);
                    self.timeouts_in_a_row = 0;
                    skipped.late += 1;
                }
                _ => {
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
    fn join(&mut self) {
        join_within(std::mem::take(&mut self.threads), PIPE_GRACE);
    }

    /// Sends a request line and waits for the next non-blank line.
    fn exchange(&mut self, request: Vec<u8>, deadline: Instant) -> Result<String, Exchange> {
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

    fn say_bye(&mut self) {
        if let Some(requests) = self.requests.take() {
            let _ = requests.send(b"{\"bye\": true}\n".to_vec());
            // Dropping the sender closes stdin once the line is written.
        }
    }

    /// Ends the process: killed at once, or first given a moment to exit by
    /// itself (it closed its output). Returns its exit status if it exited
    /// by itself.
    fn end(&mut self, kill_now: bool) -> Option<ExitStatus> {
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
fn read_line(stdout: &mut impl BufRead, max: u64) -> Result<Option<String>, Output> {
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

/// The end of a program's stderr, collected by a thread.
#[derive(Clone)]
struct StderrTail(Arc<(Mutex<TailState>, Condvar)>);

#[derive(Default)]
struct TailState {
    /// The last bytes read (at most `2 * STDERR_KEEP`).
    bytes: Vec<u8>,
    /// Bytes read in all, so that callers can mark a position.
    written: u64,
    closed: bool,
}

impl StderrTail {
    /// Starts the thread that reads it, returned to be joined.
    fn collect(stderr: Option<std::process::ChildStderr>) -> (StderrTail, Option<JoinHandle<()>>) {
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

    fn written(&self) -> u64 {
        self.0 .0.lock().unwrap_or_else(|e| e.into_inner()).written
    }

    /// Waits (at most `limit`) for the program to close its stderr.
    fn wait_closed(&self, limit: Duration) {
        let (state, changed) = &*self.0;
        let state = state.lock().unwrap_or_else(|e| e.into_inner());
        let _ = changed.wait_timeout_while(state, limit, |s| !s.closed);
    }

    /// The last lines written since byte `mark`, or `None` if there are none.
    fn since(&self, mark: u64) -> Option<String> {
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
