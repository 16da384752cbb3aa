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

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::path::Path;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::harness::runner::{CaseOutcome, Selection};
use crate::harness::suite::{CandidateRun, CaseFile};
use crate::metrics::Metrics;

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
    fn show(&self, metric: &str) -> String {
        if self.0.is_infinite() {
            "inf".to_owned()
        } else if is_error_metric(metric) && self.0 != 0.0 {
            format!("{:e}", self.0)
        } else {
            format!("{}", self.0)
        }
    }
}

/// How bad a verdict is: pass = foil < fail < error. `None` for
/// `unsupported` (nothing was drawn) and unknown names.
fn verdict_rank(verdict: &str) -> Option<u8> {
    match verdict {
        "pass" | "foil" => Some(0),
        "fail" => Some(1),
        "error" => Some(2),
        _ => None,
    }
}

const VERDICTS: [&str; 5] = ["pass", "fail", "foil", "unsupported", "error"];

/// The recorded metrics of one candidate on one case.
pub fn metrics_of(m: &Metrics) -> BTreeMap<String, Value> {
    let mut out = BTreeMap::new();
    let mut put = |name: String, v: f64| {
        out.insert(name, Value(if v.is_nan() { f64::INFINITY } else { v }));
    };
    let c = &m.coverage;
    put("coverage.mismatched".into(), c.mismatched() as f64);
    put("coverage.missing".into(), c.missing as f64);
    put("coverage.extra".into(), c.extra as f64);
    put("coverage.wrong_owner".into(), c.wrong_owner as f64);
    if let Some(w) = &m.watertight {
        put("watertight.holes".into(), w.holes as f64);
        put("watertight.overdraw".into(), w.overdraw as f64);
    }
    if let Some(l) = &m.lines {
        put("lines.crowded_steps".into(), l.crowded_steps as f64);
    }
    for ch in &m.channels {
        put(format!("{}.max_abs", ch.channel), ch.max_abs);
        put(format!("{}.rms", ch.channel), ch.rms);
    }
    if let Some(a) = &m.antialias {
        put("antialias.max_error".into(), a.max_error);
        put("antialias.rms_edge".into(), a.rms_edge);
        put("antialias.rms_all".into(), a.rms_all);
        put(
            "antialias.piglit_violations".into(),
            a.piglit_violations as f64,
        );
        put(
            "antialias.resolve_mismatches".into(),
            a.resolve_mismatches as f64,
        );
        put("antialias.invalid_values".into(), a.invalid_values as f64);
    }
    if let Some(t) = &m.time {
        put("time.max_error".into(), t.max_error);
        put("time.rms_moving".into(), t.rms_moving);
        put("time.rms_all".into(), t.rms_all);
        put("time.abs_bias".into(), t.bias_moving.abs());
        put("time.invalid_values".into(), t.invalid_values as f64);
    }
    out
}

impl Entry {
    /// The entry for one candidate's run, recorded under `rasterizer`.
    pub fn from_run(case: &str, rasterizer: &str, run: &CandidateRun, foil: bool) -> Entry {
        Entry {
            case: case.to_owned(),
            rasterizer: rasterizer.to_owned(),
            verdict: run.verdict.recorded_name(foil).to_owned(),
            metrics: run.metrics.as_ref().map(metrics_of).unwrap_or_default(),
        }
    }
}

/// What a run produced, in the baseline's terms.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Observed {
    /// Sorted by case, then rasterizer.
    pub entries: Vec<Entry>,
    /// Cases that ran without results, with why: unreadable, or the
    /// reference failed.
    pub problems: BTreeMap<String, String>,
}

impl Observed {
    /// From a run's outcomes. `recorded[k]` is the name candidate k is
    /// recorded under and `foil[k]` whether it is a foil.
    pub fn from_outcomes(outcomes: &[CaseOutcome], recorded: &[String], foil: &[bool]) -> Observed {
        let mut observed = Observed::default();
        for outcome in outcomes {
            let id = &outcome.file.id;
            if let Some(problem) = &outcome.problem {
                observed.problems.insert(id.clone(), problem.message());
            }
            for ((run, name), &is_foil) in outcome.candidates.iter().zip(recorded).zip(foil) {
                observed
                    .entries
                    .push(Entry::from_run(id, name, run, is_foil));
            }
        }
        observed
            .entries
            .sort_by(|a, b| (&a.case, &a.rasterizer).cmp(&(&b.case, &b.rasterizer)));
        observed
    }
}

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

    /// Compares what a run observed with this baseline. Only baseline
    /// results whose rasterizer is in `rasterizers` (recorded names) and
    /// whose case `selection` keeps are in scope; the shard is ignored.
    pub fn compare(
        &self,
        observed: &Observed,
        rasterizers: &[String],
        selection: &Selection,
    ) -> Comparison {
        let selection = Selection {
            shard: None,
            ..selection.clone()
        };
        let cases: BTreeSet<String> = self.results.iter().map(|e| e.case.clone()).collect();
        let kept: BTreeSet<String> = selection
            .apply(
                cases
                    .into_iter()
                    .map(|id| CaseFile {
                        id,
                        path: Default::default(),
                    })
                    .collect(),
            )
            .into_iter()
            .map(|c| c.id)
            .collect();
        let old: BTreeMap<(&str, &str), &Entry> = self
            .results
            .iter()
            .filter(|e| rasterizers.contains(&e.rasterizer) && kept.contains(&e.case))
            .map(|e| ((e.case.as_str(), e.rasterizer.as_str()), e))
            .collect();
        let new: BTreeMap<(&str, &str), &Entry> = observed
            .entries
            .iter()
            .map(|e| ((e.case.as_str(), e.rasterizer.as_str()), e))
            .collect();
        let keys: BTreeSet<(&str, &str)> = old.keys().chain(new.keys()).copied().collect();
        let mut out = Comparison::default();
        for key @ (case, rasterizer) in keys {
            let finding = |change, metric: &str, old: String, new: String| Finding {
                change,
                case: case.to_owned(),
                rasterizer: rasterizer.to_owned(),
                metric: metric.to_owned(),
                old,
                new,
            };
            match (old.get(&key), new.get(&key)) {
                (None, None) => {}
                (None, Some(_)) => out.new.push((case.to_owned(), rasterizer.to_owned())),
                (Some(o), None) => {
                    out.results += 1;
                    let why = observed
                        .problems
                        .get(case)
                        .cloned()
                        .unwrap_or_else(|| "the case was not found".to_owned());
                    out.findings.push(finding(
                        Change::Regression,
                        "runs",
                        o.verdict.clone(),
                        format!("no longer runs ({why})"),
                    ));
                }
                (Some(o), Some(n)) => {
                    out.results += 1;
                    compare_entry(o, n, &self.tolerance, &mut out, &finding);
                }
            }
        }
        out
    }
}

fn compare_entry(
    o: &Entry,
    n: &Entry,
    tolerance: &Tolerances,
    out: &mut Comparison,
    finding: &dyn Fn(Change, &str, String, String) -> Finding,
) {
    let (was_unsupported, is_unsupported) =
        (o.verdict == "unsupported", n.verdict == "unsupported");
    match (was_unsupported, is_unsupported) {
        (true, true) => {
            out.unchanged += 1;
            return;
        }
        (false, true) => {
            out.findings.push(finding(
                Change::Regression,
                "runs",
                o.verdict.clone(),
                "no longer runs (unsupported)".to_owned(),
            ));
            return;
        }
        (true, false) => {
            out.findings.push(finding(
                Change::Improvement,
                "verdict",
                o.verdict.clone(),
                n.verdict.clone(),
            ));
            return;
        }
        (false, false) => {}
    }
    let (ro, rn) = (verdict_rank(&o.verdict), verdict_rank(&n.verdict));
    let verdict = if rn > ro {
        Some(Change::Regression)
    } else if rn < ro {
        Some(Change::Improvement)
    } else {
        None
    };
    match verdict {
        Some(change) => out.findings.push(finding(
            change,
            "verdict",
            o.verdict.clone(),
            n.verdict.clone(),
        )),
        None => out.unchanged += 1,
    }
    // An error draws nothing: its metrics are absent, not zero.
    if o.verdict == "error" || n.verdict == "error" {
        return;
    }
    for (metric, old) in &o.metrics {
        let Some(new) = n.metrics.get(metric) else {
            out.findings.push(finding(
                Change::Regression,
                metric,
                old.show(metric),
                "not measured".to_owned(),
            ));
            continue;
        };
        let t = tolerance.for_metric(metric);
        let change = if t.worse(old.0, new.0) {
            Change::Regression
        } else if t.worse(new.0, old.0) {
            Change::Improvement
        } else {
            out.unchanged += 1;
            continue;
        };
        out.findings
            .push(finding(change, metric, old.show(metric), new.show(metric)));
    }
    for metric in n.metrics.keys() {
        if !o.metrics.contains_key(metric) {
            out.new_metrics += 1;
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Change {
    Regression,
    Improvement,
}

/// One metric (or the verdict, or whether the case runs) that moved.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Finding {
    pub change: Change,
    pub case: String,
    /// The recorded name.
    pub rasterizer: String,
    /// A metric name, `verdict`, or `runs`.
    pub metric: String,
    pub old: String,
    pub new: String,
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let label = match self.change {
            Change::Regression => "REGRESSION",
            Change::Improvement => "IMPROVED  ",
        };
        write!(
            f,
            "{label}  {}  {}  {}  {} → {}",
            self.case, self.rasterizer, self.metric, self.old, self.new
        )
    }
}

/// The outcome of comparing a run with a baseline.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Comparison {
    /// Sorted by case, rasterizer, then metric order in the file (verdict
    /// first).
    pub findings: Vec<Finding>,
    /// Comparisons (verdicts and metrics) within tolerance.
    pub unchanged: usize,
    /// Baseline results compared (in scope).
    pub results: usize,
    /// Results of this run that the baseline does not have: (case,
    /// recorded rasterizer).
    pub new: Vec<(String, String)>,
    /// Metrics measured now that the baseline does not record.
    pub new_metrics: usize,
}

impl Comparison {
    pub fn regressions(&self) -> usize {
        self.findings
            .iter()
            .filter(|f| f.change == Change::Regression)
            .count()
    }

    pub fn improvements(&self) -> usize {
        self.findings
            .iter()
            .filter(|f| f.change == Change::Improvement)
            .count()
    }

    /// `baseline: N regressions, M improvements, K unchanged (...)`.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "baseline: {} regressions, {} improvements, {} unchanged (verdicts and metrics of {} recorded results)",
            self.regressions(),
            self.improvements(),
            self.unchanged,
            self.results
        );
        if !self.new.is_empty() {
            s.push_str(&format!(
                "; {} new results not in the baseline",
                self.new.len()
            ));
        }
        if self.new_metrics > 0 {
            s.push_str(&format!(
                "; {} metrics not in the baseline",
                self.new_metrics
            ));
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(case: &str, verdict: &str, metrics: &[(&str, f64)]) -> Entry {
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

    fn baseline(entries: Vec<Entry>) -> Baseline {
        Baseline::new(
            vec!["baseline".into()],
            SelectionInfo::default(),
            &Observed {
                entries,
                problems: BTreeMap::new(),
            },
        )
    }

    fn compare(old: Vec<Entry>, new: Vec<Entry>) -> Comparison {
        baseline(old).compare(
            &Observed {
                entries: new,
                problems: BTreeMap::new(),
            },
            &["r".to_owned()],
            &Selection::default(),
        )
    }

    #[test]
    fn counts_regress_on_any_increase_and_errors_beyond_one_percent() {
        let old = vec![entry(
            "a",
            "foil",
            &[("coverage.mismatched", 3.0), ("depth.max_abs", 1e-3)],
        )];
        let same = compare(
            old.clone(),
            vec![entry(
                "a",
                "foil",
                &[("coverage.mismatched", 3.0), ("depth.max_abs", 1.009e-3)],
            )],
        );
        assert_eq!(
            (same.regressions(), same.improvements(), same.unchanged),
            (0, 0, 3)
        );
        let worse = compare(
            old.clone(),
            vec![entry(
                "a",
                "foil",
                &[("coverage.mismatched", 4.0), ("depth.max_abs", 1.02e-3)],
            )],
        );
        assert_eq!(worse.regressions(), 2, "{worse:?}");
        assert_eq!(
            worse.findings[0].to_string(),
            "REGRESSION  a  r  coverage.mismatched  3 → 4"
        );
        let better = compare(
            old,
            vec![entry(
                "a",
                "pass",
                &[("coverage.mismatched", 0.0), ("depth.max_abs", 0.0)],
            )],
        );
        assert_eq!((better.regressions(), better.improvements()), (0, 2));
    }

    #[test]
    fn verdicts_missing_and_new_results() {
        let old = vec![
            entry("a", "pass", &[("coverage.mismatched", 0.0)]),
            entry("b", "foil", &[]),
            entry("c", "pass", &[]),
            entry("d", "unsupported", &[]),
        ];
        let new = vec![
            entry("a", "fail", &[("coverage.mismatched", 0.0)]),
            entry("b", "unsupported", &[]),
            entry("d", "unsupported", &[]),
            entry("e", "pass", &[]),
        ];
        let c = compare(old, new);
        let lines: Vec<String> = c.findings.iter().map(|f| f.to_string()).collect();
        assert_eq!(
            lines,
            [
                "REGRESSION  a  r  verdict  pass → fail",
                "REGRESSION  b  r  runs  foil → no longer runs (unsupported)",
                "REGRESSION  c  r  runs  pass → no longer runs (the case was not found)",
            ]
        );
        assert_eq!(c.new, [("e".to_owned(), "r".to_owned())]);
        assert_eq!(c.unchanged, 2);
        assert_eq!(c.results, 4);
    }

    #[test]
    fn selection_and_rasterizers_limit_the_scope() {
        let b = baseline(vec![
            entry("lines/a", "pass", &[]),
            entry("tri/b", "pass", &[]),
        ]);
        let only_lines = Selection {
            family: Some("lines".into()),
            ..Default::default()
        };
        let observed = Observed {
            entries: vec![entry("lines/a", "pass", &[])],
            problems: BTreeMap::new(),
        };
        let c = b.compare(&observed, &["r".to_owned()], &only_lines);
        assert_eq!((c.regressions(), c.results), (0, 1));
        let c = b.compare(
            &Observed::default(),
            &["other".to_owned()],
            &Selection::default(),
        );
        assert_eq!((c.regressions(), c.results), (0, 0));
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

    #[test]
    fn worse_time_errors_regress() {
        use crate::frame::Frame;
        use crate::metrics;
        let scene = crate::scene::parse_case(
            r#"{"name": "slide", "canvas": {"width": 4, "height": 1},
                "primitives": [{"triangle": [{"from": [0, 0], "to": [2, 0]}, [4, 0], [0, 1]]}],
                "effects": {"motion_blur": {"samples": 16}}}"#,
            "inline.json",
            &crate::scene::Limits::default(),
        )
        .unwrap();
        let reference = Frame::time_only(4, 1, vec![0.25, 0.5, 1.0, 0.0]);
        let recorded = |time: Vec<f64>| {
            let m = metrics::measure(&scene, &reference, &Frame::time_only(4, 1, time), None);
            metrics_of(&m)
        };
        let entry = |metrics| Entry {
            case: "slide".into(),
            rasterizer: "r".into(),
            verdict: "pass".into(),
            metrics,
        };
        let good = recorded(vec![0.3, 0.5, 1.0, 0.0]);
        let names: Vec<&str> = good
            .keys()
            .filter(|k| k.starts_with("time."))
            .map(String::as_str)
            .collect();
        assert_eq!(
            names,
            [
                "time.abs_bias",
                "time.invalid_values",
                "time.max_error",
                "time.rms_all",
                "time.rms_moving"
            ]
        );
        assert!((good["time.max_error"].0 - 0.05).abs() < 1e-15);
        assert!(names
            .iter()
            .all(|n| *n == "time.invalid_values" || is_error_metric(n)));
        let regressed = |old: &BTreeMap<String, Value>, new: &BTreeMap<String, Value>| {
            let mut names: Vec<String> =
                compare(vec![entry(old.clone())], vec![entry(new.clone())])
                    .findings
                    .into_iter()
                    .filter(|f| f.change == Change::Regression)
                    .map(|f| f.metric)
                    .collect();
            names.sort();
            names
        };
        // Worse in every error; the bias flips sign and grows.
        let worse = recorded(vec![0.15, 0.5, 1.0, 0.0]);
        assert_eq!(
            regressed(&good, &worse),
            [
                "time.abs_bias",
                "time.max_error",
                "time.rms_all",
                "time.rms_moving"
            ]
        );
        assert!(regressed(&worse, &good).is_empty());
        // A second error of the opposite sign cancels the bias: the RMS
        // regresses, the bias improves (to 0), the largest error stays.
        let cancelled = recorded(vec![0.3, 0.45, 1.0, 0.0]);
        assert_eq!(cancelled["time.abs_bias"].0, 0.0);
        assert_eq!(
            regressed(&good, &cancelled),
            ["time.rms_all", "time.rms_moving"]
        );
        // A value that is not a number.
        let broken = recorded(vec![f64::NAN, 0.5, 1.0, 0.0]);
        assert_eq!(broken["time.max_error"].0, f64::INFINITY);
        assert!(regressed(&good, &broken).contains(&"time.invalid_values".to_owned()));
    }
}
