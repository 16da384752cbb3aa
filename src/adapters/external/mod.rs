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
//! This file holds the adapter: its name, its limits, one-shot runs and
//! the pool of persistent processes. `worker.rs` holds one persistent
//! process and its exchanges (the stream kept in step by ids);
//! `process.rs` waiting for, killing and reading a process (its group, its
//! bounded stdout, its stderr's tail); `protocol.rs` the messages: the
//! request, and reading a response into a frame; `motion.rs` what a moving
//! scene's messages add (SPEC.md §12.8: sent only to a program whose
//! version 2 hello declares motion); `hello.rs` the hello.

mod hello;
mod motion;
mod process;
mod protocol;
mod worker;

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::process::CommandExt;
use std::process::{Child, ChildStdin, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::Mutex;
use std::thread::{self, JoinHandle};
use std::time::{Duration, Instant};

use serde_json::Value;

use crate::deadline;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::{Capabilities, RasterError, Rasterizer};
use crate::scene::{FillRule, Scene};

pub use hello::Answers;
use hello::Hello;
use process::*;
use protocol::parse_response;
pub use protocol::{frame_from_answer, frame_from_response, request, request_v2};
use worker::*;

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
    /// The name and version the first hello declared.
    declared: Mutex<Option<String>>,
    /// How the program's answers are shaped, as its hello declared
    /// (coverage only, quantized coverage: SPEC.md §12.9).
    answers: Mutex<Answers>,
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
            declared: Mutex::new(None),
            answers: Mutex::new(Answers::default()),
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
        let moving = plan.motion.is_some();
        worker.await_late_hello(if moving {
            HELLO_WAIT.min(timeout)
        } else {
            Duration::ZERO
        });
        let mark = worker.stderr.written();
        if let Some(Err(why)) = &worker.hello {
            let why = format!("its hello is not a hello of SPEC.md §12.7: {why}");
            worker.end(true);
            return Err(failed(why, &worker.stderr, mark));
        }
        if let Some(Ok(hello)) = &worker.hello {
            let mut declared = self.declared.lock().unwrap_or_else(|e| e.into_inner());
            if declared.is_none() {
                *declared = hello.title();
            }
            drop(declared);
            *self.answers.lock().unwrap_or_else(|e| e.into_inner()) = hello.answers();
            if let Some(why) = hello.refuses(scene, plan) {
                // Never sent: the program said it cannot draw it.
                pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
                return Err(RasterError::Unsupported(why));
            }
        }
        if moving && worker.hello.is_none() {
            // Version 1 carries no moving vertices: never sent.
            pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
            return Err(RasterError::Unsupported(format!(
                "{}; this process of the program wrote no hello",
                motion::NOT_DECLARED
            )));
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

    /// Everything: the program says what it does not do, case by case
    /// (`unsupported`, or its hello). Moving scenes go only to a program
    /// whose version 2 hello declares motion (SPEC.md §12.8); the adapter
    /// refuses them itself, since only the hello says. The protocol has no
    /// point (SPEC.md §12), so points are refused.
    fn capabilities(&self) -> Capabilities {
        Capabilities {
            clip_space: false,
            // The protocol carries no depth format or offset (SPEC.md §12).
            depth_attachment: false,
            points: false,
            ..Capabilities::everything()
        }
    }

    fn fixed_fill_rule(&self) -> Option<FillRule> {
        self.answers
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .fill_rule
    }

    fn declared(&self) -> Option<String> {
        self.declared
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    fn rasterize(&self, scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
        // Checked here too, for callers that skip the harness: a request
        // cannot carry a point.
        if let Some(why) = self.capabilities().refuses(scene) {
            return Err(RasterError::Unsupported(why));
        }
        let mut timeout = self.timeout.clone().map_err(RasterError::Failed)?;
        let max_output = self.max_output.clone().map_err(RasterError::Failed)?;
        // The case's deadline (`--case-timeout`) stops the program too; the
        // runner then judges the case over the limit.
        if let Some(left) = deadline::remaining() {
            timeout = timeout.min(left);
        }
        let response = match &self.pool {
            // One-shot programs speak version 1: no moving vertices.
            None if plan.motion.is_some() => {
                return Err(RasterError::Unsupported(motion::NOT_DECLARED.to_owned()))
            }
            None => {
                let request =
                    serde_json::to_vec(&request(scene, plan)).expect("a JSON value serializes");
                self.one_shot(request, timeout, max_output)?
            }
            Some(pool) => self.persistent(pool, scene, plan, timeout, max_output, false)?,
        };
        let answers = *self.answers.lock().unwrap_or_else(|e| e.into_inner());
        frame_from_answer(&response, scene, plan, answers)
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

/// Reads one response line as the adapter does, into a frame for `scene`
/// drawn under `plan`, or the reason it is refused (an unsupported case, a
/// reported error, a malformed answer). The `protocol_response` fuzz target
/// drives it.
pub fn read_answer(line: &[u8], scene: &Scene, plan: &Plan) -> Result<Frame, RasterError> {
    let value = parse_response(line).map_err(RasterError::Failed)?;
    frame_from_response(&value, scene, plan)
}

/// Reads a line as a hello: `Ok(None)` when it is not one, else the reason
/// its declared capabilities refuse `scene` drawn under `plan`, if any.
pub fn read_hello(line: &[u8], scene: &Scene, plan: &Plan) -> Result<Option<String>, String> {
    let value = parse_response(line)?;
    if !hello::is_hello(&value) {
        return Ok(None);
    }
    Ok(Hello::parse(&value)?.refuses(scene, plan))
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
