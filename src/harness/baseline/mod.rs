//! Baselines: the accuracy metrics of a run, recorded per case and
//! rasterizer, so that a later run can be held to them. A rasterizer that is
//! not exact (an antialiasing method, a GPU driver, a float foil) may be
//! imperfect, but it must not get worse.
//!
//! # The file: `rastercheck-baseline/1`
//!
//! ```json
//! {
//!   "schema": "rastercheck-baseline/1",
//!   "tool": {"name": "rastercheck", "version": "0.1.0"},
//!   "command": ["baseline", "save", "base.json", "cases/lines", "-r", "dda-f32"],
//!   "selection": {"paths": ["cases/lines"], "filter": null, "family": null},
//!   "rasterizers": ["dda-f32"],
//!   "tolerance": {
//!     "counts": {"relative": 0.0, "absolute": 0.0},
//!     "errors": {"relative": 0.01, "absolute": 1e-9},
//!     "overrides": {}
//!   },
//!   "results": [
//!     {
//!       "case": "lines/midpoint_worked_example",
//!       "rasterizer": "dda-f32",
//!       "verdict": "foil",
//!       "metrics": {"coverage.extra": 6, "coverage.mismatched": 12, "...": 0}
//!     }
//!   ]
//! }
//! ```
//!
//! - `selection`: what `baseline save` ran; `baseline check` runs the same
//!   unless told otherwise.
//! - `results`: one entry per case and rasterizer, sorted by case then
//!   rasterizer. `verdict` is `pass`, `fail`, `foil` (a foil's departure),
//!   `unsupported` or `error`; `metrics` is absent when nothing was drawn
//!   (`unsupported`, `error`).
//! - Metric names: `coverage.mismatched`, `coverage.missing`,
//!   `coverage.extra`, `coverage.wrong_owner`, `watertight.holes`,
//!   `watertight.overdraw` (mesh cases), `lines.crowded_steps` (cases with
//!   midpoint lines), `<channel>.max_abs`, `<channel>.rms` per
//!   interpolation channel (`depth`, `attribute 0`, ...), and for
//!   antialiased cases `antialias.max_error`, `antialias.rms_edge`,
//!   `antialias.rms_all` (resolved coverage against the exact area) and
//!   `antialias.piglit_violations`, `antialias.resolve_mismatches`,
//!   `antialias.invalid_values`, and for scenes in which something moves
//!   `time.max_error`, `time.rms_moving`, `time.rms_all` and
//!   `time.abs_bias` (|mean signed error| over moving pixels: a bias
//!   either way is worse the larger it is) and `time.invalid_values`.
//!   Lower is better for every one. Counts are integers; errors are
//!   numbers, or `"inf"` for an error that was not a number (NaN).
//! - `tolerance`: a metric **regresses** when
//!   `new > old · (1 + relative) + absolute`, and **improves** when
//!   `old > new · (1 + relative) + absolute`. `counts` applies to the count
//!   metrics, `errors` to `max_abs`, `rms`, the antialiasing errors
//!   (`max_error`, `rms_edge`, `rms_all`) and the time errors (`max_error`,
//!   `rms_moving`, `rms_all`, `abs_bias`); `overrides` maps a metric
//!   name (`"depth.max_abs"`) or a metric kind after the last dot
//!   (`"rms"`, `"mismatched"`) to its own tolerance. Edit them by hand.
//! - A verdict regresses when it gets worse on the scale pass = foil <
//!   fail < error; a result in the baseline that no longer runs (its case
//!   is gone or unreadable, its rasterizer reports it unsupported now, the
//!   reference fails on it) regresses too. A result that is not in the
//!   baseline is reported as new and is not a failure.
//!
//! The file is written sorted and without timestamps, so it diffs cleanly.
//!
//! This file holds the file model, its tolerances, and loading and saving;
//! `observe.rs` turns a run's outcomes into entries, `compare.rs` holds a
//! run to a baseline and words what moved.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::harness::runner::Selection;

mod compare;
mod observe;

pub use compare::{Change, Comparison, Finding};
pub use observe::{metrics_of, Observed};

pub const SCHEMA: &str = "rastercheck-baseline/1";

/// A recorded baseline: the model of the JSON file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Baseline {
    pub schema: String,
    pub tool: Tool,
    /// The command line that saved it.
    pub command: Vec<String>,
    pub selection: SelectionInfo,
    /// The rasterizers recorded, sorted.
    pub rasterizers: Vec<String>,
    pub tolerance: Tolerances,
    /// Sorted by case, then rasterizer.
    pub results: Vec<Entry>,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tool {
    pub name: String,
    pub version: String,
}

/// What `baseline save` ran: case paths as given, and the selection.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SelectionInfo {
    pub paths: Vec<String>,
    pub filter: Option<String>,
    pub family: Option<String>,
}

impl SelectionInfo {
    /// The runner's selection (no shard: a baseline covers every case).
    pub fn selection(&self) -> Selection {
        Selection {
            filter: self.filter.clone(),
            family: self.family.clone(),
            shard: None,
        }
    }
}

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

    fn check(&self) -> Result<(), String> {
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

const VERDICTS: [&str; 5] = ["pass", "fail", "foil", "unsupported", "error"];

impl Baseline {
    /// A new baseline from what a run observed, with the default
    /// tolerances.
    pub fn new(command: Vec<String>, selection: SelectionInfo, observed: &Observed) -> Baseline {
        let rasterizers: BTreeSet<String> = observed
            .entries
            .iter()
            .map(|e| e.rasterizer.clone())
            .collect();
        let mut results = observed.entries.clone();
        results.sort_by(|a, b| (&a.case, &a.rasterizer).cmp(&(&b.case, &b.rasterizer)));
        Baseline {
            schema: SCHEMA.to_owned(),
            tool: Tool {
                name: "rastercheck".to_owned(),
                version: env!("CARGO_PKG_VERSION").to_owned(),
            },
            command,
            selection,
            rasterizers: rasterizers.into_iter().collect(),
            tolerance: Tolerances::default(),
            results,
        }
    }

    /// Pretty JSON with a final newline.
    pub fn to_json(&self) -> String {
        let mut text = serde_json::to_string_pretty(self).expect("a baseline serializes");
        text.push('\n');
        text
    }

    /// Parses and checks a baseline; errors do not name the file (see
    /// [`Baseline::load`]).
    pub fn parse(text: &str) -> Result<Baseline, String> {
        let b: Baseline = serde_json::from_str(text).map_err(|e| {
            let schema = serde_json::from_str::<serde_json::Value>(text)
                .ok()
                .and_then(|v| v.get("schema").and_then(|s| s.as_str()).map(str::to_owned));
            match schema {
                Some(s) if s != SCHEMA => {
                    format!("schema {s:?} is not {SCHEMA:?}, the one this version reads")
                }
                _ => format!("not a {SCHEMA} file: {e}"),
            }
        })?;
        if b.schema != SCHEMA {
            return Err(format!(
                "schema {:?} is not {SCHEMA:?}, the one this version reads",
                b.schema
            ));
        }
        b.tolerance.check()?;
        let mut seen = BTreeSet::new();
        for e in &b.results {
            if !VERDICTS.contains(&e.verdict.as_str()) {
                return Err(format!(
                    "result {} on {}: unknown verdict {:?} (one of {})",
                    e.case,
                    e.rasterizer,
                    e.verdict,
                    VERDICTS.join(", ")
                ));
            }
            if !seen.insert((&e.case, &e.rasterizer)) {
                return Err(format!(
                    "result {} on {} is recorded twice",
                    e.case, e.rasterizer
                ));
            }
            if !b.rasterizers.contains(&e.rasterizer) {
                return Err(format!(
                    "result {} names rasterizer {:?}, which is not in \"rasterizers\"",
                    e.case, e.rasterizer
                ));
            }
        }
        Ok(b)
    }

    /// Reads a baseline file; every error names the file.
    pub fn load(path: &Path) -> Result<Baseline, String> {
        let shown = path.display();
        let text = std::fs::read_to_string(path)
            .map_err(|e| format!("{shown}: cannot read the baseline: {e}"))?;
        Baseline::parse(&text).map_err(|e| format!("{shown}: {e}"))
    }

    /// Writes the file (creating its folder).
    pub fn save(&self, path: &Path) -> Result<(), String> {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        }
        std::fs::write(path, self.to_json()).map_err(|e| format!("{}: {e}", path.display()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(super) fn entry(case: &str, verdict: &str, metrics: &[(&str, f64)]) -> Entry {
        Entry {
            case: case.into(),
            rasterizer: "r".into(),
            verdict: verdict.into(),
            metrics: metrics
                .iter()
                .map(|(k, v)| ((*k).to_owned(), Value(*v)))
                .collect(),
        }
    }

    pub(super) fn baseline(entries: Vec<Entry>) -> Baseline {
        Baseline::new(
            vec!["baseline".into()],
            SelectionInfo::default(),
            &Observed {
                entries,
                problems: BTreeMap::new(),
            },
        )
    }

    #[test]
    fn the_file_round_trips_and_is_checked() {
        let b = baseline(vec![entry(
            "a",
            "foil",
            &[
                ("coverage.extra", 2.0),
                ("depth.rms", 1.5e-7),
                ("depth.max_abs", f64::INFINITY),
            ],
        )]);
        let text = b.to_json();
        assert!(text.contains("\"coverage.extra\": 2,"), "{text}");
        assert!(text.contains("\"depth.max_abs\": \"inf\""), "{text}");
        assert_eq!(Baseline::parse(&text).unwrap(), b);
        assert_eq!(b.to_json(), Baseline::parse(&text).unwrap().to_json());

        let bad = text.replace("\"relative\": 0.01", "\"relative\": -1");
        assert!(Baseline::parse(&bad).unwrap_err().contains("relative"));
        let bad = text.replace(SCHEMA, "rastercheck-baseline/9");
        assert!(Baseline::parse(&bad)
            .unwrap_err()
            .contains("rastercheck-baseline/9"));
        let bad = text.replace("\"foil\"", "\"fine\"");
        assert!(Baseline::parse(&bad)
            .unwrap_err()
            .contains("unknown verdict"));
        assert!(Baseline::parse("{").unwrap_err().contains(SCHEMA));
    }

    #[test]
    fn overrides_apply_by_name_then_kind() {
        let mut t = Tolerances::default();
        t.overrides.insert(
            "rms".into(),
            Tolerance {
                relative: 1.0,
                absolute: 0.0,
            },
        );
        t.overrides.insert(
            "depth.rms".into(),
            Tolerance {
                relative: 2.0,
                absolute: 0.0,
            },
        );
        assert_eq!(t.for_metric("attribute 0.rms").relative, 1.0);
        assert_eq!(t.for_metric("depth.rms").relative, 2.0);
        assert_eq!(t.for_metric("depth.max_abs").relative, 0.01);
        assert_eq!(t.for_metric("coverage.missing").relative, 0.0);
    }
}
