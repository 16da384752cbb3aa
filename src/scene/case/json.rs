//! The JSON access layer of the case reader: JSON paths, an object's
//! fields checked against the names a section allows (with "did you mean"
//! for an unknown key), and typed getters that name the path of a value of
//! the wrong kind.
//!
//! Nothing here knows the case format: which sections and fields exist is
//! the schema's (`schema.rs`), the documented ranges and the checks across
//! fields are `validate.rs`'s.

use std::fmt;

use serde_json::{Map, Value};

use crate::scene::number::{echo, echo_number, Number, ECHO_CHARS};

/// A JSON path under construction, e.g. `$.primitives[3].triangle[1]`.
#[derive(Clone, Debug)]
pub(super) struct Path(String);

impl Path {
    pub(super) fn root() -> Path {
        Path("$".to_owned())
    }
    /// The path one key deeper; a key longer than [`ECHO_CHARS`] is cut
    /// (its whole length shown), as every echo of input is.
    pub(super) fn key(&self, key: &str) -> Path {
        match key.char_indices().nth(ECHO_CHARS) {
            None => Path(format!("{}.{key}", self.0)),
            Some((cut, _)) => Path(format!(
                "{}.{}… ({} characters)",
                self.0,
                &key[..cut],
                key.chars().count()
            )),
        }
    }
    pub(super) fn index(&self, i: usize) -> Path {
        Path(format!("{}[{i}]", self.0))
    }
}

impl fmt::Display for Path {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

pub(super) type Fail = (Path, String);
pub(super) type Result<T, E = Fail> = std::result::Result<T, E>;

pub(super) fn fail<T>(path: &Path, message: impl Into<String>) -> Result<T> {
    Err((path.clone(), message.into()))
}

pub(super) fn kind(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// An object's fields, checked against the names a section allows.
pub(super) struct Fields<'a> {
    pub(super) map: &'a Map<String, Value>,
    path: Path,
}

impl<'a> Fields<'a> {
    pub(super) fn new(value: &'a Value, path: &Path, allowed: &[&str]) -> Result<Fields<'a>> {
        let Value::Object(map) = value else {
            return fail(path, format!("expected an object, found {}", kind(value)));
        };
        for key in map.keys() {
            if key.starts_with("//") || allowed.contains(&key.as_str()) {
                continue;
            }
            let hint = match closest(key, allowed) {
                Some(name) => format!("; did you mean \"{name}\"?"),
                None => format!("; expected one of {}", allowed.join(", ")),
            };
            return fail(&path.key(key), format!("unknown field {}{hint}", echo(key)));
        }
        Ok(Fields {
            map,
            path: path.clone(),
        })
    }

    pub(super) fn get(&self, key: &str) -> Option<(&'a Value, Path)> {
        self.map.get(key).map(|v| (v, self.path.key(key)))
    }

    pub(super) fn require(&self, key: &str) -> Result<(&'a Value, Path)> {
        self.get(key)
            .ok_or_else(|| (self.path.clone(), format!("missing field \"{key}\"")))
    }
}

/// The allowed name nearest to `key`, if it is plausibly a misspelling.
pub fn closest<'n>(key: &str, allowed: &[&'n str]) -> Option<&'n str> {
    allowed
        .iter()
        .map(|name| (edit_distance(key, name), *name))
        .filter(|(d, name)| *d <= 2.max(name.len() / 3))
        .min()
        .map(|(_, name)| name)
}

/// The Levenshtein distance between `a` and `b`, in characters.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (above + 1)
                .min(row[j] + 1)
                .min(diagonal + usize::from(ca != *cb));
            diagonal = above;
        }
    }
    row[b.len()]
}

pub(super) fn string<'v>(value: &'v Value, path: &Path) -> Result<&'v str> {
    value.as_str().ok_or_else(|| {
        (
            path.clone(),
            format!("expected a string, found {}", kind(value)),
        )
    })
}

pub(super) fn array<'v>(value: &'v Value, path: &Path) -> Result<&'v Vec<Value>> {
    value.as_array().ok_or_else(|| {
        (
            path.clone(),
            format!("expected an array, found {}", kind(value)),
        )
    })
}

pub(super) fn boolean(value: &Value, path: &Path) -> Result<bool> {
    value.as_bool().ok_or_else(|| {
        (
            path.clone(),
            format!("expected true or false, found {}", kind(value)),
        )
    })
}

/// An exact number: a JSON number read as its decimal text, or a string
/// holding a fraction or decimal.
pub(super) fn number(value: &Value, path: &Path) -> Result<Number> {
    let parsed = match value {
        Value::Number(n) => Number::from_decimal(n.as_str()),
        Value::String(s) => Number::from_string(s),
        other => {
            return fail(
                path,
                format!(
                    "expected a number or a fraction string, found {}",
                    kind(other)
                ),
            )
        }
    };
    parsed.map_err(|e| (path.clone(), e.to_string()))
}

/// A non-negative integer no larger than `max`.
pub(super) fn count(value: &Value, path: &Path, max: u64) -> Result<u64> {
    let n = number(value, path)?;
    if !n.is_integer() || n < Number::ZERO {
        return fail(
            path,
            format!("expected a whole number ≥ 0, found {}", echo_number(&n)),
        );
    }
    if n.numerator() > &dashu_int::IBig::from(max) {
        return fail(
            path,
            format!("{} is larger than the limit {max}", echo_number(&n)),
        );
    }
    Ok(n.numerator()
        .to_string()
        .parse()
        .expect("a bounded integer"))
}

pub(super) fn named<T>(
    value: &Value,
    path: &Path,
    parse: fn(&str) -> Option<T>,
    names: &[&str],
) -> Result<T> {
    let s = string(value, path)?;
    parse(s).ok_or_else(|| {
        let hint = match closest(s, names) {
            Some(name) => format!("; did you mean \"{name}\"?"),
            None => String::new(),
        };
        (
            path.clone(),
            format!("{} is not one of {}{hint}", echo(s), names.join(", ")),
        )
    })
}

/// The JSON path of the first key repeated in one object of `text`, if
/// any (`text` is valid JSON). `serde_json::Value` keeps the last of
/// repeated keys silently, so the check walks the text itself, keeping only
/// the keys of the objects it is inside.
pub(super) fn duplicate_key(text: &str) -> Option<Path> {
    use serde::de::DeserializeSeed;
    let found = std::cell::RefCell::new(None);
    let mut reader = serde_json::Deserializer::from_str(text);
    let seed = NoDuplicates {
        path: Path::root(),
        found: &found,
    };
    let _ = seed.deserialize(&mut reader);
    found.into_inner()
}

/// A visitor that walks any JSON value and records the path of the first
/// repeated key. Numbers (a one-key map under `arbitrary_precision`) and
/// other scalars are passed over.
struct NoDuplicates<'f> {
    path: Path,
    found: &'f std::cell::RefCell<Option<Path>>,
}

impl<'de> serde::de::DeserializeSeed<'de> for NoDuplicates<'_> {
    type Value = ();
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> serde::de::Visitor<'de> for NoDuplicates<'_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("any JSON value")
    }
    fn visit_bool<E>(self, _: bool) -> Result<(), E> {
        Ok(())
    }
    fn visit_i64<E>(self, _: i64) -> Result<(), E> {
        Ok(())
    }
    fn visit_u64<E>(self, _: u64) -> Result<(), E> {
        Ok(())
    }
    fn visit_f64<E>(self, _: f64) -> Result<(), E> {
        Ok(())
    }
    fn visit_str<E>(self, _: &str) -> Result<(), E> {
        Ok(())
    }
    fn visit_unit<E>(self) -> Result<(), E> {
        Ok(())
    }
    fn visit_none<E>(self) -> Result<(), E> {
        Ok(())
    }
    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let mut i = 0;
        while seq
            .next_element_seed(NoDuplicates {
                path: self.path.index(i),
                found: self.found,
            })?
            .is_some()
        {
            i += 1;
        }
        Ok(())
    }
    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        let mut seen = std::collections::HashSet::new();
        while let Some(key) = map.next_key::<String>()? {
            let path = self.path.key(&key);
            if !seen.insert(key) {
                *self.found.borrow_mut() = Some(path);
                return Err(serde::de::Error::custom("a repeated key"));
            }
            map.next_value_seed(NoDuplicates {
                path,
                found: self.found,
            })?;
        }
        Ok(())
    }
}
