//! A conservative test's growth: how far past the pixel's centre the
//! square it asks about reaches, (½ + u) px for an uncertainty u, held as
//! an exact fraction of fixed-point units, and the one comparison every
//! test makes with it, in i128 where the products fit and in big integers
//! where they do not.

use std::cmp::Ordering;

use dashu_int::IBig;

use crate::scene::Number;

/// The half side s of the square a test asks about, in units of 1/`one`
/// px (2^-f px in fixed point): s = num / den = (½ + u)·one with u = p/q
/// in lowest terms, so num = (q + 2p)·one and den = 2q; or the
/// uncertainty alone, u·one = p·one / q (what the bounding-box tests
/// compare with).
#[derive(Clone, Debug)]
pub(crate) struct Growth {
    num: IBig,
    den: IBig,
    /// `num` and `den` when both fit in i128: the fast path's operands.
    small: Option<(i128, i128)>,
}

impl Growth {
    /// (½ + u) px in units of 1/`one` px: the grown square's half side.
    pub(crate) fn half_side(uncertainty: &Number, one: i128) -> Growth {
        let p = uncertainty.numerator().clone();
        let q = IBig::from(uncertainty.denominator().clone());
        Growth::new(
            (&q + &p * IBig::from(2u8)) * IBig::from(one),
            q * IBig::from(2u8),
        )
    }

    /// u px in units of 1/`one` px: how far the grown square reaches past
    /// the pixel's own border.
    pub(crate) fn margin(uncertainty: &Number, one: i128) -> Growth {
        let p = uncertainty.numerator().clone();
        let q = IBig::from(uncertainty.denominator().clone());
        Growth::new(p * IBig::from(one), q)
    }

    fn new(num: IBig, den: IBig) -> Growth {
        let small = i128::try_from(&num).ok().zip(i128::try_from(&den).ok());
        Growth { num, den, small }
    }

    /// s as num / den, den > 0: what the line and point tests compare
    /// with (`lines.rs`).
    pub(crate) fn fraction(&self) -> (&IBig, &IBig) {
        (&self.num, &self.den)
    }

    /// value against k·s exactly (k ≥ 0, s this growth): value·den
    /// against k·num. In i128 when both products fit (always, for the
    /// uncertainties a case can state with a denominator below 2^40:
    /// |value| < 2^68 and k < 2^36, so |value·den| < 2^109 and k·num <
    /// 2^36·2^42·2^18); in big integers otherwise, never wrapping.
    #[inline]
    pub(crate) fn compare(&self, value: i128, k: i128) -> Ordering {
        if let Some((num, den)) = self.small {
            if let (Some(left), Some(right)) = (value.checked_mul(den), k.checked_mul(num)) {
                return left.cmp(&right);
            }
        }
        (IBig::from(value) * &self.den).cmp(&(IBig::from(k) * &self.num))
    }

    /// Whether value ≤ k·s.
    #[inline]
    pub(crate) fn at_most(&self, value: i128, k: i128) -> bool {
        self.compare(value, k) != Ordering::Greater
    }

    /// Whether value ≥ k·s.
    #[inline]
    pub(crate) fn at_least(&self, value: i128, k: i128) -> bool {
        self.compare(value, k) != Ordering::Less
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fast_path_agrees_with_big_integers_at_the_edges() {
        let cases = [
            Number::ZERO,
            Number::ratio(1, 512),
            Number::ratio(3, 4),
            Number::ratio(1, 3),
            Number::ONE,
        ];
        for u in &cases {
            let g = Growth::half_side(u, 1 << 17);
            let big = Growth {
                small: None,
                ..g.clone()
            };
            for value in [i128::MIN / 2, -(1 << 90), -5, 0, 7, 1 << 66, i128::MAX / 3] {
                for k in [0, 1, 1 << 35, 1 << 100] {
                    assert_eq!(
                        g.compare(value, k),
                        big.compare(value, k),
                        "{u} {value} {k}"
                    );
                }
            }
        }
        // s = (½ + ¾)·2 = 5/2 at one fraction bit: 5 ≤ 2·(5/2), 6 is not.
        let g = Growth::half_side(&Number::ratio(3, 4), 2);
        assert!(g.at_most(5, 2) && !g.at_most(6, 2));
        let m = Growth::margin(&Number::ratio(1, 3), 1);
        assert!(m.at_most(0, 3) && m.at_most(1, 3) && !m.at_most(2, 3));
    }
}
