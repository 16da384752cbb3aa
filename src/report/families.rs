//! A run's cases counted per family (the first segment of a case id): how
//! many, how many did not run, and per rasterizer its results by verdict;
//! the index's family table is drawn from these counts, which a run keeps
//! over every case while it keeps only some entries whole (`digest.rs`).

use super::json::CaseEntry;

/// The verdicts counted per family, in this order.
pub const VERDICTS: [&str; 6] = ["pass", "fail", "flaky", "foil", "error", "unsupported"];

/// One family's cases and, per rasterizer, its results by verdict
/// ([`VERDICTS`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FamilyCount {
    pub family: String,
    pub cases: usize,
    /// Cases that did not run (unreadable, reference failed, over a limit,
    /// not run).
    pub problems: usize,
    pub verdicts: Vec<[usize; VERDICTS.len()]>,
}

/// The families of `cases`, in order of first appearance, counted.
pub fn families_of(cases: &[CaseEntry], rasterizers: usize) -> Vec<FamilyCount> {
    let mut families = Vec::new();
    for case in cases {
        count_family(&mut families, case, rasterizers);
    }
    families
}

/// Counts `case` in its family, a new one at the end when it has none yet.
pub fn count_family(families: &mut Vec<FamilyCount>, case: &CaseEntry, rasterizers: usize) {
    // The last family is almost always the case's: cases come sorted by id.
    let at = match families.iter().rposition(|f| f.family == case.family) {
        Some(at) => at,
        None => {
            families.push(FamilyCount {
                family: case.family.clone(),
                verdicts: vec![[0; VERDICTS.len()]; rasterizers],
                ..FamilyCount::default()
            });
            families.len() - 1
        }
    };
    let family = &mut families[at];
    family.cases += 1;
    family.problems += usize::from(case.status != "ran");
    for (result, counts) in case.results.iter().zip(&mut family.verdicts) {
        if let Some(v) = VERDICTS.iter().position(|v| *v == result.verdict) {
            counts[v] += 1;
        }
    }
}
