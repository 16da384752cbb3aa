//! Peak heap memory of one call, counted by a global allocator.
//!
//! The binary installs [`Counting`] as its global allocator (src/main.rs).
//! It wraps the system allocator and, while [`peak`] measures a call, adds
//! each allocation's size to a running total (frees subtract) and keeps
//! that total's maximum. At all other times it only loads one flag
//! (relaxed) per allocation, so timed runs are not slowed by counting; the
//! bench measures memory in one extra, untimed run of each method.
//!
//! What is counted: every allocation through Rust's global allocator, on
//! any thread (a rayon pool's included), net of frees, above the level at
//! the call's start; the frame the call returns is part of it. What is not:
//! memory that C code allocates with its own `malloc` or `mmap` (Mesa's
//! llvmpipe and lavapipe: render targets, read-back buffers, JIT-compiled
//! shaders, bins, its threads' own heap), thread stacks, and pages the
//! allocator keeps after a free. Where no counting allocator is installed
//! (the library used from another program), [`peak`] answers `None`:
//! "not measured", never a zero.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicI64, Ordering::Relaxed, Ordering::SeqCst};

/// Whether allocations are being counted.
static ON: AtomicBool = AtomicBool::new(false);
/// Bytes allocated minus bytes freed since counting started (negative when
/// the call frees memory it found allocated).
static CURRENT: AtomicI64 = AtomicI64::new(0);
/// The largest value `CURRENT` took.
static PEAK: AtomicI64 = AtomicI64::new(0);
/// Held by the one [`peak`] call measuring: a second one, nested or on
/// another thread, runs unmeasured rather than corrupt the first's count.
static BUSY: AtomicBool = AtomicBool::new(false);

/// The system allocator, counting while [`peak`] measures.
///
/// ```ignore
/// #[global_allocator]
/// static ALLOCATOR: rastercheck::bench::memory::Counting = rastercheck::bench::memory::Counting;
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Counting;

fn grew(bytes: usize) {
    let now = CURRENT.fetch_add(bytes as i64, Relaxed) + bytes as i64;
    PEAK.fetch_max(now, Relaxed);
}

fn shrank(bytes: usize) {
    CURRENT.fetch_sub(bytes as i64, Relaxed);
}

// SAFETY: every call is passed to `System` unchanged; the counters are
// atomics and never allocate.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = System.alloc(layout);
        if ON.load(Relaxed) && !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = System.alloc_zeroed(layout);
        if ON.load(Relaxed) && !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout);
        if ON.load(Relaxed) {
            shrank(layout.size());
        }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = System.realloc(ptr, layout, new_size);
        if ON.load(Relaxed) && !p.is_null() {
            if new_size >= layout.size() {
                grew(new_size - layout.size());
            } else {
                shrank(layout.size() - new_size);
            }
        }
        p
    }
}

/// Runs `f` and returns its result with the peak heap bytes it held above
/// the level at its start (its result included, as it exists before `f`
/// returns), or `None` when nothing counts: no [`Counting`] allocator is
/// installed, or another `peak` call is measuring.
pub fn peak<T>(f: impl FnOnce() -> T) -> (T, Option<u64>) {
    if BUSY.compare_exchange(false, true, SeqCst, SeqCst).is_err() {
        return (f(), None);
    }
    CURRENT.store(0, SeqCst);
    PEAK.store(0, SeqCst);
    ON.store(true, SeqCst);
    let counting = counts_an_allocation();
    CURRENT.store(0, SeqCst);
    PEAK.store(0, SeqCst);
    let out = f();
    ON.store(false, SeqCst);
    let peak = PEAK.load(SeqCst).max(0) as u64;
    BUSY.store(false, SeqCst);
    (out, counting.then_some(peak))
}

/// Whether a [`Counting`] allocator is installed: one 64-byte allocation,
/// counted or not.
pub fn installed() -> bool {
    peak(|| ()).1.is_some()
}

/// Allocates and frees 64 bytes with counting on; whether they were seen.
fn counts_an_allocation() -> bool {
    let before = CURRENT.load(SeqCst);
    let probe = std::hint::black_box(Vec::<u8>::with_capacity(64));
    let seen = CURRENT.load(SeqCst) - before >= 64;
    drop(probe);
    seen
}

/// Bytes as B, KiB, MiB or GiB with three significant digits.
pub fn bytes_text(bytes: u64) -> String {
    const UNITS: [&str; 4] = ["B", "KiB", "MiB", "GiB"];
    let mut v = bytes as f64;
    let mut unit = 0;
    while v >= 1024.0 && unit + 1 < UNITS.len() {
        v /= 1024.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{bytes} B")
    } else if v >= 100.0 {
        format!("{v:.0} {}", UNITS[unit])
    } else if v >= 10.0 {
        format!("{v:.1} {}", UNITS[unit])
    } else {
        format!("{v:.2} {}", UNITS[unit])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The library's unit tests run on the system allocator: nothing is
    /// counted, and `peak` says so rather than report zero.
    #[test]
    fn without_the_allocator_nothing_is_measured() {
        let (v, peak) = peak(|| vec![0u8; 1 << 20]);
        assert_eq!(v.len(), 1 << 20);
        assert_eq!(peak, None);
        assert!(!installed());
    }

    #[test]
    fn bytes_read_as_units() {
        assert_eq!(bytes_text(0), "0 B");
        assert_eq!(bytes_text(1023), "1023 B");
        assert_eq!(bytes_text(1536), "1.50 KiB");
        assert_eq!(bytes_text(6 << 20), "6.00 MiB");
        assert_eq!(bytes_text(200 << 20), "200 MiB");
        assert_eq!(bytes_text(3 << 30), "3.00 GiB");
    }
}
