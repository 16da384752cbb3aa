//! Reports put together: the shards of one run back into the run, and
//! runs of the same cases on other rasterizers, drivers or machines beside
//! it, one row each (SPEC.md §10.3).
//!
//! The reports are first grouped into runs: reports with the same
//! rasterizers (name, foil, `declared`) and the same shard count are the
//! shards of one run; an unsharded report is a run of its own per host.
//! A run's shards must be exactly 1/N … N/N, each once, and interleave as
//! `--shard` deals cases out (shard k holds selected cases k, k + N, …),
//! which puts the cases back in the unsharded run's order. Then the runs
//! stand side by side: every run must hold the same case ids, each from
//! the same case file (`hash`) with the same status, and a rasterizer
//! name in more than one run becomes one row per run, named by its host
//! (and driver, when the hosts agree). Anything else (two verdicts for one
//! case and rasterizer, a shard missing or given twice, two files behind
//! one id, different tool versions or limits) is an error naming what
//! disagrees: nothing is resolved silently.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::path::{Component, Path, PathBuf};

use super::read::Input;
use crate::harness::runner::Selection;
use crate::rasterizer::ApiRecord;
use crate::report::json::{CaseEntry, RasterizerInfo, Report, Source, Totals, SCHEMA};
use crate::report::machine::Machine;

/// Errors listed before the rest are counted.
pub const MAX_ERRORS: usize = 50;

/// The merged report, and the files to copy into its folder: each
/// source file, and its path relative to the merged folder.
#[derive(Debug)]
pub struct Merged {
    pub report: Report,
    pub copies: Vec<(PathBuf, String)>,
    /// How many runs the reports formed.
    pub runs: usize,
}

/// A rasterizer as a run declares it: name, foil, `declared`.
type RowId = (String, bool, Option<String>);

/// One run: its shards, by shard number.
struct Run<'a> {
    rows: Vec<RowId>,
    count: usize,
    /// The host of an unsharded run (a shard's host does not split runs).
    host: Option<String>,
    shards: BTreeMap<usize, Vec<&'a Input>>,
}

impl Run<'_> {
    fn hosts(&self) -> String {
        let hosts: BTreeSet<&str> = self
            .shards
            .values()
            .flatten()
            .map(|i| i.report.machine.host.as_str())
            .collect();
        hosts.into_iter().collect::<Vec<_>>().join("+")
    }

    fn files(&self) -> String {
        let files: Vec<String> = self
            .shards
            .values()
            .flatten()
            .map(|i| i.file.display().to_string())
            .collect();
        files.join(", ")
    }
}

fn rows_of(report: &Report) -> Vec<RowId> {
    report
        .rasterizers
        .iter()
        .map(|r| (r.name.clone(), r.foil, r.declared.clone()))
        .collect()
}

/// Merges `inputs` (at least one) into one report whose `command` is
/// `command`. `Err` lists every disagreement found, each naming its case
/// or reports.
pub fn merge(inputs: &[Input], command: Vec<String>) -> Result<Merged, Vec<String>> {
    let mut errors = Vec::new();
    let first = &inputs[0];
    for input in &inputs[1..] {
        let (a, b) = (&first.report, &input.report);
        if (a.tool.name, a.tool.version) != (b.tool.name, b.tool.version) {
            errors.push(format!(
                "different tool versions: {} was written by {} {}, {} by {} {}",
                first.file.display(),
                a.tool.name,
                a.tool.version,
                input.file.display(),
                b.tool.name,
                b.tool.version
            ));
        }
        let limits = |r: &Report| serde_json::to_string(&r.limits).unwrap_or_default();
        if limits(a) != limits(b) {
            errors.push(format!(
                "different limits: {} ran under {}, {} under {}",
                first.file.display(),
                limits(a),
                input.file.display(),
                limits(b)
            ));
        }
    }
    let runs = group(inputs, &mut errors);
    let mut cases: Vec<Vec<(CaseEntry, &Input)>> = Vec::new();
    for run in &runs {
        cases.push(interleave(run, &mut errors));
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let labels = labels(&runs, &mut errors);
    let merged = side_by_side(&runs, cases, &labels, &mut errors);
    if !errors.is_empty() {
        return Err(errors);
    }
    let (cases, copies) = merged;
    let mut rasterizers = Vec::new();
    let mut sources = Vec::new();
    for (run, labels) in runs.iter().zip(&labels) {
        for (k, (row, label)) in run.rows.iter().zip(labels).enumerate() {
            let records: Vec<&ApiRecord> = run
                .shards
                .values()
                .flatten()
                .filter_map(|i| i.report.rasterizers[k].api_record.as_ref())
                .collect();
            rasterizers.push(RasterizerInfo {
                name: label.clone(),
                foil: row.1,
                declared: row.2.clone(),
                api_record: sum_records(&records),
            });
        }
        for input in run.shards.values().flatten() {
            sources.push(Source {
                report: input.file.display().to_string(),
                machine: input.report.machine.clone(),
                shard: input.report.shard.clone(),
                rows: labels.clone(),
            });
        }
    }
    let mut seeds: Vec<u64> = inputs.iter().flat_map(|i| i.report.seeds.clone()).collect();
    seeds.sort_unstable();
    seeds.dedup();
    let report = Report {
        schema: SCHEMA,
        tool: first.report.tool.clone(),
        complete: inputs.iter().all(|i| i.report.complete),
        command,
        machine: Machine::here(),
        shard: None,
        sources,
        rasterizers,
        limits: first.report.limits.clone(),
        seeds,
        totals: Totals::default(),
        cases,
    };
    Ok(Merged {
        report,
        copies,
        runs: runs.len(),
    })
}

/// The reports grouped into runs, shards checked: none missing, none twice.
fn group<'a>(inputs: &'a [Input], errors: &mut Vec<String>) -> Vec<Run<'a>> {
    let mut runs: Vec<Run<'a>> = Vec::new();
    for input in inputs {
        let (k, count) = match input.report.shard.as_deref().map(Selection::parse_shard) {
            None => (1, 1),
            Some(Ok(shard)) => shard,
            Some(Err(e)) => {
                errors.push(format!("{}: $.shard: {e}", input.file.display()));
                continue;
            }
        };
        let rows = rows_of(&input.report);
        let host = (count == 1).then(|| input.report.machine.host.clone());
        let run = match runs
            .iter_mut()
            .position(|r| r.rows == rows && r.count == count && r.host == host)
        {
            Some(at) => &mut runs[at],
            None => {
                runs.push(Run {
                    rows,
                    count,
                    host,
                    shards: BTreeMap::new(),
                });
                runs.last_mut().expect("just pushed")
            }
        };
        run.shards.entry(k).or_default().push(input);
    }
    for run in &runs {
        let names: Vec<&str> = run.rows.iter().map(|r| r.0.as_str()).collect();
        for (k, given) in &run.shards {
            if given.len() > 1 {
                let files: Vec<String> =
                    given.iter().map(|i| i.file.display().to_string()).collect();
                errors.push(format!(
                    "shard {k}/{} of the run of {} given {} times ({}): every case in it would have two verdicts for one rasterizer",
                    run.count,
                    names.join(", "),
                    given.len(),
                    files.join(", ")
                ));
            }
        }
        let missing: Vec<String> = (1..=run.count)
            .filter(|k| !run.shards.contains_key(k))
            .map(|k| format!("{k}/{}", run.count))
            .collect();
        if !missing.is_empty() {
            errors.push(format!(
                "the run of {} ({}) misses shard {}: its cases would be missing from the merged report",
                names.join(", "),
                run.files(),
                missing.join(", ")
            ));
        }
    }
    runs
}

/// A run's cases in the unsharded order, each with the report it came
/// from; a case in two shards, or shards that do not interleave, an error.
fn interleave<'a>(run: &Run<'a>, errors: &mut Vec<String>) -> Vec<(CaseEntry, &'a Input)> {
    let shards: Vec<&Input> = run
        .shards
        .values()
        .filter_map(|s| s.first().copied())
        .collect();
    if shards.len() != run.count {
        return Vec::new();
    }
    let total: usize = shards.iter().map(|s| s.report.cases.len()).sum();
    for (k, shard) in shards.iter().enumerate() {
        let expected = total.saturating_sub(k).div_ceil(run.count);
        if shard.report.cases.len() != expected {
            errors.push(format!(
                "{}: shard {}/{} holds {} cases where {} shards of {total} cases hold {expected}: these are not the shards of one selection",
                shard.file.display(),
                k + 1,
                run.count,
                shard.report.cases.len(),
                run.count
            ));
        }
    }
    let mut seen: HashMap<&str, &Input> = HashMap::new();
    let mut cases = Vec::with_capacity(total);
    for p in 0..total {
        let shard = shards[p % run.count];
        let Some(case) = shard.report.cases.get(p / run.count) else {
            continue;
        };
        if let Some(other) = seen.insert(&case.id, shard) {
            errors.push(format!(
                "case {}: in {} and in {}: two verdicts for it from {}",
                case.id,
                other.file.display(),
                shard.file.display(),
                run.rows.first().map_or("(no rasterizer)", |r| r.0.as_str())
            ));
        }
        cases.push((case.clone(), shard));
    }
    cases
}

/// Each run's row names: a rasterizer's own name, or, when another run
/// has one of that name, the name `on` its host (and its driver, when the
/// hosts agree).
fn labels(runs: &[Run], errors: &mut Vec<String>) -> Vec<Vec<String>> {
    let mut count: HashMap<&str, usize> = HashMap::new();
    for run in runs {
        for row in &run.rows {
            *count.entry(&row.0).or_default() += 1;
        }
    }
    let mut labels: Vec<Vec<String>> = runs
        .iter()
        .map(|run| {
            run.rows
                .iter()
                .map(|row| match count[row.0.as_str()] {
                    1 => row.0.clone(),
                    _ => format!("{} on {}", row.0, run.hosts()),
                })
                .collect()
        })
        .collect();
    let mut seen: HashMap<String, usize> = HashMap::new();
    for labels in &labels {
        for label in labels {
            *seen.entry(label.clone()).or_default() += 1;
        }
    }
    for (run, labels) in runs.iter().zip(labels.iter_mut()) {
        for (row, label) in run.rows.iter().zip(labels.iter_mut()) {
            if seen[label.as_str()] > 1 {
                if let Some(declared) = &row.2 {
                    *label = format!("{label} ({declared})");
                }
            }
        }
    }
    let mut taken: HashMap<&str, &Run> = HashMap::new();
    for (run, labels) in runs.iter().zip(&labels) {
        for label in labels {
            if let Some(other) = taken.insert(label, run) {
                errors.push(format!(
                    "rasterizer {label}: two runs of it on the same host and driver ({} and {}): every case would have two verdicts for it",
                    other.files(),
                    run.files()
                ));
            }
        }
    }
    labels
}

type CasesAndCopies = (Vec<CaseEntry>, Vec<(PathBuf, String)>);

/// The runs' cases side by side: one entry per case id, every run's
/// results in it, renamed to the rows; and the files to copy.
fn side_by_side(
    runs: &[Run],
    cases: Vec<Vec<(CaseEntry, &Input)>>,
    labels: &[Vec<String>],
    errors: &mut Vec<String>,
) -> CasesAndCopies {
    let mut copies = Vec::new();
    let by_id: Vec<HashMap<String, usize>> = cases
        .iter()
        .map(|run| {
            run.iter()
                .enumerate()
                .map(|(at, (case, _))| (case.id.clone(), at))
                .collect()
        })
        .collect();
    for (r, run) in runs.iter().enumerate().skip(1) {
        let missing: Vec<&str> = cases[0]
            .iter()
            .map(|(c, _)| c.id.as_str())
            .filter(|id| !by_id[r].contains_key(*id))
            .chain(
                cases[r]
                    .iter()
                    .map(|(c, _)| c.id.as_str())
                    .filter(|id| !by_id[0].contains_key(*id)),
            )
            .collect();
        for id in missing.iter().take(MAX_ERRORS) {
            errors.push(format!(
                "case {id}: in one run and not in the other ({} and {}): runs side by side must hold the same cases",
                runs[0].files(),
                run.files()
            ));
        }
    }
    let mut merged = Vec::with_capacity(cases[0].len());
    for (base, from) in &cases[0] {
        let mut entry = base.clone();
        entry.results.clear();
        entry.page = None;
        for (r, run_cases) in cases.iter().enumerate() {
            let Some(&at) = by_id[r].get(&base.id) else {
                continue;
            };
            let (case, input) = &run_cases[at];
            if r > 0 {
                agree(base, from, case, input, errors);
            }
            let prefix = match r {
                0 => String::new(),
                _ => format!("pages/run-{}/", r + 1),
            };
            let mut place = |file: &str| -> Option<String> {
                match inside(file) {
                    true => {
                        let to = format!("{prefix}{file}");
                        copies.push((input.dir.join(file), to.clone()));
                        Some(to)
                    }
                    false => {
                        errors.push(format!(
                            "{}: case {}: the file {file:?} is not a path inside the report folder",
                            input.file.display(),
                            case.id
                        ));
                        None
                    }
                }
            };
            if let Some(page) = &case.page {
                let placed = place(page);
                entry.page = entry.page.take().or(placed);
            }
            for (result, label) in case.results.iter().zip(&labels[r]) {
                let mut result = result.clone();
                result.rasterizer = label.clone();
                result.files = result.files.iter().filter_map(|f| place(f)).collect();
                entry.results.push(result);
            }
        }
        merged.push(entry);
    }
    (merged, copies)
}

/// Two runs' entries for one case id agree on its file and status.
fn agree(a: &CaseEntry, from_a: &Input, b: &CaseEntry, from_b: &Input, errors: &mut Vec<String>) {
    if let (Some(x), Some(y)) = (&a.hash, &b.hash) {
        if x != y {
            errors.push(format!(
                "case {}: different case files behind one id: {} in {} ({x}), {} in {} ({y})",
                a.id,
                a.path,
                from_a.file.display(),
                b.path,
                from_b.file.display()
            ));
        }
    }
    if a.status != b.status {
        errors.push(format!(
            "case {}: {} in {} but {} in {}",
            a.id,
            a.status,
            from_a.file.display(),
            b.status,
            from_b.file.display()
        ));
    }
}

/// Whether a path a report names stays inside its folder: relative, and
/// made of plain names only.
fn inside(file: &str) -> bool {
    let path = Path::new(file);
    !file.is_empty() && path.components().all(|c| matches!(c, Component::Normal(_)))
}

/// The API records of one row's shards added up: the first checker named,
/// the counts summed, the first message kept.
fn sum_records(records: &[&ApiRecord]) -> Option<ApiRecord> {
    let first = records.first()?;
    Some(ApiRecord {
        validated_by: records.iter().find_map(|r| r.validated_by.clone()),
        errors: records.iter().map(|r| r.errors).sum(),
        warnings: records.iter().map(|r| r.warnings).sum(),
        first: records
            .iter()
            .find_map(|r| r.first.clone())
            .or_else(|| first.first.clone()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::harness::discover::CaseFile;
    use crate::report::json::{LimitsInfo, ResultEntry};

    /// A report of `ids` judged `pass` by production, as shard `shard` on `host`.
    fn input(ids: &[&str], shard: Option<&str>, host: &str) -> Input {
        let mut report = Report::new(
            vec!["run".into()],
            vec![RasterizerInfo {
                name: "production".into(),
                foil: false,
                declared: None,
                api_record: None,
            }],
            LimitsInfo::of(&crate::scene::Limits::default()),
        );
        report.shard = shard.map(str::to_owned);
        report.machine.host = host.into();
        report.cases = ids
            .iter()
            .map(|id| {
                let mut case = CaseEntry::not_run(&CaseFile {
                    id: (*id).into(),
                    path: PathBuf::from(format!("cases/{id}.json")),
                });
                case.status = "ran";
                case.results.push(ResultEntry {
                    rasterizer: "production".into(),
                    verdict: "pass",
                    reasons: Vec::new(),
                    flaky: None,
                    time_ms: 0.0,
                    method: None,
                    judged_fill_rule: None,
                    ties: None,
                    judged_clip: None,
                    judged_subpixel_bits: None,
                    judged_snapping: None,
                    judged_sample_pattern: None,
                    judged_y: None,
                    judged_pixel_centre: None,
                    line_latitude: None,
                    conservative: None,
                    metrics: None,
                    files: Vec::new(),
                });
                case
            })
            .collect();
        Input {
            file: PathBuf::from(format!("{host}-{}", shard.unwrap_or("whole"))),
            dir: PathBuf::from("."),
            report,
        }
    }

    fn ids(merged: &Merged) -> Vec<&str> {
        merged.report.cases.iter().map(|c| c.id.as_str()).collect()
    }

    #[test]
    fn shards_go_back_into_the_order_they_were_dealt_from() {
        // a b c d e dealt to 2 shards: a c e, b d; given in either order.
        let one = input(&["a", "c", "e"], Some("1/2"), "x");
        let two = input(&["b", "d"], Some("2/2"), "y");
        let merged = merge(&[two.clone(), one.clone()], Vec::new()).unwrap();
        assert_eq!(ids(&merged), ["a", "b", "c", "d", "e"]);
        assert_eq!(merged.report.rasterizers.len(), 1);
        // A foil of the merge: the shards' cases one after the other are
        // not the run's order.
        let concatenated: Vec<&str> = one
            .report
            .cases
            .iter()
            .chain(&two.report.cases)
            .map(|c| c.id.as_str())
            .collect();
        assert_ne!(ids(&merged), concatenated);
    }

    #[test]
    fn shards_that_were_not_dealt_from_one_selection_are_refused() {
        let one = input(&["a", "c", "e"], Some("1/2"), "x");
        let two = input(&["b"], Some("2/2"), "y");
        let errors = merge(&[one, two], Vec::new()).unwrap_err();
        assert!(
            errors[0].contains("not the shards of one selection"),
            "{errors:?}"
        );
    }

    #[test]
    fn one_rasterizer_on_two_hosts_is_two_rows() {
        let a = input(&["a", "b"], None, "board-a");
        let b = input(&["a", "b"], None, "board-b");
        let merged = merge(&[a, b], Vec::new()).unwrap();
        let rows: Vec<&str> = merged
            .report
            .rasterizers
            .iter()
            .map(|r| r.name.as_str())
            .collect();
        assert_eq!(rows, ["production on board-a", "production on board-b"]);
        assert_eq!(
            merged.report.cases[1].results[1].rasterizer,
            "production on board-b"
        );
        assert_eq!(merged.runs, 2);
    }

    #[test]
    fn a_path_out_of_the_report_folder_is_refused() {
        let mut a = input(&["a"], None, "h");
        a.report.cases[0].page = Some("../../etc/passwd".into());
        let errors = merge(&[a], Vec::new()).unwrap_err();
        assert!(
            errors[0].contains("not a path inside the report folder"),
            "{errors:?}"
        );
    }
}
