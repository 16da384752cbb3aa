//! Stopping a run on SIGINT or SIGTERM (SPEC.md §9): the hook between the
//! signal, the runner and the external programs.
//!
//! - [`install`] (called by `rastercheck run` only) replaces the default
//!   action of SIGINT and SIGTERM with a handler that records the signal
//!   and kills every registered child with SIGKILL. A second signal ends
//!   the process at once (exit 128 + signal), for a user who does not want
//!   to wait for the cases in flight.
//! - [`install_exiting`] (every other command: `baseline`, `matrix`,
//!   `probe`, `fuzz`, `show`, ...; they have no partial report to write)
//!   kills every registered child on the first signal and ends the process
//!   at once with 128 + signal, so that no external program outlives it
//!   (each leads a process group of its own, which the terminal's signal
//!   does not reach).
//! - The runner polls [`requested`] before each case and starts no new one
//!   once it is set; it marks the cases that did not finish `not-run`.
//! - An adapter that starts a process calls [`register`] with its pid right
//!   after spawning it and [`unregister`] before (or right as) it reaps it,
//!   so that the handler never kills a reused pid. A registered child leads
//!   a process group of its own (the external adapter starts every program
//!   with `process_group(0)`), so the handler kills that group, the
//!   program's own children with it, and then the child.
//!
//! The handler only reads and writes atomics and calls `kill` and `_exit`,
//! which are async-signal-safe; the registry is a fixed array of slots, so
//! nothing is allocated or locked. Imports nothing from the crate: every
//! stage may use it, as [`crate::deadline`].

use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};

/// The signal that asked the run to stop; 0 while none has.
static STOP: AtomicI32 = AtomicI32::new(0);

/// Whether the first signal ends the process ([`install_exiting`]).
static EXIT_AT_ONCE: AtomicBool = AtomicBool::new(false);

/// Slots for the pids of running children; 0 is a free slot.
const SLOTS: usize = 1024;
static CHILDREN: [AtomicI32; SLOTS] = [const { AtomicI32::new(0) }; SLOTS];

/// SIGINT, whose exit code is 130.
pub const SIGINT: i32 = 2;
/// SIGTERM, whose exit code is 143.
pub const SIGTERM: i32 = 15;

/// The signal that asked the run to stop, if one has.
pub fn requested() -> Option<i32> {
    match STOP.load(Ordering::SeqCst) {
        0 => None,
        signal => Some(signal),
    }
}

/// Records a stop as the handler does, and kills the registered children
/// (for tests and for callers that stop a run themselves).
pub fn request(signal: i32) {
    if STOP
        .compare_exchange(0, signal, Ordering::SeqCst, Ordering::SeqCst)
        .is_ok()
    {
        kill_children();
    }
}

/// Records a child process, so that a stop kills it. Without a free slot
/// (more than 1024 children at once) it is not recorded; when a stop was
/// already requested, the child is killed at once.
pub fn register(pid: u32) {
    let Ok(pid) = i32::try_from(pid) else { return };
    if pid <= 0 {
        return;
    }
    for slot in &CHILDREN {
        if slot
            .compare_exchange(0, pid, Ordering::SeqCst, Ordering::SeqCst)
            .is_ok()
        {
            break;
        }
    }
    // A signal between the spawn and the slot: the handler did not see it.
    if requested().is_some() {
        kill_pid(pid);
    }
}

/// Forgets a child (it exited, or is being killed and reaped).
pub fn unregister(pid: u32) {
    let Ok(pid) = i32::try_from(pid) else { return };
    if pid <= 0 {
        return;
    }
    for slot in &CHILDREN {
        if slot
            .compare_exchange(pid, 0, Ordering::SeqCst, Ordering::SeqCst)
            .is_ok()
        {
            return;
        }
    }
}

/// How many children are registered now.
pub fn registered() -> usize {
    CHILDREN
        .iter()
        .filter(|s| s.load(Ordering::SeqCst) != 0)
        .count()
}

fn kill_children() {
    for slot in &CHILDREN {
        let pid = slot.load(Ordering::SeqCst);
        if pid > 0 {
            kill_pid(pid);
        }
    }
}

#[cfg(unix)]
fn kill_pid(pid: i32) {
    // SAFETY: kill(2) is async-signal-safe and takes plain integers. The
    // group first (a child that leads no group makes it fail harmlessly,
    // ESRCH), then the child itself.
    unsafe {
        libc::kill(-pid, libc::SIGKILL);
        libc::kill(pid, libc::SIGKILL);
    }
}

#[cfg(not(unix))]
fn kill_pid(_pid: i32) {}

#[cfg(unix)]
extern "C" fn on_signal(signal: libc::c_int) {
    if EXIT_AT_ONCE.load(Ordering::SeqCst) {
        kill_children();
        // SAFETY: _exit(2) is async-signal-safe.
        unsafe { libc::_exit(128 + signal) };
    }
    if STOP
        .compare_exchange(0, signal, Ordering::SeqCst, Ordering::SeqCst)
        .is_err()
    {
        // The second signal: the user does not wait for the cases in flight.
        kill_children();
        // SAFETY: _exit(2) is async-signal-safe.
        unsafe { libc::_exit(128 + signal) };
    }
    kill_children();
}

/// Installs the handler for SIGINT and SIGTERM (unix; elsewhere nothing):
/// the first signal stops the run, the second ends the process.
pub fn install() {
    EXIT_AT_ONCE.store(false, Ordering::SeqCst);
    handle();
}

/// Installs the handler for a command that has nothing to finish: the
/// first signal kills the registered children and ends the process.
pub fn install_exiting() {
    EXIT_AT_ONCE.store(true, Ordering::SeqCst);
    handle();
}

fn handle() {
    #[cfg(unix)]
    {
        let handler = on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t;
        for signal in [libc::SIGINT, libc::SIGTERM] {
            // SAFETY: the handler only touches atomics and calls
            // async-signal-safe functions.
            unsafe {
                libc::signal(signal, handler);
            }
        }
    }
}

/// The exit code of a run stopped by `signal`: 128 + its number (130 for
/// SIGINT, 143 for SIGTERM), as shells report it.
pub fn exit_code(signal: i32) -> u8 {
    u8::try_from(128 + signal).unwrap_or(255)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_are_taken_and_freed() {
        // A pid that cannot be ours: never killed (no stop requested here).
        let before = registered();
        register(i32::MAX as u32);
        assert_eq!(registered(), before + 1);
        unregister(i32::MAX as u32);
        assert_eq!(registered(), before);
        register(0);
        assert_eq!(registered(), before);
    }

    #[test]
    fn exit_codes_are_128_plus_the_signal() {
        assert_eq!(exit_code(SIGINT), 130);
        assert_eq!(exit_code(SIGTERM), 143);
    }
}
