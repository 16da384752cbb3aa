//! `summary.md`: a short markdown summary that fits a CI job summary:
//! totals, the failures first, then the worst metrics.

use super::json::{CaseEntry, Report, ResultEntry};
use super::limits::{LISTED, LOOKED};

pub fn render(report: &Report) -> String {
    let t = &report.totals;
    let mut md = String::from("# rastercheck\n\n");
    if !report.complete {
        md.push_str(&format!(
            "**The run did not finish: {} cases did not run.**\n\n",
            t.not_run
        ));
    }
    md.push_str(&format!(
        "{} cases; {} unreadable; golden files: {} match, {} differ, {} missing.\n\n",
        t.cases, t.unreadable, t.golden.matching, t.golden.differing, t.golden.missing
    ));
    md.push_str("| rasterizer | pass | fail | foil departures | unsupported | error | flaky |\n|---|---:|---:|---:|---:|---:|---:|\n");
    for v in &t.verdicts {
        let x = &v.tally;
        md.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} |\n",
            v.rasterizer, x.pass, x.fail, x.foil, x.unsupported, x.error, x.flaky
        ));
    }
    let left_out = t.cases.saturating_sub(report.cases.len());
    if left_out > 0 {
        md.push_str(&format!(
            "\nThe lists below are drawn from {} of the {} cases: the first {LISTED} and at most {LOOKED} more worth a look; the other {left_out} are counted above. report.json and junit.xml have every result.\n",
            report.cases.len(),
            t.cases
        ));
    }
    let problems: Vec<&CaseEntry> = report
        .cases
        .iter()
        .filter(|c| c.error.is_some() || c.golden == Some("differ"))
        .collect();
    let failures: Vec<(&CaseEntry, &ResultEntry)> = report
        .cases
        .iter()
        .flat_map(|c| c.results.iter().map(move |r| (c, r)))
        .filter(|(_, r)| matches!(r.verdict, "fail" | "error" | "flaky"))
        .collect();
    if !problems.is_empty() || !failures.is_empty() {
        md.push_str("\n## Failures\n\n");
        for case in problems {
            let why = case
                .error
                .clone()
                .or_else(|| case.golden_detail.clone())
                .unwrap_or_default();
            md.push_str(&format!(
                "- `{}` ({}): {}\n",
                case.id,
                case.status,
                one_line(&why)
            ));
        }
        for (case, result) in &failures {
            md.push_str(&format!(
                "- `{}` **{}** {}: {}\n",
                case.id,
                result.rasterizer,
                result.verdict,
                one_line(&result.reasons.join("; "))
            ));
        }
    }
    let mut worst: Vec<(f64, String)> = report
        .cases
        .iter()
        .flat_map(|c| c.results.iter().map(move |r| (c, r)))
        .filter_map(|(c, r)| {
            let m = r.metrics.as_ref()?;
            let ch = m.channels.iter().max_by(|a, b| {
                (a.max_abs / a.allowed_abs).total_cmp(&(b.max_abs / b.allowed_abs))
            })?;
            Some((
                ch.max_abs / ch.allowed_abs,
                format!(
                    "| `{}` | {} | {} | {:.3e} | {:.1} | {:.3e} |",
                    c.id, r.rasterizer, ch.channel, ch.max_abs, ch.max_ulp, ch.allowed_abs
                ),
            ))
        })
        .collect();
    worst.sort_by(|a, b| b.0.total_cmp(&a.0));
    if !worst.is_empty() {
        md.push_str("\n## Worst interpolation errors\n\n| case | rasterizer | channel | max error | max ulp | bound |\n|---|---|---|---:|---:|---:|\n");
        for (_, row) in worst.iter().take(10) {
            md.push_str(row);
            md.push('\n');
        }
    }
    let mut coverage: Vec<(f64, String)> = report
        .cases
        .iter()
        .flat_map(|c| c.results.iter().map(move |r| (c, r)))
        .filter_map(|(c, r)| {
            let a = r.metrics.as_ref()?.antialias.as_ref()?;
            let bound = a.allowed_rms.map_or("—".to_owned(), |b| format!("{b:.3e}"));
            Some((
                a.rms_edge,
                format!(
                    "| `{}` | {} | {} | {:.3e} | {:.3e} | {:+.2e} | {} | {} |",
                    c.id,
                    r.rasterizer,
                    a.samples,
                    a.max_error,
                    a.rms_edge,
                    a.bias_edge,
                    bound,
                    a.piglit_violations
                ),
            ))
        })
        .collect();
    coverage.sort_by(|a, b| b.0.total_cmp(&a.0));
    if !coverage.is_empty() {
        md.push_str("\n## Worst antialiasing errors\n\n| case | rasterizer | samples | max error | edge RMS | bias | RMS bound | piglit violations |\n|---|---|---:|---:|---:|---:|---:|---:|\n");
        for (_, row) in coverage.iter().take(10) {
            md.push_str(row);
            md.push('\n');
        }
    }
    md.push_str(&time_errors(report));
    md.push_str(&plots(report));
    md
}

/// The charts of `plots/` as images with their captions, and what they
/// leave out.
fn plots(report: &Report) -> String {
    let plots = super::plots::plots(report);
    let notes = super::plots::notes(report);
    let mut md = String::new();
    if plots.is_empty() && notes.is_empty() {
        return md;
    }
    md.push_str("\n## Plots\n\n");
    for p in &plots {
        md.push_str(&format!(
            "![{}]({}/{})\n\n{}\n\n",
            p.title,
            super::plots::FOLDER,
            p.file,
            p.caption
        ));
    }
    for n in &notes {
        md.push_str(&format!("- {n}\n"));
    }
    md
}

/// The worst time-coverage errors (SPEC.md §15.4), the nearest to their
/// RMS bound first.
fn time_errors(report: &Report) -> String {
    let mut rows: Vec<(f64, String)> = report
        .cases
        .iter()
        .flat_map(|c| c.results.iter().map(move |r| (c, r)))
        .filter_map(|(c, r)| {
            let t = r.metrics.as_ref()?.time.as_ref()?;
            let rules = c.rules.as_ref();
            let spatial = rules.and_then(|r| r.antialias.as_ref()).map_or(1, |a| a.samples);
            let time = rules.and_then(|r| r.motion_blur.as_ref()).map_or(0, |m| m.samples);
            let bound = t.allowed_rms.map_or("—".to_owned(), |b| format!("{b:.3e}"));
            let efficiency = t
                .sample_tests
                .as_ref()
                .map_or("—".to_owned(), |s| format!("{:.1}%", s.efficiency() * 100.0));
            let [x, y] = t.worst_pixel;
            Some((
                t.rms_moving / t.allowed_rms.unwrap_or(1.0),
                format!(
                    "| `{}` | {} | {spatial}×{time} | {:.3e} | ({x}, {y}) | {:.3e} | {:+.2e} | {bound} | {efficiency} |",
                    c.id, r.rasterizer, t.max_error, t.rms_moving, t.bias_moving
                ),
            ))
        })
        .collect();
    rows.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut md = String::new();
    if !rows.is_empty() {
        md.push_str("\n## Worst time-coverage errors\n\n| case | rasterizer | samples (space×time) | max error | worst pixel | moving RMS | bias | RMS bound | test efficiency |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
        for (_, row) in rows.iter().take(10) {
            md.push_str(row);
            md.push('\n');
        }
    }
    md
}

fn one_line(text: &str) -> String {
    let line = text.replace('\n', " ");
    if line.chars().count() > 300 {
        format!("{}…", line.chars().take(300).collect::<String>())
    } else {
        line
    }
}
