//! The cards of the HTML page: which results deserve one (failures first,
//! then a foil's departures, then passes with some error), the card of a
//! case with a problem of its own, and the card of a case × rasterizer with
//! its reasons, pictures, metrics, files and case file; links relative to
//! the report folder.
//!
//! The pictures and tables a card shows are drawn by `pictures.rs` and
//! `tables.rs`.

use std::fmt::Write as _;
use std::path::{Component, Path, PathBuf};

use super::pictures::{
    colour_key, coverage_pictures, figure, first_differences, heat_maps, picture_shape,
    COVERAGE_TWICE, TIE_WORDS,
};
use super::tables::{badge, metrics_tables};
use crate::frame::Frame;
use crate::metrics::SampleDiff;
use crate::report::escape::escape;
use crate::report::json::{CaseEntry, MetricsEntry, ResultEntry};
use crate::report::png::{self, EXTRA, MISSING, SAME_COVERED, WRONG_OWNER};
use crate::scene::Scene;

/// Case files longer than this are linked but not embedded.
pub(super) const MAX_EMBEDDED_CASE: usize = 64 * 1024;

/// Why a card is shown, in order of importance.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Kind {
    /// A failure, an error, a case that did not run, a differing golden file.
    Problem,
    /// A foil departing from the reference.
    Departure,
    /// A pass with some interpolation, coverage or time-coverage error: the
    /// heat maps and the antialiasing or time pictures are worth seeing.
    Interpolation,
}

/// One card of a case's page: the case itself (`result` None: it has a
/// problem of its own) or a case × rasterizer.
#[derive(Clone, Copy, Debug)]
pub struct Card {
    pub(super) kind: Kind,
    pub(super) result: Option<usize>,
}

impl Card {
    /// A failure, an error or a problem of the case: worth a page even
    /// when pages for lesser cards have run out.
    pub fn is_problem(&self) -> bool {
        self.kind == Kind::Problem
    }
}

pub(super) fn anchor(case: &CaseEntry, result: Option<&ResultEntry>) -> String {
    let mut id = format!("card-{}", case.id);
    if let Some(r) = result {
        id.push_str("--");
        id.push_str(&r.rasterizer);
    }
    id.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

pub(super) fn interpolation_error(m: &MetricsEntry) -> bool {
    m.channels
        .iter()
        .any(|ch| ch.max_abs != 0.0 || ch.max_abs.is_nan())
        || m.antialias
            .as_ref()
            .is_some_and(|a| a.max_error != 0.0 || a.max_error.is_nan())
        || m.time
            .as_ref()
            .is_some_and(|t| t.max_error != 0.0 || t.max_error.is_nan())
}

/// The cards a case deserves, the most important first: its own problem
/// or differing golden file, failures and errors, a foil's departures,
/// passes with some interpolation, coverage or time-coverage error.
pub fn cards_of(case: &CaseEntry) -> Vec<Card> {
    let mut out = Vec::new();
    if case.error.is_some() || case.golden == Some("differ") {
        out.push(Card {
            kind: Kind::Problem,
            result: None,
        });
    }
    for (r, result) in case.results.iter().enumerate() {
        let kind = match result.verdict {
            "fail" | "error" | "flaky" => Kind::Problem,
            "foil" => Kind::Departure,
            "pass" if result.metrics.as_ref().is_some_and(interpolation_error) => {
                Kind::Interpolation
            }
            _ => continue,
        };
        out.push(Card {
            kind,
            result: Some(r),
        });
    }
    out.sort_by_key(|card| card.kind);
    out
}

pub(super) fn card_header(
    case: &CaseEntry,
    result: Option<&ResultEntry>,
    kind_class: &str,
) -> String {
    let mut html = format!("<header><span class=\"id\">{}</span>", escape(&case.id));
    if let Some(r) = result {
        let _ = write!(
            html,
            "<span>{}</span>{}",
            escape(&r.rasterizer),
            badge(r.verdict, &r.verdict.to_uppercase())
        );
    } else {
        html.push_str(&badge(kind_class, case.status));
    }
    if let Some(rules) = &case.rules {
        let _ = write!(
            html,
            "<span class=\"muted\">{}×{} · {} · fill {} · cull {} · {} primitives</span>",
            rules.canvas[0],
            rules.canvas[1],
            rules
                .subpixel_bits
                .map_or("unsnapped".to_owned(), |b| format!("{b} subpixel bits")),
            rules.fill_rule,
            rules.cull,
            rules.primitives
        );
        if let Some(aa) = &rules.antialias {
            let _ = write!(
                html,
                "<span class=\"muted\">antialiased: {} samples, {} pattern</span>",
                aa.samples,
                escape(aa.pattern)
            );
        }
        if let Some(mb) = rules.motion_blur.as_ref().filter(|mb| mb.moving > 0) {
            let _ = write!(
                html,
                "<span class=\"muted\">motion blur: {} moving primitives, shutter [{}, {}], {} time samples, {} pattern</span>",
                mb.moving,
                mb.shutter[0],
                mb.shutter[1],
                mb.samples,
                escape(mb.pattern)
            );
        }
    }
    html.push_str("</header>");
    if let Some(d) = case.description.as_deref().filter(|d| !d.is_empty()) {
        let _ = write!(html, "<div class=\"muted\">{}</div>", escape(d));
    }
    html
}

/// A card for a case that has a problem of its own.
pub(super) fn case_card(dir: &Path, case: &CaseEntry) -> String {
    let class = if case.status == "ran" {
        "differ"
    } else {
        case.status
    };
    let mut html = format!(
        "<article class=\"card k-problem\" id=\"{}\" data-case=\"{}\" data-verdict=\"{}\">",
        anchor(case, None),
        escape(&case.id),
        escape(class)
    );
    html.push_str(&card_header(case, None, class));
    if let Some(error) = &case.error {
        let _ = write!(html, "<pre>{}</pre>", escape(error));
    }
    if case.golden == Some("differ") {
        let _ = write!(
            html,
            "<p>The reference no longer reproduces its golden file:</p><pre>{}</pre>",
            escape(case.golden_detail.as_deref().unwrap_or(""))
        );
    }
    html.push_str(&case_file(dir, case));
    html.push_str("</article>");
    html
}

pub(super) struct ResultView<'a> {
    pub(super) case: &'a CaseEntry,
    pub(super) result: &'a ResultEntry,
    pub(super) scene: Option<&'a Scene>,
    pub(super) reference: Option<&'a Frame>,
    /// The depth set a depth format allows per sample (SPEC.md §18), if any.
    pub(super) depth_allowed: Option<&'a [[f64; 2]]>,
    pub(super) candidate: Option<&'a Frame>,
    /// The mask the candidate was judged by, sample by sample: accepted tie
    /// samples are [`SampleDiff::Tie`] in it.
    pub(super) mask: Option<&'a [SampleDiff]>,
}

pub(super) fn result_card(dir: &Path, v: &ResultView) -> String {
    let (case, result) = (v.case, v.result);
    let mut html = format!(
        "<article class=\"card k-{}\" id=\"{}\" data-case=\"{}\" data-rasterizer=\"{}\" data-verdict=\"{}\">",
        escape(result.verdict),
        anchor(case, Some(result)),
        escape(&case.id),
        escape(&result.rasterizer),
        escape(result.verdict)
    );
    html.push_str(&card_header(case, Some(result), result.verdict));
    if !result.reasons.is_empty() {
        html.push_str("<ul class=\"reasons\">");
        for reason in &result.reasons {
            let _ = write!(html, "<li>{}</li>", escape(reason));
        }
        html.push_str("</ul>");
    }
    // A flaky result (`run --repeat`): every repetition's outcome, then
    // where the frames differed; the pictures below are the first's.
    if let Some(flaky) = &result.flaky {
        html.push_str("<p>Its repetitions drew different frames (the pictures are the first repetition's):</p><ul class=\"reasons\">");
        for rep in &flaky.outcomes {
            let _ = write!(
                html,
                "<li>repetition {}: {}</li>",
                rep.repetition,
                escape(&rep.describe())
            );
        }
        for difference in &flaky.differences {
            let _ = write!(html, "<li>{}</li>", escape(&difference.describe()));
        }
        html.push_str("</ul>");
    }
    // No tie rule (SPEC.md §3.1.1): its ties counted apart, never hidden.
    if let Some(ties) = &result.ties {
        let _ = write!(html, "<p class=\"ties\">{}</p>", escape(&ties.line()));
    }
    // A conservative case (SPEC.md §19): the band it used, never hidden,
    // and its picture of the three classes with its pixels.
    if let Some(m) = &result.conservative {
        let _ = write!(
            html,
            "<p class=\"conservative\">{}</p>",
            escape(&crate::metrics::conservative::summary(m))
        );
        let name = crate::report::conservative::file_name(&result.rasterizer);
        if let Some(f) = result
            .files
            .iter()
            .find(|f| f.ends_with(&format!("/{name}")))
            .filter(|f| dir.join(f).is_file())
        {
            html.push_str("<h4>conservative classes</h4><div class=\"pictures\">");
            html.push_str(&figure(
                &escape(&file_url(f)),
                "conservative",
                &format!("{}: its pixels on the three classes", result.rasterizer),
                None,
            ));
            html.push_str("</div>");
            html.push_str(&colour_key(&crate::report::conservative::KEY));
        }
    }

    // An antialiased case: its resolved coverage, drawn from the frames; a
    // moving scene: its time coverage, likewise.
    let resolved = v.reference.filter(|r| png::pictured_resolved(r));
    if let (Some(scene), Some(r), Some(c)) = (v.scene, resolved, v.candidate) {
        html.push_str(&coverage_pictures(
            case,
            scene,
            (r, c),
            v.mask,
            &result.rasterizer,
        ));
    }

    // The three pictures, as written under images/.
    let pngs: Vec<&String> = result
        .files
        .iter()
        .filter(|f| {
            f.starts_with("images/") && f.ends_with(".png") && !f.ends_with(".conservative.png")
        })
        .collect();
    if !pngs.is_empty() && resolved.is_none() {
        let find = |pred: &dyn Fn(&str) -> bool| pngs.iter().find(|f| pred(f)).copied();
        let reference = find(&|f| f.ends_with("/reference.png"));
        let diff = find(&|f| f.ends_with(".diff.png"));
        let candidate = find(&|f| !f.ends_with("/reference.png") && !f.ends_with(".diff.png"));
        let shape = picture_shape(case);
        let _ = write!(html, "<h4>coverage</h4><div class=\"pictures{shape}\">");
        // Linked, not embedded: the files are beside the page, and the
        // page's `<base>` is the report folder.
        let mut show = |file: Option<&String>, role: &str, caption: &str| {
            if let Some(f) = file.filter(|f| dir.join(f).is_file()) {
                html.push_str(&figure(&escape(&file_url(f)), role, caption, None));
            }
        };
        show(reference, "reference", "reference (exact)");
        show(candidate, "candidate", &result.rasterizer);
        show(diff, "diff", "difference mask");
        html.push_str("</div>");
        if let (Some(r), Some(c)) = (v.reference, v.candidate) {
            html.push_str(&first_differences(r, c, v.mask));
        }
        html.push_str(&colour_key(&[
            ([255, 255, 255], "covered once"),
            (COVERAGE_TWICE, "twice (overdraw)"),
            (EXTRA, "3+ times"),
            ([0, 200, 255], "snapped edges"),
        ]));
        html.push_str(&colour_key(&[
            (MISSING, "missing (holes in a mesh show here)"),
            (EXTRA, "extra"),
            (WRONG_OWNER, "wrong owner"),
            (SAME_COVERED, "covered alike"),
            ([0, 0, 0], "empty in both"),
        ]));
        if v.mask.is_some_and(|m| m.contains(&SampleDiff::Tie)) {
            html.push_str(&colour_key(&[(png::TIE_ACCEPTED, TIE_WORDS)]));
        }
    }

    if let Some(m) = &result.metrics {
        html.push_str("<h4>metrics</h4>");
        html.push_str(&metrics_tables(m));
        if let (Some(r), Some(c)) = (v.reference, v.candidate) {
            html.push_str(&heat_maps(r, c, v.depth_allowed, m));
        }
    }

    let files: Vec<&String> = result.files.iter().collect();
    if !files.is_empty() {
        html.push_str("<div class=\"files\">files: ");
        let links: Vec<String> = files
            .iter()
            .map(|f| format!("<a href=\"{}\">{}</a>", escape(&file_url(f)), escape(f)))
            .collect();
        html.push_str(&links.join(" · "));
        html.push_str("</div>");
    }
    html.push_str(&case_file(dir, case));
    html.push_str("</article>");
    html
}

/// The case file: a relative link and, when small enough, its text.
pub(super) fn case_file(dir: &Path, case: &CaseEntry) -> String {
    let mut html = String::from("<div class=\"files\">case file: ");
    match relative_url(dir, Path::new(&case.path)) {
        Some(url) => {
            let _ = write!(
                html,
                "<a class=\"case-json\" href=\"{}\">{}</a>",
                escape(&url),
                escape(&case.path)
            );
        }
        None => html.push_str(&escape(&case.path)),
    }
    html.push_str("</div>");
    // Only a small regular file is read: a FIFO would block, a huge file
    // would be read whole only to be left out.
    let small_file = std::fs::metadata(&case.path)
        .is_ok_and(|m| m.is_file() && m.len() <= MAX_EMBEDDED_CASE as u64);
    if let Some(text) = small_file
        .then(|| std::fs::read_to_string(&case.path).ok())
        .flatten()
    {
        if text.len() <= MAX_EMBEDDED_CASE {
            let _ = write!(
                html,
                "<details><summary>case JSON</summary><pre>{}</pre></details>",
                escape(&text)
            );
        }
    }
    html
}

/// A relative URL from folder `from` to file `to` (both made absolute
/// against the current directory), with `/` separators and unsafe
/// characters percent-encoded. `None` when no relative path exists (for
/// instance another drive).
pub fn relative_url(from: &Path, to: &Path) -> Option<String> {
    let absolute = |p: &Path| -> Option<PathBuf> {
        std::fs::canonicalize(p).ok().or_else(|| {
            let cwd = std::env::current_dir().ok()?;
            Some(cwd.join(p))
        })
    };
    let (from, to) = (absolute(from)?, absolute(to)?);
    let a: Vec<Component> = from.components().collect();
    let b: Vec<Component> = to.components().collect();
    if a.first() != b.first() {
        return None;
    }
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut parts: Vec<String> = vec!["..".to_owned(); a.len() - common];
    parts.extend(
        b[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    // A component holds no `/`, so joining then encoding each segment
    // encodes each component.
    Some(file_url(&parts.join("/")))
}

/// A `/`-separated path relative to the report folder as a URL: each
/// segment percent-encoded.
pub(super) fn file_url(path: &str) -> String {
    path.split('/')
        .map(url_segment)
        .collect::<Vec<_>>()
        .join("/")
}

pub(super) fn url_segment(segment: &str) -> String {
    let mut out = String::new();
    for b in segment.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~+:@!$&'()*,;=".contains(&b) {
            out.push(b as char);
        } else {
            let _ = write!(out, "%{b:02X}");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_urls_climb_and_descend() {
        let url = relative_url(Path::new("/a/b/report"), Path::new("/a/cases/x y#1.json"));
        assert_eq!(url.as_deref(), Some("../../cases/x%20y%231.json"));
        let url = relative_url(Path::new("/a"), Path::new("/a/c.json"));
        assert_eq!(url.as_deref(), Some("c.json"));
    }
}
