//! Values the flags of several commands take (`--threads`), and echoing
//! what a user typed in a message.

/// The most worker threads `--threads` accepts (README: "Exit codes").
pub const MAX_THREADS: usize = 256;

/// A `--threads` value: 0 (one per core) to [`MAX_THREADS`]. More threads
/// than that only cost memory and time (16 000 took minutes).
pub(crate) fn threads(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(n) if n <= MAX_THREADS => Ok(n),
        _ => Err(format!(
            "expected a number of threads from 0 (one per core) to {MAX_THREADS}, got {:?}",
            shorten(text)
        )),
    }
}

/// The most repetitions `run --repeat` accepts.
pub const MAX_REPEAT: usize = 100;

/// A `--repeat` value: 1 to [`MAX_REPEAT`].
pub(crate) fn repeat(text: &str) -> Result<usize, String> {
    match text.trim().parse::<usize>() {
        Ok(n) if (1..=MAX_REPEAT).contains(&n) => Ok(n),
        _ => Err(format!(
            "expected a number of repetitions from 1 to {MAX_REPEAT}, got {:?}",
            shorten(text)
        )),
    }
}

/// `text` cut to about 80 characters, for echoing in a message.
pub(crate) fn shorten(text: &str) -> String {
    crate::adapters::external::shorten(text)
}
