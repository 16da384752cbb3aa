//! A line's envelope, read before (or instead of) its answer: its `id`,
//! whether it is shaped as an answer, whether it is a hello (SPEC.md
//! §12.2, §12.7); and whether a line is JSON at all. Each reads the whole
//! line without keeping it (serde's `IgnoredAny`), never into a
//! `serde_json::Value` (issue 36: a 192 MB answer parsed into one took
//! 4 GB, to look at its id).

use std::fmt;

use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};

use super::values::{Text, NUMBER_TOKEN};

/// What an exchange looks at in each line before the answer is read: its
/// `id`, whether it carries one of an answer's fields (§12.2's
/// `primitives`, `error`, `unsupported`, `exr`), whether it is a hello
/// (§12.7). Read without keeping the rest of the line. `None` from
/// [`Envelope::read`]: not a JSON object.
pub(super) struct Envelope {
    pub(super) id: Id,
    pub(super) answer: bool,
    pub(super) hello: bool,
}

/// An envelope's `id`.
pub(super) enum Id {
    Missing,
    Null,
    Text(String),
    /// Not a string, as a `Scalar` shows it.
    Other(String),
}

impl Envelope {
    pub(super) fn read(line: &str) -> Option<Envelope> {
        let mut de = serde_json::Deserializer::from_str(line);
        let envelope = EnvelopeSeed.deserialize(&mut de).ok()?;
        de.end().ok()?;
        envelope
    }

    /// The id, when it is a string.
    pub(super) fn id_text(&self) -> Option<&str> {
        match &self.id {
            Id::Text(id) => Some(id),
            _ => None,
        }
    }
}

struct EnvelopeSeed;

impl<'de> DeserializeSeed<'de> for EnvelopeSeed {
    type Value = Option<Envelope>;
    fn deserialize<D: Deserializer<'de>>(self, deserializer: D) -> Result<Self::Value, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for EnvelopeSeed {
    type Value = Option<Envelope>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON line")
    }
    fn visit_bool<E: de::Error>(self, _: bool) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_str<E: de::Error>(self, _: &str) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
        Ok(None)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        while seq.next_element::<IgnoredAny>()?.is_some() {}
        Ok(None)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        let mut out = Envelope {
            id: Id::Missing,
            answer: false,
            hello: false,
        };
        while let Some(key) = map.next_key::<String>()? {
            match key.as_str() {
                // A number, as `serde_json` hands one over: not an object.
                NUMBER_TOKEN => {
                    map.next_value::<IgnoredAny>()?;
                    return Ok(None);
                }
                "hello" => {
                    out.hello = true;
                    map.next_value::<IgnoredAny>()?;
                }
                "id" => {
                    let text = map.next_value::<Text>()?;
                    out.id = match text {
                        Text(_, Some(id)) => Id::Text(id),
                        Text(shown, None) if shown == "null" => Id::Null,
                        Text(shown, None) => Id::Other(shown),
                    };
                }
                "primitives" | "error" | "unsupported" | "exr" => {
                    out.answer = true;
                    map.next_value::<IgnoredAny>()?;
                }
                _ => {
                    map.next_value::<IgnoredAny>()?;
                }
            }
        }
        Ok(Some(out))
    }
}

/// Whether a line is JSON at all (a version 1 answer is taken when it is,
/// and read into a frame afterwards), without keeping any of it.
pub(super) fn check_json(bytes: &[u8]) -> Result<(), String> {
    serde_json::from_slice::<IgnoredAny>(bytes)
        .map(drop)
        .map_err(|e| not_json(bytes, &e))
}

/// Why a line is not JSON at all, quoting at most 80 characters of it.
pub(super) fn not_json(bytes: &[u8], e: &serde_json::Error) -> String {
    let text = String::from_utf8_lossy(&bytes[..bytes.len().min(4096)]);
    if text.trim().is_empty() && bytes.len() <= 4096 {
        return "printed no response".to_owned();
    }
    let shown: String = text.chars().take(80).collect();
    format!(
        "printed something that is not a JSON response ({e}): {shown:?}{}",
        if bytes.len() > shown.len() { "…" } else { "" }
    )
}
