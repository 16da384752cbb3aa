//! One recorded result: a case on a rasterizer, its verdict and metrics,
//! each metric's value written as the file writes it.

use std::collections::BTreeMap;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::tolerance::is_error_metric;

/// One case on one rasterizer.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub case: String,
    pub rasterizer: String,
    /// `pass`, `fail`, `foil`, `unsupported` or `error`.
    pub verdict: String,
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub metrics: BTreeMap<String, Value>,
}

/// A metric's value. Counts are written as integers, errors as numbers;
/// infinity (an error that was NaN) as the string `"inf"`.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Value(pub f64);

impl Serialize for Value {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let v = self.0;
        if v.is_infinite() && v > 0.0 {
            s.serialize_str("inf")
        } else if v.fract() == 0.0 && (0.0..9.007_199_254_740_992e15).contains(&v) {
            s.serialize_u64(v as u64)
        } else {
            s.serialize_f64(v)
        }
    }
}

impl<'de> Deserialize<'de> for Value {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Value, D::Error> {
        use serde::de::Error;
        // Through `serde_json::Value`, which understands the
        // arbitrary-precision numbers this crate enables.
        match serde_json::Value::deserialize(d)? {
            serde_json::Value::Number(n) => match n.as_f64() {
                Some(v) if v.is_finite() && v >= 0.0 => Ok(Value(v)),
                _ => Err(D::Error::custom(format!(
                    "a metric must be a finite number ≥ 0 or \"inf\", got {n}"
                ))),
            },
            serde_json::Value::String(s) if s == "inf" => Ok(Value(f64::INFINITY)),
            other => Err(D::Error::custom(format!(
                "a metric must be a number ≥ 0 or \"inf\", got {other}"
            ))),
        }
    }
}

impl Value {
    /// As shown in `old → new`.
    pub(super) fn show(&self, metric: &str) -> String {
        if self.0.is_infinite() {
            "inf".to_owned()
        } else if is_error_metric(metric) && self.0 != 0.0 {
            format!("{:e}", self.0)
        } else {
            format!("{}", self.0)
        }
    }
}
