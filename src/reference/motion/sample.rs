//! One primitive at one sample over the shutter: the covered measure and
//! the undecided one, isolation refined until the bound is small enough.

use dashu_int::IBig;
use dashu_ratio::RBig;

use super::certified::max_bound;
use super::moving::{Moving, Rules};

/// Isolating intervals of width 2^-(bits+1)/|c2| in τ. A primitive has at
/// most 12 irrational roots at a sample (a line: 3 pieces, 2 quadratics
/// each; a triangle: 4 quadratics), each undecided over at most 2^-(bits+1),
/// half of which is the bound: 3·2^-bits in τ, at most 3·2^(16-bits) of a
/// shutter at least 2^-16 long. 60 bits give 2^-42 < 2^-40 on the first
/// pass; [`sample_measure`] refines anyway should that ever fail.
pub(super) const ISOLATION_BITS: usize = 60;

/// The largest refinement tried before the bound assertion fails.
pub(super) const MAX_ISOLATION_BITS: usize = 1024;

/// (value, bound) of one primitive at one sample, in units of τ: the
/// covered measure plus half of the undecided one, and that half. The
/// isolation is refined until the bound is at most [`max_bound`] of the
/// span, which is asserted.
pub(super) fn sample_measure(
    mover: &Moving,
    p: &[IBig; 2],
    span: [&RBig; 2],
    rules: Rules,
    isolation: usize,
) -> (RBig, RBig) {
    let allowed = max_bound() * (span[1] - span[0]);
    let mut bits = isolation;
    loop {
        let measured = mover.measure(p, span, bits, rules);
        let bound = measured.undecided / RBig::from(2u8);
        if bound <= allowed || bits >= MAX_ISOLATION_BITS {
            assert!(
                bound <= allowed,
                "time coverage bound {} exceeds 2^-40 of the shutter at {p:?} after {bits}-bit isolation",
                bound / (span[1] - span[0])
            );
            return (measured.covered + &bound, bound);
        }
        bits *= 2;
    }
}
