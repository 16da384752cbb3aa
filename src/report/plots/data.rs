//! What every chart reads from the report: the results measured, the
//! rasterizers in order (their colours), what a chart leaves out, case
//! counts and file-name slugs.

use super::charts::Value;
use crate::report::json::{CaseEntry, MetricsEntry, Report, ResultEntry};

/// The results with metrics of cases that ran.
pub(super) fn measured(
    report: &Report,
) -> impl Iterator<Item = (&CaseEntry, &ResultEntry, &MetricsEntry)> {
    report
        .cases
        .iter()
        .filter(|c| c.status == "ran")
        .flat_map(|c| c.results.iter().map(move |r| (c, r)))
        .filter_map(|(c, r)| Some((c, r, r.metrics.as_ref()?)))
}

/// The rasterizers' names, in the report's order (their colours).
pub(super) fn rasterizers(report: &Report) -> Vec<String> {
    let mut names: Vec<String> = report.rasterizers.iter().map(|r| r.name.clone()).collect();
    for (_, r, _) in measured(report) {
        if !names.contains(&r.rasterizer) {
            names.push(r.rasterizer.clone());
        }
    }
    names
}

/// "1 case", "2 cases".
pub(super) fn cases(n: usize) -> String {
    if n == 1 {
        "1 case".to_owned()
    } else {
        format!("{n} cases")
    }
}

/// What a chart leaves out: rasterizers whose every value is 0, and values
/// that are not finite.
pub(super) fn left_out(series: &[String], values: &[Value], what: &str) -> Vec<String> {
    let mut notes = Vec::new();
    for (s, name) in series.iter().enumerate() {
        let of: Vec<f64> = values
            .iter()
            .filter(|v| v.series == s)
            .map(|v| v.value)
            .collect();
        if !of.is_empty() && of.iter().all(|&v| v == 0.0) {
            notes.push(format!(
                "{name}: zero {what} on every case ({})",
                cases(of.len())
            ));
        }
        let bad = of.iter().filter(|v| !v.is_finite()).count();
        if bad > 0 {
            notes.push(format!("{name}: {bad} non-finite {what} values not drawn"));
        }
    }
    notes
}

/// A file name's part for a rasterizer: letters, digits and `-`.
pub(super) fn slug(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect()
}
