//! `plots/*.svg`: accuracy charts, computed from the report model alone (so
//! they work for any rasterizer) and written as standalone SVG:
//!
//! - `aa-error-by-family.svg`: per family, the distribution of each
//!   rasterizer's antialiasing error (edge RMS of resolved − exact area);
//! - `interpolation-ulp-by-family.svg`: per family, the distribution of
//!   each rasterizer's interpolation error in ulp (largest over channels);
//! - `aa-error-vs-samples-<rasterizer>.svg`: for a rasterizer with
//!   samples, antialiasing error against samples per pixel, one line per
//!   sample pattern;
//! - `time-error-vs-samples-<rasterizer>.svg`: for a rasterizer with
//!   moving scenes, time-coverage error against time samples, one line per
//!   time pattern.
//!
//! A chart without data is not drawn; one whose every value is 0 neither,
//! and [`notes`] says so instead.

pub mod charts;
pub mod svg;

use std::path::{Path, PathBuf};

use charts::{Curve, Distribution, Lines, Series, Value};

use super::json::{CaseEntry, MetricsEntry, Report, ResultEntry};
use crate::scene::samples::Pattern;
use crate::scene::time::TimePattern;

/// The folder of the report that holds the charts.
pub const FOLDER: &str = "plots";

/// One chart: its file name (in [`FOLDER`]), a title, a one-line caption
/// saying what it aggregates, and the SVG document.
#[derive(Clone, Debug)]
pub struct Plot {
    pub file: String,
    pub title: String,
    pub caption: String,
    pub svg: String,
}

/// The results with metrics of cases that ran.
fn measured(report: &Report) -> impl Iterator<Item = (&CaseEntry, &ResultEntry, &MetricsEntry)> {
    report
        .cases
        .iter()
        .filter(|c| c.status == "ran")
        .flat_map(|c| c.results.iter().map(move |r| (c, r)))
        .filter_map(|(c, r)| Some((c, r, r.metrics.as_ref()?)))
}

/// The rasterizers' names, in the report's order (their colours).
fn rasterizers(report: &Report) -> Vec<String> {
    let mut names: Vec<String> = report.rasterizers.iter().map(|r| r.name.clone()).collect();
    for (_, r, _) in measured(report) {
        if !names.contains(&r.rasterizer) {
            names.push(r.rasterizer.clone());
        }
    }
    names
}

/// The antialiasing error of a result: edge RMS (SPEC.md §14.3).
fn aa_error(m: &MetricsEntry) -> Option<f64> {
    m.antialias.as_ref().map(|a| a.rms_edge)
}

/// The interpolation error of a result: the largest `max_ulp` over its
/// channels (depth and attributes).
fn ulp_error(m: &MetricsEntry) -> Option<f64> {
    m.channels
        .iter()
        .map(|c| c.max_ulp)
        .max_by(|a, b| a.total_cmp(b))
}

/// The values of one metric per family and rasterizer.
fn by_family(
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

/// "1 case", "2 cases".
fn cases(n: usize) -> String {
    if n == 1 {
        "1 case".to_owned()
    } else {
        format!("{n} cases")
    }
}

/// What a chart leaves out: rasterizers whose every value is 0, and values
/// that are not finite.
fn left_out(series: &[String], values: &[Value], what: &str) -> Vec<String> {
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

fn distribution_plot(
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

/// A file name's part for a rasterizer: letters, digits and `-`.
fn slug(name: &str) -> String {
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

/// Series named after the patterns, in the documented order and then any
/// other names in order of appearance.
fn pattern_series(known: &[&str], points: Vec<(String, f64, f64)>) -> Vec<Series> {
    let mut names: Vec<String> = known.iter().map(|s| (*s).to_owned()).collect();
    for (p, _, _) in &points {
        if !names.contains(p) {
            names.push(p.clone());
        }
    }
    names
        .into_iter()
        .map(|name| Series {
            points: points
                .iter()
                .filter(|p| p.0 == name)
                .map(|p| (p.1, p.2))
                .collect(),
            label: name,
        })
        .collect()
}

/// Piglit's default RMS bound for N samples (SPEC.md §14.3), as
/// `metrics::antialias::default_rms_bound` but between the powers of two.
fn default_aa_bound(n: f64) -> f64 {
    0.333 * 0.62f64.powf(n.log2())
}

fn aa_against_samples(report: &Report, plots: &mut Vec<Plot>, notes: &mut Vec<String>) {
    let mut area_methods = Vec::new();
    for name in rasterizers(report) {
        let mut points = Vec::new();
        let mut area = Vec::new();
        for (c, r, m) in measured(report) {
            let (Some(a), Some(rules)) = (
                &m.antialias,
                c.rules.as_ref().and_then(|r| r.antialias.as_ref()),
            ) else {
                continue;
            };
            if r.rasterizer != name {
                continue;
            }
            if a.samples == 0 {
                area.push(a.rms_edge);
            } else {
                points.push((rules.pattern.to_owned(), f64::from(a.samples), a.rms_edge));
            }
        }
        if !area.is_empty() && points.is_empty() {
            area_methods.push(format!(
                "{name} (median {:.2e} over {})",
                charts::median(&area),
                cases(area.len())
            ));
        }
        if points.is_empty() {
            continue;
        }
        let title = format!("Antialiasing error against samples: {name}");
        let series = pattern_series(&Pattern::NAMES, points);
        let svg = charts::lines(&Lines {
            title: &title,
            x_label: "samples per pixel",
            y_label: "edge RMS of resolved − exact area",
            series: &series,
            curve: Some(Curve {
                label: "default RMS bound",
                f: &default_aa_bound,
            }),
        });
        match svg {
            Some(svg) => plots.push(Plot {
                file: format!("aa-error-vs-samples-{}.svg", slug(&name)),
                title,
                caption: format!(
                    "{name}: RMS of resolved − exact area over edge pixels against the \
                     candidate's samples per pixel, one line per sample pattern the case asks \
                     for; the line joins the median over the cases at each count, the faint \
                     dots are the cases (they differ from count to count); dashed: the default \
                     bound 0.333·0.62^log2(N)."
                ),
                svg,
            }),
            None => notes.push(format!(
                "{name}: zero antialiasing error at every sample count"
            )),
        }
    }
    if !area_methods.is_empty() {
        notes.push(format!(
            "Area methods (no samples), not in the charts against samples: {}",
            area_methods.join(", ")
        ));
    }
}

fn time_against_samples(report: &Report, plots: &mut Vec<Plot>, notes: &mut Vec<String>) {
    for name in rasterizers(report) {
        let mut points = Vec::new();
        for (c, r, m) in measured(report) {
            let (Some(t), Some(rules)) = (
                &m.time,
                c.rules.as_ref().and_then(|r| r.motion_blur.as_ref()),
            ) else {
                continue;
            };
            if r.rasterizer == name {
                points.push((
                    rules.pattern.to_owned(),
                    f64::from(rules.samples),
                    t.rms_moving,
                ));
            }
        }
        if points.is_empty() {
            continue;
        }
        let title = format!("Time-coverage error against time samples: {name}");
        let series = pattern_series(&TimePattern::NAMES, points);
        let svg = charts::lines(&Lines {
            title: &title,
            x_label: "time samples per spatial sample (N)",
            y_label: "moving-pixel RMS of candidate − exact",
            series: &series,
            curve: Some(Curve {
                label: "default RMS bound at 1 spatial sample",
                f: &|n| crate::metrics::time::default_rms_bound(1, 1) / n.sqrt(),
            }),
        });
        match svg {
            Some(svg) => plots.push(Plot {
                file: format!("time-error-vs-samples-{}.svg", slug(&name)),
                title,
                caption: format!(
                    "{name}: RMS of time coverage − exact time coverage over moving pixels \
                     (SPEC.md §15.4) against the case's time samples N, one line per time \
                     pattern; the line joins the median over the cases at each count, the \
                     faint dots are the cases (their spatial samples M and scenes differ); \
                     dashed: the default bound 0.75·(M·N)^-1/2 at M = 1."
                ),
                svg,
            }),
            None => notes.push(format!(
                "{name}: zero time-coverage error at every time sample count"
            )),
        }
    }
}

/// Every chart and the notes on what was not drawn.
fn everything(report: &Report) -> (Vec<Plot>, Vec<String>) {
    let mut plots = Vec::new();
    let mut notes = Vec::new();
    let mut add = |r: Result<Plot, Vec<String>>| match r {
        Ok(p) => plots.push(p),
        Err(n) => notes.extend(n),
    };
    add(distribution_plot(
        report,
        "aa-error-by-family.svg",
        "Antialiasing error by family",
        "edge RMS of resolved − exact area",
        "antialiasing error",
        "Per family and rasterizer, each antialiased case's RMS of resolved − exact area over \
         edge pixels (SPEC.md §14.3): box from the lower to the upper quartile, bar at the \
         median, whiskers to the extremes, dots the cases; 0 is exact.",
        aa_error,
    ));
    add(distribution_plot(
        report,
        "interpolation-ulp-by-family.svg",
        "Interpolation error by family",
        "largest error over channels (ulp)",
        "interpolation error",
        "Per family and rasterizer, each case's largest interpolation error in ulp over its \
         depth and attribute channels (max_ulp): box from the lower to the upper quartile, \
         bar at the median, whiskers to the extremes, dots the cases; 0 is exact.",
        ulp_error,
    ));
    aa_against_samples(report, &mut plots, &mut notes);
    time_against_samples(report, &mut plots, &mut notes);
    // Two rasterizers whose names differ only in punctuation.
    let mut seen: Vec<String> = Vec::new();
    for p in &mut plots {
        let stem = p.file.trim_end_matches(".svg").to_owned();
        let mut k = 1;
        while seen.contains(&p.file) {
            k += 1;
            p.file = format!("{stem}-{k}.svg");
        }
        seen.push(p.file.clone());
    }
    (plots, notes)
}

/// The report's charts, in the order they are shown.
pub fn plots(report: &Report) -> Vec<Plot> {
    everything(report).0
}

/// One line each on what the charts leave out: rasterizers with zero error
/// everywhere (drawn as no chart or said in the caption), area methods,
/// values that are not finite.
pub fn notes(report: &Report) -> Vec<String> {
    everything(report).1
}

/// Writes every chart to `DIR/plots/<file>` and returns the paths.
pub fn write(dir: &Path, report: &Report) -> Result<Vec<PathBuf>, String> {
    plots(report)
        .iter()
        .map(|p| {
            crate::report::files::write_file(&dir.join(FOLDER).join(&p.file), p.svg.as_bytes())
        })
        .collect()
}

#[cfg(test)]
mod tests;
