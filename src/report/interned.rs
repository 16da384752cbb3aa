//! The names a `report.json` holds (verdicts, statuses, rule and pattern
//! words) read back into the `&'static str` the report model keeps.
//!
//! Each distinct name is stored once for the life of the process and
//! shared by every later reading of it: the vocabulary is a few dozen
//! words, and a report that holds more distinct names than [`MAX_NAMES`]
//! is refused, so a hostile file cannot make the store grow without bound.

use std::collections::BTreeSet;
use std::sync::Mutex;

use serde::{Deserialize, Deserializer};

/// A word of the model's vocabulary. Spelled as an alias, not `&'static
/// str`, so that serde's derive does not take it for a string borrowed
/// from the input (which would tie every reading to `'static` input).
pub type Word = &'static str;

/// More distinct names than every vocabulary of the model together.
pub const MAX_NAMES: usize = 4096;

/// Longest name kept: the longest word of the model is far shorter.
pub const MAX_NAME_BYTES: usize = 200;

static NAMES: Mutex<BTreeSet<&'static str>> = Mutex::new(BTreeSet::new());

/// `text` as a `&'static str`: the one stored copy of it, stored on first
/// sight. `Err` when it is too long or the store is full.
pub fn intern(text: &str) -> Result<&'static str, String> {
    if text.len() > MAX_NAME_BYTES {
        return Err(format!(
            "a name of {} bytes where a word of at most {MAX_NAME_BYTES} was expected",
            text.len()
        ));
    }
    let mut names = NAMES.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(&known) = names.get(text) {
        return Ok(known);
    }
    if names.len() >= MAX_NAMES {
        return Err(format!(
            "more than {MAX_NAMES} distinct names read from reports; a report.json holds a few dozen"
        ));
    }
    let kept: &'static str = Box::leak(text.to_owned().into_boxed_str());
    names.insert(kept);
    Ok(kept)
}

/// Reads a name (`#[serde(deserialize_with = "name")]`).
pub fn name<'de, D: Deserializer<'de>>(d: D) -> Result<&'static str, D::Error> {
    let text = std::borrow::Cow::<str>::deserialize(d)?;
    intern(&text).map_err(serde::de::Error::custom)
}

/// Reads a name that may be absent or `null`.
pub fn maybe_name<'de, D: Deserializer<'de>>(d: D) -> Result<Option<&'static str>, D::Error> {
    match Option::<std::borrow::Cow<str>>::deserialize(d)? {
        Some(text) => intern(&text).map(Some).map_err(serde::de::Error::custom),
        None => Ok(None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_copy_per_name() {
        let a = intern("pass").unwrap();
        let b = intern(&String::from("pass")).unwrap();
        assert!(std::ptr::eq(a, b));
        assert!(intern(&"x".repeat(MAX_NAME_BYTES + 1)).is_err());
    }
}
