//! The index page: the run's header, totals, a family × rasterizer
//! summary, the failures first, then one table per family; built from the
//! report alone.

use std::fmt::Write as _;

use super::cards::{self, anchor, cards_of, Card, Kind};
use super::page::page_url;
use super::shell::head;
use super::tables::{badge, cell, shorten};
use crate::report::escape::escape;
use crate::report::families::{FamilyCount, VERDICTS};
use crate::report::json::{CaseEntry, Report};
use crate::report::limits::{LISTED, LOOKED, MAX_PAGES, MAX_PROBLEM_PAGES};
use crate::report::plots;

/// Rows of the failures table on the index, at most.
const MAX_FAILURE_ROWS: usize = 500;

/// The index: the run's header, totals, a family × rasterizer summary, the
/// failures first, then one table per family. Built from the report alone;
/// pictures live on the case pages, so the index stays light.
pub fn render(report: &Report, families: &[FamilyCount]) -> String {
    let t = &report.totals;
    let mut html = head("rastercheck report", None);

    // Header.
    let _ = write!(
        html,
        "<h1>rastercheck report</h1><div class=\"muted\">{} {} · schema {}</div>",
        report.tool.name, report.tool.version, report.schema
    );
    if !report.complete {
        let _ = write!(
            html,
            "<div class=\"banner\">The run did not finish: {} cases did not run.</div>",
            t.not_run
        );
    }
    let command: Vec<String> = report.command.iter().map(|a| shell_quote(a)).collect();
    let _ = write!(
        html,
        "<p>Command: <code>rastercheck {}</code></p>",
        escape(&command.join(" "))
    );
    html.push_str("<div class=\"summary\"><table><tr><th>rasterizer</th><th class=\"n\">pass</th><th class=\"n\">fail</th><th class=\"n\">foil departures</th><th class=\"n\">unsupported</th><th class=\"n\">error</th><th class=\"n\">flaky</th></tr>");
    for (v, info) in t.verdicts.iter().zip(&report.rasterizers) {
        let x = &v.tally;
        let _ = write!(
            html,
            "<tr><td><b>{}</b>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
            escape(&v.rasterizer),
            if info.foil { " <span class=\"muted\">(foil)</span>" } else { "" },
            x.pass,
            x.fail,
            x.foil,
            x.unsupported,
            x.error,
            x.flaky
        );
    }
    html.push_str("</table>");
    let g = &t.golden;
    let _ = write!(
        html,
        "<div class=\"panel\"><b>{}</b> case files · {} unreadable · {} reference failures · {} over a limit · {} not run<br>golden files: {} match, {} differ, {} missing</div></div>",
        t.cases, t.unreadable, t.reference_failed, t.limit_exceeded, t.not_run, g.matching, g.differing, g.missing
    );

    // Families, in order of first appearance, counted over every case.
    html.push_str(&family_summary(report, families));
    let left_out = t.cases.saturating_sub(report.cases.len());
    if left_out > 0 {
        let _ = write!(
            html,
            "<div class=\"banner\">This page lists {} of the {} cases: the first {LISTED} and at most {LOOKED} more worth a look (failures, errors, departures, results with some error); the other {left_out} are counted above and not listed. The failures table, the plots and the family tables below are drawn from the cases listed; report.json and junit.xml have every result.</div>",
            report.cases.len(),
            t.cases
        );
    }
    html.push_str(&failures(report));
    html.push_str(&plots(report));
    let unpaged = report
        .cases
        .iter()
        .filter(|c| c.page.is_none() && !cards_of(c).is_empty())
        .count();
    if unpaged > 0 && report.complete {
        let _ = write!(
            html,
            "<div class=\"banner\">{unpaged} cases worth a look have no page of their own (at most {MAX_PROBLEM_PAGES} pages of failures and {MAX_PAGES} others are written); report.json has every result.</div>"
        );
    }

    for count in families {
        let family = &count.family;
        let members: Vec<&CaseEntry> = report
            .cases
            .iter()
            .filter(|c| c.family == *family)
            .collect();
        let listed = match members.len() == count.cases {
            true => String::new(),
            false => format!(", {} listed", members.len()),
        };
        let _ = write!(
            html,
            "<section class=\"family\" id=\"family-{}\"><h2>{} <span class=\"muted\">({} case{}{listed})</span></h2>",
            escape(&slug(family)),
            escape(family),
            count.cases,
            if count.cases == 1 { "" } else { "s" }
        );
        html.push_str("<table class=\"cases\"><tr><th>case</th><th>golden</th>");
        for r in &report.rasterizers {
            let _ = write!(html, "<th>{}</th>", escape(&r.name));
        }
        html.push_str("</tr>\n");
        for case in members {
            let id_cell = match &case.page {
                Some(page) => format!(
                    "<a href=\"{}\">{}</a>",
                    escape(&page_url(page, &anchor(case, None))),
                    escape(&case.id)
                ),
                None => escape(&case.id),
            };
            let _ = write!(html, "<tr><td class=\"id\">{id_cell}</td><td>");
            if let Some(golden) = case.golden {
                html.push_str(&badge(golden, golden));
            }
            html.push_str("</td>");
            if case.status != "ran" {
                let why = case.error.as_deref().unwrap_or("");
                let _ = write!(
                    html,
                    "<td colspan=\"{}\">{}<span class=\"metric\">{}</span></td>",
                    report.rasterizers.len().max(1),
                    badge(case.status, case.status),
                    escape(&shorten(why, 160))
                );
            } else {
                let carded = cards_of(case);
                for (r, result) in case.results.iter().enumerate() {
                    let link = case
                        .page
                        .as_ref()
                        .filter(|_| carded.iter().any(|c| c.result == Some(r)))
                        .map(|page| page_url(page, &anchor(case, Some(result))));
                    let _ = write!(html, "<td>{}</td>", cell(result, link.as_deref()));
                }
            }
            html.push_str("</tr>\n");
        }
        html.push_str("</table></section>\n");
    }
    html.push_str("</main></body></html>\n");
    html
}

/// Per family and rasterizer, how many results passed, failed, departed,
/// were unsupported or errors, and cases with problems of their own.
fn family_summary(report: &Report, families: &[FamilyCount]) -> String {
    let mut html = String::from(
        "<h2>Families</h2><table class=\"families\"><tr><th>family</th><th class=\"n\">cases</th>",
    );
    for r in &report.rasterizers {
        let _ = write!(html, "<th>{}</th>", escape(&r.name));
    }
    html.push_str("</tr>\n");
    for count in families {
        let family = &count.family;
        let problems = count.problems;
        let _ = write!(
            html,
            "<tr><td><a href=\"#family-{}\">{}</a></td><td class=\"n\">{}{}</td>",
            escape(&slug(family)),
            escape(family),
            count.cases,
            if problems > 0 {
                format!(" <span class=\"metric\">({problems} did not run)</span>")
            } else {
                String::new()
            }
        );
        for r in 0..report.rasterizers.len() {
            html.push_str("<td>");
            if let Some(counts) = count.verdicts.get(r) {
                for (verdict, &n) in VERDICTS.iter().zip(counts) {
                    if n > 0 {
                        html.push_str(&badge(verdict, &format!("{n} {verdict}")));
                    }
                }
            }
            html.push_str("</td>");
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</table>\n");
    html
}

/// The accuracy charts (`report::plots`), linked from `plots/`, with their
/// captions, and a line for each chart not drawn.
fn plots(report: &Report) -> String {
    let charts = plots::plots(report);
    let notes = plots::notes(report);
    if charts.is_empty() && notes.is_empty() {
        return String::new();
    }
    let mut html = String::from("<h2>Plots</h2><div class=\"plots\">");
    for chart in &charts {
        let url = cards::file_url(&format!("{}/{}", plots::FOLDER, chart.file));
        let _ = write!(
            html,
            "<figure class=\"plot\"><img data-role=\"plot\" src=\"{}\" alt=\"{}\"><figcaption><b>{}</b> {}</figcaption></figure>",
            escape(&url),
            escape(&chart.title),
            escape(&chart.title),
            escape(&chart.caption)
        );
    }
    html.push_str("</div>");
    if !notes.is_empty() {
        html.push_str("<ul class=\"muted\">");
        for note in &notes {
            let _ = write!(html, "<li>{}</li>", escape(note));
        }
        html.push_str("</ul>");
    }
    html.push('\n');
    html
}

/// Every failure, error, problem and foil departure, in that order, with
/// its first reason and a link to its page.
fn failures(report: &Report) -> String {
    let mut rows: Vec<(Card, &CaseEntry)> = report
        .cases
        .iter()
        .flat_map(|case| {
            cards_of(case)
                .into_iter()
                .filter(|c| c.kind != Kind::Interpolation)
                .map(move |c| (c, case))
        })
        .collect();
    rows.sort_by_key(|(c, _)| c.kind);
    if rows.is_empty() {
        return "<h2>Failures</h2><p>None: every judged result passed.</p>\n".to_owned();
    }
    let mut html = format!(
        "<h2>Failures first <span class=\"muted\">({})</span></h2><div class=\"scroll\"><table class=\"failures\"><tr><th>case</th><th>rasterizer</th><th>verdict</th><th>why</th></tr>\n",
        rows.len()
    );
    for (card, case) in rows.iter().take(MAX_FAILURE_ROWS) {
        let result = card.result.map(|r| &case.results[r]);
        let (who, verdict, why) = match result {
            Some(r) => (
                escape(&r.rasterizer),
                badge(r.verdict, &r.verdict.to_uppercase()),
                r.reasons.first().cloned().unwrap_or_default(),
            ),
            None => (
                String::new(),
                badge(
                    if case.status == "ran" {
                        "differ"
                    } else {
                        case.status
                    },
                    if case.status == "ran" {
                        "golden differs"
                    } else {
                        case.status
                    },
                ),
                case.error
                    .clone()
                    .or_else(|| case.golden_detail.clone())
                    .unwrap_or_default(),
            ),
        };
        let id = match &case.page {
            Some(page) => format!(
                "<a href=\"{}\">{}</a>",
                escape(&page_url(page, &anchor(case, result))),
                escape(&case.id)
            ),
            None => escape(&case.id),
        };
        let _ = writeln!(
            html,
            "<tr><td class=\"id\">{id}</td><td>{who}</td><td>{verdict}</td><td class=\"metric\" title=\"{}\">{}</td></tr>",
            escape(&shorten(&why, 400)),
            escape(&shorten(&why, 140))
        );
    }
    html.push_str("</table></div>\n");
    if rows.len() > MAX_FAILURE_ROWS {
        let _ = writeln!(
            html,
            "<p class=\"muted\">and {} more; report.json has every result.</p>",
            rows.len() - MAX_FAILURE_ROWS
        );
    }
    html
}

/// A command-line argument quoted for a POSIX shell when it needs it.
fn shell_quote(arg: &str) -> String {
    if !arg.is_empty()
        && arg
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./:=+,@%".contains(c))
    {
        arg.to_owned()
    } else {
        format!("'{}'", arg.replace('\'', "'\\''"))
    }
}

/// A family's name as an HTML id.
fn slug(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}
