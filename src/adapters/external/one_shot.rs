//! One process per case (`external:…`): the request on its stdin, the
//! response on its stdout, and its whole process group killed when the
//! case is done.

use std::io::Write;
use std::sync::mpsc;
use std::thread;
use std::time::{Duration, Instant};

use super::adapter::External;
use super::envelope::check_json;
use super::limits::{MAX_OUTPUT_ENV, PIPE_GRACE};
use super::messages::seconds;
use super::process::{
    exit_description, failed, join_within, kill_group, read_bounded, wait_until_or, Output,
    StderrTail,
};
use crate::rasterizer::RasterError;

impl External {
    /// One process for this case: request on stdin, response on stdout.
    /// Whatever happens, its whole process group is killed before this
    /// returns, and the threads that fed and read it are joined.
    pub(super) fn one_shot(
        &self,
        request: Vec<u8>,
        timeout: Duration,
        max_output: u64,
    ) -> Result<String, RasterError> {
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
                Ok(bytes) => check_json(&bytes).and_then(|()| {
                    String::from_utf8(bytes).map_err(|e| format!("reading its output: {e}"))
                }),
                Err(Output::TooLong) => Err(too_long()),
                Err(Output::Read(e)) => Err(format!("reading its output: {e}")),
            }
        });
        let result = result.map_err(|why| failed(why, &stderr, 0));
        join_within(threads, PIPE_GRACE);
        result
    }
}
