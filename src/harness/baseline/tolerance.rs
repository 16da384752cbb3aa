//! How far a baseline's metric may move before it counts as changed: the
//! tolerances for counts and errors, and their overrides by name or kind.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

/// How far a metric may move before it counts as changed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tolerance {
    pub relative: f64,
    pub absolute: f64,
}

impl Tolerance {
    /// Whether `new` is worse than `old` beyond this tolerance.
    pub fn worse(&self, old: f64, new: f64) -> bool {
        new > old * (1.0 + self.relative) + self.absolute
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tolerances {
    /// For sample and step counts: by default any increase regresses.
    pub counts: Tolerance,
    /// For interpolation errors (`max_abs`, `rms`): by default 1 % plus
    /// 1e-9, so that the last bits of float arithmetic do not flicker.
    pub errors: Tolerance,
    /// Per metric name (`depth.max_abs`) or kind (`rms`); a name wins over
    /// a kind.
    #[serde(default)]
    pub overrides: BTreeMap<String, Tolerance>,
}

impl Default for Tolerances {
    fn default() -> Tolerances {
        Tolerances {
            counts: Tolerance {
                relative: 0.0,
                absolute: 0.0,
            },
            errors: Tolerance {
                relative: 0.01,
                absolute: 1e-9,
            },
            overrides: BTreeMap::new(),
        }
    }
}

impl Tolerances {
    /// The tolerance a metric is held to.
    pub fn for_metric(&self, metric: &str) -> Tolerance {
        let kind = metric.rsplit('.').next().unwrap_or(metric);
        if let Some(t) = self.overrides.get(metric).or(self.overrides.get(kind)) {
            return *t;
        }
        if is_error_metric(metric) {
            self.errors
        } else {
            self.counts
        }
    }

    pub(super) fn check(&self) -> Result<(), String> {
        let all = [("counts", &self.counts), ("errors", &self.errors)]
            .into_iter()
            .chain(self.overrides.iter().map(|(k, t)| (k.as_str(), t)));
        for (name, t) in all {
            for (field, value) in [("relative", t.relative), ("absolute", t.absolute)] {
                if !(value.is_finite() && value >= 0.0) {
                    return Err(format!(
                        "tolerance {name:?}: {field} must be a finite number ≥ 0, got {value}"
                    ));
                }
            }
        }
        Ok(())
    }
}

/// `max_abs`, `rms`, the antialiasing and the time errors are float
/// errors; everything else is a count.
pub fn is_error_metric(metric: &str) -> bool {
    [
        ".max_abs",
        ".rms",
        ".max_error",
        ".rms_edge",
        ".rms_all",
        ".rms_moving",
        ".abs_bias",
    ]
    .iter()
    .any(|kind| metric.ends_with(kind))
}
