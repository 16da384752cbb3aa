//! Holding a run to a baseline: which recorded results are in scope, each
//! verdict and metric compared under its tolerance, and the findings
//! (regressions and improvements) with the summary line.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

use super::entry::Entry;
use super::file::Baseline;
use super::observe::Observed;
use super::tolerance::Tolerances;
use crate::harness::discover::CaseFile;
use crate::harness::runner::Selection;

impl Baseline {
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

/// How bad a verdict is: pass = foil < fail = flaky < error. `None` for
/// `unsupported` (nothing was drawn) and unknown names.
fn verdict_rank(verdict: &str) -> Option<u8> {
    match verdict {
        "pass" | "foil" => Some(0),
        "fail" | "flaky" => Some(1),
        "error" => Some(2),
        _ => None,
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
    use super::super::tests::{baseline, entry};
    use super::*;
    use crate::harness::baseline::{is_error_metric, metrics_of, Entry, Value};

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
