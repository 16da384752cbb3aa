//! The measure of the instants at which a predicate holds, when the
//! predicate can change only at roots of given polynomials (SPEC.md §15.2).
//!
//! Every root in the span is an exact rational or lies inside an isolating
//! interval; overlapping ones merge into zones. Between zones no root lies,
//! so every polynomial keeps its sign and the predicate is constant: it is
//! decided once, exactly, at a rational instant strictly inside the gap.
//! A zone of positive width is undecided: the covered part of it is
//! somewhere between none and all of it.

use dashu_ratio::RBig;

use super::quadratic::{Quadratic, Root};

/// Measures of instants, in units of τ.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Measure {
    /// Instants in gaps where the predicate holds.
    pub covered: RBig,
    /// Total width of the zones around irrational roots, where it was not
    /// decided.
    pub undecided: RBig,
}

impl Measure {
    pub fn add(&mut self, other: Measure) {
        self.covered += other.covered;
        self.undecided += other.undecided;
    }
}

/// The instants of [lo, hi] (lo < hi) at which `holds` is true, where
/// `holds` is constant between consecutive real roots of `polys`.
/// Irrational roots are isolated with `bits` (see [`Quadratic::roots`]).
pub fn measure(
    span: [&RBig; 2],
    polys: &[Quadratic],
    bits: usize,
    holds: &mut dyn FnMut(&RBig) -> bool,
) -> Measure {
    let [lo, hi] = span;
    debug_assert!(lo < hi);
    let mut zones: Vec<(RBig, RBig)> = Vec::new();
    for root in polys.iter().flat_map(|p| p.roots(bits)) {
        match root {
            Root::At(t) => {
                if lo <= &t && &t <= hi {
                    zones.push((t.clone(), t));
                }
            }
            Root::Within(a, b) => {
                if &b > lo && &a < hi {
                    zones.push((a.max(lo.clone()), b.min(hi.clone())));
                }
            }
        }
    }
    zones.sort_by(|a, b| a.0.cmp(&b.0));
    let mut result = Measure::default();
    let gap =
        |from: &RBig, to: &RBig, result: &mut Measure, holds: &mut dyn FnMut(&RBig) -> bool| {
            if from < to {
                let inside = (from + to) / RBig::from(2u8);
                if holds(&inside) {
                    result.covered += to - from;
                }
            }
        };
    let mut cursor = lo.clone();
    let mut zones = zones.into_iter().peekable();
    while let Some((start, mut end)) = zones.next() {
        let mut merged = 1;
        while let Some((_, next_end)) = zones.next_if(|next| next.0 <= end) {
            end = end.max(next_end);
            merged += 1;
        }
        gap(&cursor, &start, &mut result, holds);
        if start < end {
            // One isolating interval alone holds one root and no other, its
            // ends included: the predicate is constant from `start` to the
            // root and from the root to `end`. Where it is the same on both
            // sides, the root changes nothing and the zone is decided.
            let width = &end - &start;
            let before = holds(&start);
            if merged == 1 && before == holds(&end) {
                if before {
                    result.covered += width;
                }
            } else {
                result.undecided += width;
            }
        }
        cursor = end;
    }
    gap(&cursor, hi, &mut result, holds);
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::IBig;

    fn q(c0: i64, c1: i64, c2: i64) -> Quadratic {
        Quadratic {
            c: [c0, c1, c2].map(IBig::from),
        }
    }

    fn r(n: i64, d: i64) -> RBig {
        RBig::from_parts_signed(n.into(), d.into())
    }

    #[test]
    fn rational_roots_measure_exactly() {
        // 4τ − 1 > 0 and 3 − 4τ > 0: τ in (¼, ¾).
        let polys = [q(-1, 4, 0), q(3, -4, 0)];
        let mut holds = |t: &RBig| *t > r(1, 4) && *t < r(3, 4);
        let m = measure([&RBig::ZERO, &RBig::ONE], &polys, 8, &mut holds);
        assert_eq!(m.covered, r(1, 2));
        assert_eq!(m.undecided, RBig::ZERO);
        // Clipped to a span that starts inside.
        let m = measure([&r(1, 2), &RBig::ONE], &polys, 8, &mut holds);
        assert_eq!(m.covered, r(1, 4));
    }

    #[test]
    fn irrational_roots_leave_narrow_zones() {
        // 2τ² − 1 < 0: τ < 1/√2.
        let polys = [q(-1, 0, 2)];
        let mut holds = |t: &RBig| t * t * RBig::from(2) < RBig::ONE;
        let bits = 40;
        let m = measure([&RBig::ZERO, &RBig::ONE], &polys, bits, &mut holds);
        assert!(m.undecided > RBig::ZERO);
        assert!(m.undecided <= r(1, 1 << (bits + 2)));
        // covered ≤ 1/√2 ≤ covered + undecided.
        let two = RBig::from(2);
        assert!(&m.covered * &m.covered * &two < RBig::ONE);
        let upper = &m.covered + &m.undecided;
        assert!(&upper * &upper * &two > RBig::ONE);
    }

    #[test]
    fn a_root_that_changes_nothing_leaves_no_zone() {
        // 2τ² − 1 has the root 1/√2 in the span, but the predicate (say,
        // another edge already excludes the sample) is false on both sides
        // of it, or true on both: the pixel's value stays a whole number.
        let polys = [q(-1, 0, 2)];
        for value in [false, true] {
            let m = measure([&RBig::ZERO, &RBig::ONE], &polys, 40, &mut |_| value);
            assert_eq!(m.undecided, RBig::ZERO);
            assert_eq!(m.covered, if value { RBig::ONE } else { RBig::ZERO });
        }
        // Two roots in one zone (here the same root twice, from two
        // polynomials) stay undecided: the predicate could change twice.
        let polys = [q(-1, 0, 2), q(-2, 0, 4)];
        let m = measure([&RBig::ZERO, &RBig::ONE], &polys, 40, &mut |_| true);
        assert!(m.undecided > RBig::ZERO);
    }
}
