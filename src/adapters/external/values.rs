//! Numbers and pixels as the protocol's JSON carries them: a number
//! written twice (its nearest f64 and its exact spelling), one item of an
//! answer read as a [`Scalar`] (a number kept as its text, or what else
//! stood there, shortened), a pixel and a whole number read back, and a
//! depth as its format stores it.

use std::fmt;

use serde::de::{self, Deserialize, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde_json::{json, Value};

use super::messages::shorten;
use crate::scene::depth::unorm_value;
use crate::scene::{DepthFormat, Number};

/// A number twice: its nearest f64, and (in the sibling `exact` object) its
/// exact spelling.
pub(super) fn float(n: &Number) -> Value {
    json!(n.to_f64_lossy())
}

pub(super) fn exact(n: &Number) -> Value {
    Value::String(n.to_exact_string())
}

/// A number as a request gives it: (its nearest f64, its exact spelling).
pub(super) fn float_exact(n: &Number) -> (Value, Value) {
    (float(n), exact(n))
}

/// One value of an answer's item (`[x, y, …]`), read without building a
/// `serde_json::Value`: a number as its JSON text (read as an f64 the way
/// `Value::as_f64` reads it, correctly rounded), anything else as a short
/// description for messages. A nested array or object is skipped, not
/// kept: an item costs its few scalars whatever a hostile answer puts in
/// it.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Scalar {
    Number(String),
    Other(String),
}

/// The key under which `serde_json` (with `arbitrary_precision`, as this
/// crate builds it) hands a number to `deserialize_any`: a one-entry map
/// holding the number's text. (`serde_json::number::TOKEN`, private.)
pub(super) const NUMBER_TOKEN: &str = "$serde_json::private::Number";

impl Scalar {
    /// The number, when it is a finite one.
    pub(super) fn as_f64(&self) -> Option<f64> {
        match self {
            Scalar::Number(text) => text.parse::<f64>().ok().filter(|v| v.is_finite()),
            Scalar::Other(_) => None,
        }
    }
}

impl fmt::Display for Scalar {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Scalar::Number(text) | Scalar::Other(text) => f.write_str(&shorten(text)),
        }
    }
}

impl<'de> Deserialize<'de> for Scalar {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Scalar, D::Error> {
        deserializer.deserialize_any(ScalarVisitor)
    }
}

/// [`Scalar`]'s visitor, which a reader of text reuses for what is not a
/// string.
pub(super) struct ScalarVisitor;

impl<'de> Visitor<'de> for ScalarVisitor {
    type Value = Scalar;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E: de::Error>(self, v: bool) -> Result<Scalar, E> {
        Ok(Scalar::Other(v.to_string()))
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Scalar, E> {
        Ok(Scalar::Number(v.to_string()))
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Scalar, E> {
        Ok(Scalar::Number(v.to_string()))
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Scalar, E> {
        Ok(Scalar::Number(v.to_string()))
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<Scalar, E> {
        Ok(Scalar::Other(format!("{:?}", shorten(v))))
    }
    fn visit_unit<E: de::Error>(self) -> Result<Scalar, E> {
        Ok(Scalar::Other("null".to_owned()))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Scalar, A::Error> {
        while seq.next_element::<IgnoredAny>()?.is_some() {}
        Ok(Scalar::Other("an array".to_owned()))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Scalar, A::Error> {
        match map.next_key::<String>()? {
            Some(key) if key == NUMBER_TOKEN => Ok(Scalar::Number(map.next_value::<String>()?)),
            Some(_) => {
                map.next_value::<IgnoredAny>()?;
                while map.next_entry::<IgnoredAny, IgnoredAny>()?.is_some() {}
                Ok(Scalar::Other("an object".to_owned()))
            }
            None => Ok(Scalar::Other("an object".to_owned())),
        }
    }
}

/// A value quoted in a message: a string as it is, anything else as
/// [`Scalar`] shows it; cut at about 80 characters (SPEC.md §8). The
/// second field keeps a string whole (an EXR path).
pub(super) struct Text(pub(super) String, pub(super) Option<String>);

impl<'de> serde::Deserialize<'de> for Text {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Text, D::Error> {
        struct V;
        fn other(s: Scalar) -> Text {
            Text(s.to_string(), None)
        }
        impl<'de> Visitor<'de> for V {
            type Value = Text;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a JSON value")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Text, E> {
                Ok(Text(shorten(v), Some(v.to_owned())))
            }
            fn visit_bool<E: de::Error>(self, v: bool) -> Result<Text, E> {
                ScalarVisitor.visit_bool(v).map(other)
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Text, E> {
                ScalarVisitor.visit_i64(v).map(other)
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Text, E> {
                ScalarVisitor.visit_u64(v).map(other)
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Text, E> {
                ScalarVisitor.visit_f64(v).map(other)
            }
            fn visit_unit<E: de::Error>(self) -> Result<Text, E> {
                ScalarVisitor.visit_unit().map(other)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Text, A::Error> {
                ScalarVisitor.visit_seq(seq).map(other)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Text, A::Error> {
                ScalarVisitor.visit_map(map).map(other)
            }
        }
        deserializer.deserialize_any(V)
    }
}

/// The pixel (x, y) an answer's item starts with, or why it is none of
/// the canvas (`at` names the item's JSON path).
pub(super) fn pixel_of(
    item: &[Scalar],
    (width, height): (u32, u32),
    at: &dyn Fn() -> String,
) -> Result<(u32, u32), String> {
    match (whole_below(&item[0], width), whole_below(&item[1], height)) {
        (Some(x), Some(y)) => Ok((x, y)),
        _ => Err(format!(
            "{}: ({}, {}) is not a pixel of the {width}×{height} canvas",
            at(),
            item[0],
            item[1]
        )),
    }
}

/// A whole number in [0, limit), as an answer gives it.
pub(super) fn whole_below(v: &Scalar, limit: u32) -> Option<u32> {
    v.as_f64().and_then(|c| whole_f64_below(c, limit))
}

fn whole_f64_below(c: f64, limit: u32) -> Option<u32> {
    (c.fract() == 0.0 && c >= 0.0 && c < f64::from(limit)).then_some(c as u32)
}

/// A depth an answer gives, as the case's format stores it (SPEC.md
/// §12.10): under unorm n the stored integer k in [0, 2^n − 1], read back
/// as k/(2^n − 1) rounded once to an f32, as a driver's readback is;
/// under float32 any number, stored as its nearest f32; under `exact` the
/// number itself. `None`: not a depth of the format.
pub(super) fn stored_depth(value: f64, format: DepthFormat) -> Option<f64> {
    match format {
        DepthFormat::Exact => Some(value),
        DepthFormat::Float32 => Some(f64::from(value as f32)),
        DepthFormat::Unorm16 | DepthFormat::Unorm24 => {
            let bits = format.unorm_bits()?;
            let k = whole_f64_below(value, 1 << bits)?;
            Some(f64::from(unorm_value(k, bits)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_depth_is_read_back_as_its_format_stores_it() {
        let half = stored_depth(32768.0, DepthFormat::Unorm16).unwrap();
        assert_eq!(half, f64::from(unorm_value(32768, 16)));
        assert_eq!(stored_depth(65535.0, DepthFormat::Unorm16), Some(1.0));
        // Not a stored integer of the format: refused.
        assert_eq!(stored_depth(0.5, DepthFormat::Unorm16), None);
        assert_eq!(stored_depth(65536.0, DepthFormat::Unorm16), None);
        assert_eq!(stored_depth(-1.0, DepthFormat::Unorm24), None);
        assert!(stored_depth(16_777_215.0, DepthFormat::Unorm24).is_some());
        // float32: the nearest f32; exact: the number itself.
        assert_eq!(
            stored_depth(0.1, DepthFormat::Float32),
            Some(f64::from(0.1f32))
        );
        assert_eq!(stored_depth(0.1, DepthFormat::Exact), Some(0.1));
    }
}
