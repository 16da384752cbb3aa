//! What a run observed, in the baseline's terms: the metrics recorded per
//! case and rasterizer (counts and errors by name), and the cases that ran
//! without results. Nothing here compares.

use std::collections::BTreeMap;

use super::entry::{Entry, Value};
use crate::harness::judge::CandidateRun;
use crate::harness::runner::CaseOutcome;
use crate::metrics::antialias::AntialiasMetrics;
use crate::metrics::time::TimeMetrics;
use crate::metrics::Metrics;

/// The parts of a candidate's metrics a baseline records, wherever they
/// come from: a run's [`Metrics`] ([`MetricParts::of`]) or a report's
/// entry (`report/baseline_rows.rs`), so that both give the same names and
/// values.
pub struct MetricParts<'a> {
    /// Coverage: mismatched, missing, extra, wrong owner.
    pub coverage: [u64; 4],
    /// Holes and overdraw.
    pub watertight: Option<[u64; 2]>,
    pub crowded_steps: Option<u64>,
    /// Each channel: name, max_abs, rms.
    pub channels: Vec<(&'a str, f64, f64)>,
    pub antialias: Option<&'a AntialiasMetrics>,
    pub time: Option<&'a TimeMetrics>,
}

impl<'a> MetricParts<'a> {
    pub fn of(m: &'a Metrics) -> MetricParts<'a> {
        let c = &m.coverage;
        MetricParts {
            coverage: [c.mismatched(), c.missing, c.extra, c.wrong_owner],
            watertight: m.watertight.as_ref().map(|w| [w.holes, w.overdraw]),
            crowded_steps: m.lines.as_ref().map(|l| l.crowded_steps),
            channels: m
                .channels
                .iter()
                .map(|ch| (ch.channel.as_str(), ch.max_abs, ch.rms))
                .collect(),
            antialias: m.antialias.as_ref(),
            time: m.time.as_ref(),
        }
    }

    /// The recorded metrics, by name.
    pub fn recorded(&self) -> BTreeMap<String, Value> {
        let mut out = BTreeMap::new();
        let mut put = |name: String, v: f64| {
            out.insert(name, Value(if v.is_nan() { f64::INFINITY } else { v }));
        };
        let [mismatched, missing, extra, wrong_owner] = self.coverage;
        put("coverage.mismatched".into(), mismatched as f64);
        put("coverage.missing".into(), missing as f64);
        put("coverage.extra".into(), extra as f64);
        put("coverage.wrong_owner".into(), wrong_owner as f64);
        if let Some([holes, overdraw]) = self.watertight {
            put("watertight.holes".into(), holes as f64);
            put("watertight.overdraw".into(), overdraw as f64);
        }
        if let Some(crowded_steps) = self.crowded_steps {
            put("lines.crowded_steps".into(), crowded_steps as f64);
        }
        for (channel, max_abs, rms) in &self.channels {
            put(format!("{channel}.max_abs"), *max_abs);
            put(format!("{channel}.rms"), *rms);
        }
        if let Some(a) = self.antialias {
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
        if let Some(t) = self.time {
            put("time.max_error".into(), t.max_error);
            put("time.rms_moving".into(), t.rms_moving);
            put("time.rms_all".into(), t.rms_all);
            put("time.abs_bias".into(), t.bias_moving.abs());
            put("time.invalid_values".into(), t.invalid_values as f64);
        }
        out
    }
}

/// The recorded metrics of one candidate on one case.
pub fn metrics_of(m: &Metrics) -> BTreeMap<String, Value> {
    MetricParts::of(m).recorded()
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
