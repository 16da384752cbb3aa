//! The model of `diff.json` (schema `rastercheck-diff/1`): the sides, the
//! rasterizer pairs, the counts, each change of state under its class, and
//! each metric's move; `diff.md` and `diff.html` are written from it.

use std::collections::{BTreeMap, BTreeSet};

use serde::{Serialize, Serializer};

use super::class::{kind, Class, Kind};

pub const SCHEMA: &str = "rastercheck-diff/1";

/// Serializes a metric value: a number, or `"inf"` when not finite.
fn finite_or_inf<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    if v.is_finite() {
        s.serialize_f64(*v)
    } else {
        s.serialize_str(if *v < 0.0 { "-inf" } else { "inf" })
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct Diff {
    pub schema: &'static str,
    pub old: SideInfo,
    pub new: SideInfo,
    /// The rasterizers compared, old name → new name.
    pub pairs: Vec<Pair>,
    /// Rasterizers of one report that nothing was paired with: not compared.
    pub unpaired_old: Vec<String>,
    pub unpaired_new: Vec<String>,
    pub counts: Counts,
    /// Whether anything regressed: `diff` exits 1.
    pub regression: bool,
    pub newly_failing: Vec<Change>,
    pub no_longer_judged: Vec<Change>,
    pub fixed: Vec<Change>,
    pub still_failing: Vec<Change>,
    pub other_changes: Vec<Change>,
    /// Cases only in NEW / only in OLD, with their states there.
    pub added: Vec<CaseOnly>,
    pub removed: Vec<CaseOnly>,
    /// Metrics beyond their tolerance: worse ones first, worst first; then
    /// better ones, best first.
    pub metrics: Vec<MetricDelta>,
}

#[derive(Clone, Debug, Serialize)]
pub struct SideInfo {
    pub file: String,
    pub complete: bool,
    pub rasterizers: Vec<String>,
    pub cases: usize,
}

#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Pair {
    pub old: String,
    pub new: String,
    /// `same name`, `one each` (each report has one rasterizer) or `--pair`.
    pub how: &'static str,
}

#[derive(Clone, Debug, Default, Serialize)]
pub struct Counts {
    /// Cases in both reports.
    pub compared_cases: usize,
    /// Results (case × rasterizer pair) compared.
    pub compared_results: usize,
    pub added: usize,
    pub removed: usize,
    pub newly_failing: usize,
    pub no_longer_judged: usize,
    pub fixed: usize,
    pub still_failing: usize,
    pub other_changes: usize,
    pub metrics_worse: usize,
    pub metrics_better: usize,
    /// Results (or golden checks) with at least one regression.
    pub regressed_results: usize,
}

/// One result (or one case's golden check) whose state changed.
#[derive(Clone, Debug, Serialize)]
pub struct Change {
    pub case: String,
    /// `verdict` (a rasterizer's result) or `golden` (the case's golden file).
    pub check: &'static str,
    /// The rasterizer's name in NEW (verdict changes only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rasterizer: Option<String>,
    /// Its name in OLD, when it differs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old_rasterizer: Option<String>,
    pub old: String,
    pub new: String,
    /// Why: NEW's reasons when it is not good, else OLD's.
    pub reasons: Vec<String>,
}

impl Change {
    /// The rasterizer as people read it: `production`, or `old → new`.
    pub fn who(&self) -> String {
        match (&self.old_rasterizer, &self.rasterizer) {
            (Some(o), Some(n)) => format!("{o} → {n}"),
            (None, Some(n)) => n.clone(),
            _ => "golden file".to_owned(),
        }
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct CaseOnly {
    pub case: String,
    /// Per rasterizer of that report: its state (verdict, or case status).
    pub results: BTreeMap<String, String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub golden: Option<String>,
}

impl CaseOnly {
    /// Whether any of its results is failing.
    pub fn failing(&self) -> bool {
        self.results
            .values()
            .chain(self.golden.iter())
            .any(|s| kind(s) == Kind::Failing)
    }
}

#[derive(Clone, Debug, Serialize)]
pub struct MetricDelta {
    pub case: String,
    pub rasterizer: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub old_rasterizer: Option<String>,
    pub metric: String,
    #[serde(serialize_with = "finite_or_inf")]
    pub old: f64,
    #[serde(serialize_with = "finite_or_inf")]
    pub new: f64,
    /// new − old.
    #[serde(serialize_with = "finite_or_inf")]
    pub delta: f64,
    /// `worse` or `better` (metrics within their tolerance are not listed).
    pub change: &'static str,
}

impl MetricDelta {
    pub fn who(&self) -> String {
        match &self.old_rasterizer {
            Some(o) => format!("{o} → {}", self.rasterizer),
            None => self.rasterizer.clone(),
        }
    }

    /// How much worse (or better), as a ratio of the larger value to the
    /// smaller one: infinite from 0. Larger first.
    pub(super) fn size(&self) -> f64 {
        let (lo, hi) = if self.change == "worse" {
            (self.old, self.new)
        } else {
            (self.new, self.old)
        };
        if lo > 0.0 {
            hi / lo
        } else {
            f64::INFINITY
        }
    }
}

impl Diff {
    /// Files a change of state under its class.
    pub(super) fn file(&mut self, change: Change, regressed: &mut BTreeSet<(String, String)>) {
        let Some(class) = Class::of(&change.old, &change.new) else {
            return;
        };
        if matches!(class, Class::NewlyFailing | Class::NoLongerJudged) {
            let who = change.rasterizer.clone().unwrap_or_default();
            regressed.insert((change.case.clone(), who));
        }
        match class {
            Class::NewlyFailing => self.newly_failing.push(change),
            Class::NoLongerJudged => self.no_longer_judged.push(change),
            Class::Fixed => self.fixed.push(change),
            Class::StillFailing => self.still_failing.push(change),
            Class::Other => self.other_changes.push(change),
        }
    }

    /// Whether anything was compared: a case in both reports and a pair of
    /// rasterizers.
    pub fn judged(&self) -> bool {
        self.counts.compared_cases > 0 && !self.pairs.is_empty()
    }

    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("the diff serializes")
    }
}
