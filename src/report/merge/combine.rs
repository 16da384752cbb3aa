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
use crate::report::html::cards_of;
use crate::report::json::{CaseEntry, RasterizerInfo, Report, Source, Totals, SCHEMA};
use crate::report::limits::{MAX_PAGES, MAX_PICTURED, MAX_PROBLEM_PAGES};
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
    let runs: Vec<Run<'a>> = runs.into_iter().flat_map(by_board).collect();
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
            let on = match &run.host {
                Some(host) if run.count > 1 => format!(
                    " on {host} (shards given more than once are told apart by the host each report names: RASTERCHECK_HOST names a board)"
                ),
                _ => String::new(),
            };
            errors.push(format!(
                "the run of {}{on} ({}) misses shard {}: its cases would be missing from the merged report",
                names.join(", "),
                run.files(),
                missing.join(", ")
            ));
        }
    }
    runs
}

/// A sharded run whose shards come more than once, split into one run per
/// host the reports name: the same rasterizers (and `declared` device) on
/// two boards, each sharded, are two runs, keyed by (rasterizer, device,
/// machine). A run whose shards each come once stays whole, whatever hosts
/// they ran on (a CI matrix deals shards to machines of its own choosing);
/// one whose repeated shards all name one host stays whole too, and its
/// shard given twice is an error.
fn by_board<'a>(run: Run<'a>) -> Vec<Run<'a>> {
    let repeated = run.shards.values().any(|given| given.len() > 1);
    let hosts: BTreeSet<&str> = run
        .shards
        .values()
        .flatten()
        .map(|i| i.report.machine.host.as_str())
        .collect();
    if run.count == 1 || !repeated || hosts.len() < 2 {
        return vec![run];
    }
    hosts
        .into_iter()
        .map(|host| {
            let mut shards: BTreeMap<usize, Vec<&Input>> = BTreeMap::new();
            for (k, given) in &run.shards {
                for input in given.iter().filter(|i| i.report.machine.host == host) {
                    shards.entry(*k).or_default().push(*input);
                }
            }
            Run {
                rows: run.rows.clone(),
                count: run.count,
                host: Some(host.to_owned()),
                shards,
            }
        })
        .collect()
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
    let mut caps = Caps::default();
    for (base, from) in &cases[0] {
        let mut entry = base.clone();
        entry.results.clear();
        entry.page = None;
        let mut page_from = None;
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
            let mut place = |file: &str| -> Option<(PathBuf, String)> {
                match inside(file) {
                    true => Some((input.dir.join(file), format!("{prefix}{file}"))),
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
                page_from = page_from.take().or(placed);
            }
            for (result, label) in case.results.iter().zip(&labels[r]) {
                let mut result = result.clone();
                result.rasterizer = label.clone();
                let placed: Vec<(PathBuf, String)> =
                    result.files.iter().filter_map(|f| place(f)).collect();
                // The pictures of a result count against the merged
                // report's cap, not each shard's.
                let pictured = placed.iter().any(|(_, to)| is_picture(to));
                let keep_pictures = !pictured || caps.picture();
                result.files = Vec::new();
                for (from, to) in placed {
                    if keep_pictures || !is_picture(&to) {
                        result.files.push(to.clone());
                        copies.push((from, to));
                    }
                }
                entry.results.push(result);
            }
        }
        if let Some((from, to)) = page_from {
            let problem = cards_of(&entry).iter().any(|c| c.is_problem());
            if caps.page(problem) {
                entry.page = Some(to.clone());
                copies.push((from, to));
            }
        }
        merged.push(entry);
    }
    (merged, copies)
}

/// The caps on pictures and pages (`report/limits.rs`), taken over the
/// merged report as a whole, in its case order: shards that each kept
/// under a cap may together exceed it.
#[derive(Default)]
struct Caps {
    pictured: usize,
    problem_pages: usize,
    other_pages: usize,
}

impl Caps {
    /// Takes a place for one result's pictures, if any is left.
    fn picture(&mut self) -> bool {
        take(&mut self.pictured, MAX_PICTURED)
    }

    /// Takes a place for a case's page, if any is left.
    fn page(&mut self, problem: bool) -> bool {
        match problem {
            true => take(&mut self.problem_pages, MAX_PROBLEM_PAGES),
            false => take(&mut self.other_pages, MAX_PAGES),
        }
    }
}

fn take(count: &mut usize, cap: usize) -> bool {
    let free = *count < cap;
    *count += usize::from(free);
    free
}

/// Whether a file a result names is one of its PNG pictures (capped), not
/// an EXR error map (every result with an error keeps its own).
fn is_picture(file: &str) -> bool {
    file.ends_with(".png")
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
    use crate::report::json::ResultEntry;

    /// A report of `ids` judged `pass` by production, as shard `shard` on `host`.
    fn input(ids: &[&str], shard: Option<&str>, host: &str) -> Input {
        let mut report = Report::of_production_run();
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
                case.results.push(ResultEntry::bare("production", "pass"));
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

    #[test]
    fn one_driver_sharded_on_two_boards_is_a_row_per_board() {
        // a b c d on two boards, each dealt to 2 shards: a c, b d.
        let shards = |host: &str| {
            [
                input(&["a", "c"], Some("1/2"), host),
                input(&["b", "d"], Some("2/2"), host),
            ]
        };
        let [a1, a2] = shards("board-a");
        let [b1, b2] = shards("board-b");
        let merged = merge(&[a1.clone(), b2, a2.clone(), b1], Vec::new()).unwrap();
        let rows: Vec<&str> = merged
            .report
            .rasterizers
            .iter()
            .map(|r| r.name.as_str())
            .collect();
        assert_eq!(rows, ["production on board-a", "production on board-b"]);
        assert_eq!(ids(&merged), ["a", "b", "c", "d"]);
        assert_eq!(merged.runs, 2);
        // One board's shards given twice is still two verdicts per case.
        let errors = merge(&[a1.clone(), a2, a1], Vec::new()).unwrap_err();
        assert!(errors[0].contains("given 2 times"), "{errors:?}");
        // Shards of one run on CI machines of their own: one row.
        let one = input(&["a", "c"], Some("1/2"), "runner-7");
        let two = input(&["b", "d"], Some("2/2"), "runner-3");
        assert_eq!(merge(&[one, two], Vec::new()).unwrap().runs, 1);
    }

    #[test]
    fn picture_and_page_caps_hold_over_the_merged_report() {
        // Two shards, each under the caps, over them together.
        let named = |k: usize| format!("c{k:05}");
        let all: Vec<String> = (0..MAX_PROBLEM_PAGES + 10).map(named).collect();
        let shard = |k: usize| {
            let ids: Vec<&str> = all
                .iter()
                .skip(k - 1)
                .step_by(2)
                .map(String::as_str)
                .collect();
            let mut shard = input(&ids, Some(&format!("{k}/2")), "ci");
            for case in &mut shard.report.cases {
                case.page = Some(format!("pages/{}.html", case.id));
                let result = &mut case.results[0];
                result.verdict = "fail";
                result.files = vec![
                    format!("images/{}/production.png", case.id),
                    format!("exr/{}/production.exr", case.id),
                ];
            }
            shard
        };
        let merged = merge(&[shard(1), shard(2)], Vec::new()).unwrap();
        let pictures = merged
            .copies
            .iter()
            .filter(|(_, to)| to.ends_with(".png"))
            .count();
        let maps = merged
            .copies
            .iter()
            .filter(|(_, to)| to.ends_with(".exr"))
            .count();
        assert_eq!(pictures, MAX_PICTURED);
        assert_eq!(maps, all.len(), "error maps are not capped");
        let pages = merged.report.cases.iter().filter(|c| c.page.is_some());
        assert_eq!(pages.count(), MAX_PROBLEM_PAGES);
        let pictured = merged
            .report
            .cases
            .iter()
            .filter(|c| c.results[0].files.iter().any(|f| f.ends_with(".png")))
            .count();
        assert_eq!(pictured, MAX_PICTURED);
        // The first cases in the merged order keep theirs.
        assert!(merged.report.cases[0].results[0].files[0].ends_with(".png"));
    }
}
