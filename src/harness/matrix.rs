//! The conformance matrix: every case through a list of rasterizers, one
//! row per rasterizer and one column per case family, with findings
//! computed from the results, as markdown (and into README.md between the
//! markers `<!-- matrix:begin -->` and `<!-- matrix:end -->`).
//!
//! A rasterizer that cannot start (not compiled into this build, no driver,
//! a program that will not run) is a row that says "not available" and
//! why; it is never dropped.
//!
//! What the findings say about a row's sampler and tie rule is `probe`'s
//! decision ([`Diagnosis`], made by the function [`build`] is given), never
//! a guess from the counts: overdraw is blamed on closed edges only when
//! probe finds closed edges, and on an any-coverage or area sampler when
//! probe finds one. The counts say how much; the diagnosis says why.

use std::collections::BTreeSet;
use std::path::Path;

use crate::frame::Frame;
use crate::harness::diagnosis::{Diagnosis, SamplerKind, Symptom, CENTRE};
use crate::harness::runner::{self, CaseOutcome};
use crate::harness::suite::{self, CaseFile, Verdict};
use crate::plan::Plan;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::scene::{parse_case, FillRule, Limits, Primitive};

pub const BEGIN: &str = "<!-- matrix:begin -->";
pub const END: &str = "<!-- matrix:end -->";

/// The external example in the default rows.
pub const PYTHON_EXAMPLE: &str =
    "external-persistent:python3 examples/python_rasterizer.py --persistent";

/// Lines at least this long (in pixels) are "long lines" in the findings.
pub const LONG_LINE: f64 = 256.0;

/// The rows when none are named.
pub fn default_rows() -> Vec<String> {
    [
        "production",
        "dda-f32",
        "dda-f64",
        "float-f32",
        "float-f64",
        "foil-offset-sampler",
        "foil-area-sampler",
        "foil-any-coverage",
        "tiny-skia",
        "euc",
        PYTHON_EXAMPLE,
        "vulkan",
        "lavapipe",
        "gl",
    ]
    .map(str::to_owned)
    .to_vec()
}

/// Built-in adapters a build may leave out, with the feature that has them.
const OPTIONAL: [(&str, &str); 7] = [
    ("vulkan", "vulkan"),
    ("lavapipe", "lavapipe"),
    ("gl", "gl"),
    ("softpipe", "gl"),
    ("tiny-skia", "tiny-skia"),
    ("euc", "euc"),
    ("vello-cpu", "vello"),
];

/// One family's counts for one rasterizer.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Cell {
    pub cases: usize,
    pub pass: usize,
    pub fail: usize,
    /// A foil's departures (failures that are expected).
    pub departures: usize,
    pub unsupported: usize,
    pub error: usize,
    /// Samples whose coverage differs, summed over the cases it drew.
    pub mismatched: u64,
    /// Mesh cases drawn, and their overdraw and holes.
    pub mesh_cases: usize,
    pub overdraw: u64,
    pub holes: u64,
}

/// One rasterizer's row.
#[derive(Clone, Debug)]
pub struct Row {
    pub name: String,
    pub foil: bool,
    /// `Err(reason)` when the rasterizer could not start.
    pub available: Result<(), String>,
    /// One per family, in [`Matrix::families`] order.
    pub cells: Vec<Cell>,
    /// Probe's decision on its sampler and tie rule, when it is available
    /// (`Err`: why probe could not decide).
    pub diagnosis: Option<Result<Diagnosis, String>>,
    /// The fill rule it follows whatever a case states, and is judged under
    /// (SPEC.md §3.1), when it has one.
    pub own_rule: Option<FillRule>,
}

/// How [`build`] diagnoses a row: `explore::probe::diagnose` (the harness
/// does not import the layer above it; its caller hands it down).
pub type Diagnose<'a> = &'a (dyn Fn(&dyn Rasterizer) -> Result<Diagnosis, String> + Sync);

#[derive(Clone, Debug)]
pub struct Matrix {
    /// (family, number of cases).
    pub families: Vec<(String, usize)>,
    pub rows: Vec<Row>,
    pub findings: Vec<String>,
    pub cases: usize,
    pub unreadable: usize,
}

/// The family of a case id: its first segment, or `top-level`.
pub fn family(id: &str) -> String {
    match id.split_once('/') {
        Some((first, _)) => first.to_owned(),
        None => "top-level".to_owned(),
    }
}

/// Orders families: triangles, lines, hard, top-level, then the rest.
fn family_rank(f: &str) -> (usize, String) {
    let known = ["triangles", "lines", "hard", "top-level"];
    (
        known.iter().position(|k| *k == f).unwrap_or(known.len()),
        f.to_owned(),
    )
}

/// Whether a rasterizer starts: it must draw (or refuse as unsupported) a
/// one-triangle scene. `Err` says why not.
pub fn check_available(candidate: &dyn Rasterizer) -> Result<(), String> {
    let scene = parse_case(
        r#"{"name": "matrix_smoke", "canvas": {"width": 4, "height": 4},
            "primitives": [{"triangle": [[0, 0], [4, 0], [0, 4]]}]}"#,
        "matrix",
        &Limits::default(),
    )
    .map_err(|e| e.to_string())?;
    let plan = Plan::for_scene(&scene);
    let result: Result<Result<Frame, RasterError>, _> =
        std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            candidate.rasterize(&scene, &plan)
        }));
    match result {
        Ok(Ok(_)) | Ok(Err(RasterError::Unsupported(_))) => Ok(()),
        Ok(Err(RasterError::Failed(why))) => Err(why),
        Err(panic) => Err(format!("panicked: {}", suite::panic_message(&*panic))),
    }
}

/// A rasterizer by name, or why there is none in this build. `None` for a
/// name rastercheck does not know at all.
pub fn rasterizer(name: &str) -> Option<Result<Box<dyn Rasterizer>, String>> {
    if let Some(r) = suite::rasterizer(name) {
        return Some(Ok(r));
    }
    OPTIONAL
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, feature)| {
            Err(format!(
                "not compiled into this build (cargo feature `{feature}`)"
            ))
        })
}

/// Runs every case through every named rasterizer, diagnoses each with
/// `diagnose`, and tabulates. Unknown names are the caller's to refuse
/// (see [`rasterizer`]).
pub fn build(
    files: &[CaseFile],
    limits: &Limits,
    names: &[String],
    threads: Option<usize>,
    diagnose: Diagnose,
) -> Matrix {
    let mut rows: Vec<Row> = Vec::new();
    let mut candidates: Vec<Box<dyn Rasterizer>> = Vec::new();
    // For each row, its index among `candidates` when available.
    let mut slot: Vec<Option<usize>> = Vec::new();
    for name in names {
        // The row is called what the rasterizer calls itself (NAME in
        // `-r NAME=external…`).
        let mut row_name = name.clone();
        let (available, foil) = match rasterizer(name) {
            None => (Err("unknown rasterizer".to_owned()), false),
            Some(Err(why)) => (Err(why), false),
            Some(Ok(r)) => {
                let foil = r.is_foil();
                row_name = r.name().to_owned();
                match check_available(r.as_ref()) {
                    Ok(()) => {
                        candidates.push(r);
                        (Ok(()), foil)
                    }
                    Err(why) => (Err(why), foil),
                }
            }
        };
        slot.push(available.is_ok().then(|| candidates.len() - 1));
        let diagnosis = available
            .is_ok()
            .then(|| candidates.last().map(|r| diagnose(r.as_ref())))
            .flatten();
        // Asked after probe has drawn with it: a program's hello says it.
        let own_rule = available
            .is_ok()
            .then(|| candidates.last().and_then(|r| r.fixed_fill_rule()))
            .flatten();
        rows.push(Row {
            name: row_name,
            foil,
            available,
            cells: Vec::new(),
            diagnosis,
            own_rule,
        });
    }
    let root = Path::new(".");
    let mut outcomes = runner::run_all(files, limits, &candidates, root, threads, &|_, _| {});
    runner::reject_duplicate_names(&mut outcomes);

    let mut families: Vec<String> = files
        .iter()
        .map(|f| family(&f.id))
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    families.sort_by_key(|f| family_rank(f));
    let family_sizes = families
        .iter()
        .map(|f| {
            (
                f.clone(),
                files.iter().filter(|c| family(&c.id) == *f).count(),
            )
        })
        .collect();
    for (row, slot) in rows.iter_mut().zip(&slot) {
        row.cells = vec![Cell::default(); families.len()];
        let Some(k) = *slot else { continue };
        for outcome in &outcomes {
            let Some(run) = outcome.candidates.get(k) else {
                continue;
            };
            let f = family(&outcome.file.id);
            let Some(cell) = families
                .iter()
                .position(|x| *x == f)
                .map(|i| &mut row.cells[i])
            else {
                continue;
            };
            cell.cases += 1;
            match &run.verdict {
                Verdict::Pass => cell.pass += 1,
                Verdict::Fail(_) if row.foil => cell.departures += 1,
                Verdict::Fail(_) => cell.fail += 1,
                Verdict::Unsupported(_) => cell.unsupported += 1,
                Verdict::Error(_) => cell.error += 1,
            }
            if let Some(m) = &run.metrics {
                cell.mismatched += m.coverage.mismatched();
                if let Some(w) = &m.watertight {
                    cell.mesh_cases += 1;
                    cell.overdraw += w.overdraw;
                    cell.holes += w.holes;
                }
            }
        }
    }
    let findings = findings(&rows, &slot, &outcomes);
    let unreadable = outcomes
        .iter()
        .filter(|o| matches!(o.problem, Some(runner::Problem::Unreadable(_))))
        .count();
    Matrix {
        families: family_sizes,
        rows,
        findings,
        cases: files.len(),
        unreadable,
    }
}

fn plural(n: impl Into<u64>, one: &str, many: &str) -> String {
    let n = n.into();
    format!("{n} {}", if n == 1 { one } else { many })
}

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

fn findings(rows: &[Row], slot: &[Option<usize>], outcomes: &[CaseOutcome]) -> Vec<String> {
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
                plural(overdraw, "overdrawn sample", "overdrawn samples"),
                od_cases.len(),
                plural(meshes as u64, "mesh case", "mesh cases"),
                examples(&od_cases),
                cause(Symptom::Overdraw)
            ));
        }
        if holes > 0 {
            said = true;
            out.push(format!(
                "{name} leaves {} in {} of {} ({}): samples inside the mesh that no triangle draws. {}",
                plural(holes, "hole", "holes"),
                hole_cases.len(),
                plural(meshes as u64, "mesh case", "mesh cases"),
                examples(&hole_cases),
                cause(Symptom::Holes)
            ));
        }
        if owner > 0 {
            said = true;
            out.push(format!(
                "{name} keeps {} watertight (no overdraw, no holes) but gives {} to the other triangle ({}). {}",
                plural(owner_cases.len() as u64, "mesh case", "mesh cases"),
                plural(owner, "tie sample", "tie samples"),
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
                plural(beyond as u64, "case", "cases")
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
                plural(errors.len() as u64, "case", "cases"),
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

fn cell_text(cell: &Cell, foil: bool) -> String {
    if cell.cases == 0 {
        return "–".to_owned();
    }
    if cell.unsupported == cell.cases {
        return format!("all {} unsupported", cell.cases);
    }
    let mut parts = if foil {
        vec![
            format!("{} exact", cell.pass),
            plural(cell.departures as u64, "departure", "departures"),
        ]
    } else {
        vec![format!("{} pass", cell.pass), format!("{} fail", cell.fail)]
    };
    if cell.unsupported > 0 {
        parts.push(format!("{} unsupported", cell.unsupported));
    }
    if cell.error > 0 {
        parts.push(plural(cell.error as u64, "error", "errors"));
    }
    let mut metrics = vec![format!("{} mismatched", cell.mismatched)];
    if cell.mesh_cases > 0 {
        metrics.push(format!("overdraw {}", cell.overdraw));
        metrics.push(format!("holes {}", cell.holes));
    }
    format!("{}<br>{}", parts.join(" · "), metrics.join(" · "))
}

impl Matrix {
    /// The table, then the findings, as markdown.
    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
        s += "| rasterizer |";
        for (f, n) in &self.families {
            s += &format!(" {f} ({n}) |");
        }
        s += "\n|---|";
        for _ in &self.families {
            s += "---|";
        }
        s += "\n";
        for row in &self.rows {
            let label = if row.foil {
                format!("`{}` (foil)", row.name)
            } else {
                format!("`{}`", row.name)
            };
            s += &format!("| {label} |");
            match &row.available {
                Err(why) => {
                    s += &format!(
                        " not available: {}",
                        why.replace('|', "\\|").replace('\n', " ")
                    );
                    s += " |";
                    for _ in 1..self.families.len() {
                        s += " |";
                    }
                }
                Ok(()) => {
                    for cell in &row.cells {
                        s += &format!(" {} |", cell_text(cell, row.foil));
                    }
                }
            }
            s += "\n";
        }
        s += "\nEach cell: verdicts (a foil's failures are departures, never failures), then the samples whose coverage differs from the reference summed over the family, and for mesh cases the overdrawn samples and holes.\n";
        s += "\n**Findings**\n\n";
        if self.findings.is_empty() {
            s += "- nothing to report.\n";
        }
        for f in &self.findings {
            s += &format!("- {f}\n");
        }
        s
    }

    /// The block written between the README markers.
    pub fn readme_block(&self, date: &str) -> String {
        let features: Vec<&str> = [
            ("tiny-skia", cfg!(feature = "tiny-skia")),
            ("euc", cfg!(feature = "euc")),
            ("vulkan", cfg!(feature = "vulkan")),
            ("lavapipe", cfg!(feature = "lavapipe")),
            ("gl", cfg!(feature = "gl")),
            ("vello", cfg!(feature = "vello")),
        ]
        .iter()
        .filter(|(_, on)| *on)
        .map(|(n, _)| *n)
        .collect();
        format!(
            "Generated by `rastercheck matrix --write-readme README.md` on {date} with rastercheck {} (cargo features: {}), over {} cases.\n\n{}",
            env!("CARGO_PKG_VERSION"),
            if features.is_empty() { "none".to_owned() } else { features.join(", ") },
            self.cases,
            self.to_markdown()
        )
    }
}

/// `text` with the part between the markers replaced by `block`; the
/// markers and everything outside them are kept.
pub fn replace_block(text: &str, block: &str) -> Result<String, String> {
    let start = text
        .find(BEGIN)
        .ok_or_else(|| format!("no {BEGIN} marker"))?;
    let after_begin = start + BEGIN.len();
    let end = text[after_begin..]
        .find(END)
        .map(|i| after_begin + i)
        .ok_or_else(|| format!("no {END} marker after {BEGIN}"))?;
    Ok(format!(
        "{}\n{}\n{}",
        &text[..after_begin],
        block.trim_end(),
        &text[end..]
    ))
}

/// Today's date (UTC) as YYYY-MM-DD.
pub fn today() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    civil_date((secs / 86_400) as i64)
}

/// The proleptic Gregorian date of a day count since 1970-01-01
/// (Howard Hinnant's `civil_from_days`).
pub fn civil_date(days: i64) -> String {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates() {
        assert_eq!(civil_date(0), "1970-01-01");
        assert_eq!(civil_date(11_016), "2000-02-29");
        assert_eq!(civil_date(20_000), "2024-10-04");
    }

    #[test]
    fn only_the_marked_block_is_replaced() {
        let text = format!("a\n{BEGIN}\nold\n{END}\nb\n");
        let new = replace_block(&text, "new\n").unwrap();
        assert_eq!(new, format!("a\n{BEGIN}\nnew\n{END}\nb\n"));
        assert!(replace_block("no markers", "x").is_err());
    }
}
