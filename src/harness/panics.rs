//! The text of a caught panic, and the one panic that is not a crash: a
//! deadline's unwinding, passed on to the runner that set it.

use crate::deadline;

/// The message a panic carried.
/// `what: message` for a caught panic; a deadline's unwinding
/// ([`deadline::Exceeded`]) is not a crash and goes on unwinding to the
/// runner that set the deadline.
pub fn pass_on_deadline(panic: Box<dyn std::any::Any + Send>, what: &str) -> String {
    if deadline::is_exceeded(&*panic) {
        std::panic::resume_unwind(panic);
    }
    format!("{what}: {}", panic_message(&*panic))
}

pub fn panic_message(panic: &(dyn std::any::Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "panicked".to_owned())
}
