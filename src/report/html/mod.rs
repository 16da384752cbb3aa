//! The HTML pages: `index.html`, light and built from the report alone,
//! and one page per case worth a look (`pages/<id>.html`), written while
//! the case's frames are in memory (`report::case_files`) and opened only
//! when wanted. Inline CSS, no network, no script but a few lines that
//! record on `<body>` what the browser test reads (pictures decoded, script
//! errors, load time).
//!
//! The index: a header with the command, the totals per rasterizer and the
//! golden files; a table of families × rasterizers; the failures first
//! (failures, errors, problems and a foil's departures, with their first
//! reason and a link to the card); then one section per family with a table
//! of cases × rasterizers, each result linking to its card.
//!
//! A case page holds the case's cards ([`cards_of`]), the most important
//! first:
//!
//! 1. failures and errors, unreadable cases, broken references, golden
//!    files that differ;
//! 2. a foil's departures;
//! 3. passing results with a nonzero interpolation error (their heat maps).
//!
//! A result card shows the reference, the candidate and the difference mask
//! (the PNGs `case_files` wrote, linked; colour key in `png.rs`), the
//! reasons, every metric, one heat map per interpolated channel
//! (|candidate − exact| per pixel on a viridis scale from 0 to the
//! channel's largest error), its files, and the case file. Links are
//! relative to the report folder, which the page's `<base>` names.
//!
//! An antialiased case's card shows its resolved coverage instead (drawn
//! from the frames, for passes too): the exact area and the candidate's
//! resolved value in grey, the signed error (red too much, blue too
//! little), and for a candidate whose samples differ every sample as a dot
//! coloured by how it differs (colour keys in `png.rs`). Passing antialiased results
//! with any coverage error get a card like passes with interpolation error.
//! With several samples per pixel a heat map shows each pixel's largest
//! error over its samples.
//!
//! A scene in which something moves (SPEC.md §15.4) is shown the same way
//! by its time coverage: the exact time coverage and the candidate's in
//! grey, and the signed error, with the time metrics (and the sample test
//! efficiency of a method that counts it). Passing results with any time
//! error get a card too.
//!
//! The pages are built in four rooms: this file (the index and the case
//! page), `cards.rs` (which results get a card, and the case and result
//! cards), `tables.rs` (table cells and metrics tables) and `pictures.rs`
//! (coverage pictures, heat maps, difference lists, PNG data URIs).

use std::fmt::Write as _;
use std::path::Path;

use super::json::{CaseEntry, Report};
use super::{escape, MAX_PAGES, MAX_PROBLEM_PAGES};
use crate::frame::Frame;
use crate::harness::runner::CaseOutcome;

mod cards;
mod pictures;
mod tables;

use cards::{anchor, case_card, result_card, Kind, ResultView};
pub use cards::{cards_of, relative_url, Card};
pub use pictures::base64;
use tables::{badge, cell, shorten};

const STYLE: &str = r#"
:root { --fg:#1d2330; --muted:#667085; --line:#d9dee7; --bg:#f6f7f9; --card:#fff;
  --pass:#1a7f37; --fail:#c62828; --foil:#8250df; --unsupported:#9a6700; --error:#b42318; }
* { box-sizing: border-box; }
body { margin:0; font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif; color:var(--fg); background:var(--bg); }
main { max-width:1760px; margin:0 auto; padding:20px 28px 60px; }
h1 { font-size:24px; margin:0 0 4px; } h2 { font-size:20px; margin:32px 0 10px; border-bottom:2px solid var(--line); padding-bottom:4px; }
h3 { font-size:16px; margin:0; } h4 { font-size:13px; margin:14px 0 6px; text-transform:uppercase; letter-spacing:.04em; color:var(--muted); }
code, pre { font:12.5px/1.4 ui-monospace,SFMono-Regular,Menlo,Consolas,monospace; }
pre { background:#f1f3f6; border:1px solid var(--line); border-radius:6px; padding:8px 10px; overflow:auto; max-height:420px; white-space:pre-wrap; word-break:break-word; }
a { color:#0b62c4; text-decoration:none; } a:hover { text-decoration:underline; }
.muted { color:var(--muted); }
.banner { background:#fff4e5; border:1px solid #f0b35a; border-radius:6px; padding:8px 12px; margin:10px 0; }
.summary { display:flex; flex-wrap:wrap; gap:16px; align-items:flex-start; margin-top:14px; }
.panel { background:var(--card); border:1px solid var(--line); border-radius:8px; padding:12px 14px; }
table { border-collapse:collapse; background:var(--card); }
th, td { border:1px solid var(--line); padding:4px 8px; text-align:left; vertical-align:top; }
th { background:#eef1f5; font-weight:600; }
td.n, th.n { text-align:right; font-variant-numeric:tabular-nums; }
table.cases { width:100%; } table.cases td { font-size:13px; }
table.cases td.id { font-family:ui-monospace,Menlo,Consolas,monospace; font-size:12.5px; white-space:nowrap; }
.badge { display:inline-block; min-width:44px; text-align:center; font-size:11px; font-weight:700; letter-spacing:.03em; color:#fff; border-radius:4px; padding:1px 6px; margin-right:6px; }
.pass { background:var(--pass); } .fail { background:var(--fail); } .foil { background:var(--foil); }
.unsupported { background:var(--unsupported); } .error, .unreadable, .reference-failed, .limit-exceeded, .differ { background:var(--error); }
.not-run, .missing { background:#8c959f; } .match { background:var(--pass); }
.metric { color:var(--muted); font-size:12px; }
.card { background:var(--card); border:1px solid var(--line); border-left:5px solid var(--line); border-radius:8px; padding:14px 16px; margin:16px 0; }
.card.k-fail, .card.k-error, .card.k-problem { border-left-color:var(--fail); }
.card.k-foil { border-left-color:var(--foil); } .card.k-pass { border-left-color:var(--pass); }
.card header { display:flex; flex-wrap:wrap; align-items:baseline; gap:8px 12px; }
.card header .id { font-family:ui-monospace,Menlo,Consolas,monospace; font-size:15px; font-weight:600; }
.reasons { margin:8px 0; padding-left:20px; color:#7a1c1c; }
.pictures { display:flex; gap:14px; padding-bottom:6px; align-items:flex-start; }
.pictures figure { flex:0 1 auto; min-width:0; }
.pictures.stack { flex-direction:column; overflow-x:auto; }
.pictures.stack figure { flex:none; } .pictures.stack img { max-width:none; }
.pictures.tall { max-height:640px; overflow-y:auto; } .pictures.tall figure { flex:none; }
.pictures.heat { flex-wrap:wrap; }
figure { margin:0; } figcaption { font-size:12px; color:var(--muted); margin-top:3px; }
figure img { display:block; image-rendering:pixelated; border:1px solid #000; max-width:100%; height:auto; }
.key { display:flex; flex-wrap:wrap; gap:4px 14px; font-size:12px; margin:8px 0 2px; color:var(--fg); }
.key span { white-space:nowrap; } .key i { display:inline-block; width:12px; height:12px; border:1px solid #555; vertical-align:-2px; margin-right:4px; }
.metrics { display:flex; flex-wrap:wrap; gap:14px; align-items:flex-start; }
.ramp { display:inline-block; width:140px; height:12px; border:1px solid #555; vertical-align:-2px; margin:0 4px; }
details { margin-top:8px; } summary { cursor:pointer; color:#0b62c4; }
.files { font-size:12px; }
.scroll { max-height:460px; overflow:auto; border:1px solid var(--line); border-radius:6px; }
table.failures td:nth-child(2) { white-space:nowrap; }
.plots { display:flex; flex-wrap:wrap; gap:16px; }
.plots figure.plot { background:var(--card); border:1px solid var(--line); border-radius:8px; padding:8px; max-width:700px; }
.plots figure.plot img { border:none; image-rendering:auto; }
"#;

/// After load, records on `<body>` for the browser test: the pictures that
/// decoded of all (`data-images`), the script errors seen
/// (`data-errors`), and the milliseconds from navigation to load
/// (`data-load-ms`).
const SCRIPT: &str = r#"var rastercheckErrors = 0;
window.addEventListener('error', function () { rastercheckErrors++; }, true);
window.addEventListener('load', function () {
  var imgs = document.images, ok = 0;
  for (var i = 0; i < imgs.length; i++) { if (imgs[i].complete && imgs[i].naturalWidth > 0) ok++; }
  document.body.dataset.images = ok + '/' + imgs.length;
  document.body.dataset.errors = rastercheckErrors;
  document.body.dataset.loadMs = Math.round(performance.now());
});"#;

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

fn head(title: &str, base: Option<&str>) -> String {
    let mut html = String::from("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    if let Some(base) = base {
        let _ = writeln!(html, "<base href=\"{}\">", escape(base));
    }
    let _ = write!(html, "<title>{}</title>\n<style>", escape(title));
    html.push_str(STYLE);
    html.push_str("</style>\n<script>");
    html.push_str(SCRIPT);
    html.push_str("</script></head>\n<body><main>\n");
    html
}

/// The file of a case's page, relative to the report folder.
pub fn page_file(id: &str) -> String {
    format!("pages/{id}.html")
}

/// A link from the report folder to a case's page, at `anchor`.
fn page_url(page: &str, anchor: &str) -> String {
    format!("{}#{anchor}", cards::file_url(page))
}

/// The page of one case: its cards (see [`cards_of`]) drawn from the
/// outcome's frames, which must still be in memory. Its links are
/// relative to the report folder `dir` (a `<base>` points there).
pub fn page(dir: &Path, case: &CaseEntry, shown: &[Card], outcome: &CaseOutcome) -> String {
    let depth = page_file(&case.id).matches('/').count();
    let mut html = head(
        &format!("{} · rastercheck", case.id),
        Some(&"../".repeat(depth)),
    );
    let _ = write!(
        html,
        "<p class=\"muted\"><a href=\"index.html\">rastercheck report</a> › {} › {}</p>",
        escape(&case.family),
        escape(&case.id)
    );
    let reference = outcome.reference.as_ref().map(|r| &r.frame);
    for card in shown {
        match card.result {
            None => html.push_str(&case_card(dir, case)),
            Some(r) => {
                let view = ResultView {
                    case,
                    result: &case.results[r],
                    scene: outcome.scene.as_ref(),
                    reference,
                    depth_allowed: outcome
                        .reference
                        .as_ref()
                        .and_then(|r| r.depth_allowed.as_deref()),
                    candidate: outcome
                        .candidates
                        .get(r)
                        .and_then(|run| run.frame.as_ref())
                        .filter(|f| reference.is_some_and(|r| same_shape(r, f))),
                };
                html.push_str(&result_card(dir, &view));
            }
        }
        html.push('\n');
    }
    html.push_str("</main></body></html>\n");
    html
}

/// Rows of the failures table on the index, at most.
const MAX_FAILURE_ROWS: usize = 500;

/// The index: the run's header, totals, a family × rasterizer summary, the
/// failures first, then one table per family. Built from the report alone;
/// pictures live on the case pages, so the index stays light.
pub fn render(report: &Report) -> String {
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
    html.push_str("<div class=\"summary\"><table><tr><th>rasterizer</th><th class=\"n\">pass</th><th class=\"n\">fail</th><th class=\"n\">foil departures</th><th class=\"n\">unsupported</th><th class=\"n\">error</th></tr>");
    for (v, info) in t.verdicts.iter().zip(&report.rasterizers) {
        let x = &v.tally;
        let _ = write!(
            html,
            "<tr><td><b>{}</b>{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">{}</td></tr>",
            escape(&v.rasterizer),
            if info.foil { " <span class=\"muted\">(foil)</span>" } else { "" },
            x.pass,
            x.fail,
            x.foil,
            x.unsupported,
            x.error
        );
    }
    html.push_str("</table>");
    let g = &t.golden;
    let _ = write!(
        html,
        "<div class=\"panel\"><b>{}</b> case files · {} unreadable · {} reference failures · {} over a limit · {} not run<br>golden files: {} match, {} differ, {} missing</div></div>",
        t.cases, t.unreadable, t.reference_failed, t.limit_exceeded, t.not_run, g.matching, g.differing, g.missing
    );

    // Families, in order of first appearance.
    let mut families: Vec<&str> = Vec::new();
    for case in &report.cases {
        if !families.contains(&case.family.as_str()) {
            families.push(&case.family);
        }
    }
    html.push_str(&family_summary(report, &families));
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

    for family in &families {
        let members: Vec<&CaseEntry> = report
            .cases
            .iter()
            .filter(|c| c.family == *family)
            .collect();
        let _ = write!(
            html,
            "<section class=\"family\" id=\"family-{}\"><h2>{} <span class=\"muted\">({} case{})</span></h2>",
            escape(&slug(family)),
            escape(family),
            members.len(),
            if members.len() == 1 { "" } else { "s" }
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
fn family_summary(report: &Report, families: &[&str]) -> String {
    let mut html = String::from(
        "<h2>Families</h2><table class=\"families\"><tr><th>family</th><th class=\"n\">cases</th>",
    );
    for r in &report.rasterizers {
        let _ = write!(html, "<th>{}</th>", escape(&r.name));
    }
    html.push_str("</tr>\n");
    for family in families {
        let members: Vec<&CaseEntry> = report
            .cases
            .iter()
            .filter(|c| c.family == *family)
            .collect();
        let problems = members.iter().filter(|c| c.status != "ran").count();
        let _ = write!(
            html,
            "<tr><td><a href=\"#family-{}\">{}</a></td><td class=\"n\">{}{}</td>",
            escape(&slug(family)),
            escape(family),
            members.len(),
            if problems > 0 {
                format!(" <span class=\"metric\">({problems} did not run)</span>")
            } else {
                String::new()
            }
        );
        for r in 0..report.rasterizers.len() {
            let mut counts: Vec<(&str, usize)> = Vec::new();
            for verdict in ["pass", "fail", "foil", "error", "unsupported"] {
                let n = members
                    .iter()
                    .filter(|c| c.results.get(r).is_some_and(|x| x.verdict == verdict))
                    .count();
                if n > 0 {
                    counts.push((verdict, n));
                }
            }
            html.push_str("<td>");
            for (verdict, n) in counts {
                html.push_str(&badge(verdict, &format!("{n} {verdict}")));
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
    let charts = super::plots::plots(report);
    let notes = super::plots::notes(report);
    if charts.is_empty() && notes.is_empty() {
        return String::new();
    }
    let mut html = String::from("<h2>Plots</h2><div class=\"plots\">");
    for chart in &charts {
        let url = cards::file_url(&format!("{}/{}", super::plots::FOLDER, chart.file));
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

/// Whether a candidate's frame can be pictured beside the reference's: the
/// same samples, or resolved or time coverage of the same canvas.
fn same_shape(reference: &Frame, candidate: &Frame) -> bool {
    if reference.time.is_some() || candidate.time.is_some() {
        let time = |f: &Frame| f.time.as_ref().map(Vec::len);
        return time(candidate) == time(reference);
    }
    let resolved = |f: &Frame| f.resolved.as_ref().map(Vec::len);
    reference.sample_count() == candidate.sample_count() && candidate.samples == reference.samples
        || candidate.samples == 0
            && resolved(candidate).is_some()
            && resolved(candidate) == resolved(reference)
}

fn slug(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect()
}
