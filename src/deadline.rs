//! The time limit per case (`--case-timeout`, SPEC.md §8).
//!
//! Rust cannot stop a thread from outside, so the limit is cooperative: the
//! runner gives the current thread a deadline before the reference draws a
//! case, and a fresh one before each candidate ([`within`]); the loops whose
//! length grows with the input (primitives, rows, slabs of exact areas,
//! pixels of a moving primitive) call [`check`], which unwinds out of the
//! work with an [`Exceeded`] payload once the deadline has passed.
//! `resume_unwind` does not run the panic hook, so nothing is printed; the
//! runner reports the case as having exceeded the limit and goes on with
//! the next. Work that never polls (a third-party rasterizer) is judged when
//! it returns: taking longer than the limit is exceeding it, so the verdict
//! does not depend on where the polls are.
//!
//! A stop of the run (SIGINT, SIGTERM) ends the work at its next poll the
//! same way, so a long case does not hold the run past the signal.
//!
//! Without a deadline, [`check`] is one thread-local read.

use std::any::Any;
use std::cell::Cell;
use std::time::{Duration, Instant};

thread_local! {
    /// This thread's deadline, and the limit it was set from (for the
    /// message).
    static DEADLINE: Cell<Option<(Instant, Duration)>> = const { Cell::new(None) };
}

/// The payload that unwinds out of work whose deadline has passed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Exceeded {
    pub limit: Duration,
}

impl std::fmt::Display for Exceeded {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "took longer than the time limit of {} s per case (raise it with --case-timeout)",
            seconds(self.limit)
        )
    }
}

fn seconds(d: Duration) -> String {
    let s = format!("{:.3}", d.as_secs_f64());
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// Runs `work` with a deadline `limit` from now on this thread (none when
/// `None`): `Err` when it polled past the deadline or returned after it.
/// Other panics go on unwinding. Deadlines nest: the outer one is restored
/// afterwards.
pub fn within<T>(limit: Option<Duration>, work: impl FnOnce() -> T) -> Result<T, Exceeded> {
    let Some(limit) = limit else {
        return Ok(work());
    };
    let started = Instant::now();
    let outer = DEADLINE.with(|d| d.replace(Some((started + limit, limit))));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(work));
    DEADLINE.with(|d| d.set(outer));
    match result {
        Ok(_) if started.elapsed() > limit => Err(Exceeded { limit }),
        Ok(value) => Ok(value),
        Err(payload) => match payload.downcast_ref::<Exceeded>() {
            Some(&exceeded) => Err(exceeded),
            None => std::panic::resume_unwind(payload),
        },
    }
}

/// The time left before this thread's deadline (zero once it has passed),
/// or `None` without one: for work that waits rather than polls (an
/// external program), so that it stops waiting at the deadline.
pub fn remaining() -> Option<Duration> {
    DEADLINE
        .with(Cell::get)
        .map(|(deadline, _)| deadline.saturating_duration_since(Instant::now()))
}

/// Unwinds with [`Exceeded`] when this thread's deadline has passed, or
/// when the run was stopped (SIGINT or SIGTERM, [`crate::stop`]): then the
/// case in flight stops at its next poll instead of running to its end,
/// and the runner records it as not run.
#[inline]
pub fn check() {
    if let Some((deadline, limit)) = DEADLINE.with(Cell::get) {
        if Instant::now() > deadline || crate::stop::requested().is_some() {
            std::panic::resume_unwind(Box::new(Exceeded { limit }));
        }
    }
}

/// Whether a caught panic is a deadline's unwinding, which a `catch_unwind`
/// inside the work must pass on (`resume_unwind`) rather than report as a
/// crash.
pub fn is_exceeded(payload: &(dyn Any + Send)) -> bool {
    payload.is::<Exceeded>()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_polling_loop_stops_at_the_deadline() {
        let limit = Duration::from_millis(20);
        let started = Instant::now();
        let result = within(Some(limit), || loop {
            check();
            std::hint::spin_loop();
        });
        assert_eq!(result, Err::<(), _>(Exceeded { limit }));
        // Stopped by the poll, not by running forever.
        assert!(started.elapsed() < Duration::from_secs(10));
    }

    #[test]
    fn work_that_never_polls_is_judged_when_it_returns() {
        let limit = Duration::from_millis(1);
        let result = within(Some(limit), || {
            std::thread::sleep(Duration::from_millis(20));
            7
        });
        assert_eq!(result, Err(Exceeded { limit }));
        assert_eq!(within(Some(Duration::from_secs(60)), || 7), Ok(7));
        assert_eq!(within(None, || 7), Ok(7));
    }

    #[test]
    fn without_a_deadline_check_does_nothing_and_deadlines_nest() {
        check();
        let inner = within(Some(Duration::from_secs(60)), || {
            within(Some(Duration::ZERO), check).unwrap_err();
            // The outer, generous deadline is back.
            check();
            1
        });
        assert_eq!(inner, Ok(1));
        check();
    }

    #[test]
    fn other_panics_go_on_unwinding() {
        let caught = std::panic::catch_unwind(|| {
            let _ = within(Some(Duration::from_secs(60)), || {
                std::panic::resume_unwind(Box::new("a bug"))
            });
        });
        let payload = caught.unwrap_err();
        assert!(!is_exceeded(&*payload));
        assert_eq!(payload.downcast_ref::<&str>(), Some(&"a bug"));
    }

    #[test]
    fn the_message_names_the_limit_and_the_flag() {
        let e = Exceeded {
            limit: Duration::from_millis(250),
        };
        assert_eq!(
            e.to_string(),
            "took longer than the time limit of 0.25 s per case (raise it with --case-timeout)"
        );
    }
}
