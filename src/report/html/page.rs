//! The page of one case, drawn while its frames are in memory, and where
//! case pages live.

use std::fmt::Write as _;
use std::path::Path;

use super::cards::{self, case_card, result_card, Card, ResultView};
use super::shell::head;
use crate::frame::Frame;
use crate::harness::runner::CaseOutcome;
use crate::report::escape::escape;
use crate::report::json::CaseEntry;

/// The file of a case's page, relative to the report folder.
pub fn page_file(id: &str) -> String {
    format!("pages/{id}.html")
}

/// A link from the report folder to a case's page, at `anchor`.
pub(super) fn page_url(page: &str, anchor: &str) -> String {
    format!("{}#{anchor}", cards::file_url(page))
}

/// The page of one case: its cards (see [`cards_of`](super::cards::cards_of)) drawn from the
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
                    mask: outcome
                        .candidates
                        .get(r)
                        .and_then(|run| run.metrics.as_ref())
                        .map(|m| m.coverage.mask.as_slice())
                        .filter(|m| !m.is_empty()),
                };
                html.push_str(&result_card(dir, &view));
            }
        }
        html.push('\n');
    }
    html.push_str("</main></body></html>\n");
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
