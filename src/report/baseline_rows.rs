//! A report's rows in a baseline's terms: `baseline check --report` holds
//! the results a report (one run's, or a merge of shards or devices)
//! already has to a baseline, without running anything. Each row of the
//! report (a rasterizer, or in a merged report a rasterizer on one device)
//! is taken under the name it is recorded as in the baseline.

use crate::harness::baseline::{Entry, MetricParts, Observed};
use crate::report::json::{MetricsEntry, Report};

/// The recorded metrics of a report's result: the same names and values a
/// run's `Metrics` give ([`MetricParts`]).
pub fn metrics_of_entry(
    m: &MetricsEntry,
) -> std::collections::BTreeMap<String, crate::harness::baseline::Value> {
    let c = &m.coverage;
    MetricParts {
        coverage: [c.mismatched, c.missing, c.extra, c.wrong_owner],
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
    .recorded()
}

/// What `report` observed, for each `(row, recorded)` pair: row `row` of
/// the report recorded as `recorded`. A case that did not run (unreadable,
/// over a limit, the reference failed, or not run at all: an incomplete
/// report) is a problem with the report's words, as in a run.
pub fn observed(report: &Report, pairs: &[(String, String)]) -> Observed {
    let mut observed = Observed::default();
    for case in &report.cases {
        if let Some(error) = &case.error {
            observed.problems.insert(case.id.clone(), error.clone());
        } else if case.status != "ran" {
            observed.problems.insert(
                case.id.clone(),
                format!("it did not run in the report (status {})", case.status),
            );
        }
        for (row, recorded) in pairs {
            if let Some(result) = case.results.iter().find(|r| &r.rasterizer == row) {
                observed.entries.push(Entry {
                    case: case.id.clone(),
                    rasterizer: recorded.clone(),
                    verdict: result.verdict.to_owned(),
                    metrics: result
                        .metrics
                        .as_ref()
                        .map(metrics_of_entry)
                        .unwrap_or_default(),
                });
            }
        }
    }
    observed
        .entries
        .sort_by(|a, b| (&a.case, &a.rasterizer).cmp(&(&b.case, &b.rasterizer)));
    observed
}

/// The rows of a report, by name, in order.
pub fn rows(report: &Report) -> Vec<String> {
    report.rasterizers.iter().map(|r| r.name.clone()).collect()
}

#[cfg(test)]
mod tests {
    use super::metrics_of_entry;
    use crate::harness::baseline::metrics_of;
    use crate::harness::judge::run_candidate;
    use crate::harness::oracle::run_reference;
    use crate::production::foils::{DdaF32, EmptyAntialias, FloatF32, Truncate};
    use crate::production::Production;
    use crate::rasterizer::Rasterizer;
    use crate::report::json::MetricsEntry;
    use crate::scene::{parse_case, Limits};

    /// A run's metrics and the report's entry for them are read apart (the
    /// harness cannot see the report's types); both must give a baseline
    /// the same names and values, so a baseline holds a report as it holds
    /// the run that wrote it. Over cases with every part a baseline
    /// records: watertight meshes, midpoint lines, channels, antialiasing,
    /// motion.
    #[test]
    fn a_report_entry_records_what_its_run_records() {
        let cases = [
            "clip/mesh_across_near",
            "lines/diamond_colour_interpolation",
            "lines/interpolation_major_linear",
            "antialias/probe_standard4",
            "motion/aa_standard4_time_random",
        ];
        // Production, and foils that miss samples and draw extra ones.
        let candidates: [&dyn Rasterizer; 5] = [
            &Production,
            &DdaF32,
            &FloatF32,
            &Truncate::UNDECLARED,
            &EmptyAntialias,
        ];
        let mut parts = std::collections::BTreeSet::new();
        for case in cases {
            let path = format!("{}/cases/{case}.json", env!("CARGO_MANIFEST_DIR"));
            let text = std::fs::read_to_string(&path).expect("the case file");
            let scene = parse_case(&text, &path, &Limits::default()).expect("a valid case");
            let reference = run_reference(&scene);
            for candidate in candidates {
                let run = run_candidate(&scene, &reference, candidate);
                let Some(m) = &run.metrics else { continue };
                let recorded = metrics_of(m);
                assert_eq!(
                    metrics_of_entry(&MetricsEntry::from_metrics(m)),
                    recorded,
                    "{} on {case}",
                    candidate.name()
                );
                parts.extend(
                    recorded
                        .keys()
                        .map(|k| k.split('.').next().unwrap().to_owned()),
                );
            }
        }
        for part in ["coverage", "watertight", "lines", "antialias", "time"] {
            assert!(parts.contains(part), "no case recorded {part}: {parts:?}");
        }
        assert!(parts.len() > 5, "no channel recorded: {parts:?}");
    }
}
