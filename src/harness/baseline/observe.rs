//! What a run observed, in the baseline's terms: the metrics recorded per
//! case and rasterizer (counts and errors by name), and the cases that ran
//! without results. Nothing here compares.

use std::collections::BTreeMap;

use super::entry::{Entry, Value};
use crate::harness::judge::CandidateRun;
use crate::harness::runner::CaseOutcome;
use crate::metrics::Metrics;

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
