//! The tables of the HTML page: the cell of one result in a family's
//! table (verdict badge and key metrics), and a result card's metrics
//! tables (coverage, watertightness, lines, antialiasing, time coverage,
//! interpolation channels).

use std::fmt::Write as _;

use crate::metrics::time::TimeMetrics;
use crate::report::escape::escape;
use crate::report::json::{ChannelEntry, MetricsEntry, ResultEntry};

pub(super) fn badge(class: &str, text: &str) -> String {
    format!(
        "<span class=\"badge {}\">{}</span>",
        escape(class),
        escape(text)
    )
}

pub(super) fn worst_channel(m: &MetricsEntry) -> Option<&ChannelEntry> {
    m.channels
        .iter()
        .max_by(|a, b| (a.max_abs / a.allowed_abs).total_cmp(&(b.max_abs / b.allowed_abs)))
}

/// The table cell of one result: verdict and key metrics.
pub(super) fn cell(result: &ResultEntry, link: Option<&str>) -> String {
    let mut html = badge(result.verdict, &result.verdict.to_uppercase());
    if let Some(m) = &result.metrics {
        let c = &m.coverage;
        let mut parts = vec![if m.time.is_some() {
            "time coverage".to_owned()
        } else if c.samples == 0 {
            "no samples".to_owned()
        } else {
            format!("{} mismatched", c.mismatched)
        }];
        if let Some(w) = &m.watertight {
            parts.push(format!("{} holes, {} overdraw", w.holes, w.overdraw));
        }
        if let Some(l) = &m.lines {
            if l.crowded_steps > 0 {
                parts.push(format!("{} crowded steps", l.crowded_steps));
            }
        }
        if let Some(a) = &m.antialias {
            parts.push(format!(
                "aa max {:.2e} · edge rms {:.2e}",
                a.max_error, a.rms_edge
            ));
            if a.piglit_violations > 0 {
                parts.push(format!("{} piglit violations", a.piglit_violations));
            }
        }
        if let Some(t) = &m.time {
            parts.push(format!(
                "time max {:.2e} · rms {:.2e}",
                t.max_error, t.rms_moving
            ));
            if t.invalid_values > 0 {
                parts.push(format!("{} invalid values", t.invalid_values));
            }
        }
        if let Some(ch) = worst_channel(m) {
            let ratio = ch.max_abs / ch.allowed_abs;
            let share = if ratio < 0.01 {
                "< 1% of bound".to_owned()
            } else {
                format!("{:.0}% of bound", ratio * 100.0)
            };
            parts.push(format!("interp {:.2e} ({share})", ch.max_abs));
        }
        let _ = write!(
            html,
            "<span class=\"metric\">{}</span>",
            escape(&parts.join(" · "))
        );
    } else if let Some(why) = result.reasons.first() {
        let _ = write!(
            html,
            "<span class=\"metric\" title=\"{}\">{}</span>",
            escape(why),
            escape(&shorten(why, 80))
        );
    }
    if let Some(link) = link {
        let _ = write!(html, " <a href=\"{}\">details</a>", escape(link));
    }
    html
}

pub(super) fn shorten(text: &str, n: usize) -> String {
    let line = text.replace('\n', " ");
    if line.chars().count() > n {
        format!("{}…", line.chars().take(n).collect::<String>())
    } else {
        line
    }
}

pub(super) fn metrics_tables(m: &MetricsEntry) -> String {
    let c = &m.coverage;
    let mut html = String::from("<div class=\"metrics\">");
    let mut rows = vec![
        ("samples", c.samples.to_string()),
        ("reference covers", c.reference_covered.to_string()),
        ("candidate covers", c.candidate_covered.to_string()),
        ("missing", c.missing.to_string()),
        ("extra", c.extra.to_string()),
        ("wrong owner", c.wrong_owner.to_string()),
        ("mismatched", c.mismatched.to_string()),
    ];
    if let Some(w) = &m.watertight {
        rows.push(("mesh interior", w.interior.to_string()));
        rows.push(("holes", w.holes.to_string()));
        rows.push(("overdraw", w.overdraw.to_string()));
    }
    if let Some(l) = &m.lines {
        rows.push(("midpoint lines", l.lines.to_string()));
        rows.push(("crowded steps", l.crowded_steps.to_string()));
    }
    // A moving scene has no samples: its table is the time table alone.
    if m.time.is_none() {
        html.push_str(&name_value_table("coverage", &rows));
    }
    if let Some(a) = &m.antialias {
        let bound = |b: Option<f64>| b.map_or("—".to_owned(), |b| format!("{b:.3e}"));
        let rows = [
            (
                "samples per pixel",
                if a.samples == 0 {
                    "none (area)".to_owned()
                } else {
                    a.samples.to_string()
                },
            ),
            ("edge pixels", format!("{} of {}", a.edge_pixels, a.pixels)),
            (
                "max |error|",
                format!(
                    "{:.3e} at ({}, {})",
                    a.max_error, a.worst_pixel[0], a.worst_pixel[1]
                ),
            ),
            ("bound", bound(a.allowed_error)),
            ("edge RMS", format!("{:.3e}", a.rms_edge)),
            ("RMS bound", bound(a.allowed_rms)),
            ("RMS, all pixels", format!("{:.3e}", a.rms_all)),
            ("edge bias", format!("{:+.3e}", a.bias_edge)),
            (
                "full / empty pixels",
                format!("{} / {}", a.full_pixels, a.empty_pixels),
            ),
            ("piglit violations", a.piglit_violations.to_string()),
            (
                "not their own box resolve",
                a.resolve_mismatches.to_string(),
            ),
            ("not a finite number ≥ 0", a.invalid_values.to_string()),
        ];
        html.push_str(&name_value_table("resolved coverage − exact area", &rows));
    }
    if let Some(t) = &m.time {
        html.push_str(&time_table(t));
    }
    if !m.channels.is_empty() {
        html.push_str("<table><tr><th>channel</th><th class=\"n\">samples</th><th class=\"n\">max |error|</th><th class=\"n\">max ulp</th><th class=\"n\">rms</th><th class=\"n\">bound</th><th class=\"n\">ulp bound</th></tr>");
        for ch in &m.channels {
            let _ = write!(
                html,
                "<tr><td>{}</td><td class=\"n\">{}</td><td class=\"n\">{:.3e}</td><td class=\"n\">{:.1}</td><td class=\"n\">{:.3e}</td><td class=\"n\">{:.3e}</td><td class=\"n\">{}</td></tr>",
                escape(&ch.channel),
                ch.samples,
                ch.max_abs,
                ch.max_ulp,
                ch.rms,
                ch.allowed_abs,
                ch.allowed_ulp.map_or("—".to_owned(), |u| format!("{u}"))
            );
        }
        html.push_str("</table>");
    }
    html.push_str("</div>");
    html
}

/// The time metrics of a moving scene (SPEC.md §15.4).
pub(super) fn time_table(t: &TimeMetrics) -> String {
    let bound = |b: Option<f64>| b.map_or("—".to_owned(), |b| format!("{b:.3e}"));
    let mut rows = vec![
        (
            "moving pixels",
            format!("{} of {}", t.moving_pixels, t.pixels),
        ),
        (
            "max |error|",
            format!(
                "{:.3e} at ({}, {})",
                t.max_error, t.worst_pixel[0], t.worst_pixel[1]
            ),
        ),
        (
            "there: candidate / exact",
            format!("{:.6} / {:.6}", t.worst_candidate, t.worst_exact),
        ),
        ("bound", bound(t.allowed_error)),
        ("moving RMS", format!("{:.3e}", t.rms_moving)),
        ("RMS bound", bound(t.allowed_rms)),
        ("RMS, all pixels", format!("{:.3e}", t.rms_all)),
        ("moving bias", format!("{:+.3e}", t.bias_moving)),
        (
            "nonzero pixels: reference / candidate",
            format!("{} / {}", t.reference_pixels, t.candidate_pixels),
        ),
        ("not a finite number ≥ 0", t.invalid_values.to_string()),
    ];
    if let Some(s) = &t.sample_tests {
        rows.push((
            "sample tests: covered / all",
            format!(
                "{} / {} ({:.1}%)",
                s.covered,
                s.tests,
                s.efficiency() * 100.0
            ),
        ));
    }
    name_value_table("time coverage − exact", &rows)
}

/// A two-column table under one heading: a metric's name, and its value
/// (escaped) right-aligned.
fn name_value_table(heading: &str, rows: &[(&str, String)]) -> String {
    let mut html = format!("<table><tr><th colspan=\"2\">{heading}</th></tr>");
    for (name, value) in rows {
        let _ = write!(
            html,
            "<tr><td>{name}</td><td class=\"n\">{}</td></tr>",
            escape(value)
        );
    }
    html.push_str("</table>");
    html
}
