//! Every chart of a report, in the order they are shown, the notes on what
//! was not drawn, and the charts written to `DIR/plots/`.

use std::path::{Path, PathBuf};

use super::by_family::{aa_error, distribution_plot, ulp_error};
use super::by_samples::{aa_against_samples, time_against_samples};
use super::plot::{Plot, FOLDER};
use crate::report::files::write_file;
use crate::report::json::Report;

/// Every chart and the notes on what was not drawn.
fn everything(report: &Report) -> (Vec<Plot>, Vec<String>) {
    let mut plots = Vec::new();
    let mut notes = Vec::new();
    let mut add = |r: Result<Plot, Vec<String>>| match r {
        Ok(p) => plots.push(p),
        Err(n) => notes.extend(n),
    };
    add(distribution_plot(
        report,
        "aa-error-by-family.svg",
        "Antialiasing error by family",
        "edge RMS of resolved − exact area",
        "antialiasing error",
        "Per family and rasterizer, each antialiased case's RMS of resolved − exact area over \
         edge pixels (SPEC.md §14.3): box from the lower to the upper quartile, bar at the \
         median, whiskers to the extremes, dots the cases; 0 is exact.",
        aa_error,
    ));
    add(distribution_plot(
        report,
        "interpolation-ulp-by-family.svg",
        "Interpolation error by family",
        "largest error over channels (ulp)",
        "interpolation error",
        "Per family and rasterizer, each case's largest interpolation error in ulp over its \
         depth and attribute channels (max_ulp): box from the lower to the upper quartile, \
         bar at the median, whiskers to the extremes, dots the cases; 0 is exact.",
        ulp_error,
    ));
    aa_against_samples(report, &mut plots, &mut notes);
    time_against_samples(report, &mut plots, &mut notes);
    // Two rasterizers whose names differ only in punctuation.
    let mut seen: Vec<String> = Vec::new();
    for p in &mut plots {
        let stem = p.file.trim_end_matches(".svg").to_owned();
        let mut k = 1;
        while seen.contains(&p.file) {
            k += 1;
            p.file = format!("{stem}-{k}.svg");
        }
        seen.push(p.file.clone());
    }
    (plots, notes)
}

/// The report's charts, in the order they are shown.
pub fn plots(report: &Report) -> Vec<Plot> {
    everything(report).0
}

/// One line each on what the charts leave out: rasterizers with zero error
/// everywhere (drawn as no chart or said in the caption), area methods,
/// values that are not finite.
pub fn notes(report: &Report) -> Vec<String> {
    let mut notes = everything(report).1;
    let (listed, all) = (report.cases.len(), report.totals.cases);
    if listed < all {
        notes.push(format!(
            "The charts are drawn from {listed} of the {all} cases (the first and those worth a look)."
        ));
    }
    notes
}

/// Writes every chart to `DIR/plots/<file>` and returns the paths.
pub fn write(dir: &Path, report: &Report) -> Result<Vec<PathBuf>, String> {
    plots(report)
        .iter()
        .map(|p| write_file(&dir.join(FOLDER).join(&p.file), p.svg.as_bytes()))
        .collect()
}
