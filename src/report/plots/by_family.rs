//! The charts by family: per family and rasterizer, the distribution of
//! one metric (antialiasing error, interpolation error in ulp).

use super::charts::{self, Distribution, Value};
use super::data::{left_out, measured, rasterizers};
use super::plot::Plot;
use crate::report::json::{MetricsEntry, Report};

/// The antialiasing error of a result: edge RMS (SPEC.md §14.3).
pub(super) fn aa_error(m: &MetricsEntry) -> Option<f64> {
    m.antialias.as_ref().map(|a| a.rms_edge)
}

/// The interpolation error of a result: the largest `max_ulp` over its
/// channels (depth and attributes).
pub(super) fn ulp_error(m: &MetricsEntry) -> Option<f64> {
    m.channels
        .iter()
        .map(|c| c.max_ulp)
        .max_by(|a, b| a.total_cmp(b))
}

/// The values of one metric per family and rasterizer.
pub(super) fn by_family(
    report: &Report,
    metric: fn(&MetricsEntry) -> Option<f64>,
) -> (Vec<String>, Vec<String>, Vec<Value>) {
    let series = rasterizers(report);
    let mut families: Vec<String> = Vec::new();
    let mut values = Vec::new();
    for (c, r, m) in measured(report) {
        let Some(value) = metric(m) else {
            continue;
        };
        let category = match families.iter().position(|f| *f == c.family) {
            Some(i) => i,
            None => {
                families.push(c.family.clone());
                families.len() - 1
            }
        };
        let s = series
            .iter()
            .position(|n| *n == r.rasterizer)
            .expect("listed");
        values.push(Value {
            category,
            series: s,
            value,
        });
    }
    (families, series, values)
}

pub(super) fn distribution_plot(
    report: &Report,
    file: &str,
    title: &str,
    y_label: &str,
    what: &str,
    caption: &str,
    metric: fn(&MetricsEntry) -> Option<f64>,
) -> Result<Plot, Vec<String>> {
    let (families, series, values) = by_family(report, metric);
    let notes = left_out(&series, &values, what);
    let svg = charts::distribution(&Distribution {
        title,
        y_label,
        categories: &families,
        series: &series,
        values: &values,
    });
    match svg {
        Some(svg) => {
            let mut caption = caption.to_owned();
            for n in &notes {
                caption.push_str(&format!(" {n}."));
            }
            Ok(Plot {
                file: file.to_owned(),
                title: title.to_owned(),
                caption,
                svg,
            })
        }
        None if values.is_empty() => Err(Vec::new()),
        None => Err(notes),
    }
}
