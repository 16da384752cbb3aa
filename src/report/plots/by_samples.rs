//! The charts against samples: for each rasterizer with samples (or time
//! samples), the error against their count, one line per pattern.

use super::charts::{self, Curve, Lines, Series};
use super::data::{cases, measured, rasterizers, slug};
use super::plot::Plot;
use crate::report::json::Report;
use crate::scene::samples::Pattern;
use crate::scene::time::TimePattern;

/// Series named after the patterns, in the documented order and then any
/// other names in order of appearance.
pub(super) fn pattern_series(known: &[&str], points: Vec<(String, f64, f64)>) -> Vec<Series> {
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
pub(super) fn default_aa_bound(n: f64) -> f64 {
    0.333 * 0.62f64.powf(n.log2())
}

pub(super) fn aa_against_samples(report: &Report, plots: &mut Vec<Plot>, notes: &mut Vec<String>) {
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

pub(super) fn time_against_samples(
    report: &Report,
    plots: &mut Vec<Plot>,
    notes: &mut Vec<String>,
) {
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
