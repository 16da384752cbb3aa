//! `rastercheck diff OLD NEW`: what changed between two runs, from their
//! `report.json` files (SPEC.md §10.2). The model here is `diff.json`
//! (schema `rastercheck-diff/1`); `diff.md` and `diff.html` are written
//! from it (`render.rs`), so they cannot disagree.
//!
//! `read.rs` reads one report; [`compare`] pairs rasterizers and cases,
//! classifies each result that changed, and measures each metric's move.

pub mod read;
pub mod render;

use std::collections::{BTreeMap, BTreeSet};

use serde::{Serialize, Serializer};

use crate::harness::baseline::Tolerances;
pub use read::{read, Side};

pub const SCHEMA: &str = "rastercheck-diff/1";

/// How a result's state counts: judged good, failing, or not judged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Good,
    Failing,
    Unjudged,
}

/// The kind of a state: a verdict, a case status, or a golden status.
pub fn kind(state: &str) -> Kind {
    match state {
        "pass" | "foil" | "match" => Kind::Good,
        "fail" | "error" | "unreadable" | "reference-failed" | "limit-exceeded" | "differ"
        | "missing" => Kind::Failing,
        // unsupported, not-run, absent
        _ => Kind::Unjudged,
    }
}

/// Where a changed result goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// Good or not judged before, failing now: a regression.
    NewlyFailing,
    /// Judged before (good or failing), not judged now: a regression
    /// (coverage lost).
    NoLongerJudged,
    /// Failing before, good now.
    Fixed,
    /// Failing before and now (the state may have changed).
    StillFailing,
    /// Any other change of state (not judged → good, pass ↔ foil,
    /// unsupported ↔ not-run): not a regression.
    Other,
}

impl Class {
    /// The class of a change of state; `None` when nothing changed.
    pub fn of(old: &str, new: &str) -> Option<Class> {
        use Kind::*;
        Some(match (kind(old), kind(new)) {
            (Good | Unjudged, Failing) => Class::NewlyFailing,
            (Failing, Good) => Class::Fixed,
            (Failing, Failing) => Class::StillFailing,
            (Good | Failing, Unjudged) => Class::NoLongerJudged,
            _ if old == new => return None,
            _ => Class::Other,
        })
    }
}

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
    fn size(&self) -> f64 {
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

/// Pairs the rasterizers: the `explicit` pairs (`--pair OLD=NEW`) first,
/// then equal names; when that pairs nothing, no pair was given and each
/// report has one rasterizer, those two. `Err` names a `--pair` name that
/// is not in its report.
pub fn pair(old: &Side, new: &Side, explicit: &[(String, String)]) -> Result<Vec<Pair>, String> {
    let mut pairs = Vec::new();
    for (o, n) in explicit {
        for (name, side, which) in [(o, old, "OLD"), (n, new, "NEW")] {
            if !side.rasterizers.contains(name) {
                return Err(format!(
                    "--pair {o}={n}: {which} ({}) has no rasterizer {name:?}; it has {}",
                    side.file.display(),
                    side.rasterizers.join(", ")
                ));
            }
        }
        if pairs.iter().any(|p: &Pair| &p.old == o || &p.new == n) {
            return Err(format!("--pair {o}={n}: a rasterizer is paired twice"));
        }
        pairs.push(Pair {
            old: o.clone(),
            new: n.clone(),
            how: "--pair",
        });
    }
    for name in &old.rasterizers {
        let taken = pairs.iter().any(|p| &p.old == name || &p.new == name);
        if !taken && new.rasterizers.contains(name) {
            pairs.push(Pair {
                old: name.clone(),
                new: name.clone(),
                how: "same name",
            });
        }
    }
    if pairs.is_empty() && old.rasterizers.len() == 1 && new.rasterizers.len() == 1 {
        pairs.push(Pair {
            old: old.rasterizers[0].clone(),
            new: new.rasterizers[0].clone(),
            how: "one each",
        });
    }
    Ok(pairs)
}

fn side_info(side: &Side) -> SideInfo {
    SideInfo {
        file: side.file.display().to_string(),
        complete: side.complete,
        rasterizers: side.rasterizers.clone(),
        cases: side.cases.len(),
    }
}

fn case_only(id: &str, side: &Side) -> CaseOnly {
    let case = &side.cases[id];
    CaseOnly {
        case: id.to_owned(),
        results: side
            .rasterizers
            .iter()
            .map(|r| (r.clone(), case.state(r)))
            .collect(),
        golden: case.golden.clone(),
    }
}

/// Compares two reports under the given rasterizer pairs.
pub fn compare(old: &Side, new: &Side, pairs: Vec<Pair>) -> Diff {
    let tolerances = Tolerances::default();
    let old_ids: BTreeSet<&String> = old.cases.keys().collect();
    let new_ids: BTreeSet<&String> = new.cases.keys().collect();
    let mut diff = Diff {
        schema: SCHEMA,
        old: side_info(old),
        new: side_info(new),
        unpaired_old: old
            .rasterizers
            .iter()
            .filter(|r| !pairs.iter().any(|p| &p.old == *r))
            .cloned()
            .collect(),
        unpaired_new: new
            .rasterizers
            .iter()
            .filter(|r| !pairs.iter().any(|p| &p.new == *r))
            .cloned()
            .collect(),
        pairs,
        counts: Counts::default(),
        regression: false,
        newly_failing: Vec::new(),
        no_longer_judged: Vec::new(),
        fixed: Vec::new(),
        still_failing: Vec::new(),
        other_changes: Vec::new(),
        added: new_ids
            .difference(&old_ids)
            .map(|id| case_only(id, new))
            .collect(),
        removed: old_ids
            .difference(&new_ids)
            .map(|id| case_only(id, old))
            .collect(),
        metrics: Vec::new(),
    };
    let mut regressed: BTreeSet<(String, String)> = BTreeSet::new();
    let pairs = diff.pairs.clone();
    for id in old_ids.intersection(&new_ids) {
        let (o, n) = (&old.cases[*id], &new.cases[*id]);
        diff.counts.compared_cases += 1;
        // The golden file is the reference's, one per case.
        if let (Some(og), Some(ng)) = (&o.golden, &n.golden) {
            let change = Change {
                case: (*id).clone(),
                check: "golden",
                rasterizer: None,
                old_rasterizer: None,
                old: og.clone(),
                new: ng.clone(),
                reasons: n.golden_detail.iter().cloned().collect(),
            };
            diff.file(change, &mut regressed);
        }
        for p in &pairs {
            diff.counts.compared_results += 1;
            let (os, ns) = (o.state(&p.old), n.state(&p.new));
            let renamed = (p.old != p.new).then(|| p.old.clone());
            let change = Change {
                case: (*id).clone(),
                check: "verdict",
                rasterizer: Some(p.new.clone()),
                old_rasterizer: renamed.clone(),
                reasons: if kind(&ns) == Kind::Good {
                    o.reasons(&p.old)
                } else {
                    n.reasons(&p.new)
                },
                old: os,
                new: ns,
            };
            diff.file(change, &mut regressed);
            let (Some(or), Some(nr)) = (o.results.get(&p.old), n.results.get(&p.new)) else {
                continue;
            };
            for (metric, &ov) in &or.metrics {
                let Some(&nv) = nr.metrics.get(metric) else {
                    continue;
                };
                let t = tolerances.for_metric(metric);
                let change = if t.worse(ov, nv) {
                    "worse"
                } else if t.worse(nv, ov) {
                    "better"
                } else {
                    continue;
                };
                if change == "worse" {
                    diff.counts.metrics_worse += 1;
                    regressed.insert(((*id).clone(), p.new.clone()));
                } else {
                    diff.counts.metrics_better += 1;
                }
                diff.metrics.push(MetricDelta {
                    case: (*id).clone(),
                    rasterizer: p.new.clone(),
                    old_rasterizer: renamed.clone(),
                    metric: metric.clone(),
                    old: ov,
                    new: nv,
                    delta: nv - ov,
                    change,
                });
            }
        }
    }
    diff.metrics.sort_by(|a, b| {
        (a.change != "worse")
            .cmp(&(b.change != "worse"))
            .then(b.size().total_cmp(&a.size()))
            .then(b.delta.abs().total_cmp(&a.delta.abs()))
            .then((&a.case, &a.rasterizer, &a.metric).cmp(&(&b.case, &b.rasterizer, &b.metric)))
    });
    let c = &mut diff.counts;
    c.added = diff.added.len();
    c.removed = diff.removed.len();
    c.newly_failing = diff.newly_failing.len();
    c.no_longer_judged = diff.no_longer_judged.len();
    c.fixed = diff.fixed.len();
    c.still_failing = diff.still_failing.len();
    c.other_changes = diff.other_changes.len();
    c.regressed_results = regressed.len();
    diff.regression = !regressed.is_empty();
    diff
}

impl Diff {
    /// Files a change of state under its class.
    fn file(&mut self, change: Change, regressed: &mut BTreeSet<(String, String)>) {
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
