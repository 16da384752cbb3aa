//! Whether a process is still running (Linux `/proc`): one of its threads,
//! or of the processes it started, is runnable. A version 1 program's
//! answers carry no id, so a line it writes after its answer can be told
//! from the next answer only by when it comes; a process still running
//! after its answer may yet write one, and a process asleep (waiting for
//! its next request, most often) has written all it will until it is
//! woken ([`Worker::unread`](super::worker::Worker::unread)).

use std::fs;

/// How deep the processes a program started are looked into.
const MAX_DEPTH: u32 = 4;

/// How many processes and threads are looked at, at most.
const MAX_TASKS: usize = 256;

/// Whether a thread of `pid`, or of a process it started (to
/// [`MAX_DEPTH`] levels), is runnable or in an uninterruptible wait;
/// `None` when `/proc` cannot say (not Linux, or not readable).
pub(super) fn running(pid: u32) -> Option<bool> {
    let mut looked = 0;
    running_in(pid, 0, &mut looked)
}

fn running_in(pid: u32, depth: u32, looked: &mut usize) -> Option<bool> {
    let tasks = fs::read_dir(format!("/proc/{pid}/task")).ok()?;
    let mut children = Vec::new();
    for task in tasks.flatten() {
        *looked += 1;
        if *looked > MAX_TASKS {
            break;
        }
        let path = task.path();
        let Ok(stat) = fs::read_to_string(path.join("stat")) else {
            continue; // it ended between the two looks
        };
        if busy(&stat) {
            return Some(true);
        }
        if depth < MAX_DEPTH {
            if let Ok(list) = fs::read_to_string(path.join("children")) {
                children.extend(
                    list.split_whitespace()
                        .filter_map(|c| c.parse::<u32>().ok()),
                );
            }
        }
    }
    for child in children {
        if running_in(child, depth + 1, looked) == Some(true) {
            return Some(true);
        }
    }
    Some(false)
}

/// Whether a `/proc/…/stat` line's state is R (runnable) or D (an
/// uninterruptible wait, a page fault most often: it runs on after it).
/// The state follows the command's name, which is in parentheses and may
/// hold any byte, so it is found after the last `)`.
fn busy(stat: &str) -> bool {
    let state = stat
        .rfind(')')
        .and_then(|end| stat[end + 1..].split_whitespace().next());
    matches!(state, Some("R" | "D"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};

    #[test]
    fn the_state_is_read_after_the_last_parenthesis() {
        assert!(busy("12 (a) b) R 1 12 12"));
        assert!(!busy("12 (R) S 1 12 12"));
        assert!(busy("12 (x) D 1"));
        assert!(!busy("12 (x) Z 1"));
        assert!(!busy("no state"));
    }

    /// A process that sleeps is not running; one that spins is, and so
    /// is a shell whose child spins (the shell itself waits).
    #[test]
    fn a_sleeping_process_is_not_running_and_a_spinning_child_is() {
        use std::os::unix::process::CommandExt;
        let Some(_) = running(std::process::id()) else {
            eprintln!("SKIPPED: /proc cannot say whether a process runs here");
            return;
        };
        let start = |script: &str| {
            Command::new("sh")
                .args(["-c", script])
                .stdout(Stdio::null())
                .process_group(0)
                .spawn()
                .unwrap()
        };
        let mut sleeper = start("exec sleep 30");
        let mut spinner = start("sh -c 'while :; do :; done'; exit 0");
        let seen = |pid: u32, want: bool| {
            // A process just started runs for a moment, and a spinning one
            // may be seen between two time slices: looked at until seen.
            let end = Instant::now() + Duration::from_secs(10);
            while Instant::now() < end {
                if running(pid) == Some(want) {
                    return true;
                }
                std::thread::sleep(Duration::from_millis(5));
            }
            false
        };
        let asleep = seen(sleeper.id(), false);
        let spinning = seen(spinner.id(), true);
        for child in [&mut sleeper, &mut spinner] {
            // SAFETY: kill(2) on the process group the child leads.
            unsafe { libc::kill(-(child.id() as libc::pid_t), libc::SIGKILL) };
            let _ = child.wait();
        }
        assert!(asleep, "a sleeping process was seen running");
        assert!(spinning, "a shell whose child spins was never seen running");
    }
}
