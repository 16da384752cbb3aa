//! What a convention probe concludes (`clip.rs`, `points.rs`): scenes
//! stated under two of a few combinations of a convention, each drawn by
//! the candidate and compared with the reference under every combination;
//! `mismatches[k][c]` counts the samples that differ under statement k
//! and combination c.

/// The conclusion from the mismatch counts.
pub(super) struct Verdict {
    /// Every sample of both statements is the reference's under what each
    /// states: it follows each case's convention.
    pub follows: bool,
    /// One combination explains every sample of both statements: its own.
    pub fixed: bool,
    /// The combination that explains the first statement best (its own,
    /// when `fixed`).
    pub best: usize,
    /// The combination with the fewest differing samples over both.
    pub nearest: usize,
}

/// `mismatches` over `combinations` per statement, the statements being
/// the combinations `stated` (indices into them).
pub(super) fn verdict(mismatches: &[Vec<usize>], stated: [usize; 2]) -> Verdict {
    let combinations = mismatches[0].len();
    let best = |k: usize| {
        (0..combinations)
            .min_by_key(|&c| mismatches[k][c])
            .expect("a combination")
    };
    let (b0, b1) = (best(0), best(1));
    let exact = mismatches[0][b0] == 0 && mismatches[1][b1] == 0;
    let nearest = (0..combinations)
        .min_by_key(|&c| mismatches[0][c] + mismatches[1][c])
        .expect("a combination");
    Verdict {
        follows: exact && b0 == stated[0] && b1 == stated[1],
        fixed: exact && b0 == b1,
        best: b0,
        nearest,
    }
}
