//! The diff for people: `diff.md` (sized for a pull-request comment: counts
//! first, then tables of at most [`MD_ROWS`] rows), `diff.html` (one
//! self-contained page, every table whole) and the console's summary.

use std::fmt::Write;

use super::model::{CaseOnly, Change, Diff, MetricDelta};
use crate::report::escape::escape;

/// Rows per table in `diff.md`; the rest is counted ("and N more").
pub const MD_ROWS: usize = 50;

/// The most bytes of table rows `diff.md` holds: GitHub takes comments of
/// up to 65 536 characters. Rows past it are counted, not written.
pub const MD_BUDGET: usize = 60_000;

/// Characters of reasons kept per row in `diff.md`.
const MD_REASON: usize = 160;

/// A metric value as people read it.
pub fn number(v: f64) -> String {
    if !v.is_finite() {
        return if v < 0.0 { "-inf" } else { "inf" }.to_owned();
    }
    let a = v.abs();
    if v == v.trunc() && a < 1e9 {
        format!("{v:.0}")
    } else if (0.01..1e5).contains(&a) {
        let s = format!("{v:.4}");
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        format!("{v:.3e}")
    }
}

/// The delta with its sign.
pub fn signed(v: f64) -> String {
    if v > 0.0 {
        format!("+{}", number(v))
    } else {
        number(v)
    }
}

fn cut(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        text.to_owned()
    } else {
        let mut s: String = text.chars().take(max).collect();
        s.push('…');
        s
    }
}

/// One line of counts: what regressed, then the rest.
pub fn headline(d: &Diff) -> String {
    let c = &d.counts;
    format!(
        "{} newly failing, {} no longer judged, {} metrics worse; {} fixed, {} still failing, {} metrics better, {} other changes; {} cases added, {} removed",
        c.newly_failing,
        c.no_longer_judged,
        c.metrics_worse,
        c.fixed,
        c.still_failing,
        c.metrics_better,
        c.other_changes,
        c.added,
        c.removed
    )
}

/// What was compared with what, one line per note.
pub fn notes(d: &Diff) -> Vec<String> {
    let mut notes = Vec::new();
    for p in &d.pairs {
        match p.how {
            "one each" => notes.push(format!(
                "paired rasterizer {} (OLD) with {} (NEW): each report has one",
                p.old, p.new
            )),
            "--pair" => notes.push(format!(
                "paired rasterizer {} (OLD) with {} (NEW): --pair",
                p.old, p.new
            )),
            _ => {}
        }
    }
    if !d.unpaired_old.is_empty() {
        notes.push(format!(
            "not compared, only in OLD: {}",
            d.unpaired_old.join(", ")
        ));
    }
    if !d.unpaired_new.is_empty() {
        notes.push(format!(
            "not compared, only in NEW: {}",
            d.unpaired_new.join(", ")
        ));
    }
    for (side, which) in [(&d.old, "OLD"), (&d.new, "NEW")] {
        if !side.complete {
            notes.push(format!(
                "{which} ({}) is incomplete: its not-run cases are not judged",
                side.file
            ));
        }
    }
    notes.push("times are not compared".to_owned());
    notes
}

fn md_cell(text: &str) -> String {
    text.replace('\\', "\\\\")
        .replace('|', "\\|")
        .replace(['\n', '\r'], " ")
        .replace('<', "&lt;")
}

fn md_table(out: &mut String, title: &str, head: &[&str], rows: Vec<Vec<String>>) {
    if rows.is_empty() {
        return;
    }
    let _ = writeln!(out, "\n### {title} ({})\n", rows.len());
    let _ = writeln!(out, "| {} |", head.join(" | "));
    let _ = writeln!(out, "|{}", "---|".repeat(head.len()));
    let mut written = 0;
    for row in rows.iter().take(MD_ROWS) {
        if out.len() > MD_BUDGET {
            break;
        }
        let cells: Vec<String> = row.iter().map(|c| md_cell(c)).collect();
        let _ = writeln!(out, "| {} |", cells.join(" | "));
        written += 1;
    }
    if rows.len() > written {
        let _ = writeln!(
            out,
            "\nand {} more (diff.html and diff.json list them all)",
            rows.len() - written
        );
    }
}

fn change_rows(changes: &[Change], reason_len: usize) -> Vec<Vec<String>> {
    changes
        .iter()
        .map(|c| {
            vec![
                format!("`{}`", c.case),
                c.who(),
                format!("{} → {}", c.old, c.new),
                cut(&c.reasons.join("; "), reason_len),
            ]
        })
        .collect()
}

fn metric_rows(metrics: &[MetricDelta], change: &str) -> Vec<Vec<String>> {
    metrics
        .iter()
        .filter(|m| m.change == change)
        .map(|m| {
            vec![
                format!("`{}`", m.case),
                m.who(),
                m.metric.clone(),
                number(m.old),
                number(m.new),
                signed(m.delta),
            ]
        })
        .collect()
}

fn only_rows(cases: &[CaseOnly]) -> Vec<Vec<String>> {
    cases
        .iter()
        .map(|c| {
            let mut states: Vec<String> =
                c.results.iter().map(|(r, s)| format!("{r}: {s}")).collect();
            if let Some(g) = &c.golden {
                states.push(format!("golden: {g}"));
            }
            vec![format!("`{}`", c.case), states.join(", ")]
        })
        .collect()
}

const CHANGE_HEAD: [&str; 4] = ["case", "rasterizer", "old → new", "reasons"];
const METRIC_HEAD: [&str; 6] = ["case", "rasterizer", "metric", "old", "new", "delta"];

/// `diff.md`: the verdict, the counts, then one table per kind of change.
pub fn markdown(d: &Diff) -> String {
    let mut out = String::new();
    let verdict = if d.regression {
        "❌ **regression**"
    } else {
        "✅ no regression"
    };
    let _ = writeln!(out, "## rastercheck diff: {verdict}\n");
    let _ = writeln!(
        out,
        "`{}` → `{}`: {} cases compared, {} results\n",
        d.old.file, d.new.file, d.counts.compared_cases, d.counts.compared_results
    );
    let c = &d.counts;
    let _ = writeln!(out, "| | count |\n|---|---|");
    for (name, n) in [
        ("newly failing", c.newly_failing),
        ("no longer judged", c.no_longer_judged),
        ("metrics worse", c.metrics_worse),
        ("fixed", c.fixed),
        ("still failing", c.still_failing),
        ("metrics better", c.metrics_better),
        ("other changes", c.other_changes),
        ("cases added", c.added),
        ("cases removed", c.removed),
    ] {
        let _ = writeln!(out, "| {name} | {n} |");
    }
    let notes = notes(d);
    let _ = writeln!(out);
    for note in notes {
        let _ = writeln!(out, "- {}", md_cell(&note));
    }
    md_table(
        &mut out,
        "Newly failing",
        &CHANGE_HEAD,
        change_rows(&d.newly_failing, MD_REASON),
    );
    md_table(
        &mut out,
        "No longer judged",
        &CHANGE_HEAD,
        change_rows(&d.no_longer_judged, MD_REASON),
    );
    md_table(
        &mut out,
        "Metrics worse, worst first",
        &METRIC_HEAD,
        metric_rows(&d.metrics, "worse"),
    );
    md_table(
        &mut out,
        "Fixed",
        &CHANGE_HEAD,
        change_rows(&d.fixed, MD_REASON),
    );
    md_table(
        &mut out,
        "Metrics better, best first",
        &METRIC_HEAD,
        metric_rows(&d.metrics, "better"),
    );
    md_table(
        &mut out,
        "Cases added",
        &["case", "results"],
        only_rows(&d.added),
    );
    md_table(
        &mut out,
        "Cases removed",
        &["case", "results"],
        only_rows(&d.removed),
    );
    md_table(
        &mut out,
        "Other changes",
        &CHANGE_HEAD,
        change_rows(&d.other_changes, MD_REASON),
    );
    md_table(
        &mut out,
        "Still failing",
        &CHANGE_HEAD,
        change_rows(&d.still_failing, MD_REASON),
    );
    out
}

fn html_table(out: &mut String, title: &str, head: &[&str], rows: Vec<Vec<String>>, class: &str) {
    if rows.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "<h2 class=\"{class}\">{} ({})</h2>\n<table><tr>{}</tr>",
        escape(title),
        rows.len(),
        head.iter()
            .map(|h| format!("<th>{}</th>", escape(h)))
            .collect::<String>()
    );
    for row in rows {
        let cells: String = row
            .iter()
            .map(|c| format!("<td>{}</td>", escape(c.trim_matches('`'))))
            .collect();
        let _ = writeln!(out, "<tr>{cells}</tr>");
    }
    let _ = writeln!(out, "</table>");
}

/// `diff.html`: one self-contained page (no script, no network), every
/// row of every table.
pub fn html(d: &Diff) -> String {
    let mut out = String::new();
    let verdict = if d.regression {
        "regression"
    } else {
        "no regression"
    };
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>rastercheck diff: {verdict}</title><style>\
         body{{font-family:sans-serif;margin:2em}}table{{border-collapse:collapse;margin-bottom:1.5em}}\
         td,th{{border:1px solid #ccc;padding:.2em .5em;text-align:left;vertical-align:top}}\
         td:nth-child(n+4){{font-family:monospace}}.bad{{color:#b00}}.good{{color:#070}}\
         </style></head><body>\n<h1 class=\"{}\">rastercheck diff: {verdict}</h1>\n",
        if d.regression { "bad" } else { "good" }
    );
    let _ = writeln!(
        out,
        "<p>{} → {}: {} cases compared, {} results</p>\n<p>{}</p>\n<ul>",
        escape(&d.old.file),
        escape(&d.new.file),
        d.counts.compared_cases,
        d.counts.compared_results,
        escape(&headline(d))
    );
    for note in notes(d) {
        let _ = writeln!(out, "<li>{}</li>", escape(&note));
    }
    let _ = writeln!(out, "</ul>");
    let all = usize::MAX;
    html_table(
        &mut out,
        "Newly failing",
        &CHANGE_HEAD,
        change_rows(&d.newly_failing, all),
        "bad",
    );
    html_table(
        &mut out,
        "No longer judged",
        &CHANGE_HEAD,
        change_rows(&d.no_longer_judged, all),
        "bad",
    );
    html_table(
        &mut out,
        "Metrics worse, worst first",
        &METRIC_HEAD,
        metric_rows(&d.metrics, "worse"),
        "bad",
    );
    html_table(
        &mut out,
        "Fixed",
        &CHANGE_HEAD,
        change_rows(&d.fixed, all),
        "good",
    );
    html_table(
        &mut out,
        "Metrics better, best first",
        &METRIC_HEAD,
        metric_rows(&d.metrics, "better"),
        "good",
    );
    html_table(
        &mut out,
        "Cases added",
        &["case", "results"],
        only_rows(&d.added),
        "",
    );
    html_table(
        &mut out,
        "Cases removed",
        &["case", "results"],
        only_rows(&d.removed),
        "",
    );
    html_table(
        &mut out,
        "Other changes",
        &CHANGE_HEAD,
        change_rows(&d.other_changes, all),
        "",
    );
    html_table(
        &mut out,
        "Still failing",
        &CHANGE_HEAD,
        change_rows(&d.still_failing, all),
        "",
    );
    let _ = writeln!(out, "</body></html>");
    out
}
