//! Building the matrix: every case through every row's rasterizer, each
//! available row diagnosed by `probe`, the verdicts counted per family.

use std::collections::BTreeSet;
use std::path::Path;

use super::findings::findings;
use super::table::{family, family_rank, Cell, Matrix, Row};
use crate::explore::probe::diagnose;
use crate::frame::Frame;
use crate::harness::discover::CaseFile;
use crate::harness::judge::Verdict;
use crate::harness::panics::panic_message;
use crate::harness::runner;
use crate::plan::Plan;
use crate::rasterizer::{RasterError, Rasterizer};
use crate::registry::{self, Missing};
use crate::scene::{parse_case, Limits};

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
        Err(panic) => Err(format!("panicked: {}", panic_message(&*panic))),
    }
}

/// A rasterizer by name, or why there is none in this build. `None` for a
/// name rastercheck does not know at all.
pub fn rasterizer(name: &str) -> Option<Result<Box<dyn Rasterizer>, String>> {
    match registry::resolve(name) {
        Ok(r) => Some(Ok(r)),
        Err(Missing::NotCompiled { feature }) => Some(Err(format!(
            "not compiled into this build (cargo feature `{feature}`)"
        ))),
        Err(Missing::Unknown) => None,
    }
}

/// Runs every case through every named rasterizer, diagnoses each with
/// probe, and tabulates. Unknown names are the caller's to refuse
/// (see [`rasterizer`]).
pub fn build(
    files: &[CaseFile],
    limits: &Limits,
    names: &[String],
    threads: Option<usize>,
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
                // The matrix draws each case once: never flaky.
                Verdict::Flaky(_) => cell.fail += 1,
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
