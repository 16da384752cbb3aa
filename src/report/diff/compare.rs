//! Two reports compared under the rasterizer pairs: cases in one report
//! only, each result that changed filed under its class, each metric's
//! move.

use std::collections::BTreeSet;

use super::class::{kind, Kind};
use super::model::{CaseOnly, Change, Counts, Diff, MetricDelta, Pair, SideInfo, SCHEMA};
use super::read::Side;
use crate::harness::baseline::Tolerances;

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
