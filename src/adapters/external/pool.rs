//! The pool of persistent processes (`external-persistent:…`): a line to
//! an idle process and a line back, in the version it speaks (v2's ids
//! keep the stream in step; under v1 a process that writes anything but
//! one line per request is replaced, and an answer that does not fit its
//! request retires it), an idle process that exited or wrote unasked
//! never reused, a stuck or vanished process retired and its case sent
//! once more, and every process said goodbye to when the adapter is
//! dropped.

use std::sync::atomic::Ordering;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use super::adapter::External;
use super::answer::frame_from_line;
use super::answer_error::AnswerError;
use super::envelope::check_json;
use super::hello::{self, Hello};
use super::limits::{BYE_GRACE, HELLO_WAIT, MAX_OUTPUT_ENV, MAX_SKIPPED_LINES};
use super::messages::{seconds, shorten};
use super::motion;
use super::process::{exit_description, failed, kill, kill_group, wait_until, Output};
use super::protocol::{Outgoing, Request};
use super::space::needs_a_hello;
use super::worker::{Exchange, Unread, Worker};
use crate::deadline;
use crate::frame::Frame;
use crate::plan::Plan;
use crate::rasterizer::RasterError;
use crate::scene::Scene;

impl External {
    /// A line to a process of the pool, and a line back, read into a
    /// frame. The request is written in the version the process speaks: v2
    /// (an id, the answer found by it) when its first line was a hello of
    /// version 2, else v1. An idle process is sent nothing if it exited or
    /// wrote unasked ([`Worker::unfit`]): it is ended, and another taken.
    pub(super) fn persistent(
        &self,
        pool: &Mutex<Vec<Worker>>,
        scene: &Scene,
        plan: &Plan,
        timeout: Duration,
        max_output: u64,
        retried: bool,
    ) -> Result<Frame, RasterError> {
        let deadline = Instant::now() + timeout;
        if let Some((why, hello)) = &*self.broken.lock().unwrap_or_else(|e| e.into_inner()) {
            // Its answers cannot be matched to requests: nothing more is
            // sent, and nothing waited for. What its hello refuses is still
            // unsupported.
            if let Some(refused) = hello.as_ref().and_then(|h| h.refuses(scene, plan)) {
                return Err(RasterError::Unsupported(refused));
            }
            return Err(RasterError::Failed(format!(
                "not sent: {why}; no case is sent to it for the rest of the run"
            )));
        }
        let idle = loop {
            let idle = pool.lock().unwrap_or_else(|e| e.into_inner()).pop();
            let Some(mut worker) = idle else { break None };
            if worker.unfit().is_none() {
                break Some(worker);
            }
            // Out of step or gone: never sent this case, which goes to the
            // next idle process or a fresh one.
            worker.end(true);
        };
        let mut worker = match idle {
            Some(worker) => worker,
            None => {
                let mut worker = Worker::start(self.start()?, max_output);
                if !self.said_no_hello.load(Ordering::Relaxed) {
                    // A program whose hello the preflight read is waited
                    // for until the case's time limit: its hello will come.
                    let mut command = vec![self.program.clone()];
                    command.extend_from_slice(&self.args);
                    let wait = if hello::seen(&command) {
                        timeout
                    } else {
                        HELLO_WAIT.min(timeout)
                    };
                    worker.await_hello(Instant::now() + wait);
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
            self.heard(hello);
            if let Some(why) = hello.refuses(scene, plan) {
                // Never sent: the program said it cannot draw it.
                pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
                return Err(RasterError::Unsupported(why));
            }
        }
        if let (None, Some(why)) = (&worker.hello, needs_a_hello(scene)) {
            // Version 1 carries no clip space, points or depth formats.
            pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
            return Err(RasterError::Unsupported(why));
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
                Ok(result) => Ok(frame_from_line(
                    result?.as_bytes(),
                    scene,
                    plan,
                    self.answers(),
                )?),
                // The process was stuck on an earlier case, or vanished or
                // flooded before answering this one, and is gone: this
                // case is sent once more, to a fresh one.
                Err(_) if !retried => self.retry(pool, scene, plan, max_output),
                Err(why) => Err(why),
            };
        }
        let request = Outgoing::Request(Box::new(Request::v1(scene, plan)));
        let had_hello = worker.hello.is_some();
        let reused = worker.sent > 0;
        let line = worker.exchange(request, deadline);
        // A hello that came in place of the answer (a program slow to
        // start) was written before the program read this request: it
        // holds for it (SPEC.md §12.7). A malformed one ends the process.
        let late = match &worker.hello {
            Some(Ok(hello)) if !had_hello => {
                self.heard(hello);
                hello.refuses(scene, plan)
            }
            _ => None,
        };
        let line = match (&worker.hello, line) {
            (Some(Err(why)), _) if !had_hello => Err(Exchange::Late(format!(
                "its hello is not a hello of SPEC.md §12.7: {why}"
            ))),
            (_, Ok(_)) if late.is_some() => {
                // Its answer is read and not judged: its hello refuses the case.
                pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
                return Err(RasterError::Unsupported(late.unwrap_or_default()));
            }
            (_, line) => line,
        };
        let result = match line {
            // Version 1 carries no ids: one line per request, and a second
            // one already written means the answer cannot be told apart.
            Ok(line) => match worker.unread() {
                Unread::Nothing => check_json(line.as_bytes())
                    .map(|()| line)
                    .map_err(|why| (why, true)),
                Unread::Line(Ok(next)) => Err((
                    format!(
                        "it wrote more than one line for one request (protocol v1 carries no \
                         ids, so its answers cannot be told apart): {:?}, then {:?}; the \
                         process was replaced",
                        shorten(&line),
                        shorten(&next)
                    ),
                    true,
                )),
                Unread::Line(Err(_)) | Unread::Bytes => Err((
                    format!(
                        "it wrote more than its answer to one request (protocol v1 carries no \
                         ids, so its answers cannot be told apart): {:?}, then more; the \
                         process was replaced",
                        shorten(&line)
                    ),
                    true,
                )),
            },
            Err(Exchange::Late(why)) => Err((why, true)),
            Err(Exchange::TimedOut | Exchange::Flood) => {
                Err((format!("timed out after {}", seconds(timeout)), true))
            }
            // A process reused after an earlier answer that vanished before
            // writing anything: the case is not the culprit, and is sent
            // once more, to a fresh process.
            Err(Exchange::Closed) if reused && !retried => {
                worker.end(false);
                return self.retry(pool, scene, plan, max_output);
            }
            Err(Exchange::Closed) => Err(("closed its output".to_owned(), false)),
            // Version 1 matches no ids; only v2 exchanges end so.
            Err(Exchange::NoId(line)) => Err((format!("an answer without an id: {line:?}"), true)),
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
            Ok(line) => match frame_from_line(line.as_bytes(), scene, plan, self.answers()) {
                Err(AnswerError::Unfit(why)) => {
                    // An answer that does not fit its request may be
                    // another request's: the process is never reused.
                    worker.end(true);
                    Err(failed(
                        format!(
                            "{why}; the process was replaced (under protocol v1 an answer \
                             that does not fit its request may be another request's)"
                        ),
                        &worker.stderr,
                        mark,
                    ))
                }
                judged => {
                    pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
                    Ok(judged?)
                }
            },
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
    /// process is then stuck on the earlier request, and is killed. A
    /// reused process that closes its output before a byte of its answer
    /// (it exited after the last one), or floods, is ended too. `Err`
    /// says so, for the caller to send the case to a fresh process.
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
    ) -> Result<Result<String, RasterError>, RasterError> {
        let id = format!(
            "{}#{}",
            scene.name,
            self.next_id.fetch_add(1, Ordering::Relaxed)
        );
        let mark = worker.stderr.written();
        let request = Outgoing::Request(Box::new(Request::v2(scene, plan, &id)));
        let reused = worker.sent > 0;
        let (answer, skipped) = worker.exchange_v2(request, &id, deadline, max_output);
        let keep = |worker: Worker| pool.lock().unwrap_or_else(|e| e.into_inner()).push(worker);
        let strays = skipped.describe();
        // A reused process that vanished before writing anything but late
        // answers, or flooded (its flood may have begun while it was
        // idle): the case is sent once more, to a fresh process.
        let retry = reused
            && match &answer {
                Err(Exchange::Closed) => skipped.strays == 0,
                Err(Exchange::Flood) => true,
                _ => false,
            };
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
            Err(Exchange::Late(why)) => (why, true),
            Err(Exchange::NoId(line)) => {
                let cause = format!(
                    "its answers carry no `id` (the first, to request {id:?}: {line:?}); \
                     protocol v2 answers must echo the request's id (SPEC.md §12.7)"
                );
                return Ok(Err(self.give_up(worker, cause, mark)));
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
                if let Some(other) = &skipped.wrong_id {
                    let cause = format!(
                        "answer id {other} for request {id:?}; protocol v2 answers must echo \
                         the request's id (SPEC.md §12.7)"
                    );
                    if self.wrong_ids.fetch_add(1, Ordering::Relaxed) > 0 {
                        // The second case answered under another id: the
                        // program does not echo them.
                        return Ok(Err(self.give_up(
                            worker,
                            format!("{cause}, the second time in this run"),
                            mark,
                        )));
                    }
                    let err = failed(
                        format!("{why}: {cause}; the process is kept"),
                        &worker.stderr,
                        mark,
                    );
                    worker.timeouts_in_a_row = 0;
                    keep(worker);
                    return Ok(Err(err));
                }
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
        let err = failed(why, &worker.stderr, mark);
        if retry {
            return Err(err);
        }
        Ok(Err(err))
    }
}

impl External {
    /// Sends the case once more, to a fresh process (the pool's idle ones
    /// are looked at first), with a fresh time limit within the case's
    /// deadline.
    fn retry(
        &self,
        pool: &Mutex<Vec<Worker>>,
        scene: &Scene,
        plan: &Plan,
        max_output: u64,
    ) -> Result<Frame, RasterError> {
        let timeout = match (self.timeout.clone(), deadline::remaining()) {
            (Ok(t), Some(left)) => t.min(left),
            (Ok(t), None) => t,
            (Err(why), _) => return Err(RasterError::Failed(why)),
        };
        self.persistent(pool, scene, plan, timeout, max_output, true)
    }

    /// Keeps what a hello declares for the cases from now on: its name (the
    /// first hello's) and how its answers are shaped.
    fn heard(&self, hello: &Hello) {
        let mut declared = self.declared.lock().unwrap_or_else(|e| e.into_inner());
        if declared.is_none() {
            *declared = hello.title();
        }
        drop(declared);
        *self.answers.lock().unwrap_or_else(|e| e.into_inner()) = hello.answers();
        *self.conservative.lock().unwrap_or_else(|e| e.into_inner()) =
            hello.conservative().map(|c| c.support());
    }

    /// Ends `worker` and sends the program no more cases: its answers
    /// cannot be matched to requests (`cause`). The error for the case in
    /// flight says so, once; every later case names the cause without
    /// being sent or waited for.
    fn give_up(&self, mut worker: Worker, cause: String, mark: u64) -> RasterError {
        let hello = worker.hello.as_ref().and_then(|h| h.as_ref().ok()).cloned();
        *self.broken.lock().unwrap_or_else(|e| e.into_inner()) = Some((cause.clone(), hello));
        worker.end(true);
        failed(
            format!("protocol error: {cause}; no case is sent to it for the rest of the run"),
            &worker.stderr,
            mark,
        )
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
