//! Where and when a report was made: the host's name and the UTC date
//! (`report.json`'s `machine`, SPEC.md §10), so that reports merged from
//! many machines (`rastercheck merge`) still say which one gave which
//! verdict. The driver and device are in each rasterizer's `declared`.

use serde::{Deserialize, Serialize};

use crate::harness::today::today;

/// Longest host name kept (a POSIX host name is at most 255 bytes).
const MAX_HOST_BYTES: usize = 255;

#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Machine {
    /// The host's name (`gethostname`), or `""` when it cannot be read.
    pub host: String,
    /// The day the run started, UTC, as YYYY-MM-DD.
    pub date: String,
}

impl Machine {
    /// This machine, today.
    pub fn here() -> Machine {
        Machine {
            host: host_name(),
            date: today(),
        }
    }
}

/// The host's name, as `hostname` prints it; `RASTERCHECK_HOST` overrides
/// it (a lab names its boards; a test stands in for several machines).
fn host_name() -> String {
    let named = std::env::var("RASTERCHECK_HOST").ok().or_else(system_host);
    let mut host: String = named.unwrap_or_default().trim().to_owned();
    if host.len() > MAX_HOST_BYTES {
        let mut end = MAX_HOST_BYTES;
        while !host.is_char_boundary(end) {
            end -= 1;
        }
        host.truncate(end);
    }
    host
}

#[cfg(unix)]
fn system_host() -> Option<String> {
    let mut buffer = [0u8; MAX_HOST_BYTES + 1];
    // SAFETY: the buffer is valid for its length; gethostname writes at
    // most that many bytes and we read up to the first NUL only.
    let status = unsafe { libc::gethostname(buffer.as_mut_ptr().cast(), buffer.len()) };
    if status != 0 {
        return None;
    }
    let end = buffer.iter().position(|&b| b == 0).unwrap_or(buffer.len());
    Some(String::from_utf8_lossy(&buffer[..end]).into_owned())
}

#[cfg(not(unix))]
fn system_host() -> Option<String> {
    std::env::var("COMPUTERNAME").ok()
}
