//! The findings under the matrix: what the counts and probe's diagnoses
//! say about each row, in sentences.

use super::table::Row;
use crate::explore::probe::diagnosis::{SamplerKind, Symptom, CENTRE};
use crate::harness::judge::Verdict;
use crate::harness::runner::CaseOutcome;
use crate::metrics::counted::counted;
use crate::scene::{FillRule, Primitive};

/// Lines at least this long (in pixels) are "long lines" in the findings.
pub const LONG_LINE: f64 = 256.0;

fn examples(ids: &[String]) -> String {
    let shown: Vec<&str> = ids.iter().take(3).map(String::as_str).collect();
    let more = ids.len().saturating_sub(shown.len());
    format!(
        "`{}`{}",
        shown.join("`, `"),
        if more > 0 {
            format!(" and {more} more")
        } else {
            String::new()
        }
    )
}

/// Whether a case is about ties: a sample, a vertex or a line exactly on a
/// decision boundary (by its id: `tie`, `shared_edge`, `fill_rule`).
fn is_tie_case(id: &str) -> bool {
    id.contains("tie") || id.contains("shared_edge") || id.contains("fill_rule")
}

/// The length of the longest line in a case, in pixels.
fn longest_line(outcome: &CaseOutcome) -> f64 {
    outcome.scene.as_ref().map_or(0.0, |s| {
        s.primitives
            .iter()
            .filter_map(|p| match p {
                Primitive::Line(l) => {
                    let [a, b] = &l.vertices;
                    let dx = b.x.to_f64_lossy() - a.x.to_f64_lossy();
                    let dy = b.y.to_f64_lossy() - a.y.to_f64_lossy();
                    Some(dx.hypot(dy))
                }
                Primitive::Triangle(_) | Primitive::Polygon(_) | Primitive::Point(_) => None,
            })
            .fold(0.0, f64::max)
    })
}

pub(super) fn findings(
    rows: &[Row],
    slot: &[Option<usize>],
    outcomes: &[CaseOutcome],
) -> Vec<String> {
    let mut out = Vec::new();
    let mut clean: Vec<String> = Vec::new();
    for (row, slot) in rows.iter().zip(slot) {
        let name = format!("`{}`", row.name);
        let Some(k) = *slot else {
            if let Err(why) = &row.available {
                out.push(format!("{name} is not available: {why}."));
            }
            continue;
        };
        let runs = || {
            outcomes
                .iter()
                .filter_map(move |o| o.candidates.get(k).map(|r| (o, r)))
        };
        // Watertightness on mesh cases stated under the top-left rule.
        let (mut meshes, mut overdraw, mut holes, mut owner) = (0usize, 0u64, 0u64, 0u64);
        let (mut od_cases, mut hole_cases, mut owner_cases) = (Vec::new(), Vec::new(), Vec::new());
        for (o, r) in runs() {
            let top_left = o
                .scene
                .as_ref()
                .is_some_and(|s| s.rules.fill_rule == FillRule::TopLeft);
            let (Some(m), true) = (&r.metrics, top_left) else {
                continue;
            };
            let Some(w) = &m.watertight else { continue };
            meshes += 1;
            overdraw += w.overdraw;
            holes += w.holes;
            if w.overdraw > 0 {
                od_cases.push(o.file.id.clone());
            }
            if w.holes > 0 {
                hole_cases.push(o.file.id.clone());
            }
            if w.is_watertight() && m.coverage.wrong_owner > 0 {
                owner += m.coverage.wrong_owner;
                owner_cases.push(o.file.id.clone());
            }
        }
        let mut said = false;
        // Why: probe's decision, or why there is none.
        let judged = row.own_rule.map_or("top-left", FillRule::name);
        let cause = |symptom: Symptom| match &row.diagnosis {
            Some(Ok(d)) => d.cause(symptom, judged),
            Some(Err(e)) => format!("Probe could not say why: {e}."),
            None => String::new(),
        };
        if overdraw > 0 {
            said = true;
            out.push(format!(
                "{name} is not watertight under the {judged} rule: {} in {} of {} ({}). {}",
                counted(overdraw, "overdrawn sample", "overdrawn samples"),
                od_cases.len(),
                counted(meshes as u64, "mesh case", "mesh cases"),
                examples(&od_cases),
                cause(Symptom::Overdraw)
            ));
        }
        if holes > 0 {
            said = true;
            out.push(format!(
                "{name} leaves {} in {} of {} ({}): samples inside the mesh that no triangle draws. {}",
                counted(holes, "hole", "holes"),
                hole_cases.len(),
                counted(meshes as u64, "mesh case", "mesh cases"),
                examples(&hole_cases),
                cause(Symptom::Holes)
            ));
        }
        if owner > 0 {
            said = true;
            out.push(format!(
                "{name} keeps {} watertight (no overdraw, no holes) but gives {} to the other triangle ({}). {}",
                counted(owner_cases.len() as u64, "mesh case", "mesh cases"),
                counted(owner, "tie sample", "tie samples"),
                examples(&owner_cases),
                cause(Symptom::WrongOwner)
            ));
        }
        // Tie cases.
        let ties: Vec<_> = runs()
            .filter(|(o, r)| is_tie_case(&o.file.id) && r.metrics.is_some())
            .collect();
        let failed: Vec<String> = ties
            .iter()
            .filter(|(_, r)| matches!(r.verdict, Verdict::Fail(_)))
            .map(|(o, _)| o.file.id.clone())
            .collect();
        if !failed.is_empty() {
            said = true;
            out.push(format!(
                "{name} {} {} of the {} tie cases it draws ({}).",
                if row.foil { "departs on" } else { "fails" },
                failed.len(),
                ties.len(),
                examples(&failed)
            ));
        }
        // Long lines.
        let long: Vec<_> = runs()
            .filter(|(o, _)| longest_line(o) >= LONG_LINE)
            .collect();
        let drawn: Vec<_> = long.iter().filter(|(_, r)| r.metrics.is_some()).collect();
        let departed: Vec<String> = drawn
            .iter()
            .filter(|(_, r)| matches!(r.verdict, Verdict::Fail(_)))
            .map(|(o, _)| o.file.id.clone())
            .collect();
        if !departed.is_empty() {
            said = true;
            out.push(format!(
                "{name} {} {} of {} long-line cases (a line of {LONG_LINE} px or more; {}).",
                if row.foil { "departs on" } else { "fails" },
                departed.len(),
                drawn.len(),
                examples(&departed)
            ));
        }
        // Whole families it cannot draw.
        let lines: Vec<_> = runs()
            .filter(|(o, _)| {
                o.scene
                    .as_ref()
                    .is_some_and(|s| s.primitives.iter().all(|p| matches!(p, Primitive::Line(_))))
            })
            .collect();
        if !lines.is_empty()
            && lines
                .iter()
                .all(|(_, r)| matches!(r.verdict, Verdict::Unsupported(_)))
        {
            out.push(format!(
                "{name} draws no lines: all {} line-only cases are unsupported.",
                lines.len()
            ));
        }
        // Interpolation beyond the bound.
        let mut worst: Option<(f64, String, String)> = None;
        let mut beyond = 0;
        for (o, r) in runs() {
            let Some(m) = &r.metrics else { continue };
            if m.channels.iter().any(|c| !c.within_bounds()) {
                beyond += 1;
            }
            for c in &m.channels {
                // How far past the tighter of its bounds (absolute, ulp).
                let ulp_ratio = c.allowed_ulp.map_or(0.0, |u| c.max_ulp / u);
                let ratio = (c.max_abs / c.allowed_abs).max(ulp_ratio);
                if !c.within_bounds() && worst.as_ref().is_none_or(|w| ratio > w.0) {
                    worst = Some((ratio, o.file.id.clone(), c.channel.clone()));
                }
            }
        }
        if let Some((ratio, id, channel)) = worst {
            said = true;
            out.push(format!(
                "{name} interpolates beyond the bound in {} (worst: {channel} of `{id}`, {ratio:.1}× the bound).",
                counted(beyond as u64, "case", "cases")
            ));
        }
        let errors: Vec<String> = runs()
            .filter(|(_, r)| matches!(r.verdict, Verdict::Error(_)))
            .map(|(o, _)| o.file.id.clone())
            .collect();
        if !errors.is_empty() {
            said = true;
            out.push(format!(
                "{name} broke (error) on {} ({}).",
                counted(errors.len() as u64, "case", "cases"),
                examples(&errors)
            ));
        }
        // "Top-left ties" is probe's word as well as the counts'.
        let top_left = matches!(&row.diagnosis, Some(Ok(d)) if d.sampler.kind == SamplerKind::Point
            && d.offset == Some(CENTRE)
            && d.fill_rule.as_deref() == Some("top-left")
            && d.fill_rule_consistent);
        if !said && meshes > 0 && top_left {
            clean.push(name);
        }
    }
    out.splice(0..0, sampler_findings(rows));
    if !clean.is_empty() {
        out.insert(
            0,
            format!(
                "{}: watertight with top-left ties on every mesh case, every tie and long-line case exact, interpolation within the bound.",
                clean.join(", ")
            ),
        );
    }
    out
}

/// The rows grouped by probe's diagnosis: "Probe: `a`, `b` are
/// point-sampled at the pixel centre, tie rule top-left.", one finding per
/// diagnosis, in the order rows first show it.
fn sampler_findings(rows: &[Row]) -> Vec<String> {
    let mut groups: Vec<(String, Vec<String>)> = Vec::new();
    for row in rows {
        let Some(diagnosis) = &row.diagnosis else {
            continue;
        };
        let said = match diagnosis {
            Ok(d) => d.summary(),
            Err(e) => format!("not diagnosed ({e})"),
        };
        let name = format!("`{}`", row.name);
        match groups.iter_mut().find(|(s, _)| *s == said) {
            Some((_, names)) => names.push(name),
            None => groups.push((said, vec![name])),
        }
    }
    groups
        .into_iter()
        .map(|(said, names)| format!("Probe: {}: {said}.", names.join(", ")))
        .collect()
}
