//! How values are quoted in messages: a long text cut, a duration in
//! seconds.

use std::time::Duration;

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

pub(super) fn seconds(d: Duration) -> String {
    format!("{} s", d.as_secs_f64())
}
