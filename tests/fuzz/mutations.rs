//! Mutations of the real case files under `cases/`: byte flips and
//! insertions, truncations, duplicated keys, swapped types, extreme and
//! nudged numbers.

use proptest::prelude::*;
use serde_json::Value;

use crate::random_json::{json_text, number_text, string_text};

#[derive(Clone, Debug)]
pub(crate) enum Mutation {
    FlipByte(usize, u8),
    InsertByte(usize, u8),
    DeleteRange(usize, usize),
    Truncate(usize),
    DuplicateRange(usize, usize),
    /// Replace the k-th JSON value (in document order) by another of a
    /// different type, or by an extreme number.
    Replace(usize, String),
    /// Add a second copy of the k-th object's first key, with a new value.
    DuplicateKey(usize, String),
    /// Remove the k-th object's or array's k-th entry.
    Remove(usize, usize),
    /// Move the k-th number (in document order) by a small amount, keeping
    /// the case readable more often than not.
    Nudge(usize, String),
}

pub(crate) fn mutation() -> impl Strategy<Value = Mutation> {
    let replacement = prop_oneof![
        3 => number_text(),
        2 => string_text(),
        1 => json_text(),
        1 => Just("null".to_owned()),
        1 => Just("[]".to_owned()),
        1 => Just("{}".to_owned()),
        1 => Just("true".to_owned()),
    ];
    prop_oneof![
        2 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::FlipByte(i, b)),
        1 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::InsertByte(i, b)),
        1 => (any::<usize>(), 1usize..64).prop_map(|(i, n)| Mutation::DeleteRange(i, n)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
        1 => (any::<usize>(), 1usize..256).prop_map(|(i, n)| Mutation::DuplicateRange(i, n)),
        6 => (any::<usize>(), replacement.clone()).prop_map(|(k, v)| Mutation::Replace(k, v)),
        2 => (any::<usize>(), replacement).prop_map(|(k, v)| Mutation::DuplicateKey(k, v)),
        2 => (any::<usize>(), any::<usize>()).prop_map(|(k, i)| Mutation::Remove(k, i)),
        4 => (any::<usize>(), prop::sample::select(vec!["1", "-1", "0.5", "-0.5", "1/3", "-1/256", "1/65536", "8", "-8"]))
            .prop_map(|(k, d)| Mutation::Nudge(k, d.to_owned())),
    ]
}

/// A marker string that stands for raw JSON text while a `Value` is
/// serialized, so that replacements keep their exact spelling (numbers
/// with huge exponents, duplicate keys).
const MARK: &str = "\u{1}RAW\u{1}";

fn marked() -> String {
    serde_json::to_string(MARK).unwrap()
}

/// The k-th value of `v` in document order (k modulo the count).
fn nth_value(v: &mut Value, k: usize) -> &mut Value {
    fn count(v: &Value) -> usize {
        1 + match v {
            Value::Array(a) => a.iter().map(count).sum(),
            Value::Object(o) => o.values().map(count).sum(),
            _ => 0,
        }
    }
    fn find(v: &mut Value, k: usize) -> &mut Value {
        if k == 0 {
            return v;
        }
        let mut k = k - 1;
        let children: Vec<&mut Value> = match v {
            Value::Array(a) => a.iter_mut().collect(),
            Value::Object(o) => o.values_mut().collect(),
            _ => unreachable!("k is below the count"),
        };
        for child in children {
            let n = count(child);
            if k < n {
                return find(child, k);
            }
            k -= n;
        }
        unreachable!("k is below the count")
    }
    let k = k % count(v);
    find(v, k)
}

/// Applies a mutation. Text mutations may split a multi-byte character;
/// the bytes are then read lossily, as a file of bad UTF-8 would not reach
/// the reader anyway.
pub(crate) fn mutate(text: &str, m: &Mutation) -> String {
    let bytes = text.as_bytes();
    let at = |i: usize| i % (bytes.len() + 1);
    let lossy = |b: Vec<u8>| String::from_utf8_lossy(&b).into_owned();
    match m {
        Mutation::FlipByte(i, b) => {
            let mut b2 = bytes.to_vec();
            if !b2.is_empty() {
                let i = i % b2.len();
                b2[i] ^= b.max(&1);
            }
            lossy(b2)
        }
        Mutation::InsertByte(i, b) => {
            let mut b2 = bytes.to_vec();
            b2.insert(at(*i), *b);
            lossy(b2)
        }
        Mutation::DeleteRange(i, n) => {
            let start = at(*i);
            let end = (start + n).min(bytes.len());
            lossy([&bytes[..start], &bytes[end..]].concat())
        }
        Mutation::Truncate(i) => lossy(bytes[..at(*i)].to_vec()),
        Mutation::DuplicateRange(i, n) => {
            let start = at(*i);
            let end = (start + n).min(bytes.len());
            lossy([&bytes[..end], &bytes[start..]].concat())
        }
        Mutation::Replace(k, raw) => with_value(text, |v| {
            *nth_value(v, *k) = Value::String(MARK.to_owned());
            Some(raw.clone())
        }),
        Mutation::DuplicateKey(k, raw) => with_value(text, |v| {
            let Value::Object(o) = nth_value(v, *k) else {
                return None;
            };
            let key = o.keys().next()?.clone();
            // serde_json's map keeps one entry per key: write the duplicate
            // as raw text right after the first.
            let first = o
                .insert(key.clone(), Value::String(MARK.to_owned()))
                .unwrap();
            Some(format!(
                "{}, {}: {raw}",
                first,
                serde_json::to_string(&key).unwrap()
            ))
        }),
        Mutation::Nudge(k, delta) => with_value(text, |v| {
            let mut numbers = Vec::new();
            collect_numbers(v, &mut numbers);
            if numbers.is_empty() {
                return None;
            }
            let n = numbers.swap_remove(k % numbers.len());
            let old = n.to_string();
            *n = Value::String(MARK.to_owned());
            // The sum is exact; write it as a fraction string when the
            // delta is one, as the decimal text otherwise.
            Some(match rastercheck::scene::Number::from_decimal(&old) {
                Ok(x) => {
                    let d = rastercheck::scene::Number::from_string(delta).unwrap();
                    let sum = &x + &d;
                    let s = sum.to_exact_string();
                    if s.contains('/') {
                        format!("\"{s}\"")
                    } else {
                        s
                    }
                }
                Err(_) => old,
            })
        }),
        Mutation::Remove(k, i) => with_value(text, |v| {
            match nth_value(v, *k) {
                Value::Array(a) if !a.is_empty() => {
                    let i = i % a.len();
                    a.remove(i);
                }
                Value::Object(o) if !o.is_empty() => {
                    let key = o.keys().nth(i % o.len()).unwrap().clone();
                    o.remove(&key);
                }
                _ => {}
            }
            None
        }),
    }
}

fn collect_numbers<'v>(v: &'v mut Value, out: &mut Vec<&'v mut Value>) {
    match v {
        Value::Number(_) => out.push(v),
        Value::Array(a) => a.iter_mut().for_each(|c| collect_numbers(c, out)),
        Value::Object(o) => o.values_mut().for_each(|c| collect_numbers(c, out)),
        _ => {}
    }
}

/// Parses `text` as JSON, lets `edit` change it (placing `MARK` where raw
/// text goes), and writes it back. Text that is not JSON is returned as is.
fn with_value(text: &str, edit: impl FnOnce(&mut Value) -> Option<String>) -> String {
    let Ok(mut v) = serde_json::from_str::<Value>(text) else {
        return text.to_owned();
    };
    let raw = edit(&mut v);
    let out = serde_json::to_string_pretty(&v).unwrap();
    match raw {
        Some(raw) => out.replacen(&marked(), &raw, 1),
        None => out,
    }
}

pub(crate) fn mutated_case(texts: Vec<String>) -> impl Strategy<Value = String> {
    (
        prop::sample::select(texts),
        prop::collection::vec(mutation(), 1..4),
    )
        .prop_map(|(text, mutations)| mutations.iter().fold(text, |t, m| mutate(&t, m)))
}
