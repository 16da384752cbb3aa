//! Coverage against the reference, sample by sample. With antialiasing a
//! pixel holds N sample slots, and the comparison is the same at sample
//! granularity (SPEC.md §14.3). A candidate without a mask (an area method,
//! `samples` = 0), or one whose slots do not line up with the reference's,
//! has no samples to compare: `samples` is then 0 and the mask empty.

use super::ties::forgiven;
use crate::frame::Frame;
use crate::reference::TieSet;

/// How one sample of a candidate differs from the reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SampleDiff {
    Same,
    /// Covered fewer times than the reference covers it.
    Missing,
    /// Covered more times than the reference covers it.
    Extra,
    /// Covered as often, but the last primitive to cover it differs: the
    /// sample went to the wrong side of a shared edge.
    WrongOwner,
    /// A tie sample (exactly on an edge) that a candidate with no tie rule
    /// decided otherwise than the reference, by a choice of sides: accepted
    /// and counted apart (SPEC.md §3.1.1), not a mismatch.
    Tie,
}

#[derive(Clone, Debug, PartialEq)]
pub struct CoverageMetrics {
    /// Samples compared: every sample of the frame, or 0 when the candidate
    /// has no mask.
    pub samples: u64,
    pub reference_covered: u64,
    pub candidate_covered: u64,
    /// Samples covered fewer times than the reference.
    pub missing: u64,
    /// Samples covered more times than the reference.
    pub extra: u64,
    pub wrong_owner: u64,
    /// One entry per sample.
    pub mask: Vec<SampleDiff>,
}

impl CoverageMetrics {
    pub fn mismatched(&self) -> u64 {
        self.missing + self.extra + self.wrong_owner
    }

    /// Whether the candidate's samples were compared at all.
    pub fn has_mask(&self) -> bool {
        self.samples > 0
    }
}

/// Whether the candidate's sample slots line up with the reference's.
pub fn comparable(reference: &Frame, candidate: &Frame) -> bool {
    candidate.samples > 0
        && candidate.samples == reference.samples
        && candidate.sample_count() == reference.sample_count()
        && candidate.last.len() == reference.last.len()
}

pub fn compare(reference: &Frame, candidate: &Frame) -> CoverageMetrics {
    compare_off_ties(reference, candidate, None)
}

/// [`compare`], for a candidate with no tie rule judged off `ties`: a tie
/// sample whose outcome a choice of sides gives is the same (it is counted
/// apart, `ties.rs`).
pub fn compare_off_ties(
    reference: &Frame,
    candidate: &Frame,
    ties: Option<&TieSet>,
) -> CoverageMetrics {
    let mut m = CoverageMetrics {
        samples: reference.sample_count() as u64,
        reference_covered: reference.covered_samples(),
        candidate_covered: candidate.covered_samples(),
        missing: 0,
        extra: 0,
        wrong_owner: 0,
        mask: Vec::with_capacity(reference.sample_count()),
    };
    if !comparable(reference, candidate) {
        m.samples = 0;
        return m;
    }
    for i in 0..reference.sample_count() {
        let (r, c) = (reference.coverage[i], candidate.coverage[i]);
        let diff = if forgiven(ties, candidate, i) {
            if (c, candidate.last[i]) == (r, reference.last[i]) {
                SampleDiff::Same
            } else {
                SampleDiff::Tie
            }
        } else if c < r {
            m.missing += 1;
            SampleDiff::Missing
        } else if c > r {
            m.extra += 1;
            SampleDiff::Extra
        } else if reference.last[i] != candidate.last[i] {
            m.wrong_owner += 1;
            SampleDiff::WrongOwner
        } else {
            SampleDiff::Same
        };
        m.mask.push(diff);
    }
    m
}
