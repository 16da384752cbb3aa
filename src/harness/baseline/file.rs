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

use std::collections::BTreeSet;
use std::path::Path;

use serde::{Deserialize, Serialize};

use super::entry::Entry;
use super::observe::Observed;
use super::tolerance::Tolerances;
use crate::harness::runner::Selection;

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

const VERDICTS: [&str; 6] = ["pass", "fail", "foil", "unsupported", "error", "flaky"];

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
