//! A candidate with no tie rule (`fill_rule: "none"`, SPEC.md §3.1.1)
//! judged off the ties: at each tie sample of the reference's tie set
//! (`reference::tie_set`) any outcome a choice of sides gives is accepted
//! and counted here, apart; every other sample is judged as usual. The
//! counts are reported, never hidden, and never a failure.

use serde::Serialize;

use super::counted::counted;
use crate::frame::Frame;
use crate::reference::{TieOutcome, TieSet};

/// What a candidate with no tie rule made of the tie samples.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct TieMetrics {
    /// Samples lying exactly on an edge of some primitive.
    pub tie_samples: u64,
    /// Tie samples it decided otherwise than the reference under the
    /// case's rule, by a choice of sides (accepted).
    pub other_side: u64,
    /// Tie samples covered more often than any consistent rule covers
    /// them: both sides of a shared edge took them (accepted, counted).
    pub overdrawn: u64,
    /// Tie samples covered less often than every consistent rule covers
    /// them: neither side took them (accepted, counted).
    pub holes: u64,
    /// Tie samples whose outcome no choice of sides gives (judged as any
    /// other sample, so already among the coverage failures).
    pub not_allowed: u64,
    /// Tie samples the reference covers under the case's rule: a candidate
    /// that draws nothing fails (SPEC.md §6.1) only where the reference
    /// covers more than these.
    pub reference_covered: u64,
}

impl TieMetrics {
    /// The console's and the case page's line.
    pub fn line(&self) -> String {
        let mut line = format!(
            "judged off the ties: {}, {} overdrawn, {}",
            counted(self.tie_samples, "tie sample", "tie samples"),
            self.overdrawn,
            counted(self.holes, "hole", "holes")
        );
        if self.other_side > 0 {
            line.push_str(&format!(
                ", {} decided otherwise than the case's rule",
                self.other_side
            ));
        }
        if self.not_allowed > 0 {
            line.push_str(&format!(
                ", {} by no choice of sides (judged)",
                self.not_allowed
            ));
        }
        line
    }
}

/// Whether slot `i`'s outcome in `candidate` is one a choice of sides
/// gives at a tie sample of `ties` (then it is not judged against the
/// reference's).
pub fn forgiven(ties: Option<&TieSet>, candidate: &Frame, i: usize) -> bool {
    ties.and_then(|t| t.get(i)).is_some_and(|tie| {
        matches!(
            tie.outcome(candidate.coverage[i], candidate.last[i]),
            TieOutcome::Allowed { .. }
        )
    })
}

/// The tie counts of `candidate`; `None` when its slots do not line up
/// with the tie set's (no mask: an area method has no samples to tie).
pub fn measure(ties: &TieSet, reference: &Frame, candidate: &Frame) -> Option<TieMetrics> {
    if candidate.samples == 0
        || candidate.sample_count() != reference.sample_count()
        || candidate.last.len() != reference.last.len()
    {
        return None;
    }
    let mut m = TieMetrics::default();
    for (&i, tie) in &ties.samples {
        if i >= candidate.sample_count() {
            continue;
        }
        m.tie_samples += 1;
        m.reference_covered += u64::from(reference.coverage[i] > 0);
        let (count, last) = (candidate.coverage[i], candidate.last[i]);
        match tie.outcome(count, last) {
            TieOutcome::Allowed { overdrawn, hole } => {
                m.overdrawn += u64::from(overdrawn);
                m.holes += u64::from(hole);
                m.other_side +=
                    u64::from((count, last) != (reference.coverage[i], reference.last[i]));
            }
            TieOutcome::NotAllowed => m.not_allowed += 1,
        }
    }
    Some(m)
}

/// For a candidate judged under a tie rule whose coverage differs: how
/// many of the differing samples (`differs`, of `slots`) are ties (lie
/// exactly on an edge), in a
/// sentence, or `None` when none is. A rule that differs only there is
/// another rule, or none (SPEC.md §3.1.1); the sentence says so.
pub fn named(ties: &TieSet, slots: usize, differs: impl Fn(usize) -> bool) -> Option<String> {
    let differing = (0..slots).filter(|&i| differs(i)).count();
    let tied = ties
        .samples
        .keys()
        .filter(|&&i| i < slots && differs(i))
        .count();
    (tied > 0).then(|| {
        let all = if tied == differing {
            "; it differs only at ties, so it follows another tie rule than it is judged under, or none (a library with no tie rule declares fill_rule \"none\", SPEC.md §3.1.1)"
        } else {
            ""
        };
        format!(
            "ties: {tied} of the {differing} differing samples lie exactly on an edge{all}"
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::TieSample;

    #[test]
    fn counts_each_outcome_apart() {
        let mut ties = TieSet::default();
        let shared = TieSample {
            inside: 0,
            last_inside: 0,
            on_edge: vec![1, 2],
            fewest: 1,
            most: 1,
        };
        for slot in 0..4 {
            ties.samples.insert(slot, shared.clone());
        }
        let mut reference = Frame::new(3, 2, false, 0);
        let mut candidate = Frame::new(3, 2, false, 0);
        for slot in 0..4 {
            reference.coverage[slot] = 1;
            reference.last[slot] = 1;
        }
        // Slot 0 as the reference, 1 to the other side, 2 overdrawn, 3 a
        // hole; slot 4 is no tie.
        let outcomes = [(1, 1), (1, 2), (2, 2), (0, 0), (1, 1)];
        for (slot, (count, last)) in outcomes.into_iter().enumerate() {
            candidate.coverage[slot] = count;
            candidate.last[slot] = last;
        }
        let m = measure(&ties, &reference, &candidate).expect("slots line up");
        assert_eq!(
            m,
            TieMetrics {
                tie_samples: 4,
                other_side: 3,
                overdrawn: 1,
                holes: 1,
                not_allowed: 0,
                reference_covered: 4,
            }
        );
        assert_eq!(
            m.line(),
            "judged off the ties: 4 tie samples, 1 overdrawn, 1 hole, 3 decided otherwise than the case's rule"
        );
        assert!(forgiven(Some(&ties), &candidate, 2));
        assert!(!forgiven(Some(&ties), &candidate, 4));
        assert!(!forgiven(None, &candidate, 0));
        let one_of_two = named(&ties, 6, |i| i == 1 || i == 4).expect("slot 1 is a tie");
        assert!(
            one_of_two.starts_with("ties: 1 of the 2 differing"),
            "{one_of_two}"
        );
        assert!(named(&ties, 6, |i| i == 4).is_none());
        let only = named(&ties, 6, |i| i == 1).expect("a tie");
        assert!(only.contains("differs only at ties"), "{only}");
    }
}
