//! The matrix's data: one [`Row`] per rasterizer, one [`Cell`] per case
//! family, and the family a case belongs to.

use crate::explore::probe::diagnosis::Diagnosis;
use crate::scene::FillRule;

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
pub(super) fn family_rank(f: &str) -> (usize, String) {
    let known = ["triangles", "lines", "hard", "top-level"];
    (
        known.iter().position(|k| *k == f).unwrap_or(known.len()),
        f.to_owned(),
    )
}
